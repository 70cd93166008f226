// Exclusive prefix sums in place over an array of VF_SCAN_T (a build option: uint, or the
// accumulation type). Used for the per-tile totals that the fused contour kernels produce (see
// sim/opencl/Scan.h): each work-group scans a block of VF_LOCAL·VF_SCAN_ITEMS entries and leaves
// the block's total; the host scans the totals the same way, recursively, and adds them back.
// Work-efficient (every entry is read and written a constant number of times) and deterministic.

#define VF_SCAN_ITEMS 8
#define VF_SCAN_BLOCK (VF_LOCAL * VF_SCAN_ITEMS)

VF_DEFINE_LOCAL_SCAN(VF_SCAN_T)

VF_KERNEL void scanBlocks(__global VF_SCAN_T *data, uint n, __global VF_SCAN_T *blockTotals)
{
    __local VF_SCAN_T scratch[VF_SCAN_SCRATCH];
    // Each work-item sums a run of VF_SCAN_ITEMS entries in registers, so only one value per
    // work-item goes through the (barrier-bound) local scan.
    const uint first = get_global_id(0) * VF_SCAN_ITEMS;
    VF_SCAN_T items[VF_SCAN_ITEMS];
    VF_SCAN_T sum = 0;
    for (uint k = 0; k < VF_SCAN_ITEMS; ++k) {
        items[k] = first + k < n ? data[first + k] : (VF_SCAN_T)0;
        sum += items[k];
    }
    VF_SCAN_T total;
    VF_SCAN_T running = VF_LOCAL_SCAN(VF_SCAN_T)(scratch, sum, &total);
    for (uint k = 0; k < VF_SCAN_ITEMS; ++k) {
        if (first + k < n)
            data[first + k] = running;
        running += items[k];
    }
    if (get_local_id(0) == 0)
        blockTotals[get_group_id(0)] = total;
}

VF_KERNEL void addBlockBase(__global VF_SCAN_T *data, uint n, __global const VF_SCAN_T *blockBase)
{
    const uint i = get_global_id(0);
    if (i < n)
        data[i] += blockBase[i / VF_SCAN_BLOCK];
}

// The whole scan of a short array (up to VF_LOCAL·VF_SCAN_BLOCK entries) in one work-group and one
// launch: each work-item sums a contiguous run, the runs' totals are scanned locally, and each
// work-item writes its run's prefixes. For the counting kernels' tile totals, where the launches
// of the levels cost more than the work.
VF_KERNEL void scanOneGroup(__global VF_SCAN_T *data, uint n)
{
    __local VF_SCAN_T scratch[VF_SCAN_SCRATCH];
    const uint run = (n + VF_LOCAL - 1) / VF_LOCAL, first = get_local_id(0) * run, end = min(first + run, n);
    VF_SCAN_T sum = 0;
    for (uint i = first; i < end; ++i)
        sum += data[i];
    VF_SCAN_T total;
    VF_SCAN_T running = VF_LOCAL_SCAN(VF_SCAN_T)(scratch, sum, &total);
    for (uint i = first; i < end; ++i) {
        const VF_SCAN_T value = data[i];
        data[i] = running;
        running += value;
    }
}
