#pragma once
// Shared helpers for GL tests: a headless context per process, the Cornell box, and image
// sampling in normalized coordinates and by regions.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <glm/glm.hpp>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "Log.h"
#include "RenderSettings.h"
#include "Renderer.h"
#include "context/HeadlessContext.h"
#include "reference/PathTracer.h"
#include "reference/ReferenceScene.h"
#include "scene/CameraView.h"
#include "scene/GltfLoader.h"
#include "scene/Scene.h"

namespace lit::test {

inline std::filesystem::path sourceDir() { return LIT_SOURCE_DIR; }
inline std::filesystem::path outputDir() {
    std::filesystem::path dir = LIT_TEST_OUTPUT_DIR;
    std::filesystem::create_directories(dir);
    return dir;
}

// Linear HDR image, rows bottom-up as GL returns them.
struct HdrImage {
    int width = 0, height = 0;
    std::vector<float> rgb;

    glm::vec3 at(int x, int y) const {
        const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
        return {rgb[i], rgb[i + 1], rgb[i + 2]};
    }
    // Mean over a rectangle given in [0,1]² image coordinates, origin top-left (as in a picture).
    glm::vec3 mean(float u0, float v0, float u1, float v1) const {
        glm::dvec3 sum(0.0);
        int count = 0;
        const int x0 = static_cast<int>(u0 * width), x1 = static_cast<int>(u1 * width);
        const int y0 = static_cast<int>(v0 * height), y1 = static_cast<int>(v1 * height);
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                sum += glm::dvec3(at(x, height - 1 - y));
                ++count;
            }
        return count ? glm::vec3(sum / double(count)) : glm::vec3(0.0f);
    }
};

// Mean of a (2r+1)² pixel window around pixel (x, y) given bottom-up (GL) coordinates.
inline glm::vec3 windowMean(const HdrImage& image, int cx, int cy, int r) {
    glm::dvec3 sum(0.0);
    int count = 0;
    for (int y = cy - r; y <= cy + r; ++y)
        for (int x = cx - r; x <= cx + r; ++x) {
            if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
            sum += glm::dvec3(image.at(x, y));
            ++count;
        }
    return count ? glm::vec3(sum / double(count)) : glm::vec3(0.0f);
}

// Pixel (bottom-up) where a world-space point appears.
inline glm::ivec2 projectToPixel(const CameraView& camera, const glm::vec3& world, int width, int height) {
    const glm::vec4 clip = camera.projection * camera.view * glm::vec4(world, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {static_cast<int>((ndc.x * 0.5f + 0.5f) * width), static_cast<int>((ndc.y * 0.5f + 0.5f) * height)};
}

inline float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// Mean absolute per-channel difference between a and b, relative to b's mean.
inline double relativeDifference(const HdrImage& a, const HdrImage& b) {
    double difference = 0.0, total = 0.0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) {
        difference += std::abs(double(a.rgb[i]) - b.rgb[i]);
        total += b.rgb[i];
    }
    return difference / total;
}

// The inner pixels of each region label 0 .. labels − 1 of a width × height image (`region` per
// pixel, −1 for none): those whose four neighbours carry the same label, so that no pixel
// straddles a region's edge.
inline std::vector<std::vector<std::size_t>> innerPixels(const std::vector<int>& region, int labels, int width,
                                                         int height) {
    std::vector<std::vector<std::size_t>> out(static_cast<std::size_t>(labels));
    for (int y = 1; y + 1 < height; ++y)
        for (int x = 1; x + 1 < width; ++x) {
            const std::size_t p = static_cast<std::size_t>(y * width + x);
            bool inner = region[p] >= 0;
            for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
                inner = inner && region[static_cast<std::size_t>((y + dy) * width + x + dx)] == region[p];
            if (inner) out[static_cast<std::size_t>(region[p])].push_back(p);
        }
    return out;
}

// Mean RGB of `rgb` (3 floats a pixel) over `pixels`.
inline glm::dvec3 meanRgb(const std::vector<float>& rgb, const std::vector<std::size_t>& pixels) {
    glm::dvec3 sum(0.0);
    for (const std::size_t p : pixels) sum += glm::dvec3(rgb[3 * p], rgb[3 * p + 1], rgb[3 * p + 2]);
    return pixels.empty() ? sum : sum / static_cast<double>(pixels.size());
}

// A headless GL 4.5 context for the duration of one test (each test case runs in its own
// process). Fixtures that build passes derive from it and return early when it failed.
class ContextFixture : public ::testing::Test {
protected:
    void SetUp() override {
        try {
            context_ = std::make_unique<HeadlessContext>();
        } catch (const std::exception& e) {
            GTEST_FAIL() << "no headless GL 4.5 context: " << e.what();
        }
    }

