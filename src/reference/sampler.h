// Low-discrepancy samples for the reference renderers: the first two dimensions of the
// Sobol sequence (a (0,2)-sequence in base 2), Owen-scrambled with the hash-based
// nested uniform scramble of Burley 2020 ("Practical Hash-based Owen Scrambling", JCGT
// 9(4)), as in pbrt-v4's FastOwenScrambler.
//
// Each pixel (or surface point) and each pair of dimensions gets its own scramble seed,
// hashed from (seed, pixel index, dimension pair), and the sample index is shuffled per
// dimension pair with the same scramble (Burley's "shuffled" Sobol) so that dimension pairs
// of one path are decorrelated (padding). Because the Sobol generator matrices are upper
// triangular, every prefix of 2^m shuffled samples is still a (0,m,2)-net: passes of
// doubling sample counts stay stratified, which is what the progressive loop relies on.
//
// Everything is a pure function of (seed, pixel, index, dimension): no shared RNG state,
// so results do not depend on the thread count or the order of evaluation.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdint>

namespace vct {

inline uint32_t reverseBits32(uint32_t v) {
    v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
    v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
    v = ((v >> 4) & 0x0F0F0F0Fu) | ((v & 0x0F0F0F0Fu) << 4);
    v = ((v >> 8) & 0x00FF00FFu) | ((v & 0x00FF00FFu) << 8);
    return (v >> 16) | (v << 16);
}

// 64-bit finalizer (splitmix64 / Stafford's Mix13): a good avalanche for seeds.
inline uint64_t mixBits64(uint64_t v) {
    v ^= v >> 31;
    v *= 0x7fb5d329728ea185ull;
    v ^= v >> 27;
    v *= 0x81dadef4bc2dd44dull;
    v ^= v >> 33;
    return v;
}

inline uint64_t hashSeed(uint64_t a, uint64_t b, uint64_t c = 0) {
    return mixBits64(a * 0x9E3779B97F4A7C15ull ^ mixBits64(b + 0x632BE59BD9B4E019ull) ^
                     mixBits64(c * 0xD6E8FEB86659FD93ull + 1));
}

// Owen scramble of a 32-bit binary fraction (bit 31 = 1/2): each bit is flipped by a
// hash of the bits above it (Burley 2020, listing 3 with the improved constants).
inline uint32_t owenScramble(uint32_t v, uint32_t seed) {
    v = reverseBits32(v);
    v ^= v * 0x3d20adeau;
    v += seed;
    v *= (seed >> 16) | 1u;
    v ^= v * 0x05526c56u;
    v ^= v * 0x53a22864u;
    return reverseBits32(v);
}

// Sobol dimension 0 (van der Corput) and dimension 1 as 32-bit fractions.
inline uint32_t sobolDim0(uint32_t index) { return reverseBits32(index); }
inline uint32_t sobolDim1(uint32_t index) {
    uint32_t r = 0;
    for (uint32_t v = 1u << 31; index; index >>= 1, v ^= v >> 1)
        if (index & 1u) r ^= v;
    return r;
}

inline float fractionToFloat(uint32_t x) {
    return std::min(float(x) * 0x1p-32f, 0x1.fffffep-1f);  // [0, 1)
}

// Sample `index` of the 2D dimension pair `dimPair` for the stream `streamSeed` (one per
// pixel or surface point).
inline glm::vec2 sobol2D(uint64_t streamSeed, uint32_t dimPair, uint32_t index) {
    uint64_t h = hashSeed(streamSeed, dimPair);
    uint32_t shuffled = owenScramble(index, uint32_t(h));
    uint32_t x = owenScramble(sobolDim0(shuffled), uint32_t(h >> 32));
    uint32_t y = owenScramble(sobolDim1(shuffled), uint32_t(mixBits64(h) >> 32));
    return {fractionToFloat(x), fractionToFloat(y)};
}

// Seed of the sample stream of one pixel / surface point.
inline uint64_t streamSeed(uint64_t seed, uint64_t pixelIndex) { return hashSeed(seed, pixelIndex, 0x5eed); }

}  // namespace vct
