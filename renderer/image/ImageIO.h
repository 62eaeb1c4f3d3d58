#pragma once
// Writing images (stb_image_write). Rows are given bottom-up as OpenGL reads them and flipped.

#include <cstdint>
#include <filesystem>
#include <span>

namespace lit {

// 8-bit RGBA → PNG. Throws std::runtime_error naming the path when the write fails.
void writePng(const std::filesystem::path& path, int width, int height, std::span<const std::uint8_t> rgba,
              bool flipVertically = true);
// Linear float RGB → Radiance .hdr. Throws std::runtime_error naming the path when the write fails.
void writeHdr(const std::filesystem::path& path, int width, int height, std::span<const float> rgb,
              bool flipVertically = true);

// Files are written to "<path>.tmp" first and renamed, so a failed write never leaves a
// truncated image where a good one was.

}  // namespace lit
