#include "image/ImageIO.h"

#include "io/AtomicFile.h"

// The implementation lives in libstb (Debian); only the declarations are included here.
#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace lit {

namespace fs = std::filesystem;

namespace {

// Rows in file order (top-down) from rows given bottom-up when `flip` is set. A copy is made
// either way: stb's own flip switch is process-wide state, and stbi_write_hdr wants a mutable
// pointer in older versions.
template <typename T>
std::vector<T> rowsInFileOrder(std::span<const T> pixels, std::size_t rowElements, int height, bool flip) {
    std::vector<T> out(rowElements * static_cast<std::size_t>(height));
    for (int y = 0; y < height; ++y) {
        const int source = flip ? height - 1 - y : y;
        std::copy_n(pixels.begin() + static_cast<std::ptrdiff_t>(rowElements * static_cast<std::size_t>(source)), rowElements,
                    out.begin() + static_cast<std::ptrdiff_t>(rowElements * static_cast<std::size_t>(y)));
    }
    return out;
}

// `what` starts the message: "cannot write out.png" or "cannot encode a PNG".
void checkInput(const std::string& what, int width, int height, std::size_t have, int channels) {
    if (width <= 0 || height <= 0)
        throw std::runtime_error(what + ": image size " + std::to_string(width) + "x" + std::to_string(height) +
                                 " is empty");
    const std::size_t need = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * static_cast<std::size_t>(channels);
    if (have < need)
        throw std::runtime_error(what + ": " + std::to_string(have) + " values given for a " + std::to_string(width) +
                                 "x" + std::to_string(height) + " image that needs " + std::to_string(need));
}

// stb_image_write's callback: append the encoded bytes to a vector.
void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

std::vector<std::uint8_t> encodePngRows(int width, int height, std::span<const std::uint8_t> rgba, bool flip,
                                        const std::string& what) {
    checkInput(what, width, height, rgba.size(), 4);
    const std::size_t rowBytes = static_cast<std::size_t>(width) * 4;
    const std::vector<std::uint8_t> rows = rowsInFileOrder(rgba, rowBytes, height, flip);
    std::vector<std::uint8_t> png;
    if (!stbi_write_png_to_func(&appendBytes, &png, width, height, 4, rows.data(), static_cast<int>(rowBytes)))
        throw std::runtime_error(what + ": stb_image_write could not encode the PNG");
    return png;
}

}  // namespace

std::vector<std::uint8_t> encodePng(int width, int height, std::span<const std::uint8_t> rgba, bool flipVertically) {
    return encodePngRows(width, height, rgba, flipVertically, "cannot encode a PNG");
}

void writePng(const fs::path& path, int width, int height, std::span<const std::uint8_t> rgba, bool flipVertically) {
    writeFileAtomically(path, encodePngRows(width, height, rgba, flipVertically, "cannot write " + path.string()));
}

void writeHdr(const fs::path& path, int width, int height, std::span<const float> rgb, bool flipVertically) {
    const std::string what = "cannot write " + path.string();
    checkInput(what, width, height, rgb.size(), 3);
    const std::vector<float> rows = rowsInFileOrder(rgb, static_cast<std::size_t>(width) * 3, height, flipVertically);
    std::vector<std::uint8_t> hdr;
    if (!stbi_write_hdr_to_func(&appendBytes, &hdr, width, height, 3, rows.data()))
        throw std::runtime_error(what + ": stb_image_write could not encode the HDR image");
    writeFileAtomically(path, hdr);
}

HdrImage readHdr(const fs::path& path) {
    const std::string what = "cannot read " + path.string();
    // stbi_is_hdr first: stbi_loadf also converts 8-bit images (PNG, JPEG) to float, which would
    // silently compare a tone-mapped image with a linear one.
    if (!stbi_is_hdr(path.string().c_str()))
        throw std::runtime_error(what + ": not a Radiance .hdr image (or the file cannot be opened)");
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<float, void (*)(void*)> pixels(stbi_loadf(path.string().c_str(), &width, &height, &channels, 3),
                                                          stbi_image_free);
    if (!pixels) throw std::runtime_error(what + ": " + (stbi_failure_reason() ? stbi_failure_reason() : "unknown error"));
    HdrImage image;
    image.width = width;
    image.height = height;
    // The file's rows are top-down; flip them to the bottom-up order used everywhere else.
    image.rgb = rowsInFileOrder(std::span<const float>(pixels.get(), static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3),
                                static_cast<std::size_t>(width) * 3, height, true);
    return image;
}

}  // namespace lit
