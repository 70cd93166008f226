// The stable-fluids step of sim/FluidSolver.cpp in float32 (advection, implicit viscosity, stylus,
// body force, pressure projection), and the preconditioned CG of sim/LinearSolve.cpp it solves with. Host side
// and the reasons behind the solver's shape: sim/opencl/DeviceFluid.cpp. Comes after flow.h.cl and
// flow_fluid.cl (the stream function's layout). The host defines VF_LOCAL (work-group size of every kernel over
// cells or faces), VF_GROUP (size of the single-work-group kernels), VF_SMOOTHING_SWEEPS and
// VF_COARSEST_SWEEPS. One file, because the step's kernels and the CG and multigrid kernels they
// solve with share the level layout, coefficient planes and partial-sum slots defined here.
//
// Kernels over a lattice run 2D ranges of VF_LOCAL x 1 work-groups, rows of work-groups along the
// lattice's rows, the first dimension rounded up (so they check i against the row length). That
// spares a division per work-item, which PoCL's vectoriser turns into one scalar division per lane.
// Element-wise CG kernels run over the whole padded storage, whose length is a multiple of
// VF_LOCAL, without any check. Reductions combine in a fixed order within a work-group, then one
// partial per work-group is combined by a single-work-group kernel in a fixed order: the same input
// on the same device gives bit-identical results.

#define KERNEL_1D __kernel __attribute__((reqd_work_group_size(VF_LOCAL, 1, 1)))
#define SINGLE_GROUP __kernel __attribute__((reqd_work_group_size(VF_GROUP, 1, 1)))

// ---- MAC sampling -------------------------------------------------------------------------------

// A position on a row-major cols x rows lattice (cols, rows >= 2): the lattice point (i, j) at the
// low corner of the square holding it and the fractions across (detail::LatticePoint). As
// detail::locate: positions outside are clamped onto the lattice, NaN to the low end (it fails
// `0 < g`), so no position, however bad, indexes out of bounds.
typedef struct {
    int i, j;
    float fx, fy;
} MacPoint;

VF_INLINE MacPoint macLocate(int cols, int rows, float gx, float gy)
{
    gx = fmin(select(0.0f, gx, isless(0.0f, gx)), (float)(cols - 1));
    gy = fmin(select(0.0f, gy, isless(0.0f, gy)), (float)(rows - 1));
    MacPoint q;
    q.i = min(convert_int(gx), cols - 2);
    q.j = min(convert_int(gy), rows - 2);
    q.fx = gx - (float)q.i;
    q.fy = gy - (float)q.j;
    return q;
}

VF_INLINE float macBilinear(__global const float* f, int cols, MacPoint q)
{
    const int k = q.j * cols + q.i;
    return (1.0f - q.fy) * ((1.0f - q.fx) * f[k] + q.fx * f[k + 1])
         + q.fy * ((1.0f - q.fx) * f[k + cols] + q.fx * f[k + cols + 1]);
}

// The velocity at (gx, gy) in cell units (x / hx, y / hy), as MacVelocity::sample: u lives at
// (i, j + 1/2), v at (i + 1/2, j).
VF_INLINE float macSampleU(__global const float* u, int nx, int ny, float gx, float gy)
{
    return macBilinear(u, nx + 1, macLocate(nx + 1, ny, gx, gy - 0.5f));
}

VF_INLINE float macSampleV(__global const float* v, int nx, int ny, float gx, float gy)
{
    return macBilinear(v, nx, macLocate(nx, ny + 1, gx - 0.5f, gy));
}

// ---- Faces --------------------------------------------------------------------------------------

// One velocity component on its lattice: u on vertical faces ((nx + 1) x ny, at (i, j + 1/2) in
// cells), v on horizontal ones (nx x (ny + 1), at (i + 1/2, j)). The lattice lines across the
// component's own axis at both ends lie on the walls, where the normal velocity is zero.
typedef struct {
    int cols, rows, normalX;
    float offsetX, offsetY;
} FaceGrid;

// Kernels over faces take both components in one launch: rows 0 to ny - 1 of the range are the
// rows of u, the ny + 1 after them those of v.
typedef struct {
    FaceGrid grid;
    int i, j, index;  // index into the component's array
    int valid, wall;
} Face;

VF_INLINE Face faceAt(int nx, int ny, int i, int row)
{
    Face f;
    f.grid.normalX = row < ny;
    f.grid.cols = f.grid.normalX ? nx + 1 : nx;
    f.grid.rows = f.grid.normalX ? ny : ny + 1;
    f.grid.offsetX = f.grid.normalX ? 0.0f : 0.5f;
    f.grid.offsetY = f.grid.normalX ? 0.5f : 0.0f;
    f.i = i;
    f.j = f.grid.normalX ? row : row - ny;
    f.index = f.j * f.grid.cols + i;
    f.valid = i < f.grid.cols;
    f.wall = f.grid.normalX ? i == 0 || i == f.grid.cols - 1 : f.j == 0 || f.j == f.grid.rows - 1;
    return f;
}

