#pragma once
// How the process's heap hands memory back. Called first thing in main() by the programs that run
// simulations (the app, the benchmarks), never by the library itself: it is a setting of the
// whole process.

namespace vf::sim {

// glibc maps blocks above a threshold straight from the system and unmaps them when freed, but it
// raises that threshold to the largest mapped block freed (up to 32 MiB). After the first large
// grid is freed, the contours and grids that every step frees and allocates again, of one to a few
// MiB, come from the heap instead, and the holes they leave stay resident. A fixed threshold of
// 1 MiB keeps them mapped, at the same speed; a smaller one costs page faults (the figures:
// docs/BENCHMARKS.md, "Sessions"). Does nothing on other C libraries.
void keepLargeBlocksMapped();

} // namespace vf::sim
