#pragma once
// Helpers for the GL tests that compare pictures of a red/blue checker (the Blender scenes of
// tools/blender/make_texture_transform.py and make_second_uv_set.py): which colour each pixel
// shows, how many pixels two pictures agree on, and the checker edges along one pixel row.

#include <vector>

#include "GlTestSupport.h"

namespace lit::test {

// 1 red, 2 blue, 0 neither (background, a blend at an edge), per pixel of `rgb` (3 floats each).
inline std::vector<int> checkerClasses(const std::vector<float>& rgb) {
    std::vector<int> out(rgb.size() / 3);
    for (std::size_t p = 0; p < out.size(); ++p) {
        const glm::vec3 c{rgb[3 * p], rgb[3 * p + 1], rgb[3 * p + 2]};
        out[p] = c.r > 2.0f * c.b && c.r > 0.02f ? 1 : c.b > 2.0f * c.r && c.b > 0.02f ? 2 : 0;
    }
    return out;
}

// The fraction of the pixels in `mask` where both pictures show the same checker colour.
inline double checkerAgreement(const std::vector<int>& a, const std::vector<int>& b, const std::vector<bool>& mask) {
    int same = 0, total = 0;
    for (std::size_t p = 0; p < mask.size(); ++p) {
        if (!mask[p]) continue;
        ++total;
        same += a[p] == b[p] && a[p] != 0;
    }
    return total ? double(same) / total : 0.0;
}

// Checker colour changes along pixel row `y` of a `width`-wide picture, over the pixels in `mask`.
inline int checkerEdgesAlongRow(const std::vector<int>& cls, const std::vector<bool>& mask, int y, int width) {
    int edges = 0, last = 0;
    for (int x = 0; x < width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y * width + x);
        if (!mask[i] || cls[i] == 0) continue;
        edges += last != 0 && cls[i] != last;
        last = cls[i];
    }
    return edges;
}

}  // namespace lit::test
