#pragma once
// Per-vertex arrays that grow by an eighth when they must, not by doubling: the contours and the
// proximity grid grow a little every step, and doubling would leave up to as much again resident
// (the session benchmarks measure memory per vertex).
#include <cstddef>
#include <vector>

namespace vf::sim {

template <typename T>
void reserveTight(std::vector<T>& v, std::size_t n)
{
    if (n > v.capacity())
        v.reserve(n + n / 8);
}

template <typename T>
void resizeTight(std::vector<T>& v, std::size_t n)
{
    reserveTight(v, n);
    v.resize(n);
}

// For an array rebuilt from scratch each time: past its capacity the old storage is freed before
// the new one is allocated, so the two are never resident together (a reserve() would copy).
template <typename T>
void resizeDiscarding(std::vector<T>& v, std::size_t n)
{
    if (n > v.capacity()) {
        std::vector<T>().swap(v);
        v.reserve(n + n / 8);
    }
    v.resize(n);
}

} // namespace vf::sim
