// Eight one-byte pixel values as the lanes of a 64-bit word: the frame's byte buffers (states,
// flags, marks) are handled a block row (eight pixels) at a time.
#pragma once

#include <bit>
#include <cstdint>

namespace rs::lanes {

// Byte k of a word loaded with memcpy is the pixel at offset k: the shifts below rely on it.
static_assert(std::endian::native == std::endian::little);

constexpr uint64_t kEachByte = 0x0101010101010101ull;

/// 0x01 in each byte of `m` that is not zero, 0x00 in the others.
constexpr uint64_t nonZeroBytes(uint64_t m) {
    constexpr uint64_t low7 = 0x7f * kEachByte;
    return ((((m & low7) + low7) | m) >> 7) & kEachByte;
}

/// The sum of the bytes of `v`, each 0 or 1 (a multiply, where std::popcount is a library
/// call on the x86-64 baseline this builds for).
constexpr uint32_t sumOfBytes(uint64_t v) {
    return uint32_t((v * kEachByte) >> 56);
}

}  // namespace rs::lanes