VF_INLINE Face thisFace(int nx, int ny)
{
    return faceAt(nx, ny, get_global_id(0), get_global_id(1));
}

// Where the fluid at face f came from over a step, in cell units: (*x, *y) from the face's
// position; (stepX, stepY) = (dt / hx, dt / hy), negated to trace forward. Midpoint rule (RK2), as
// trace() in FluidSolver.cpp.
VF_INLINE void traceFace(__global const float* u, __global const float* v, int nx, int ny, Face f,
                         float stepX, float stepY, float* x, float* y)
{
    const float gx = (float)f.i + f.grid.offsetX, gy = (float)f.j + f.grid.offsetY;
    const float midX = gx - 0.5f * stepX * macSampleU(u, nx, ny, gx, gy);
    const float midY = gy - 0.5f * stepY * macSampleV(v, nx, ny, gx, gy);
    *x = gx - stepX * macSampleU(u, nx, ny, midX, midY);
    *y = gy - stepY * macSampleV(v, nx, ny, midX, midY);
}

// A position in cell units on the lattice of the face's component.
VF_INLINE MacPoint locateOnFaces(FaceGrid g, float x, float y)
{
    return macLocate(g.cols, g.rows, x - g.offsetX, y - g.offsetY);
}

// Semi-Lagrangian advection (Stam 1999) of both components: each interior face takes the old value
// found where its fluid came from; wall faces are zero.
KERNEL_1D void advect(__global const float* u, __global const float* v, __global float* uOut,
                      __global float* vOut, int nx, int ny, float stepX, float stepY)
{
    const Face f = thisFace(nx, ny);
    if (!f.valid)
        return;
    float x, y;
    traceFace(u, v, nx, ny, f, stepX, stepY, &x, &y);
    const float value =
        macBilinear(f.grid.normalX ? u : v, f.grid.cols, locateOnFaces(f.grid, x, y));
    (f.grid.normalX ? uOut : vOut)[f.index] = f.wall ? 0.0f : value;
}

// MacCormack (Selle et al. 2008) after advect() wrote the semi-Lagrangian result `forward`: trace
// that result forward again, correct by half the round-trip error, and clamp to the range of the
// four old values the semi-Lagrangian step interpolated from (retraced here rather than stored).
KERNEL_1D void macCormack(__global const float* u, __global const float* v,
                          __global const float* uForward, __global const float* vForward,
                          __global float* uOut, __global float* vOut, int nx, int ny, float stepX,
                          float stepY)
{
    const Face f = thisFace(nx, ny);
    if (!f.valid)
        return;
    __global const float* old = f.grid.normalX ? u : v;
    __global const float* forward = f.grid.normalX ? uForward : vForward;
    float x, y;
    traceFace(u, v, nx, ny, f, stepX, stepY, &x, &y);
    const MacPoint q = locateOnFaces(f.grid, x, y);
    __global const float* r0 = old + q.j * f.grid.cols + q.i;
    __global const float* r1 = r0 + f.grid.cols;
    const float low = fmin(fmin(r0[0], r0[1]), fmin(r1[0], r1[1]));
    const float high = fmax(fmax(r0[0], r0[1]), fmax(r1[0], r1[1]));
    traceFace(u, v, nx, ny, f, -stepX, -stepY, &x, &y);
    const float roundTrip = macBilinear(forward, f.grid.cols, locateOnFaces(f.grid, x, y));
    const float value = clamp(forward[f.index] + 0.5f * (old[f.index] - roundTrip), low, high);
    (f.grid.normalX ? uOut : vOut)[f.index] = f.wall ? 0.0f : value;
}

// FluidSolver::applyStylus for one pen segment from a to b: u += w (v_pen - u) strength on the
// interior faces, w = (1 - (d/r)^2)^2 within the radius. Written with 1/r^2 so that no radius
// overflows, and so that coordinates too large for float32 (an infinite or NaN distance) fall
// outside the radius.
KERNEL_1D void stylus(__global float* u, __global float* v, int nx, int ny, float hx, float hy,
                      float ax, float ay, float bx, float by, float inverseRadius2, float penX,
                      float penY, float strength)
{
    const Face f = thisFace(nx, ny);
    if (!f.valid || f.wall)
        return;
    const float px = ((float)f.i + f.grid.offsetX) * hx - ax;
    const float py = ((float)f.j + f.grid.offsetY) * hy - ay;
    const float abx = bx - ax, aby = by - ay;
    const float length2 = abx * abx + aby * aby;
    const float t = length2 > 0.0f ? clamp((px * abx + py * aby) / length2, 0.0f, 1.0f) : 0.0f;
    const float dx = px - t * abx, dy = py - t * aby;
    const float w = 1.0f - (dx * dx + dy * dy) * inverseRadius2;
    if (w > 0.0f) {
        __global float* component = f.grid.normalX ? u : v;
        const float target = f.grid.normalX ? penX : penY;
        component[f.index] += w * w * strength * (target - component[f.index]);
    }
}

