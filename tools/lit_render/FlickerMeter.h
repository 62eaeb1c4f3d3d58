#pragma once
// Temporal stability along a camera path (--bench-path): the mean absolute luminance change from
// one frame to the next of pixels whose surface did not move, relative to the frame's mean
// luminance. Each pixel's world point (from its depth) is projected into the previous frame; it
// counts when the previous frame saw the same point there (within 1 % of its distance, at all
// four bilinear taps, so silhouettes are left out), and is compared with the previous frame's
// luminance interpolated at that spot.

#include <cstddef>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "scene/CameraView.h"

namespace lit::cli {

class FlickerMeter {
public:
    // One frame of the path: its camera, linear RGB and depth (rows bottom-up, as the renderer
    // reads them back).
    void add(const CameraView& camera, int width, int height, std::vector<float> rgb, std::vector<float> depth);
    // Mean over the frame pairs measured, and the largest pair; 0 before two frames.
    double mean() const;
    double max() const;
    std::size_t pairs() const { return pairs_.size(); }

private:
    struct Frame {
        glm::mat4 viewProjection;
        glm::vec3 position;
        std::vector<float> depth, luminance;
    };
    // The world point a pixel of `f` saw, from its depth (`inverse`: of f's view-projection).
    static glm::vec3 world(const Frame& f, const glm::mat4& inverse, int width, int height, int x, int y);
    void measure(const Frame& prev, const Frame& cur, int width, int height);

    std::optional<Frame> previous_;
    std::vector<double> pairs_;
};

}  // namespace lit::cli
