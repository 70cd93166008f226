// The fluid as the flow of the contour kernels (sim/opencl/FlowBinding.h): the staggered MAC field
// sampled as sim/FluidSolver.h samples it (MacVelocity::sample and ::vorticity, same clamping and
// corner differences), in float32, and blended linearly in time between the field at the step's
// start (u0, v0 at t0) and at its end (u1, v1 at t1) as sim/FluidFlow does, so RK4's mid-step
// samples (eq. 1) see the flow of that moment. u0 and v0 hold, after the start field, the field
// halfway through the step (FluidFlow's m_middle; DeviceFluid keeps it), which answers s = ½ alone.
// u1 holds, after the end field, its vorticity at the cell corners (DeviceFluid keeps it too), so
// the end field's vorticity is one bilinear sample.
// Comes after flow.h.cl; fluid.cl traces through the same helpers. Every helper is force-inlined:
// PoCL's vectoriser gives up on kernels that call large functions that are not inlined.

// The halfway field, stored after the start field.
VF_INLINE __global const float* macHalfwayU(__global const float* u0, int nx, int ny)
{
    return u0 + (nx + 1) * ny;
}

VF_INLINE __global const float* macHalfwayV(__global const float* v0, int nx, int ny)
{
    return v0 + nx * (ny + 1);
}

// s clamped to [0, 1]; 1 (the end field) when the span is empty, as FluidFlow::blend. RK4
// (contours.cl) passes its stages' s exactly (0, ½, 1), so its middle stages sample the halfway
// field alone.
VF_INLINE float macBlend(float dt, float s)
{
    return dt > 0.0f ? clamp(s, 0.0f, 1.0f) : 1.0f;
}

// The field's vorticity on the (nx + 1) x (ny + 1) cell corners, stored after its u (fluid.cl,
// cornerVorticity).
VF_INLINE __global const float* macCornerVorticityAfter(__global const float* u, int nx, int ny)
{
    return u + (nx + 1) * ny;
}

// The sampler is written once for a type T with integer type I: float and int for one point
// (the names below without a suffix), floatv and intv for lanes (suffix Lanes). `GATHER(f, k)` reads
// f[k] for each of T's values.
#define VF_GATHER_ONE(f, k) (f)[k]
#define VF_DEFINE_MAC_SAMPLER(T, I, S, CONVERT_T, CONVERT_I, GATHER)                             \
    /* A position on a row-major cols x rows lattice (cols, rows >= 2): the lattice point (i, j) \
       at the low corner of the square holding it and the fractions across                     \
       (detail::LatticePoint). No float2 here: PoCL's loop vectoriser refuses them. */         \
    typedef struct {                                                                           \
        I i, j;                                                                                \
        T fx, fy;                                                                              \
    } MacPoint##S;                                                                             \
                                                                                               \
    /* As detail::locate: positions outside are clamped onto the lattice, NaN to the low end   \
       (it fails `0 < g`), so no position, however bad, indexes out of bounds. */              \
    VF_INLINE MacPoint##S macLocate##S(int cols, int rows, T gx, T gy)                         \
    {                                                                                          \
        gx = fmin(select((T)(0.0f), gx, isless((T)(0.0f), gx)), (T)(cols - 1));                \
        gy = fmin(select((T)(0.0f), gy, isless((T)(0.0f), gy)), (T)(rows - 1));                \
        MacPoint##S q;                                                                         \
        q.i = min(CONVERT_I(gx), (I)(cols - 2));                                               \
        q.j = min(CONVERT_I(gy), (I)(rows - 2));                                               \
        q.fx = gx - CONVERT_T(q.i);                                                            \
        q.fy = gy - CONVERT_T(q.j);                                                            \
        return q;                                                                              \
    }                                                                                          \
                                                                                               \
    /* Bilinear interpolation across the square at q of the values at its corners. */          \
    VF_INLINE T macBlendCorners##S(MacPoint##S q, T low, T right, T down, T diagonal)          \
    {                                                                                          \
        return (1.0f - q.fy) * ((1.0f - q.fx) * low + q.fx * right)                            \
             + q.fy * ((1.0f - q.fx) * down + q.fx * diagonal);                                \
    }                                                                                          \
                                                                                               \
    VF_INLINE T macBilinear##S(__global const float *f, int cols, MacPoint##S q)               \
    {                                                                                          \
        const I k = q.j * cols + q.i;                                                          \
        return macBlendCorners##S(q, GATHER(f, k), GATHER(f, k + 1), GATHER(f, k + cols),      \
                                  GATHER(f, k + cols + 1));                                    \
    }                                                                                          \
                                                                                               \
    /* The velocity at (gx, gy) in cell units (x / hx, y / hy): u lives at (i, j + 1/2), v at  \
       (i + 1/2, j). */                                                                        \
    VF_INLINE T macSampleU##S(__global const float *u, int nx, int ny, T gx, T gy)             \
    {                                                                                          \
        return macBilinear##S(u, nx + 1, macLocate##S(nx + 1, ny, gx, gy - 0.5f));             \
    }                                                                                          \
                                                                                               \
    VF_INLINE T macSampleV##S(__global const float *v, int nx, int ny, T gx, T gy)             \
    {                                                                                          \
        return macBilinear##S(v, nx, macLocate##S(nx, ny + 1, gx - 0.5f, gy));                 \
    }                                                                                          \
                                                                                               \
    /* The velocity at (x, y) `along` of the way through the step. RK4 asks at s = 0, ½, ½, 1, \
       each answered by one field (FluidFlow::interpolate); the work-items of a launch share   \
       t, so the branches agree. */                                                            \
    VF_INLINE void macVelocity##S(FLOW_PARAMS, T x, T y, float along, T *ux, T *uy)            \
    {                                                                                          \
        const float s = macBlend(dt, along);                                                   \
        const T gx = x / hx, gy = y / hy;                                                      \
        __global const float *u = s == 0.0f ? u0 : s == 0.5f ? macHalfwayU(u0, nx, ny) : u1;   \
        __global const float *v = s == 0.0f ? v0 : s == 0.5f ? macHalfwayV(v0, nx, ny) : v1;   \
        *ux = macSampleU##S(u, nx, ny, gx, gy);                                                \
        *uy = macSampleV##S(v, nx, ny, gx, gy);                                                \
        if (s != 0.0f && s != 0.5f && s != 1.0f) {                                             \
            const T x0 = macSampleU##S(u0, nx, ny, gx, gy), y0 = macSampleV##S(v0, nx, ny, gx, gy); \
            *ux = x0 + s * (*ux - x0);                                                         \
            *uy = y0 + s * (*uy - y0);                                                         \
        }                                                                                      \
    }                                                                                          \
                                                                                               \
    /* The end field's vorticity at (x, y), blended from its stored corner vorticity as        \
       macVorticity blends its corner differences. */                                          \
    VF_INLINE T macEndVorticity##S(FLOW_PARAMS, T x, T y)                                       \
    {                                                                                          \
        const MacPoint##S q = macLocate##S(nx + 1, ny + 1, x / hx, y / hy);                    \
        return macBilinear##S(macCornerVorticityAfter(u1, nx, ny), nx + 1, q);                 \
    }