// FluidSolver::applyForce: u = u decay + a dt on the interior faces, decay = e^(-damping dt).
KERNEL_1D void bodyForce(__global float* u, __global float* v, __global const float* au,
                         __global const float* av, int nx, int ny, float decay, float dt)
{
    const Face f = thisFace(nx, ny);
    if (!f.valid || f.wall)
        return;
    __global float* component = f.grid.normalX ? u : v;
    const float a = (f.grid.normalX ? au : av)[f.index];
    component[f.index] = component[f.index] * decay + a * dt;
}

// ---- Linear systems: storage --------------------------------------------------------------------

// One multigrid level: mx x my unknowns stored with a ring of ghost cells (stride mx + 2) whose
// values and couplings stay zero, as in sim/LinearSolve.h, at `offset` in the level arrays.
typedef struct {
    int mx, my, offset;
} Level;

VF_INLINE Level level(int mx, int my, int offset)
{
    Level l;
    l.mx = mx;
    l.my = my;
    l.offset = offset;
    return l;
}

VF_INLINE int stride(Level l) { return l.mx + 2; }
VF_INLINE int cellCount(Level l) { return l.mx * l.my; }
VF_INLINE int cellIndex(Level l, int i, int j) { return l.offset + (j + 1) * (l.mx + 2) + i + 1; }

// The coefficients of every level, the Level arrays of sim/LinearSolve.h as four planes of one
// buffer (`plane` floats apart; separate scalars, not a float4, which PoCL would not vectorise):
// the diagonal minus the couplings, the coupling of k to k + 1 and to k + stride, 1 / diagonal.
typedef struct {
    __global float *own, *east, *south, *inverse;
} Coefficients;

VF_INLINE Coefficients coefficients(__global float* coef, int plane)
{
    Coefficients c;
    c.own = coef;
    c.east = coef + plane;
    c.south = coef + 2 * plane;
    c.inverse = coef + 3 * plane;
    return c;
}

// (A x)_k from the values at k and its neighbours east, west, south and north.
VF_INLINE float applyWith(Coefficients c, int k, int s, float xk, float xe, float xw, float xs,
                          float xn)
{
    return c.own[k] * xk + c.east[k] * (xk - xe) + c.east[k - 1] * (xk - xw)
         + c.south[k] * (xk - xs) + c.south[k - s] * (xk - xn);
}

VF_INLINE float applyAt(Coefficients c, __global const float* x, int k, int s)
{
    return applyWith(c, k, s, x[k], x[k + 1], x[k - 1], x[k + s], x[k - s]);
}

// The state of one CG solve, shared by its kernels (mirrored by CgState in DeviceFluid.cpp).
typedef struct {
    float tolerance, mean, rho, alpha, beta;
    int done, iterations, unused;
} CgState;

// Per-work-group partial results, slot * groups + group (Partial in DeviceFluid.cpp).
#define PARTIAL_SCALE 0  // what the tolerance is relative to, from the kernel that wrote b
#define PARTIAL_SUM_R 1
#define PARTIAL_MAX_R 2
#define PARTIAL_SUM_X 3
#define PARTIAL_DQ 4
#define PARTIAL_RZ 5

// A fixed-order reduction over the work-group, the result in work-item 0 only: one barrier, then
// work-item 0 combines the values in order. On PoCL every barrier costs a pass over the work-group,
// and this takes half the time of a two-barrier reduction (a tree has log2(size) of them); on a GPU
// it is a short serial chain in local memory. A second reduction in the same kernel needs its own
// `scratch` (one float per work-item): work-item 0 may still be reading the first.
VF_INLINE float combine(float a, float b, int takeMax) { return takeMax ? fmax(a, b) : a + b; }

VF_INLINE float groupReduce(float value, int takeMax, __local float* scratch)
{
    const int id = get_local_id(0);
    scratch[id] = value;
    barrier(CLK_LOCAL_MEM_FENCE);
    float total = scratch[0];
    if (id == 0)
        for (int k = 1; k < (int)get_local_size(0); ++k)
            total = combine(total, scratch[k], takeMax);
    return total;
}

// One partial per work-group of a 1D or 2D range; every work-item must call it (it holds a
// barrier).
VF_INLINE void storePartial(__global float* partials, int slot, float value, int takeMax,
                            __local float* scratch)
{
    const float total = groupReduce(value, takeMax, scratch);
    const int groups = get_num_groups(0) * get_num_groups(1);
    if (get_local_id(0) == 0)
        partials[slot * groups + get_group_id(1) * get_num_groups(0) + get_group_id(0)] = total;
}

