// Work-group building blocks shared by the scan (scan.cl) and the contour kernels (contours*.cl).
// Every kernel runs with the fixed local size VF_LOCAL (a build option): PoCL compiles a kernel
// once per local size, and a fixed size lets the local arrays below be sized at compile time.

#ifdef VF_FP64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#endif

#define VF_INLINE inline __attribute__((always_inline))
#define VF_KERNEL __kernel __attribute__((reqd_work_group_size(VF_LOCAL, 1, 1)))
#define VF_CAT_(a, b) a##b
#define VF_CAT(a, b) VF_CAT_(a, b)  // pastes after expanding macros such as VF_SCAN_T
#define VF_LOCAL_SCAN(T) VF_CAT(localExclusiveScan_, T)

// VF_LOCAL_SCAN(T)(scratch, value, &total): the sum of `value` over the work-items before this
// one, and the work-group's total in *total; `scratch` holds VF_SCAN_SCRATCH entries. Two levels:
// VF_SCAN_RUNS work-items each add up a run of consecutive values, one adds up the run totals.
// Four barriers (a barrier costs a CPU device a pass over the whole work-group; Hillis–Steele
// would take 2·log2(VF_LOCAL)), and the order of additions is fixed by the indices alone, so float
// sums are reproducible run to run. Every work-item of the group must call it.
#define VF_SCAN_RUNS 8
#define VF_SCAN_RUN (VF_LOCAL / VF_SCAN_RUNS)
#define VF_SCAN_SCRATCH (VF_LOCAL + VF_SCAN_RUNS)
#define VF_DEFINE_LOCAL_SCAN(T)                                                                \
    VF_INLINE T VF_LOCAL_SCAN(T)(__local T *scratch, T value, T *total)                        \
    {                                                                                          \
        const uint lid = get_local_id(0);                                                      \
        scratch[lid] = value;                                                                  \
        barrier(CLK_LOCAL_MEM_FENCE);                                                          \
        if (lid < VF_SCAN_RUNS) {                                                              \
            T sum = 0;                                                                         \
            for (uint k = lid * VF_SCAN_RUN; k < (lid + 1) * VF_SCAN_RUN; ++k)                 \
                scratch[k] = sum += scratch[k];                                                \
            scratch[VF_LOCAL + lid] = sum;                                                     \
        }                                                                                      \
        barrier(CLK_LOCAL_MEM_FENCE);                                                          \
        if (lid == 0) {                                                                        \
            T sum = 0;                                                                         \
            for (uint k = VF_LOCAL; k < VF_SCAN_SCRATCH; ++k)                                  \
                scratch[k] = sum += scratch[k];                                                \
        }                                                                                      \
        barrier(CLK_LOCAL_MEM_FENCE);                                                          \
        const uint run = lid / VF_SCAN_RUN;                                                    \
        const T before = (run > 0 ? scratch[VF_LOCAL + run - 1] : (T)0) +                      \
                         (lid % VF_SCAN_RUN > 0 ? scratch[lid - 1] : (T)0);                    \
        *total = scratch[VF_SCAN_SCRATCH - 1];                                                 \
        barrier(CLK_LOCAL_MEM_FENCE);                                                          \
        return before;                                                                         \
    }

// VF_LOCAL_REDUCE(name)(scratch, value), defined by VF_DEFINE_LOCAL_REDUCE(T, name, combine):
// `combine` over the work-group, returned to every work-item; `scratch` holds
// VF_SCAN_SCRATCH entries. The same two levels as the scan, in an order fixed by the indices.
#define VF_LOCAL_REDUCE(name) VF_CAT(localReduce_, name)
#define VF_DEFINE_LOCAL_REDUCE(T, name, combine)                                               \
    VF_INLINE T VF_LOCAL_REDUCE(name)(__local T *scratch, T value)                             \
    {                                                                                          \
        const uint lid = get_local_id(0);                                                      \
        scratch[lid] = value;                                                                  \
        barrier(CLK_LOCAL_MEM_FENCE);                                                          \
        if (lid < VF_SCAN_RUNS) {                                                              \
            T result = scratch[lid * VF_SCAN_RUN];                                             \
            for (uint k = lid * VF_SCAN_RUN + 1; k < (lid + 1) * VF_SCAN_RUN; ++k)             \
                result = combine(result, scratch[k]);                                          \
            scratch[VF_LOCAL + lid] = result;                                                  \
        }                                                                                      \
        barrier(CLK_LOCAL_MEM_FENCE);                                                          \
        T result = scratch[VF_LOCAL];                                                          \
        for (uint k = VF_LOCAL + 1; k < VF_SCAN_SCRATCH; ++k)                                  \
            result = combine(result, scratch[k]);                                              \
        return result;                                                                         \
    }
