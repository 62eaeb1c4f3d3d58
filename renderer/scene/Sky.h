#pragma once
// The sky model, in one place for every renderer: the background of the final image, the light
// that voxel cones receive when they leave the volume (shaders/include/sky.glsl, the GLSL twin of
// skyRadiance below; tests/gl/test_sky.cpp checks that they agree), and what the CPU reference
// path tracer's rays see when they miss the scene. Also the default sun of scenes without lights.
// Radiance in W/(sr·m²), irradiance in W/m² (docs/UNITS.md).

#include "RenderSettings.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <vector>

namespace lit {

struct Scene;

// An equirectangular radiance image: u = 0.5 + atan(x, −z)/2π, v = acos(y)/π, row 0 straight up.
struct SkyImage {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> texels;  // linear radiance, width × height, row 0 first
};

class SkyLoadError : public std::runtime_error {
public:
    explicit SkyLoadError(const std::string& message) : std::runtime_error(message) {}
};

// Reads a Radiance .hdr (RGBE) through stb_image. Throws SkyLoadError naming the file.
SkyImage loadSkyImage(const std::filesystem::path& file);

// The sky of one frame with SkySettings::mode resolved (never Auto).
struct Sky {
    SkyMode mode = SkyMode::None;
    glm::vec3 zenith{0.0f}, horizon{0.0f}, ground{0.0f};
    float intensity = 1.0f;
    const SkyImage* image = nullptr;  // mode Hdr only; not owned
};

// Whether any node holds a light (a light no node holds is not rendered).
bool sceneHasLights(const Scene& scene);
// Auto becomes Gradient for a scene without lights and None otherwise; Hdr without an image
// (not loaded, failed) becomes Gradient.
Sky resolveSky(const Scene& scene, const RenderSettings& settings, const SkyImage* image);

// Radiance arriving from `direction` (world space, any length > 0). Bilinear lookup of the image
// at full resolution (texel centres at (i + ½)/size; u wraps, v clamps), as sky.glsl at lod 0.
glm::vec3 skyRadiance(const Sky& sky, glm::vec3 direction);

// The sky as a self-contained function of a world direction, for renderers that evaluate it on
// the CPU (the reference path tracer's rays that leave the scene: reference::Environment). Loads
// settings.sky.hdrPath when the mode is Hdr (the closure owns the image; an unreadable file gives
// the gradient, with the error in `*error` when given). Empty function when the sky is None.
std::function<glm::vec3(const glm::vec3&)> makeSkyFunction(const Scene& scene, const RenderSettings& settings,
                                                          std::string* error = nullptr);

// The default sun of a scene without lights: whether there is one, and the unit world direction
// its light travels (from the sun at defaultSunElevation above the horizon, azimuth
// defaultSunAzimuth from +Z towards +X).
bool hasDefaultSun(const Scene& scene, const RenderSettings& settings);
glm::vec3 defaultSunDirection(const RenderSettings& settings);
// Adds that sun to `scene` as a directional light node ("default sun"), for renderers that take
// their lights from the scene (the reference path tracer); returns whether it did. Call
// makeSkyFunction before: once the sun is in, an Auto sky sees a lit scene and resolves to None.
bool addDefaultSun(Scene& scene, const RenderSettings& settings);

}  // namespace lit
