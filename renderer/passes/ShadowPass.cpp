#include "passes/ShadowPass.h"

#include "scene/GpuScene.h"
#include "scene/Scene.h"

#include <shared.h>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace lit {

ShadowPass::ShadowPass(const std::filesystem::path& shaderRoot)
    : program_(shaderRoot, "shadow",
               {{GL_VERTEX_SHADER, "shadow.vert.glsl"}, {GL_FRAGMENT_SHADER, "shadow.frag.glsl"}}),
      sheetProgram_(shaderRoot, "shadow sheets",
                    {{GL_VERTEX_SHADER, "shadow_sheet.vert.glsl"}, {GL_FRAGMENT_SHADER, "shadow_sheet.frag.glsl"}}),
      sheetSampler_("shadow sheets"),
      sheetFramebuffer_("shadow sheets"),
      framebuffer_("shadow"),
      uniforms_("shadow pass uniforms", sizeof(gpu::ShadowPassUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT),
      comparisonSampler_("shadow comparison"),
      cascadeUniforms_("shadow cascade uniforms", sizeof(gpu::ShadowCascadeUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT) {
    comparisonSampler_.set(GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    comparisonSampler_.set(GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    comparisonSampler_.set(GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    comparisonSampler_.set(GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    comparisonSampler_.set(GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    comparisonSampler_.set(GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    sheetSampler_.set(GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    sheetSampler_.set(GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    sheetSampler_.set(GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    sheetSampler_.set(GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    ensureMaps(kUnusedMapSize, 0, 0);
    cascadeMaps_ = gl::Texture("shadow cascades",
                               {GL_TEXTURE_2D_ARRAY, GL_DEPTH_COMPONENT32F, kUnusedMapSize, kUnusedMapSize, 1, 1});
    const float one = 1.0f;
    glClearTexImage(cascadeMaps_.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
    const gpu::ShadowCascadeUniforms none{};
    cascadeUniforms_.update(none);
}

void ShadowPass::ensureSheetMaps(bool sheets) {
    // Colour layers only for the maps there are; one white texel keeps an unused binding valid.
    const int size2d = sheets && layers2d_ > 0 ? size_ : 1, layers = std::max(layers2d_, 1);
    const int sizeCube = sheets && cubes_ > 0 ? size_ : 1, faces = 6 * std::max(cubes_, 1);
    if (sheetMaps2d_ && sheetMaps2d_.desc().width == size2d && sheetMaps2d_.desc().depth == layers &&
        sheetMapsCube_.desc().width == sizeCube && sheetMapsCube_.desc().depth == faces)
        return;
    sheetMaps2d_ = gl::Texture("shadow sheets 2D", {GL_TEXTURE_2D_ARRAY, GL_RGBA16F, size2d, size2d, layers, 1});
    sheetMapsCube_ = gl::Texture("shadow sheets cube", {GL_TEXTURE_CUBE_MAP_ARRAY, GL_RGBA16F, sizeCube, sizeCube, faces, 1});
    const float clear[4] = {1.0f, 1.0f, 1.0f, 1.0f};  // nothing in the way: all light passes
    glClearTexImage(sheetMaps2d_.id(), 0, GL_RGBA, GL_FLOAT, clear);
    glClearTexImage(sheetMapsCube_.id(), 0, GL_RGBA, GL_FLOAT, clear);
}

void ShadowPass::ensureMaps(int size, int layers2d, int cubes) {
    if (size == size_ && layers2d == layers2d_ && cubes == cubes_) return;
    size_ = size;
    layers2d_ = layers2d;
    cubes_ = cubes;
    // A kind of map no light uses gets one small layer (or cube), so that its binding stays valid
    // without taking a full map's memory (six 8192² faces are 1.6 GB).
    const int size2d = layers2d > 0 ? size : kUnusedMapSize, sizeCube = cubes > 0 ? size : kUnusedMapSize;
    maps2d_ = gl::Texture("shadow maps 2D", {GL_TEXTURE_2D_ARRAY, GL_DEPTH_COMPONENT32F, size2d, size2d, std::max(layers2d, 1), 1});
    mapsCube_ = gl::Texture("shadow maps cube",
                            {GL_TEXTURE_CUBE_MAP_ARRAY, GL_DEPTH_COMPONENT32F, sizeCube, sizeCube, 6 * std::max(cubes, 1), 1});
    // Clear to the far plane so lights without a rendered map (none yet) see everything lit.
    const float one = 1.0f;
    glClearTexImage(maps2d_.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
    glClearTexImage(mapsCube_.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
}

std::size_t ShadowPass::memoryBytes() const {
    const auto bytes = [](const gl::Texture& t, std::size_t perTexel) {
        return t ? static_cast<std::size_t>(t.desc().width) * static_cast<std::size_t>(t.desc().height) *
                       static_cast<std::size_t>(t.desc().depth) * perTexel
                 : 0u;
    };
    return bytes(maps2d_, 4) + bytes(mapsCube_, 4) + bytes(sheetMaps2d_, 8) + bytes(sheetMapsCube_, 8) +
           bytes(cascadeMaps_, 4);
}

void ShadowPass::bindMaps() const {
    maps2d_.bind(LIT_TEX_SHADOW_2D);
    mapsCube_.bind(LIT_TEX_SHADOW_CUBE);
    comparisonSampler_.bind(LIT_TEX_SHADOW_2D);
    comparisonSampler_.bind(LIT_TEX_SHADOW_CUBE);
    cascadeMaps_.bind(LIT_TEX_SHADOW_CASCADES);
    comparisonSampler_.bind(LIT_TEX_SHADOW_CASCADES);
    cascadeUniforms_.bindBase(GL_UNIFORM_BUFFER, LIT_UBO_SHADOW_CASCADES);
    if (sheetMaps2d_) {
        sheetMaps2d_.bind(LIT_TEX_SHADOW_SHEETS);
        sheetSampler_.bind(LIT_TEX_SHADOW_SHEETS);
        sheetMapsCube_.bind(LIT_TEX_SHADOW_SHEETS_CUBE);
        sheetSampler_.bind(LIT_TEX_SHADOW_SHEETS_CUBE);
    }
}

void ShadowPass::execute(const Scene& scene, const GpuScene& gpuScene, const LightSetup& lights,
                         const RenderSettings& settings, DrawCounters& counters, const ItemCuller& cull) {
    const int size = std::clamp(settings.shadows.mapSize, 16, 8192);
    ensureMaps(size, static_cast<int>(lights.shadows2d.size()), static_cast<int>(lights.shadowsCube.size()));
    const bool sheets = lights.sheetShadows && !(lights.shadows2d.empty() && lights.shadowsCube.empty());
    ensureSheetMaps(sheets);
    if (gpuScene.empty()) return;

    beginDepthViews(size, settings, gpuScene);
    for (const ShadowView& view : lights.shadows2d)
        drawDepthView(scene, gpuScene, maps2d_, view.layer, view.viewProjection[0], view.position, view.farPlane,
                      counters, cull);
    for (const ShadowView& view : lights.shadowsCube)
        for (int face = 0; face < 6; ++face)
            drawDepthView(scene, gpuScene, mapsCube_, view.layer * 6 + face, view.viewProjection[face], view.position,
                          view.farPlane, counters, cull);

    glDisable(GL_POLYGON_OFFSET_FILL);
    if (sheets) drawSheets(scene, gpuScene, lights, counters, cull);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void ShadowPass::beginDepthViews(int size, const RenderSettings& settings, const GpuScene& gpuScene) {
    glViewport(0, 0, size, size);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);  // both faces cast: thin single-sided walls must block light
    glEnable(GL_POLYGON_OFFSET_FILL);
    // Slope-scaled bias in depth-buffer units; the constant part is in the receiver test.
    glPolygonOffset(settings.shadows.slopeBias, 1.0f);
    program_.use();
    uniforms_.bindBase(GL_UNIFORM_BUFFER, LIT_UBO_SHADOW_PASS);
    gpuScene.materials().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_MATERIALS);
    framebuffer_.bind();
    framebuffer_.setDrawBuffers(0);
}

void ShadowPass::drawDepthView(const Scene& scene, const GpuScene& gpuScene, const gl::Texture& target, int layer,
                               const glm::mat4& viewProjection, const glm::vec3& position, float farPlane,
                               DrawCounters& counters, const ItemCuller& cull) {
    framebuffer_.attachLayer(GL_DEPTH_ATTACHMENT, target, layer);
    const float one = 1.0f;
    glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &one);
    gpu::ShadowPassUniforms u{viewProjection, glm::vec4(position, farPlane)};
    uniforms_.update(u);
    if (cull) {
        cull(viewProjection, visibleItems_);
        gpuScene.drawList(scene, program_, GpuScene::Bind::AlphaOnly, counters, visibleItems_);
    } else {
        gpuScene.draw(scene, program_, GpuScene::Bind::AlphaOnly, counters);
    }
}

void ShadowPass::executeCascades(const Scene& scene, const GpuScene& gpuScene, const LightSetup& lights,
                                 const CameraView& camera, const Aabb& bounds, const RenderSettings& settings,
                                 bool redrawAll, DrawCounters& counters, const ItemCuller& cull) {
    const int size = std::clamp(settings.shadows.mapSize, 16, 8192);
    const int count = std::clamp(settings.shadows.cascades, 0, LIT_MAX_SHADOW_CASCADES);
    const int lightsCascaded = count > 0 ? static_cast<int>(lights.cascaded.size()) : 0;
    const int layers = lightsCascaded * count;
    const int side = layers > 0 ? size : kUnusedMapSize;
    if (cascadeMaps_.desc().width != side || cascadeMaps_.desc().depth != std::max(layers, 1)) {
        cascadeMaps_ = gl::Texture("shadow cascades",
                                   {GL_TEXTURE_2D_ARRAY, GL_DEPTH_COMPONENT32F, side, side, std::max(layers, 1), 1});
        const float one = 1.0f;
        glClearTexImage(cascadeMaps_.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
        redrawAll = true;
    }
    drawnCascades_.resize(static_cast<std::size_t>(layers));
    if (redrawAll) std::fill(drawnCascades_.begin(), drawnCascades_.end(), ShadowCascade{});

    // Every cascade's new fit; then the maps that must move are drawn, all of them after `redrawAll`,
    // else the finest one only, so that a moving camera's frames share the drawing (docs/ARCHITECTURE.md,
    // "Shadow cascades"). A map not drawn yet keeps its old square, which still holds its slice's
    // pixels but those at its edge (they read the next map out).
    std::vector<ShadowCascade> fits(static_cast<std::size_t>(layers));
    int fitted = 0;
    for (int slot = 0; slot < lightsCascaded; ++slot) {
        const gpu::GpuLight& light =
            lights.lights[static_cast<std::size_t>(lights.cascaded[static_cast<std::size_t>(slot)])];
        const std::vector<ShadowCascade> lightFits =
            fitShadowCascades(glm::vec3(light.directionType), bounds, camera, count, settings.shadows.cascadeDistance,
                              settings.shadows.cascadeSplit, size);
        fitted = static_cast<int>(lightFits.size());
        std::copy(lightFits.begin(), lightFits.end(), fits.begin() + slot * count);
    }
    bool begun = false;
    for (int c = 0; c < fitted; ++c)
        for (int slot = 0; slot < lightsCascaded; ++slot) {
            const int layer = slot * count + c;
            ShadowCascade& drawn = drawnCascades_[static_cast<std::size_t>(layer)];
            const ShadowCascade& fit = fits[static_cast<std::size_t>(layer)];
            if (drawn == fit || (begun && !redrawAll)) continue;
            if (!begun) beginDepthViews(size, settings, gpuScene);
            begun = true;
            drawDepthView(scene, gpuScene, cascadeMaps_, layer, fit.viewProjection, glm::vec3(0.0f), 0.0f, counters,
                          cull);
            drawn = fit;
            ++cascadesDrawn_;
        }
    if (begun) {
        glDisable(GL_POLYGON_OFFSET_FILL);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    // The uniforms describe what each map holds.
    // A map never drawn (none yet past a change of the scene's bounds) ends the list the shader reads.
    int usable = fitted;
    for (int slot = 0; slot < lightsCascaded; ++slot)
        for (int c = 0; c < usable; ++c)
            if (!(drawnCascades_[static_cast<std::size_t>(slot * count + c)].worldTexel > 0.0f)) usable = c;
    gpu::ShadowCascadeUniforms u{};
    u.counts.x = usable;
    for (int slot = 0; slot < lightsCascaded; ++slot)
        for (int c = 0; c < fitted; ++c) {
            const int layer = slot * count + c;
            const ShadowCascade& drawn = drawnCascades_[static_cast<std::size_t>(layer)];
            // The constant bias a share of the map's side, as the scene-wide map's is of its depth range.
            const float mapSide = drawn.worldTexel * static_cast<float>(size);
            u.cascades[slot * LIT_MAX_SHADOW_CASCADES + c] = {
                drawn.viewProjection,
                glm::vec4(drawn.worldTexel, settings.shadows.depthBias * mapSide / std::max(drawn.depthRange, 1e-6f),
                          static_cast<float>(layer), 0.0f)};
        }
    cascadeUniforms_.update(u);
}

void ShadowPass::drawSheets(const Scene& scene, const GpuScene& gpuScene, const LightSetup& lights,
                            DrawCounters& counters, const ItemCuller& cull) {
    // Over each layer's (cube face's) opaque depth (tested, not written): the transmittances multiply, the
    // nearest depth stays (alpha by GL_MIN).
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendEquationSeparate(GL_FUNC_ADD, GL_MIN);
    glBlendFuncSeparate(GL_DST_COLOR, GL_ZERO, GL_ONE, GL_ONE);
    sheetProgram_.use();
    sheetFramebuffer_.bind();
    const GLint light = sheetProgram_.location("uLight"), nearFar = sheetProgram_.location("uNearFar");
    const auto renderView = [&](const gl::Texture& colours, const gl::Texture& depths, int layer,
                                const glm::mat4& viewProjection, const ShadowView& view) {
        sheetFramebuffer_.attachLayer(GL_COLOR_ATTACHMENT0, colours, layer);
        sheetFramebuffer_.attachLayer(GL_DEPTH_ATTACHMENT, depths, layer);
        sheetFramebuffer_.setDrawBuffers(1);
        const float clear[4] = {1.0f, 1.0f, 1.0f, 1.0f};
        glClearNamedFramebufferfv(sheetFramebuffer_.id(), GL_COLOR, 0, clear);
        const gpu::GpuLight& l = lights.lights[static_cast<std::size_t>(view.light)];
        const bool directional = static_cast<int>(l.directionType.w) == LIT_LIGHT_DIRECTIONAL;
        glProgramUniform4f(sheetProgram_.id(), light, directional ? l.directionType.x : view.position.x,
                           directional ? l.directionType.y : view.position.y,
                           directional ? l.directionType.z : view.position.z, directional ? 0.0f : 1.0f);
        glProgramUniform2f(sheetProgram_.id(), nearFar, directional ? 0.0f : view.nearPlane,
                           directional ? 0.0f : view.farPlane);
        gpu::ShadowPassUniforms u{viewProjection, glm::vec4(view.position, view.farPlane)};
        uniforms_.update(u);
        if (cull) cull(viewProjection, culledItems_);
        gpuScene.sheetItems(cull ? &culledItems_ : nullptr, visibleItems_);
        gpuScene.drawList(scene, sheetProgram_, GpuScene::Bind::Everything, counters, visibleItems_);
    };
    for (const ShadowView& view : lights.shadows2d)
        renderView(sheetMaps2d_, maps2d_, view.layer, view.viewProjection[0], view);
    for (const ShadowView& view : lights.shadowsCube)
        for (int face = 0; face < 6; ++face)
            renderView(sheetMapsCube_, mapsCube_, view.layer * 6 + face, view.viewProjection[face], view);
    glDisable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ZERO);
    glDepthMask(GL_TRUE);
}

}  // namespace lit
