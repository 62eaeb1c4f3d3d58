#pragma once
// Writing images (stb_image_write). Rows are given bottom-up as OpenGL reads them and flipped.

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace lit {

// 8-bit RGBA → PNG. Throws std::runtime_error naming the path when the write fails.
void writePng(const std::filesystem::path& path, int width, int height, std::span<const std::uint8_t> rgba,
              bool flipVertically = true);
// Linear float RGB → Radiance .hdr. Throws std::runtime_error naming the path when the write fails.
void writeHdr(const std::filesystem::path& path, int width, int height, std::span<const float> rgb,
              bool flipVertically = true);

// Files are written to a temporary beside `path` first and renamed (io/AtomicFile.h), so a
// failed write never leaves a truncated image where a good one was.

// 8-bit RGBA → PNG bytes in memory (for images embedded in a glTF buffer). Throws
// std::runtime_error when the size is empty or `rgba` holds too few values.
std::vector<std::uint8_t> encodePng(int width, int height, std::span<const std::uint8_t> rgba,
                                    bool flipVertically = true);

}  // namespace lit
