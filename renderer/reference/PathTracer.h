#pragma once
// The reference path tracer: Lit's ground truth. Renders the same Scene through the same camera
// with the same BRDF (MicrofacetBrdf.h = brdf.glsl) and light units (PunctualLights.h =
// lights.glsl) as the rasterizer, with exact visibility, and splits the result into Lit's four
// terms so that each VCT term has its own truth:
//   direct diffuse / direct specular     light → surface → eye, split by BRDF lobe at the first hit
//                                        (emission seen directly is added to direct diffuse, as Lit does)
//   indirect diffuse / indirect specular light → (≥ 1 more surface) → first surface → eye, split by
//                                        the lobe of the first surface's BRDF
// Next-event estimation for punctual lights and emissive triangles, multiple importance sampling
// (power heuristic) between emitter and BRDF sampling, cosine / GGX visible-normal sampling of
// the BRDF's three lobes (docs/MATERIALS.md: diffuse, specular, clear coat; ReferenceBsdf.h),
// Russian roulette past 3 bounces. Deterministic: a pixel's sample s under seed S always draws the
// same random numbers, whatever the thread count or tile order. docs/REFERENCE.md has the details
// and every place where the reference differs from the rasterizer on purpose.

#include "RenderSettings.h"
#include "reference/ReferenceScene.h"
#include "reference/ViewSupport.h"
#include "scene/CameraView.h"

#include <glm/glm.hpp>

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

namespace lit::reference {

// Radiance arriving from infinitely far away along a world direction (unit), W/(sr·m²): what a
// ray that leaves the scene sees. Empty = black (Lit's background). A sky plugs in here; the
// reference samples it only by BRDF sampling (no importance sampling of the environment).
using Environment = std::function<glm::vec3(const glm::vec3& direction)>;

inline constexpr int kAllBounces = -1;  // no bounce limit: paths end by Russian roulette (or at kMaxPathVertices)
inline constexpr int kMaxPathVertices = 64;  // a guard against endless paths in closed white rooms

struct ReferenceSettings {
    int bounces = 1;             // indirect bounces: 0 = direct only, 1 = Lit's one-bounce VCT, kAllBounces
    std::uint64_t seed = 0;      // the same seed renders the same image
    int russianRouletteStart = 3;  // bounces after which paths may end at random (all bounces only)
    Environment environment;     // radiance of rays that leave the scene; empty = black
    // Camera rays through the pixel centres only, as the rasterizer samples (no anti-aliasing), instead
    // of spread over the pixel: for comparisons that must not depend on how an edge or a highlight
    // falls inside a pixel.
    bool pixelCentres = false;
};

enum class Term { DirectDiffuse, DirectSpecular, IndirectDiffuse, IndirectSpecular };
inline constexpr int kTermCount = 4;

// The four term images being accumulated: per pixel the sum of its samples and their count.
// Rows bottom-up, as the rasterizer's images (docs/CONVENTIONS.md).
struct ReferenceImage {
    int width = 0, height = 0;
    std::vector<glm::dvec3> sums[kTermCount];  // W/(sr·m²) × samples
    std::vector<std::uint32_t> samples;        // per pixel

    void resize(int w, int h);
    void clear();
    std::size_t pixelCount() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
    // Mean radiance of one term at a pixel (0 before its first sample).
    glm::vec3 mean(Term term, std::size_t pixel) const;
    // Linear RGB floats of `view` (Final: the sum of the terms `settings` switches on; the four
    // term views: that term), bottom-up rows, as Renderer::readHdrRgb. Throws
    // std::invalid_argument for views the reference does not render (albedo, voxels, ...).
    std::vector<float> viewRgb(View view, const RenderSettings& settings) const;
    std::uint32_t minSamples() const;
};


// What the camera sees through each pixel's centre: for masks (regions, shadow edges) in tests
// and in the accuracy benchmark.
struct FirstHit {
    int node = -1;  // scene node index, -1 for background
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};  // shading normal facing the camera
    std::uint32_t litBy = 0;  // bit i set: punctual light i (< 32) reaches the point unoccluded with n·l > 0 and E > 0
    bool emissive = false;    // the surface emits light
    float metalness = 0.0f, roughness = 1.0f;  // the material there (for masks at material edges)
};
std::vector<FirstHit> traceFirstHits(const ReferenceScene& scene, const CameraView& camera, int width, int height);

class PathTracer {
public:
    // The scene must outlive the tracer. `camera` as the rasterizer gets it (same aspect).
    PathTracer(const ReferenceScene& scene, const CameraView& camera, int width, int height, ReferenceSettings settings);

    // Adds `count` samples to every pixel, in parallel over tiles (TBB). Stops early, leaving
    // later tiles without this pass's samples, when `cancel` becomes true; returns false then.
    bool addSamples(int count, const std::atomic<bool>* cancel = nullptr);

    const ReferenceImage& image() const { return image_; }
    int samplesDone() const { return passSamples_; }  // samples per pixel completed by every pixel
    std::uint64_t raysTraced() const { return rays_.load(); }  // closest-hit and shadow rays so far
    const ReferenceSettings& settings() const { return settings_; }

private:
    const ReferenceScene& scene_;
    glm::mat4 inverseViewProjection_;
    ReferenceSettings settings_;
    ReferenceImage image_;
    int passSamples_ = 0;
    std::atomic<std::uint64_t> rays_{0};
};

// Exposure, the ACES filmic fit (tonemap.glsl) and the sRGB transfer function, as the GL tone
// mapper and GL_FRAMEBUFFER_SRGB write it: linear RGB floats → RGBA8, same row order.
std::vector<std::uint8_t> toneMapToRgba8(const std::vector<float>& rgb, float exposure);

}  // namespace lit::reference
