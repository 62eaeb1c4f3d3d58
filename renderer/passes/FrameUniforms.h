#pragma once
// The per-frame uniform block (shared.h FrameUniforms) from a camera and the settings, so the
// Renderer and tests that drive passes directly fill it the same way.

#include "RenderSettings.h"
#include "scene/CameraView.h"

#include <shared.h>

namespace lit {

// `shaderView` is the LIT_VIEW_* value of settings.view; `lightCount` the GpuLight entries bound.
inline gpu::FrameUniforms makeFrameUniforms(const CameraView& camera, const RenderSettings& settings, int shaderView,
                                            int lightCount) {
    gpu::FrameUniforms frame{};
    frame.view = camera.view;
    frame.projection = camera.projection;
    frame.viewProjection = camera.projection * camera.view;
    frame.inverseViewProjection = glm::inverse(frame.viewProjection);
    frame.cameraPosition = glm::vec4(camera.position, 1.0f);
    const float w = static_cast<float>(settings.width), h = static_cast<float>(settings.height);
    frame.viewport = glm::vec4(w, h, 1.0f / w, 1.0f / h);
    frame.exposure = glm::vec4(settings.exposure, settings.shadowPcfRadius, 0.0f, 0.0f);
    frame.counts = glm::ivec4(lightCount, shaderView, 0, 0);
    return frame;
}

}  // namespace lit
