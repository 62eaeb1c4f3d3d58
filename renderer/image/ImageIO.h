#pragma once
// Writing images (stb_image_write) and reading Radiance .hdr images (stb_image). Rows are given
// bottom-up as OpenGL reads them, and flipped to and from the files' top-down order.

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

// A linear float RGB image, rows bottom-up (as Renderer::readHdrRgb gives them).
struct HdrImage {
    int width = 0, height = 0;
    std::vector<float> rgb;  // 3 floats per pixel
};
// Radiance .hdr (as writeHdr writes it) → linear RGB. Throws std::runtime_error naming the path
// when the file cannot be read or is not an HDR image.
HdrImage readHdr(const std::filesystem::path& path);

// 8-bit RGBA → PNG bytes in memory (for images embedded in a glTF buffer). Throws
// std::runtime_error when the size is empty or `rgba` holds too few values.
std::vector<std::uint8_t> encodePng(int width, int height, std::span<const std::uint8_t> rgba,
                                    bool flipVertically = true);

}  // namespace lit