// In a single-work-group kernel: the `groups` partials of `slot` combined, in a fixed order, in
// work-item 0.
VF_INLINE float reducePartials(__global const float* partials, int slot, int groups, int takeMax,
                               __local float* scratch)
{
    float value = 0.0f;
    for (int g = get_local_id(0); g < groups; g += VF_GROUP)
        value = combine(value, partials[slot * groups + g], takeMax);
    return groupReduce(value, takeMax, scratch);
}

// ---- Linear systems: the multigrid hierarchy (sim/LinearSolve.cpp) ------------------------------
// Kernels over a level's cells: work-item (i, j) of a 2D range.

// The finest level of center * I + ax * Lx + ay * Ly (Stencil5): at the ends of a Dirichlet axis
// the end cell keeps the coupling to the fixed zero beyond it in its own diagonal.
KERNEL_1D void levelFine(__global float* coef, int plane, int mx, int my, float center, float ax,
                         float ay, int dirichletX, int dirichletY)
{
    const int i = get_global_id(0), j = get_global_id(1);
    if (i >= mx)
        return;
    const Coefficients c = coefficients(coef, plane);
    const int k = cellIndex(level(mx, my, 0), i, j);
    const int wallsX = dirichletX ? (i == 0) + (i == mx - 1) : 0;
    const int wallsY = dirichletY ? (j == 0) + (j == my - 1) : 0;
    c.own[k] = center + ax * wallsX + ay * wallsY;
    c.east[k] = i + 1 < mx ? ax : 0.0f;
    c.south[k] = j + 1 < my ? ay : 0.0f;
}

// The Galerkin coarse level of PcgSolver::coarsen, one coarse cell per work-item: the group's own
// diagonals add up; the couplings leaving the group through its last column (row) add up, halved
// along a coarsened axis; couplings inside the group cancel.
KERNEL_1D void levelCoarsen(__global float* coef, int plane, int fineMx, int fineMy,
                            int fineOffset, int mx, int my, int offset, int groupX, int groupY)
{
    const int ci = get_global_id(0), cj = get_global_id(1);
    if (ci >= mx)
        return;
    const Level fine = level(fineMx, fineMy, fineOffset);
    const Coefficients c = coefficients(coef, plane);
    const float scaleX = groupX == 2 ? 0.5f : 1.0f, scaleY = groupY == 2 ? 0.5f : 1.0f;
    float own = 0.0f, east = 0.0f, south = 0.0f;
    for (int j = cj * groupY; j < min(cj * groupY + groupY, fineMy); ++j)
        for (int i = ci * groupX; i < min(ci * groupX + groupX, fineMx); ++i) {
            const int k = cellIndex(fine, i, j);
            own += c.own[k];
            east += i % groupX == groupX - 1 ? scaleX * c.east[k] : 0.0f;
            south += j % groupY == groupY - 1 ? scaleY * c.south[k] : 0.0f;
        }
    const int k = cellIndex(level(mx, my, offset), ci, cj);
    c.own[k] = own;
    c.east[k] = east;
    c.south[k] = south;
}

KERNEL_1D void levelInverse(__global float* coef, int plane, int mx, int my, int offset)
{
    const int i = get_global_id(0), j = get_global_id(1);
    if (i >= mx)
        return;
    const Level l = level(mx, my, offset);
    const Coefficients c = coefficients(coef, plane);
    const int k = cellIndex(l, i, j), s = stride(l);
    c.inverse[k] = 1.0f / (c.own[k] + c.east[k] + c.east[k - 1] + c.south[k] + c.south[k - s]);
}

// ---- Linear systems: the V-cycle ----------------------------------------------------------------

// Red-black Gauss-Seidel: the nth cell of `colour` ((i + j) % 2) in row j. `fromZero`: the first
// half-sweep from x = 0, which reads no neighbours, so x need not be cleared first.
VF_INLINE int cellsOfColour(Level l) { return (l.mx + 1) / 2; }  // per row, at most

VF_INLINE void relaxCell(Coefficients c, __global float* x, __global const float* b, Level l,
                         int colour, int fromZero, int nth, int j)
{
    const int i = 2 * nth + ((colour + j) & 1);
    if (i >= l.mx)
        return;
    const int k = cellIndex(l, i, j), s = stride(l);
    const float neighbours = fromZero ? 0.0f
                                      : c.east[k] * x[k + 1] + c.east[k - 1] * x[k - 1]
                                            + c.south[k] * x[k + s] + c.south[k - s] * x[k - s];
    x[k] = (b[k] + neighbours) * c.inverse[k];
}

