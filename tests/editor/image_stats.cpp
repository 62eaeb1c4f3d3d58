// lit_image_stats FILE.png [X Y W H]
// Prints "WIDTH HEIGHT MEAN STDDEV MEAN_R MEAN_G MEAN_B": the image size, the mean and standard
// deviation of its R, G and B values together (0..255), and the mean of each channel, over the
// whole image or the rectangle given (pixels, origin top left). The editor tests use it to tell
// a real capture from a blank one and to see which way a colour edit moved the render.
// lit_image_stats --difference A.png B.png
// Prints "RMSE MEAN_A MEAN_B": the RMSE of the two images' linear luminance (sRGB decoded) as a
// fraction of B's mean, and both means; the images must be the same size.

#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

namespace {

struct StbiFree {
    void operator()(unsigned char* pixels) const { stbi_image_free(pixels); }
};

bool parseInt(const char* text, int& value) {
    char* end = nullptr;
    const long parsed = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || parsed < 0 || parsed > 1 << 20) return false;
    value = static_cast<int>(parsed);
    return true;
}

using Pixels = std::unique_ptr<unsigned char, StbiFree>;

double linear(unsigned char srgb) {
    const double c = srgb / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

int difference(const char* pathA, const char* pathB) {
    int widthA = 0, heightA = 0, widthB = 0, heightB = 0, channels = 0;
    const Pixels a(stbi_load(pathA, &widthA, &heightA, &channels, 3));
    const Pixels b(stbi_load(pathB, &widthB, &heightB, &channels, 3));
    if (!a || !b) {
        std::fprintf(stderr, "lit_image_stats: cannot read %s: %s\n", !a ? pathA : pathB, stbi_failure_reason());
        return 1;
    }
    if (widthA != widthB || heightA != heightB) {
        std::fprintf(stderr, "lit_image_stats: %s is %dx%d, %s %dx%d\n", pathA, widthA, heightA, pathB, widthB,
                     heightB);
        return 2;
    }
    const std::size_t count = static_cast<std::size_t>(widthA) * heightA;
    double sumA = 0.0, sumB = 0.0, sumSquares = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        const unsigned char* pa = a.get() + i * 3;
        const unsigned char* pb = b.get() + i * 3;
        // Rec. 709 luminance of the linear values.
        const double la = 0.2126 * linear(pa[0]) + 0.7152 * linear(pa[1]) + 0.0722 * linear(pa[2]);
        const double lb = 0.2126 * linear(pb[0]) + 0.7152 * linear(pb[1]) + 0.0722 * linear(pb[2]);
        sumA += la;
        sumB += lb;
        sumSquares += (la - lb) * (la - lb);
    }
    const double meanB = sumB / static_cast<double>(count);
    const double rmse = meanB > 0.0 ? std::sqrt(sumSquares / static_cast<double>(count)) / meanB : 0.0;
    std::printf("%.6f %.6f %.6f\n", rmse, sumA / static_cast<double>(count), meanB);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 4 && std::string(argv[1]) == "--difference") return difference(argv[2], argv[3]);
    if (argc != 2 && argc != 6) {
        std::fprintf(stderr, "usage: lit_image_stats FILE.png [X Y W H] | --difference A.png B.png\n");
        return 2;
    }
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<unsigned char, StbiFree> pixels(stbi_load(argv[1], &width, &height, &channels, 3));
    if (!pixels) {
        std::fprintf(stderr, "lit_image_stats: cannot read %s: %s\n", argv[1], stbi_failure_reason());
        return 1;
    }
    int x = 0, y = 0, w = width, h = height;
    if (argc == 6 && !(parseInt(argv[2], x) && parseInt(argv[3], y) && parseInt(argv[4], w) && parseInt(argv[5], h))) {
        std::fprintf(stderr, "lit_image_stats: X Y W H must be whole numbers\n");
        return 2;
    }
    if (w == 0 || h == 0 || x + w > width || y + h > height) {
        std::fprintf(stderr, "lit_image_stats: rectangle %d,%d %dx%d is empty or outside the %dx%d image\n", x, y, w, h,
                     width, height);
        return 2;
    }
    double channelSum[3] = {0.0, 0.0, 0.0};
    double sumSquares = 0.0;
    for (int row = y; row < y + h; ++row) {
        for (int column = x; column < x + w; ++column) {
            const unsigned char* p = pixels.get() + (static_cast<std::size_t>(row) * width + column) * 3;
            for (int c = 0; c < 3; ++c) {
                const double v = p[c];
                channelSum[c] += v;
                sumSquares += v * v;
            }
        }
    }
    const double pixelCount = static_cast<double>(w) * h;
    const double count = 3.0 * pixelCount;
    // Sums of whole numbers below 2^53: exact, so the order of adding does not matter.
    const double mean = (channelSum[0] + channelSum[1] + channelSum[2]) / count;
    const double variance = std::max(sumSquares / count - mean * mean, 0.0);
    std::printf("%d %d %.3f %.3f %.3f %.3f %.3f\n", width, height, mean, std::sqrt(variance), channelSum[0] / pixelCount,
                channelSum[1] / pixelCount, channelSum[2] / pixelCount);
    return 0;
}
