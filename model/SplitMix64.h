#pragma once
// SplitMix64 (Steele, Lea and Flood 2014): a tiny generator whose every output is fixed by the
// seed, unlike the standard library's distributions, so a seeded tool (spatter, a pattern's stone)
// makes the same drops on every machine.
#include <cstdint>

namespace vf::model {

class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed) : m_state(seed) {}
    // Uniform in [0, 1), 53 bits.
    double unit()
    {
        std::uint64_t z = (m_state += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return double((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
    }

private:
    std::uint64_t m_state;
};

} // namespace vf::model