// The coarse right-hand side of coarse cell (ci, cj): the fine residual b - A x summed over its
// group.
VF_INLINE void restrictCell(Coefficients c, __global const float* x, __global float* b, Level fine,
                           Level coarse, int groupX, int groupY, int ci, int cj)
{
    if (ci >= coarse.mx)
        return;
    const int s = stride(fine);
    float sum = 0.0f;
    for (int j = cj * groupY; j < min(cj * groupY + groupY, fine.my); ++j)
        for (int i = ci * groupX; i < min(ci * groupX + groupX, fine.mx); ++i) {
            const int k = cellIndex(fine, i, j);
            sum += b[k] - applyAt(c, x, k, s);
        }
    b[cellIndex(coarse, ci, cj)] = sum;
}

// Piecewise-constant interpolation: fine cell (i, j) adds its group's coarse correction.
VF_INLINE void prolongCell(__global float* x, Level fine, Level coarse, int groupX, int groupY,
                           int i, int j)
{
    if (i < fine.mx)
        x[cellIndex(fine, i, j)] += x[cellIndex(coarse, i / groupX, j / groupY)];
}

// The levels above the tail run as one launch per operation; every V-cycle kernel does nothing
// once the solve is done, so that iterations queued past convergence cost only their launch.
KERNEL_1D void mgRelax(__global float* coef, int plane, __global float* x, __global const float* b,
                       __global const CgState* state, int mx, int my, int offset, int colour,
                       int fromZero)
{
    if (state->done)
        return;
    relaxCell(coefficients(coef, plane), x, b, level(mx, my, offset), colour, fromZero,
              get_global_id(0), get_global_id(1));
}

KERNEL_1D void mgRestrict(__global float* coef, int plane, __global const float* x,
                          __global float* b, __global const CgState* state, int fineMx,
                          int fineMy, int fineOffset, int mx, int my, int offset, int groupX,
                          int groupY)
{
    if (state->done)
        return;
    restrictCell(coefficients(coef, plane), x, b, level(fineMx, fineMy, fineOffset),
                 level(mx, my, offset), groupX, groupY, get_global_id(0), get_global_id(1));
}

KERNEL_1D void mgProlong(__global float* x, __global const CgState* state, int fineMx, int fineMy,
                         int fineOffset, int mx, int my, int offset, int groupX, int groupY)
{
    if (state->done)
        return;
    prolongCell(x, level(fineMx, fineMy, fineOffset), level(mx, my, offset), groupX, groupY,
                get_global_id(0), get_global_id(1));
}

// The small levels, where a launch per operation would cost more than the work, run in one
// work-group: each phase covers its `cols` x `rows` items in steps of VF_GROUP (the same trip count
// for every work-item), then a barrier makes its global writes visible to the group.
#define FOR_EACH_ITEM(cols, rows, body)                                                            \
    for (int base = 0; base < (cols) * (rows); base += VF_GROUP) {                                \
        const int t = base + (int)get_local_id(0);                                                 \
        const int i = t % (cols), j = t / (cols);                                                  \
        if (j < (rows))                                                                            \
            body;                                                                                  \
    }                                                                                              \
    barrier(CLK_GLOBAL_MEM_FENCE)

VF_INLINE void groupRelax(Coefficients c, __global float* x, __global const float* b, Level l,
                          int colour, int fromZero)
{
    FOR_EACH_ITEM(cellsOfColour(l), l.my, relaxCell(c, x, b, l, colour, fromZero, i, j));
}

// The level table: mx, my, offset, and the grouping into the next level (groupX, groupY).
#define LEVEL_INTS 5

VF_INLINE Level levelAt(__global const int* table, int l)
{
    return level(table[LEVEL_INTS * l], table[LEVEL_INTS * l + 1], table[LEVEL_INTS * l + 2]);
}