VF_DEFINE_MAC_SAMPLER(float, int, , convert_float, convert_int, VF_GATHER_ONE)
VF_DEFINE_MAC_SAMPLER(floatv, intv, Lanes, VF_CONVERT_FLOATV, VF_CONVERT_INTV, gatherLanes)

// As detail::cornerDifferences: v across cell corner (i, j) along x and u across it along y,
// central around the corner, the nearest interior difference on the canvas edge.
VF_INLINE float macCornerDv(__global const float* v, int nx, int i, int j)
{
    const int a = clamp(i - 1, 0, nx - 2);
    return v[j * nx + a + 1] - v[j * nx + a];
}

VF_INLINE float macCornerDu(__global const float* u, int nx, int ny, int i, int j)
{
    const int b = clamp(j - 1, 0, ny - 2);
    return u[(b + 1) * (nx + 1) + i] - u[b * (nx + 1) + i];
}

// dv/dx - du/dy, bilinear from the cell corners (MacVelocity::vorticity).
VF_INLINE float macVorticity(__global const float* u, __global const float* v, int nx, int ny,
                             float hx, float hy, float2 p)
{
    const MacPoint q = macLocate(nx + 1, ny + 1, p.x / hx, p.y / hy);
    const float dv = macBlendCorners(q, macCornerDv(v, nx, q.i, q.j),
                                     macCornerDv(v, nx, q.i + 1, q.j),
                                     macCornerDv(v, nx, q.i, q.j + 1),
                                     macCornerDv(v, nx, q.i + 1, q.j + 1));
    const float du = macBlendCorners(q, macCornerDu(u, nx, ny, q.i, q.j),
                                     macCornerDu(u, nx, ny, q.i + 1, q.j),
                                     macCornerDu(u, nx, ny, q.i, q.j + 1),
                                     macCornerDu(u, nx, ny, q.i + 1, q.j + 1));
    return dv / hx - du / hy;
}

VF_INLINE float2 flowVelocity(FLOW_PARAMS, float2 p, float s)
{
    float x, y;
    macVelocity(FLOW_PASS, p.x, p.y, s, &x, &y);
    return (float2)(x, y);
}

VF_INLINE void flowVelocityLanes(FLOW_PARAMS, floatv x, floatv y, float s, floatv *u, floatv *v)
{
    macVelocityLanes(FLOW_PASS, x, y, s, u, v);
}

VF_INLINE float flowVorticity(FLOW_PARAMS, float2 p, float along)
{
    const float s = macBlend(dt, along);
    if (s == 0.5f)
        return macVorticity(macHalfwayU(u0, nx, ny), macHalfwayV(v0, nx, ny), nx, ny, hx, hy, p);
    const float end = macEndVorticity(FLOW_PASS, p.x, p.y);
    if (s == 1.0f)
        return end;
    const float start = macVorticity(u0, v0, nx, ny, hx, hy, p);
    return start + s * (end - start);
}

VF_DEFINE_VORTICITY_BY_LANE(macVorticityByLane)

// The end field's vorticity (all that refinement asks for) in lanes; any other moment lane by lane.
VF_INLINE floatv flowVorticityLanes(FLOW_PARAMS, floatv x, floatv y, float along)
{
    return macBlend(dt, along) == 1.0f ? macEndVorticityLanes(FLOW_PASS, x, y)
                                       : macVorticityByLane(FLOW_PASS, x, y, along);
}
