#pragma once
// Values the contour kernels (contours*.cl) share with the host: defined here only, and handed to
// the kernels as build options under the names of contourCodeDefinitions().
#include "sim/opencl/OpenCl.h"

#include <cstddef>
#include <string>

namespace vf::sim::opencl {

// The status buffer's words and flags (contours.cl):
// statusAcross counts a collapse decision's recentrings into another bucket of the sweep grid,
// statusOverflow the entries of its overflow list (contours_refine.cl, moveSweepEntry).
enum : std::size_t { statusSticky = 0, statusPass = 1, statusAcross = 2, statusStrain = 3, statusOverflow = 4, statusWords = 5 };
constexpr cl_uint flagNonFinite = 1, flagSplitMismatch = 2;  // sticky
// Per pass. A short edge raises flagShortEdge0 << c for the colour c (0, 1 or 2) of its vertex in
// the collapse passes.
constexpr cl_uint flagShortEdge0 = 1, flagsShortEdge = 7 * flagShortEdge0, flagRecentred = 8, flagSplitCapped = 16;
// The modes of contourTermTiles and contourTermSums (contours_area.cl) and of the motion.
enum : cl_int { termsArea = 0, termsWinding = 1 };
enum : cl_int { motionFlow = 0, motionDrop = 1, motionComb = 2, motionCircularComb = 3, motionSwirl = 4 };

// As build options, -DNAME=VALUE for each of the names the kernels use.
inline std::string contourCodeDefinitions()
{
    struct Definition {
        const char* name;
        unsigned long value;
        const char* suffix;  // "u" for the flags, compared with uint words
    };
    const Definition table[] = {{"STATUS_STICKY", statusSticky, ""},
                                {"STATUS_PASS", statusPass, ""},
                                {"STATUS_ACROSS", statusAcross, ""},
                                {"STATUS_STRAIN", statusStrain, ""},
                                {"STATUS_OVERFLOW", statusOverflow, ""},
                                {"FLAG_NON_FINITE", flagNonFinite, "u"},
                                {"FLAG_SPLIT_MISMATCH", flagSplitMismatch, "u"},
                                {"FLAG_SHORT_EDGE_0", flagShortEdge0, "u"},
                                {"FLAG_RECENTRED", flagRecentred, "u"},
                                {"FLAG_SPLIT_CAPPED", flagSplitCapped, "u"},
                                {"TERMS_AREA", termsArea, ""},
                                {"TERMS_WINDING", termsWinding, ""},
                                {"MOTION_FLOW", motionFlow, ""},
                                {"MOTION_DROP", motionDrop, ""},
                                {"MOTION_COMB", motionComb, ""},
                                {"MOTION_CIRCULAR_COMB", motionCircularComb, ""},
                                {"MOTION_SWIRL", motionSwirl, ""}};
    std::string options;
    for (const Definition& d : table)
        options += std::string(" -D") + d.name + "=" + std::to_string(d.value) + d.suffix;
    return options;
}

} // namespace vf::sim::opencl