// The V-cycle of PcgSolver::cycle from level `first` down to `last` (the coarsest), x = M b with
// x starting at zero. Half-sweeps in palindromic colour order (red-black before the coarse
// correction, black-red after; red, then black-red pairs on the coarsest level), so the cycle is a
// symmetric operator, as CG requires of its preconditioner. The coarsest level (at most
// kCoarsestSize cells) is swept by one work-item: its sweeps would otherwise be barrier after
// barrier around a handful of cells.
SINGLE_GROUP void mgTail(__global float* coef, int plane, __global float* x, __global float* b,
                         __global const CgState* state, __global const int* table, int first,
                         int last)
{
    if (state->done)
        return;
    const Coefficients c = coefficients(coef, plane);
    for (int l = first; l < last; ++l) {
        const Level fine = levelAt(table, l), coarse = levelAt(table, l + 1);
        const int groupX = table[LEVEL_INTS * l + 3], groupY = table[LEVEL_INTS * l + 4];
        for (int sweep = 0; sweep < VF_SMOOTHING_SWEEPS; ++sweep) {
            groupRelax(c, x, b, fine, 0, sweep == 0);
            groupRelax(c, x, b, fine, 1, 0);
        }
        FOR_EACH_ITEM(coarse.mx, coarse.my,
                      restrictCell(c, x, b, fine, coarse, groupX, groupY, i, j));
    }
    const Level coarsest = levelAt(table, last);
    if (get_local_id(0) == 0)
        for (int halfSweep = 0; halfSweep <= 2 * VF_COARSEST_SWEEPS; ++halfSweep)
            for (int j = 0; j < coarsest.my; ++j)
                for (int nth = 0; nth < cellsOfColour(coarsest); ++nth)
                    relaxCell(c, x, b, coarsest, halfSweep & 1, halfSweep == 0, nth, j);
    barrier(CLK_GLOBAL_MEM_FENCE);
    for (int l = last - 1; l >= first; --l) {
        const Level fine = levelAt(table, l), coarse = levelAt(table, l + 1);
        const int groupX = table[LEVEL_INTS * l + 3], groupY = table[LEVEL_INTS * l + 4];
        FOR_EACH_ITEM(fine.mx, fine.my, prolongCell(x, fine, coarse, groupX, groupY, i, j));
        for (int sweep = 0; sweep < VF_SMOOTHING_SWEEPS; ++sweep) {
            groupRelax(c, x, b, fine, 1, 0);
            groupRelax(c, x, b, fine, 0, 0);
        }
    }
}

// ---- Linear systems: preconditioned CG (PcgSolver::solve) ---------------------------------------
// The vectors live on the finest level (offset 0): x, b, the residual r (the V-cycle's b array),
// the preconditioned residual z (its x array), the direction d (two copies, see cgApply) and q.
// Kernels over cells (2D) keep the ghost cells at zero; element-wise kernels (1D, over the whole
// storage) keep them at zero by construction (what they add there is zero).

// r = b - A x, and d = 0 so that the first direction is z itself.
KERNEL_1D void cgResidual(__global float* coef, int plane, __global const float* x,
                          __global const float* b, __global float* r, __global float* d, int mx,
                          int my, __global float* partials)
{
    __local float sums[VF_LOCAL], maxima[VF_LOCAL];
    const Level l = level(mx, my, 0);
    const int i = get_global_id(0), j = get_global_id(1);
    float rk = 0.0f;
    if (i < mx) {
        const int k = cellIndex(l, i, j);
        rk = b[k] - applyAt(coefficients(coef, plane), x, k, stride(l));
        r[k] = rk;
        d[k] = 0.0f;
    }
    storePartial(partials, PARTIAL_SUM_R, rk, 0, sums);
    storePartial(partials, PARTIAL_MAX_R, fabs(rk), 1, maxima);
}

// The mean over the unknowns of what `slot` summed: of r for a singular system, whose constant part
// no x can reach, and of x at the end (PcgSolver::removeMeanIfSingular).
SINGLE_GROUP void cgMean(__global CgState* state, __global const float* partials, int slot,
                         int groups, int cells)
{
    __local float scratch[VF_GROUP];
    const float sum = reducePartials(partials, slot, groups, 0, scratch);
    if (get_local_id(0) == 0)
        state->mean = sum / (float)cells;
}

// The sum of x over the storage (zero on the ghost cells), for its mean.
KERNEL_1D void cgSum(__global const float* x, __global float* partials)
{
    __local float scratch[VF_LOCAL];
    storePartial(partials, PARTIAL_SUM_X, x[get_global_id(0)], 0, scratch);
}

// Subtracts the mean from the unknowns; the largest magnitude left is what the start of a solve
// checks.
KERNEL_1D void cgRemoveMean(__global float* values, __global const CgState* state, int mx, int my,
                            __global float* partials)
{
    __local float scratch[VF_LOCAL];
    const int i = get_global_id(0), j = get_global_id(1);
    float magnitude = 0.0f;
    if (i < mx) {
        const int k = cellIndex(level(mx, my, 0), i, j);
        values[k] -= state->mean;
        magnitude = fabs(values[k]);
    }
    storePartial(partials, PARTIAL_MAX_R, magnitude, 1, scratch);
}

// Stop at max |r| <= max(absolute, relative * scale), scale from what the kernel that wrote b
// reduced into PARTIAL_SCALE (see DeviceFluid.cpp for what each system measures).
SINGLE_GROUP void cgStart(__global CgState* state, __global const float* partials, int groups,
                          float absolute, float relative)
{
    __local float scales[VF_GROUP], residuals[VF_GROUP];
    const float scale = reducePartials(partials, PARTIAL_SCALE, groups, 1, scales);
    const float residual = reducePartials(partials, PARTIAL_MAX_R, groups, 1, residuals);
    if (get_local_id(0) == 0) {
        state->tolerance = fmax(absolute, relative * scale);
        state->rho = 0.0f;
        state->beta = 0.0f;
        state->iterations = 0;
        state->done = residual <= state->tolerance;
    }
}

