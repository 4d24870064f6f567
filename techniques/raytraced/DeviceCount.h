#pragma once
// The host's side of a 64-bit count that shaders add to in two 32-bit words (shaders/raytraced/count64.glsl:
// the low word, then the high one): its size in a buffer, zeroing it and reading it back.
#include <cstdint>
#include <cstring>

namespace sb {

/// Bytes of one count in a storage buffer (std430: two uints).
constexpr size_t kDeviceCountBytes = 2 * sizeof(uint32_t);

/// Zeroes the count at `words` (a mapped, host-coherent buffer the device is not writing).
inline void zeroDeviceCount(void* words) {
    std::memset(words, 0, kDeviceCountBytes);
}

/// The count at `words`: high * 2^32 + low. Read after the frame's fence.
inline uint64_t readDeviceCount(const void* words) {
    uint32_t w[2];
    std::memcpy(w, words, sizeof w);
    return (uint64_t(w[1]) << 32) | w[0];
}

} // namespace sb
