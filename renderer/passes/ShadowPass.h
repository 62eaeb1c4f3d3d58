#pragma once
// Shadow maps: one layer of a 2D depth array per directional/spot light, one cube of a cube
// array per point light. Depth is rendered with slope-scaled polygon offset; the lighting pass
// filters it with PCF (lights.glsl). With LightSetup::sheetShadows, each layer and cube face also
// gets what the transmissive sheets in front of its nearest opaque surface let through (a colour
// layer, shadow_sheet.frag.glsl; docs/MATERIALS.md, "Transmission").

#include "passes/LightSetup.h"
#include "passes/Pass.h"
#include "passes/ShadowCascades.h"
#include "scene/GpuScene.h"

namespace lit {

class ShadowPass : public Pass {
public:
    explicit ShadowPass(const std::filesystem::path& shaderRoot);

    // Renders every shadow view of `lights`. Reallocates the maps when the size or count changes.
    // Each view (each cube face of a point light) draws the items `cull` picks for its
    // view-projection; every item when `cull` is empty.
    void execute(const Scene& scene, const GpuScene& gpuScene, const LightSetup& lights,
                 const RenderSettings& settings, DrawCounters& counters, const ItemCuller& cull = {});

    // The camera's cascades of the directional lights in `lights.cascaded` (ShadowCascades.h): draws
    // the finest map whose fit moved since it was drawn (every one with `redrawAll`: the lights,
    // the geometry or the maps changed) and uploads the fits the maps hold (LIT_UBO_SHADOW_CASCADES).
    void executeCascades(const Scene& scene, const GpuScene& gpuScene, const LightSetup& lights,
                         const CameraView& camera, const Aabb& bounds, const RenderSettings& settings, bool redrawAll,
                         DrawCounters& counters, const ItemCuller& cull = {});
    // Cascade maps drawn since the pass was made (a counter for tests and the profiler).
    std::uint64_t cascadesDrawn() const { return cascadesDrawn_; }

    // Binds the shadow arrays to their texture units (LIT_TEX_SHADOW_2D / _CUBE / _SHEETS /
    // _CASCADES) and the cascades' uniforms.
    void bindMaps() const;
    const gl::Texture& maps2d() const { return maps2d_; }
    // Bytes of the depth and colour layers allocated now (SceneMemory's shadowMapBytes estimates
    // it for the full-size ones; unused kinds add a small layer or cube).
    std::size_t memoryBytes() const;
    // Side of the one layer or cube allocated for a kind of map no light uses.
    static constexpr int kUnusedMapSize = 16;

    std::vector<gl::Program*> programs() override { return {&program_, &sheetProgram_}; }

private:
    void ensureMaps(int size, int layers2d, int cubes);
    // The depth-only state of every map's drawing, then one view (layer or cube face) of `target`.
    void beginDepthViews(int size, const RenderSettings& settings, const GpuScene& gpuScene);
    void drawDepthView(const Scene& scene, const GpuScene& gpuScene, const gl::Texture& target, int layer,
                       const glm::mat4& viewProjection, const glm::vec3& position, float farPlane,
                       DrawCounters& counters, const ItemCuller& cull);
    // The sheet layers at the maps' size for the kinds of map in use (sheets), else one white texel
    // (the bindings stay valid).
    void ensureSheetMaps(bool sheets);
    // Renders the transmissive sheets of each view (each cube face) into its sheet layer.
    void drawSheets(const Scene& scene, const GpuScene& gpuScene, const LightSetup& lights, DrawCounters& counters,
                    const ItemCuller& cull);

    gl::Program program_;
    gl::Program sheetProgram_;
    gl::Texture sheetMaps2d_;    // RGBA16F, one layer per 2D map (LIT_TEX_SHADOW_SHEETS)
    gl::Texture sheetMapsCube_;  // RGBA16F cube array, one cube per point light (LIT_TEX_SHADOW_SHEETS_CUBE)
    gl::Sampler sheetSampler_;
    gl::Framebuffer sheetFramebuffer_;
    gl::Texture maps2d_;
    gl::Texture mapsCube_;
    gl::Framebuffer framebuffer_;
    gl::Buffer uniforms_;
    gl::Sampler comparisonSampler_;
    gl::Texture cascadeMaps_;     // DEPTH32F, one layer per cascade of each cascaded light (LIT_TEX_SHADOW_CASCADES)
    gl::Buffer cascadeUniforms_;  // ShadowCascadeUniforms
    std::vector<ShadowCascade> drawnCascades_;  // per layer: the fit it holds (default: none)
    std::uint64_t cascadesDrawn_ = 0;
    int size_ = 0, layers2d_ = 0, cubes_ = 0;
    std::vector<std::uint32_t> visibleItems_;  // the current view's culling result (kept to reuse its memory)
    std::vector<std::uint32_t> culledItems_;   // the same before drawSheets keeps only the sheets
};

}  // namespace lit
