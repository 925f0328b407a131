// The deterministic random numbers behind sample kernels and noise tiles: SplitMix64
// (Steele et al. 2014), whose output is fixed by the seed on every platform, unlike the
// standard library's distributions.
#pragma once

#include <cstdint>

namespace vct {

struct SplitMix64 {
    uint64_t state;

    explicit SplitMix64(uint64_t seed) : state(seed) {}
    uint64_t next() {
        uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    // Uniform in [0, 1) with 53 random bits.
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }
    // Uniform in [a, b).
    float uniform(float a, float b) { return a + (b - a) * float(uniform()); }
};

}  // namespace vct
