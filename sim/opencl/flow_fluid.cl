// The fluid as the flow of the contour kernels (sim/opencl/FlowBinding.h): the curl of the cubic
// B-spline over the stream function ψ at the cell corners, as sim/StreamFunction.h samples it (the
// same reflection at the walls and clamping), in float32, and blended linearly in time between the
// step's start (s = 0) and end (s = 1) as sim/FluidFlow does, so RK4's mid-step samples (eq. 1) see
// the flow of that moment. flowField holds three ψ lattices of (nx + 3) × (ny + 3) corners (one
// ghost corner past each wall): at the step's start, halfway through it, and at its end
// (DeviceFluid keeps them, fluid.cl's streamFunction computes them); the halfway lattice answers
// s = ½ alone. Comes after flow.h.cl. Every helper is force-inlined: PoCL's vectoriser gives up on
// kernels that call large functions that are not inlined.

// Corners of one ψ lattice, and where each lattice starts in flowField.
VF_INLINE int streamStride(int nx) { return nx + 3; }
VF_INLINE int streamCorners(int nx, int ny) { return (nx + 3) * (ny + 3); }
#define STREAM_START 0
#define STREAM_HALFWAY 1
#define STREAM_END 2
#define STREAM_DAMPING_CELLS 2.0f  // StreamField::dampingCells

// s clamped to [0, 1]; 1 (the end) when the span is empty, as FluidFlow::blend. RK4 (contours.cl)
// passes its stages' s exactly (0, ½, 1), so its middle stages sample the halfway field alone.
VF_INLINE float streamBlend(float dt, float s)
{
    return dt > 0.0f ? clamp(s, 0.0f, 1.0f) : 1.0f;
}