    std::unique_ptr<HeadlessContext> context_;
};

// The reference's image of `scene` (`rs`) from `camera`, with `bounces` (reference::kAllBounces:
// every bounce) and `samples` per pixel, sampled at the pixel centres as the rasterizer samples.
inline reference::ReferenceImage tracedAtPixelCentres(const reference::ReferenceScene& rs, const CameraView& camera,
                                                      int width, int height, int bounces, int samples) {
    reference::ReferenceSettings settings;
    settings.bounces = bounces;
    settings.pixelCentres = true;
    reference::PathTracer tracer(rs, camera, width, height, settings);
    tracer.addSamples(samples);
    return tracer.image();
}

// A context and a Renderer.
class GlFixture : public ContextFixture {
protected:
    void SetUp() override {
        ContextFixture::SetUp();
        if (HasFatalFailure()) return;
        renderer_ = std::make_unique<Renderer>(sourceDir() / "shaders", log_);
    }

    Scene loadCornellBox() { return loadGltf(sourceDir() / "assets" / "cornell_box.gltf", log_); }

    CameraView cameraFor(const Scene& scene, const RenderSettings& settings) const {
        return sceneCameraView(scene, scene.cameras.empty() ? -1 : 0,
                               float(settings.output.width) / float(settings.output.height));
    }

    HdrImage render(const Scene& scene, const RenderSettings& settings, int frames = 1) {
        renderer_->setScene(scene);
        const CameraView camera = cameraFor(scene, settings);
        for (int i = 0; i < frames; ++i) renderer_->render(scene, camera, settings);
        HdrImage image{settings.output.width, settings.output.height, renderer_->readHdrRgb()};
        return image;
    }

    // Each region's mean RGB (`regions`: pixel indices by name) in the direct light alone: Lit with
    // GI off, and the reference without bounces at 16 samples on the pixel centres.
    struct DirectLightPerRegion {
        std::map<std::string, glm::dvec3> lit, reference;
    };
    DirectLightPerRegion directLightPerRegion(const Scene& scene, RenderSettings settings,
                                              const std::map<std::string, std::vector<std::size_t>>& regions,
                                              Log& log) {
        settings.gi.enabled = false;
        const std::vector<float> lit = render(scene, settings).rgb;
        const std::vector<float> reference =
            tracedAtPixelCentres(reference::ReferenceScene(scene, log), cameraFor(scene, settings),
                                 settings.output.width, settings.output.height, 0, 16)
                .viewRgb(View::Final, settings);
        DirectLightPerRegion out;
        for (const auto& [name, pixels] : regions) {
            out.lit[name] = meanRgb(lit, pixels);
            out.reference[name] = meanRgb(reference, pixels);
        }
        return out;
    }

    // L_ID + L_IS rendered with `settings` (its view is set here; the first frame does the GI update).
    std::vector<float> renderIndirect(const Scene& scene, RenderSettings settings) {
        settings.debug.view = View::IndirectDiffuse;
        const HdrImage diffuse = render(scene, settings);
        settings.debug.view = View::IndirectSpecular;
        const HdrImage specular = render(scene, settings);
        std::vector<float> sum(diffuse.rgb.size());
        for (std::size_t i = 0; i < sum.size(); ++i) sum[i] = diffuse.rgb[i] + specular.rgb[i];
        return sum;
    }

    static RenderSettings smallSettings(int size = 128) {
        RenderSettings s;
        s.output.width = size;
        s.output.height = size;
        s.gi.enabled = false;
        s.gi.voxelResolution = 64;
        // These tests measure a frame's light, mostly against references sampled at the pixel
        // centres, and how it converges over frames; anti-aliasing (which blends jittered frames)
        // has its own tests (test_antialiasing.cpp), as has specular anti-aliasing, which widens
        // the lobes by the pixel's footprint (test_specular_antialiasing.cpp).
        s.output.antialiasing = false;
        s.output.specularAntialiasing = false;
        return s;
    }

    // Mean radiance around where `world` appears in `image` (rendered with cameraFor(scene, settings)).
    glm::vec3 radianceAt(const Scene& scene, const RenderSettings& settings, const HdrImage& image,
                         const glm::vec3& world, int radius = 2) const {
        const glm::ivec2 p = projectToPixel(cameraFor(scene, settings), world, image.width, image.height);
        return windowMean(image, p.x, p.y, radius);
    }

    Log log_;
    std::unique_ptr<Renderer> renderer_;
};

}  // namespace lit::test
