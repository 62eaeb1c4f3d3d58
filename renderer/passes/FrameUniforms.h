#pragma once
// The per-frame uniform block (shared.h FrameUniforms) from a camera and the settings, so the
// Renderer and tests that drive passes directly fill it the same way.

#include "RenderSettings.h"
#include "scene/CameraView.h"
#include "scene/Sky.h"

#include <shared.h>

namespace lit {

// `shaderView` is the LIT_VIEW_* value of settings.debug.view; `lightCount` the GpuLight entries bound;
// `sky` the resolved sky (none: black, as before there was a sky).
inline gpu::FrameUniforms makeFrameUniforms(const CameraView& camera, const RenderSettings& settings, int shaderView,
                                            int lightCount, const Sky* sky = nullptr) {
    gpu::FrameUniforms frame{};
    frame.view = camera.view;
    frame.projection = camera.projection;
    frame.viewProjection = camera.projection * camera.view;
    frame.inverseViewProjection = glm::inverse(frame.viewProjection);
    frame.cameraPosition = glm::vec4(camera.position, 1.0f);
    const float w = static_cast<float>(settings.output.width), h = static_cast<float>(settings.output.height);
    frame.viewport = glm::vec4(w, h, 1.0f / w, 1.0f / h);
    frame.exposure = glm::vec4(settings.output.exposureScale(), settings.shadows.pcfRadius, 0.0f, 0.0f);
    const int flags = settings.output.specularAntialiasing ? LIT_FRAME_SPECULAR_ANTIALIASING : 0;
    frame.counts = glm::ivec4(lightCount, shaderView, 0, flags);
    if (sky) {
        const int mode = sky->mode == SkyMode::Uniform    ? LIT_SKY_UNIFORM
                         : sky->mode == SkyMode::Gradient ? LIT_SKY_GRADIENT
                         : sky->mode == SkyMode::Hdr      ? LIT_SKY_HDR
                                                          : LIT_SKY_NONE;
        frame.skyZenith = glm::vec4(sky->zenith, static_cast<float>(mode));
        frame.skyHorizon = glm::vec4(sky->horizon, sky->intensity);
        frame.skyGround = glm::vec4(sky->ground, 0.0f);
    }
    return frame;
}

}  // namespace lit