// d = z + beta d and q = A d in one launch: the new direction at the four neighbours is recomputed
// from z and the old d rather than read back, so the old and new d are separate buffers (swapped
// every iteration by the host).
KERNEL_1D void cgApply(__global float* coef, int plane, __global const float* z,
                       __global const float* d, __global float* dNext, __global float* q,
                       __global const CgState* state, int mx, int my, __global float* partials)
{
    __local float scratch[VF_LOCAL];
    if (state->done)
        return;
    const Level l = level(mx, my, 0);
    const int i = get_global_id(0), j = get_global_id(1);
    const float beta = state->beta;
    float curvature = 0.0f;
    if (i < mx) {
        const int k = cellIndex(l, i, j), s = stride(l);
        const float dk = z[k] + beta * d[k];
        const float qk = applyWith(coefficients(coef, plane), k, s, dk, z[k + 1] + beta * d[k + 1],
                                   z[k - 1] + beta * d[k - 1], z[k + s] + beta * d[k + s],
                                   z[k - s] + beta * d[k - s]);
        dNext[k] = dk;
        q[k] = qk;
        curvature = dk * qk;
    }
    storePartial(partials, PARTIAL_DQ, curvature, 0, scratch);
}

// alpha = rho / d.Ad; a curvature that is not positive only happens on breakdown (NaN input, or
// roundoff at an already converged solution) and ends the solve, as in PcgSolver::solve.
SINGLE_GROUP void cgAlpha(__global CgState* state, __global const float* partials, int groups)
{
    __local float scratch[VF_GROUP];
    if (state->done)
        return;
    const float curvature = reducePartials(partials, PARTIAL_DQ, groups, 0, scratch);
    if (get_local_id(0) == 0) {
        state->iterations += 1;
        state->alpha = state->rho / curvature;
        state->done = !(curvature > 0.0f);
    }
}

KERNEL_1D void cgStep(__global float* x, __global float* r, __global const float* d,
                      __global const float* q, __global const CgState* state,
                      __global float* partials)
{
    __local float scratch[VF_LOCAL];
    if (state->done)
        return;
    const int k = get_global_id(0);
    const float alpha = state->alpha;
    x[k] += alpha * d[k];
    r[k] -= alpha * q[k];
    storePartial(partials, PARTIAL_MAX_R, fabs(r[k]), 1, scratch);
}

// After cgStep: done when max |r| is within the tolerance, before the preconditioner runs.
SINGLE_GROUP void cgConverged(__global CgState* state, __global const float* partials, int groups)
{
    __local float scratch[VF_GROUP];
    if (state->done)
        return;
    const float residual = reducePartials(partials, PARTIAL_MAX_R, groups, 1, scratch);
    if (get_local_id(0) == 0)
        state->done = residual <= state->tolerance;
}

// The preconditioner for strongly diagonally dominant systems (DeviceFluid.cpp): z = r / diagonal.
KERNEL_1D void cgJacobi(__global float* coef, int plane, __global float* z,
                        __global const float* r, __global const CgState* state)
{
    if (state->done)
        return;
    const int k = get_global_id(0);
    z[k] = r[k] * coefficients(coef, plane).inverse[k];
}

KERNEL_1D void cgDot(__global const float* r, __global const float* z,
                     __global const CgState* state, __global float* partials)
{
    __local float scratch[VF_LOCAL];
    if (state->done)
        return;
    const int k = get_global_id(0);
    storePartial(partials, PARTIAL_RZ, r[k] * z[k], 0, scratch);
}

// After z = M r: beta = r.z / previous r.z (0 on the first direction); an r.z that is not positive
// only happens on breakdown and ends the solve.
SINGLE_GROUP void cgBeta(__global CgState* state, __global const float* partials, int groups)
{
    __local float scratch[VF_GROUP];
    if (state->done)
        return;
    const float rho = reducePartials(partials, PARTIAL_RZ, groups, 0, scratch);
    if (get_local_id(0) == 0) {
        state->done = !(rho > 0.0f);
        state->beta = state->rho > 0.0f ? rho / state->rho : 0.0f;
        state->rho = rho;
    }
}

// ---- The fluid's systems ------------------------------------------------------------------------

// Implicit viscosity: the interior faces of one component as the unknowns (x = b = u*, the first
// guess), with max |u*| as the scale of the tolerance.
KERNEL_1D void gatherFaces(__global const float* faces, int cols, int firstCol, int firstRow,
                           int mx, int my, __global float* x, __global float* b,
                           __global float* partials)
{
    __local float scratch[VF_LOCAL];
    const int i = get_global_id(0), j = get_global_id(1);
    float magnitude = 0.0f;
    if (i < mx) {
        const float value = faces[(j + firstRow) * cols + i + firstCol];
        const int k = cellIndex(level(mx, my, 0), i, j);
        x[k] = value;
        b[k] = value;
        magnitude = fabs(value);
    }
    storePartial(partials, PARTIAL_SCALE, magnitude, 1, scratch);
}

