// SplitMix64 (Steele, Lea, Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014): a counter-based
// draw, the same number for the same input whichever draws were asked for before it.
#pragma once
#include <cstdint>

namespace cnc {

inline std::uint64_t splitmix64(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30U)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27U)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31U);
}

// The key of stream `stream` of a seed: the streams of one seed (each line of a link, each driver) draw apart.
inline std::uint64_t stream_key(std::uint64_t seed, std::uint64_t stream) {
    return splitmix64(splitmix64(seed) ^ stream);
}

// Draw number `n` of the stream `key`, uniform in [0, 1) with 53 random bits: a function of (key, n) alone.
inline double unit_draw(std::uint64_t key, std::uint64_t n) {
    constexpr double kTwoPowMinus53 = 1.0 / 9007199254740992.0;
    return static_cast<double>(splitmix64(key ^ splitmix64(n)) >> 11U) * kTwoPowMinus53;
}

}  // namespace cnc