// The sampler is written once for a type T with integer type I: float and int for one point
// (suffix Point), floatv and intv for lanes (suffix Lanes). `GATHER(f, k)` reads f[k] for each of
// T's values; `ANY(c)` whether a comparison holds for any of them. No float2 here: PoCL's loop
// vectoriser refuses them.
#define VF_GATHER_ONE(f, k) (f)[k]
#define VF_ANY_ONE(c) (c)
#define VF_DEFINE_STREAM_SAMPLER(T, I, S, CONVERT_T, CONVERT_I, GATHER, ANY)                     \
    /* detail::reflectInto: a lattice coordinate in [−n, 2n] reflected into [0, n], clamped     \
       beyond (NaN to 0: it fails `0 < g`); *sign is −1 where it was reflected. */              \
    VF_INLINE T streamReflect##S(T g, int n, T *sign)                                          \
    {                                                                                          \
        const I below = isless(g, (T)(0.0f)), above = isgreater(g, (T)(n));                   \
        *sign = select((T)(1.0f), (T)(-1.0f), below | above);                                  \
        g = select(g, -g, below);                                                              \
        g = select(g, (T)(2.0f * n) - g, above);                                               \
        return fmin(select((T)(0.0f), g, isless((T)(0.0f), g)), (T)(n));                       \
    }                                                                                          \
                                                                                               \
    /* detail::dampingAlong: m(o / band) outside the canvas along one axis, and *slope its      \
       derivative along the axis (1 and 0 inside). */                                          \
    VF_INLINE T streamDampingAlong##S(T g, float extent, float band, T *slope)                  \
    {                                                                                          \
        const I below = isless(g, (T)(0.0f));                                                  \
        const T s = fmin(fmax(select(g - extent, -g, below) / band, (T)(0.0f)), (T)(1.0f));      \
        const T dm = -30.0f * s * s * (1.0f - s) * (1.0f - s) / band;                          \
        *slope = select(dm, -dm, below);                                                       \
        return 1.0f - s * s * s * (10.0f - 15.0f * s + 6.0f * s * s);                          \
    }                                                                                          \
                                                                                               \
    /* The 4 × 4 corners around a point and the spline's weights there (StreamField::Stencil): \
       w the B-spline, d its derivative, dd its second derivative, along x and along y; and    \
       StreamField::dampingAt, φ and its gradient. */                                          \
    typedef struct {                                                                           \
        I corner;                                                                              \
        T flipX, flipY;                                                                        \
        T wx[4], dx[4], ddx[4], wy[4], dy[4], ddy[4];                                           \
        T damp, dampX, dampY;                                                                  \
    } StreamStencil##S;                                                                        \
                                                                                               \
    VF_INLINE void streamWeights##S(T t, T *w, T *d, T *dd)                                    \
    {                                                                                          \
        const T u = 1.0f - t, t2 = t * t, t3 = t2 * t;                                         \
        w[0] = u * u * u / 6.0f;                                                               \
        w[1] = (3.0f * t3 - 6.0f * t2 + 4.0f) / 6.0f;                                          \
        w[2] = (-3.0f * t3 + 3.0f * t2 + 3.0f * t + 1.0f) / 6.0f;                              \
        w[3] = t3 / 6.0f;                                                                      \
        d[0] = -0.5f * u * u;                                                                  \
        d[1] = 0.5f * (3.0f * t2 - 4.0f * t);                                                  \
        d[2] = 0.5f * (-3.0f * t2 + 2.0f * t + 1.0f);                                          \
        d[3] = 0.5f * t2;                                                                      \
        dd[0] = u;                                                                             \
        dd[1] = 3.0f * t - 2.0f;                                                               \
        dd[2] = 1.0f - 3.0f * t;                                                               \
        dd[3] = t;                                                                             \
    }                                                                                          \
                                                                                               \
    VF_INLINE StreamStencil##S streamStencil##S(int nx, int ny, float hx, float hy, T x, T y)  \
    {                                                                                          \
        StreamStencil##S s;                                                                    \
        const T gx = streamReflect##S(x / hx, nx, &s.flipX);                                   \
        const T gy = streamReflect##S(y / hy, ny, &s.flipY);                                   \
        const I i = min(CONVERT_I(gx), (I)(nx - 1)), j = min(CONVERT_I(gy), (I)(ny - 1));      \
        streamWeights##S(gx - CONVERT_T(i), s.wx, s.dx, s.ddx);                                \
        streamWeights##S(gy - CONVERT_T(j), s.wy, s.dy, s.ddy);                                \
        s.corner = j * streamStride(nx) + i;                                                   \
        T slopeX, slopeY;                                                                      \
        const T mx = streamDampingAlong##S(x, nx * hx, STREAM_DAMPING_CELLS * hx, &slopeX);    \
        const T my = streamDampingAlong##S(y, ny * hy, STREAM_DAMPING_CELLS * hy, &slopeY);    \
        s.damp = mx * my;                                                                      \
        s.dampX = slopeX * my;                                                                 \
        s.dampY = mx * slopeY;                                                                 \
        return s;                                                                              \
    }                                                                                          \
                                                                                               \
    /* Two sums Σ_b wy[b] · Σ_a wx[a] · psi over the stencil's 4 × 4 corners, with the weights   \
       (wxA, wyA) and (wxB, wyB), from one gather of the corners (StreamField::Stencil::sums). */ \
    VF_INLINE void streamSums##S(__global const float *psi, int nx, StreamStencil##S s, const T *wxA, const T *wyA, \
                                 const T *wxB, const T *wyB, T *a, T *b)                       \
    {                                                                                          \
        *a = 0.0f;                                                                             \
        *b = 0.0f;                                                                             \
        for (int r = 0; r < 4; ++r) {                                                          \
            const I k = s.corner + r * streamStride(nx);                                       \
            const T p0 = GATHER(psi, k), p1 = GATHER(psi, k + 1), p2 = GATHER(psi, k + 2),     \
                    p3 = GATHER(psi, k + 3);                                                   \
            *a += wyA[r] * (wxA[0] * p0 + wxA[1] * p1 + wxA[2] * p2 + wxA[3] * p3);            \
            *b += wyB[r] * (wxB[0] * p0 + wxB[1] * p1 + wxB[2] * p2 + wxB[3] * p3);            \
        }                                                                                      \
    }                                                                                          \
                                                                                               \
    /* StreamField::velocity of the lattice at psi. */                                         \
    VF_INLINE void streamVelocity##S(__global const float *psi, int nx, float hx, float hy,    \
                                     StreamStencil##S s, T *ux, T *uy)                         \
    {                                                                                          \
        T dPsiDy, dPsiDx;                                                                      \
        streamSums##S(psi, nx, s, s.wx, s.dy, s.dx, s.wy, &dPsiDy, &dPsiDx);                   \
        *ux = s.flipX * dPsiDy / hy;                                                           \
        *uy = -s.flipY * dPsiDx / hx;                                                          \
        if (ANY(isless(s.damp, (T)(1.0f)))) {                                                  \
            /* curl(φ·ψ) = φ·curl ψ + ψ·(∂φ/∂y, −∂φ/∂x), ψ the reflection's value. */           \
            T psiHere, unused;                                                                 \
            streamSums##S(psi, nx, s, s.wx, s.wy, s.wx, s.wy, &psiHere, &unused);              \
            psiHere *= s.flipX * s.flipY;                                                      \
            *ux = s.damp * *ux + psiHere * s.dampY;                                            \
            *uy = s.damp * *uy - psiHere * s.dampX;                                            \
        }                                                                                      \
    }                                                                                          \
                                                                                               \
    /* StreamField::vorticity of the lattice at psi: −∇²ψ. */                                  \
    VF_INLINE T streamVorticity##S(__global const float *psi, int nx, float hx, float hy,      \
                                   StreamStencil##S s)                                         \
    {                                                                                          \
        T psiXX, psiYY;                                                                        \
        streamSums##S(psi, nx, s, s.ddx, s.wy, s.wx, s.ddy, &psiXX, &psiYY);                   \
        return -s.damp * s.flipX * s.flipY * (psiXX / (hx * hx) + psiYY / (hy * hy));          \
    }                                                                                          \
                                                                                               \
    /* The velocity at (x, y) `along` of the way through the step. RK4 asks at s = 0, ½, ½, 1, \
       each answered by one lattice (FluidFlow::interpolate); the work-items of a launch share \
       s, so the branches agree. */                                                            \
    VF_INLINE void flowVelocity##S(FLOW_PARAMS, T x, T y, float along, T *ux, T *uy)           \
    {                                                                                          \
        const float s = streamBlend(dt, along);                                                \
        const StreamStencil##S st = streamStencil##S(nx, ny, hx, hy, x, y);                    \
        const int lattice = s == 0.0f ? STREAM_START : s == 0.5f ? STREAM_HALFWAY : STREAM_END; \
        streamVelocity##S(flowField + lattice * streamCorners(nx, ny), nx, hx, hy, st, ux, uy); \
        if (s != 0.0f && s != 0.5f && s != 1.0f) {                                             \
            T x0, y0;                                                                          \
            streamVelocity##S(flowField, nx, hx, hy, st, &x0, &y0);                            \
            *ux = x0 + s * (*ux - x0);                                                         \
            *uy = y0 + s * (*uy - y0);                                                         \
        }                                                                                      \
    }                                                                                          \
                                                                                               \
    VF_INLINE T flowVorticity##S(FLOW_PARAMS, T x, T y, float along)                           \
    {                                                                                          \
        const float s = streamBlend(dt, along);                                                \
        const StreamStencil##S st = streamStencil##S(nx, ny, hx, hy, x, y);                    \
        const int lattice = s == 0.0f ? STREAM_START : s == 0.5f ? STREAM_HALFWAY : STREAM_END; \
        const T w = streamVorticity##S(flowField + lattice * streamCorners(nx, ny), nx, hx, hy, st); \
        if (s == 0.0f || s == 0.5f || s == 1.0f)                                               \
            return w;                                                                          \
        const T w0 = streamVorticity##S(flowField, nx, hx, hy, st);                            \
        return w0 + s * (w - w0);                                                              \
    }

VF_DEFINE_STREAM_SAMPLER(float, int, Point, convert_float, convert_int, VF_GATHER_ONE, VF_ANY_ONE)
VF_DEFINE_STREAM_SAMPLER(floatv, intv, Lanes, VF_CONVERT_FLOATV, VF_CONVERT_INTV, gatherLanes, any)

VF_INLINE float2 flowVelocity(FLOW_PARAMS, float2 p, float s)
{
    float x, y;
    flowVelocityPoint(FLOW_PASS, p.x, p.y, s, &x, &y);
    return (float2)(x, y);
}

VF_INLINE float flowVorticity(FLOW_PARAMS, float2 p, float s)
{
    return flowVorticityPoint(FLOW_PASS, p.x, p.y, s);
}
