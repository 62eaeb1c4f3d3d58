#include "FlickerMeter.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace lit::cli {

void FlickerMeter::add(const CameraView& camera, int width, int height, std::vector<float> rgb,
                       std::vector<float> depth) {
    Frame current{camera.projection * camera.view, camera.position, std::move(depth), {}};
    current.luminance.resize(current.depth.size());
    for (std::size_t i = 0; i < current.luminance.size(); ++i)
        current.luminance[i] = 0.2126f * rgb[3 * i] + 0.7152f * rgb[3 * i + 1] + 0.0722f * rgb[3 * i + 2];
    if (previous_) measure(*previous_, current, width, height);
    previous_ = std::move(current);
}

double FlickerMeter::mean() const {
    return pairs_.empty() ? 0.0 : std::accumulate(pairs_.begin(), pairs_.end(), 0.0) / pairs_.size();
}

double FlickerMeter::max() const { return pairs_.empty() ? 0.0 : *std::max_element(pairs_.begin(), pairs_.end()); }

glm::vec3 FlickerMeter::world(const Frame& f, const glm::mat4& inverse, int width, int height, int x, int y) {
    const float d = f.depth[static_cast<std::size_t>(y) * width + x];
    const glm::vec4 w =
        inverse * glm::vec4((x + 0.5f) / width * 2.0f - 1.0f, (y + 0.5f) / height * 2.0f - 1.0f, d * 2.0f - 1.0f, 1.0f);
    return glm::vec3(w) / w.w;
}

void FlickerMeter::measure(const Frame& prev, const Frame& cur, int width, int height) {
    const glm::mat4 curInverse = glm::inverse(cur.viewProjection), prevInverse = glm::inverse(prev.viewProjection);
    double change = 0.0, total = 0.0;
    std::size_t counted = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * width + x;
            if (cur.depth[i] >= 1.0f) continue;
            const glm::vec3 p = world(cur, curInverse, width, height, x, y);
            const glm::vec4 clip = prev.viewProjection * glm::vec4(p, 1.0f);
            if (clip.w <= 0.0f) continue;
            const float px = (clip.x / clip.w * 0.5f + 0.5f) * width - 0.5f;
            const float py = (clip.y / clip.w * 0.5f + 0.5f) * height - 0.5f;
            const int x0 = static_cast<int>(std::floor(px)), y0 = static_cast<int>(std::floor(py));
            if (x0 < 0 || y0 < 0 || x0 + 1 >= width || y0 + 1 >= height) continue;
            const float tolerance = 0.01f * glm::length(p - prev.position);
            bool same = true;
            float value = 0.0f;
            for (int t = 0; t < 4 && same; ++t) {
                const int tx = x0 + (t & 1), ty = y0 + (t >> 1);
                if (prev.depth[static_cast<std::size_t>(ty) * width + tx] >= 1.0f) {
                    same = false;
                    break;
                }
                same = glm::length(world(prev, prevInverse, width, height, tx, ty) - p) <=
                       tolerance + 2.0f * glm::length(p - prev.position) / height;  // + a pixel's footprint
                const float wx = (t & 1) ? px - x0 : 1.0f - (px - x0), wy = (t >> 1) ? py - y0 : 1.0f - (py - y0);
                value += wx * wy * prev.luminance[static_cast<std::size_t>(ty) * width + tx];
            }
            if (!same) continue;
            change += std::abs(static_cast<double>(cur.luminance[i]) - value);
            ++counted;
        }
    for (float l : cur.luminance) total += l;
    const double mean = total / static_cast<double>(cur.luminance.size());
    if (counted > 0 && mean > 0.0) pairs_.push_back(change / static_cast<double>(counted) / mean);
}

}  // namespace lit::cli
