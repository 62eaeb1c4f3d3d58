#include "image/ImageIO.h"

// The implementation lives in libstb (Debian); only the declarations are included here.
#include <stb_image_write.h>

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <system_error>
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

void checkInput(const fs::path& path, int width, int height, std::size_t have, int channels) {
    if (width <= 0 || height <= 0)
        throw std::runtime_error("cannot write " + path.string() + ": image size " + std::to_string(width) + "x" +
                                 std::to_string(height) + " is empty");
    const std::size_t need = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * static_cast<std::size_t>(channels);
    if (have < need)
        throw std::runtime_error("cannot write " + path.string() + ": " + std::to_string(have) + " values given for a " +
                                 std::to_string(width) + "x" + std::to_string(height) + " image that needs " +
                                 std::to_string(need));
}

// Creates the parent folder, lets `write` fill "<path>.tmp", then renames it over `path`, so a
// failed write never leaves a truncated image where a good one was.
template <typename WriteFn>
void writeAtomically(const fs::path& path, WriteFn write) {
    std::error_code ec;
    if (path.has_parent_path()) {
        fs::create_directories(path.parent_path(), ec);
        if (ec) throw std::runtime_error("cannot write " + path.string() + ": cannot create folder " +
                                         path.parent_path().string() + " (" + ec.message() + ")");
    }
    const fs::path tmp = fs::path(path.string() + ".tmp");
    if (!write(tmp.string().c_str())) {
        fs::remove(tmp, ec);
        throw std::runtime_error("cannot write " + path.string() + " (stb_image_write failed to write " + tmp.string() + ")");
    }
    fs::rename(tmp, path, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        throw std::runtime_error("cannot write " + path.string() + ": rename from " + tmp.string() + " failed (" +
                                 ec.message() + ")");
    }
}

}  // namespace

void writePng(const fs::path& path, int width, int height, std::span<const std::uint8_t> rgba, bool flipVertically) {
    checkInput(path, width, height, rgba.size(), 4);
    const std::size_t rowBytes = static_cast<std::size_t>(width) * 4;
    const std::vector<std::uint8_t> rows = rowsInFileOrder(rgba, rowBytes, height, flipVertically);
    writeAtomically(path, [&](const char* file) {
        return stbi_write_png(file, width, height, 4, rows.data(), static_cast<int>(rowBytes)) != 0;
    });
}

void writeHdr(const fs::path& path, int width, int height, std::span<const float> rgb, bool flipVertically) {
    checkInput(path, width, height, rgb.size(), 3);
    const std::vector<float> rows = rowsInFileOrder(rgb, static_cast<std::size_t>(width) * 3, height, flipVertically);
    writeAtomically(path, [&](const char* file) { return stbi_write_hdr(file, width, height, 3, rows.data()) != 0; });
}

}  // namespace lit
