#include "scene/Sky.h"

#include "scene/Scene.h"
#include "scene/SceneBuilder.h"

#include <shared.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

namespace lit {

SkyImage loadSkyImage(const std::filesystem::path& file) {
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<float, void (*)(void*)> pixels(stbi_loadf(file.string().c_str(), &width, &height, &channels, 3),
                                                          stbi_image_free);
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        throw SkyLoadError(file.string() + ": cannot read the sky image: " + (reason ? reason : "unknown error"));
    }
    SkyImage image;
    image.width = width;
    image.height = height;
    image.texels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    for (std::size_t i = 0; i < image.texels.size(); ++i)
        image.texels[i] = glm::vec3(pixels.get()[3 * i], pixels.get()[3 * i + 1], pixels.get()[3 * i + 2]);
    return image;
}

bool sceneHasLights(const Scene& scene) {
    return std::any_of(scene.nodes.begin(), scene.nodes.end(), [&](const Node& node) {
        return node.light >= 0 && static_cast<std::size_t>(node.light) < scene.lights.size();
    });
}

Sky resolveSky(const Scene& scene, const RenderSettings& settings, const SkyImage* image) {
    Sky sky;
    sky.mode = settings.sky.mode;
    if (sky.mode == SkyMode::Auto) sky.mode = sceneHasLights(scene) ? SkyMode::None : SkyMode::Gradient;
    if (sky.mode == SkyMode::Hdr && (!image || image->texels.empty())) sky.mode = SkyMode::Gradient;
    const auto vec = [](const std::array<float, 3>& a) { return glm::vec3(a[0], a[1], a[2]); };
    sky.zenith = vec(settings.sky.zenith);
    sky.horizon = vec(settings.sky.horizon);
    sky.ground = vec(settings.sky.ground);
    sky.intensity = settings.sky.intensity;
    sky.image = sky.mode == SkyMode::Hdr ? image : nullptr;
    return sky;
}

namespace {

glm::vec3 texel(const SkyImage& image, int x, int y) {
    x = ((x % image.width) + image.width) % image.width;  // u repeats
    y = std::clamp(y, 0, image.height - 1);               // v clamps
    return image.texels[static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x)];
}

glm::vec3 imageRadiance(const SkyImage& image, glm::vec3 d) {
    constexpr float pi = std::numbers::pi_v<float>;
    const float u = 0.5f + std::atan2(d.x, -d.z) / (2.0f * pi);
    const float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / pi;
    // GL's bilinear filter: texel centres at (i + ½)/size.
    const float x = u * static_cast<float>(image.width) - 0.5f;
    const float y = v * static_cast<float>(image.height) - 0.5f;
    const float x0 = std::floor(x), y0 = std::floor(y);
    const float fx = x - x0, fy = y - y0;
    const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
    const glm::vec3 top = glm::mix(texel(image, ix, iy), texel(image, ix + 1, iy), fx);
    const glm::vec3 bottom = glm::mix(texel(image, ix, iy + 1), texel(image, ix + 1, iy + 1), fx);
    return glm::mix(top, bottom, fy);
}

}  // namespace

glm::vec3 skyRadiance(const Sky& sky, glm::vec3 direction) {
    if (sky.mode == SkyMode::None || sky.mode == SkyMode::Auto) return glm::vec3(0.0f);
    const glm::vec3 d = glm::normalize(direction);
    glm::vec3 radiance(0.0f);
    if (sky.mode == SkyMode::Uniform) {
        radiance = sky.zenith;
    } else if (sky.mode == SkyMode::Gradient) {
        radiance = d.y >= 0.0f ? glm::mix(sky.horizon, sky.zenith, std::sqrt(d.y))
                               : glm::mix(sky.horizon, sky.ground,
                                          std::min(1.0f, -d.y * static_cast<float>(LIT_SKY_GROUND_BLEND)));
    } else if (sky.image) {
        radiance = imageRadiance(*sky.image, d);
    }
    return radiance * sky.intensity;
}

std::function<glm::vec3(const glm::vec3&)> makeSkyFunction(const Scene& scene, const RenderSettings& settings,
                                                          std::string* error) {
    std::shared_ptr<SkyImage> image;
    if (settings.sky.mode == SkyMode::Hdr) {
        try {
            image = std::make_shared<SkyImage>(loadSkyImage(settings.sky.hdrPath));
        } catch (const SkyLoadError& e) {
            if (error) *error = e.what();
        }
    }
    const Sky sky = resolveSky(scene, settings, image.get());
    if (sky.mode == SkyMode::None) return {};
    return [sky, image](const glm::vec3& direction) { return skyRadiance(sky, direction); };
}

bool hasDefaultSun(const Scene& scene, const RenderSettings& settings) {
    return settings.sky.sunIrradiance > 0.0f && !sceneHasLights(scene);
}

bool addDefaultSun(Scene& scene, const RenderSettings& settings) {
    if (!hasDefaultSun(scene, settings)) return false;
    Light sun;
    sun.name = "default sun";
    sun.type = LightType::Directional;
    sun.intensity = settings.sky.sunIrradiance;  // W/m²
    addLightNode(scene, sun, glm::vec3(0.0f), defaultSunDirection(settings));
    scene.updateWorldTransforms();
    return true;
}

glm::vec3 defaultSunDirection(const RenderSettings& settings) {
    const float e = settings.sky.sunElevation, a = settings.sky.sunAzimuth;
    const glm::vec3 towardsSun(std::sin(a) * std::cos(e), std::sin(e), std::cos(a) * std::cos(e));
    return -glm::normalize(towardsSun);
}

}  // namespace lit
