#pragma once
// 32-bit little-endian words in byte buffers (GLB headers and chunk headers, glTF 2.0 §4.4).

#include <cstdint>

namespace lit {

inline std::uint32_t readLittleEndian32(const unsigned char* p) {
    return std::uint32_t(p[0]) | (std::uint32_t(p[1]) << 8) | (std::uint32_t(p[2]) << 16) | (std::uint32_t(p[3]) << 24);
}

inline void writeLittleEndian32(unsigned char* p, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) p[i] = static_cast<unsigned char>(value >> (8 * i));
}

}  // namespace lit