KERNEL_1D void scatterFaces(__global float* faces, int cols, int firstCol, int firstRow, int mx,
                            int my, __global const float* x)
{
    const int i = get_global_id(0), j = get_global_id(1);
    if (i < mx)
        faces[(j + firstRow) * cols + i + firstCol] = x[cellIndex(level(mx, my, 0), i, j)];
}

// The projection's right-hand side b = -div u* per cell, and as the scale of its tolerance the
// largest sum of the magnitudes of the four terms of a divergence: the size that float32 rounding
// in div u is relative to.
KERNEL_1D void divergence(__global const float* u, __global const float* v, int nx, int ny,
                          float hx, float hy, __global float* b, __global float* partials)
{
    __local float scratch[VF_LOCAL];
    const int i = get_global_id(0), j = get_global_id(1);
    float scale = 0.0f;
    if (i < nx) {
        __global const float* uc = u + j * (nx + 1) + i;
        __global const float* vc = v + j * nx + i;
        b[cellIndex(level(nx, ny, 0), i, j)] = -((uc[1] - uc[0]) / hx + (vc[nx] - vc[0]) / hy);
        scale = (fabs(uc[1]) + fabs(uc[0])) / hx + (fabs(vc[nx]) + fabs(vc[0])) / hy;
    }
    storePartial(partials, PARTIAL_SCALE, scale, 1, scratch);
}

// The stream function of the field (u, v) on the corners with their ghosts (flow_fluid.cl), as
// StreamField::of: the fluxes summed along the bottom wall, then up each column, one value along
// the top wall, and odd reflection about every wall. It becomes the lattice at the step's end; the
// one halfway is the mean of it and the start lattice, which `fromRest` also overwrites (a field
// with no step behind it: start, halfway and end are one). One work-item per padded column: a
// ghost column computes the two columns it reflects.
KERNEL_1D void streamFunction(__global const float* u, __global const float* v, int nx, int ny, float hx, float hy,
                              int fromRest, __global float* stream)
{
    const int c = get_global_id(0) - 1;  // corner column −1 … nx + 1
    if (c > nx + 1)
        return;
    const int stride = streamStride(nx), corners = streamCorners(nx, ny);
    const int column = clamp(c, 0, nx), mirror = c < 0 ? 1 : c > nx ? nx - 1 : column;
    float bottom = 0.0f, bottomMirror = 0.0f;
    for (int i = 0; i < max(column, mirror); ++i) {
        const float flux = -v[i] * hx;
        bottom += i < column ? flux : 0.0f;
        bottomMirror += i < mirror ? flux : 0.0f;
    }
    __global float* end = stream + STREAM_END * corners;
    float psi = bottom, psiMirror = bottomMirror, top = 0.0f;
    for (int j = 0; j <= ny; ++j) {  // corner row j is lattice row j + 1
        if (j > 0) {
            psi += u[(j - 1) * (nx + 1) + column] * hy;
            psiMirror += u[(j - 1) * (nx + 1) + mirror] * hy;
        }
        end[(j + 1) * stride + c + 1] = c == column ? psi : 2.0f * psi - psiMirror;
    }
    // The top wall takes corner (0, ny)'s value: the sum of u up column 0.
    for (int j = 0; j < ny; ++j)
        top += u[j * (nx + 1)] * hy;
    end[(ny + 1) * stride + c + 1] = top;
    // Ghost rows: odd reflection about the bottom and top walls.
    end[c + 1] = 2.0f * end[stride + c + 1] - end[2 * stride + c + 1];
    end[(ny + 2) * stride + c + 1] = 2.0f * top - end[ny * stride + c + 1];
    for (int j = 0; j < ny + 3; ++j) {
        const int k = j * stride + c + 1;
        if (fromRest)
            stream[STREAM_START * corners + k] = end[k];
        stream[STREAM_HALFWAY * corners + k] = 0.5f * (stream[STREAM_START * corners + k] + end[k]);
    }
}

// u -= grad p on the interior faces: face (i, j) separates cell (i, j) from the cell before it
// along the face's normal axis.
KERNEL_1D void subtractGradient(__global float* u, __global float* v, __global const float* p,
                                int nx, int ny, float hx, float hy)
{
    const Face f = thisFace(nx, ny);
    if (!f.valid || f.wall)
        return;
    const Level cells = level(nx, ny, 0);
    const int k = cellIndex(cells, f.i, f.j);
    const int previous = f.grid.normalX ? 1 : stride(cells);
    __global float* component = f.grid.normalX ? u : v;
    component[f.index] -= (p[k] - p[k - previous]) / (f.grid.normalX ? hx : hy);
}
