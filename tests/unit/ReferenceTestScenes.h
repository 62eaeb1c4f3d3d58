#pragma once
// Scenes the reference path tracer's tests share (test_reference.cpp, test_reference_materials.cpp).

#include "QuietLog.h"
#include "reference/PathTracer.h"
#include "reference/ReferenceScene.h"
#include "scene/CameraView.h"
#include "scene/SceneBuilder.h"

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace lit::reference::testing {

// A camera node looking from `position` at `target` (yfov 0.8 rad, square images).
inline void addCamera(Scene& scene, const glm::vec3& position, const glm::vec3& target) {
    Camera camera;
    camera.yfov = 0.8f;
    camera.znear = 0.05f;
    camera.zfar = 50.0f;
    addCameraNode(scene, camera, position, target);
}

// A unit box of the scene's first material (already added) seen from (1.6, 1.3, 1.9) under a
// uniform grey sky of radiance `sky`, every bounce, `samples` per pixel (at the pixel centres,
// the view directions of traceFirstHits, when `pixelCentres`): the mean diffuse (L_DD + L_ID) and
// specular (L_DS + L_IS) radiance, green channel, over the pixels whose 3 × 3 neighbourhood lies
// on the box. A convex box never sees itself: every point is lit by the sky alone.
// `perPixel(hit, eye)` sees each of those pixels.
struct BoxUnderSky {
    double diffuse = 0.0, specular = 0.0;
    int pixels = 0;
};
template <typename PerPixel>
BoxUnderSky boxUnderSky(Scene& scene, float sky, int samples, bool pixelCentres, PerPixel&& perPixel) {
    addMeshNode(scene, makeBoxMesh("box", glm::vec3(1.0f), 0), glm::vec3(0.0f));
    addCamera(scene, glm::vec3(1.6f, 1.3f, 1.9f), glm::vec3(0.0f));
    scene.updateWorldTransforms();
    lit::testing::QuietLog log;
    const ReferenceScene reference(scene, log);
    const CameraView view = sceneCameraView(scene, 0, 1.0f);
    ReferenceSettings settings;
    settings.bounces = kAllBounces;
    settings.environment = [sky](const glm::vec3&) { return glm::vec3(sky); };
    settings.pixelCentres = pixelCentres;
    constexpr int kSize = 32;
    PathTracer tracer(reference, view, kSize, kSize, settings);
    tracer.addSamples(samples);
    const std::vector<FirstHit> hits = traceFirstHits(reference, view, kSize, kSize);
    BoxUnderSky out;
    for (int y = 1; y + 1 < kSize; ++y)
        for (int x = 1; x + 1 < kSize; ++x) {
            bool inside = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) inside &= hits[static_cast<std::size_t>((y + dy) * kSize + x + dx)].node >= 0;
            if (!inside) continue;
            const std::size_t p = static_cast<std::size_t>(y * kSize + x);
            perPixel(hits[p], view.position);
            const ReferenceImage& image = tracer.image();
            out.diffuse += image.mean(Term::DirectDiffuse, p).g + image.mean(Term::IndirectDiffuse, p).g;
            out.specular += image.mean(Term::DirectSpecular, p).g + image.mean(Term::IndirectSpecular, p).g;
            ++out.pixels;
        }
    EXPECT_GT(out.pixels, 100) << "the box must fill the view";
    if (out.pixels > 0) {
        out.diffuse /= out.pixels;
        out.specular /= out.pixels;
    }
    return out;
}

}  // namespace lit::reference::testing
