#include "Renderer.h"

#include <shared.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <string>
#include <tuple>

#include "gi/VoxelGi.h"
#include "gl/Capabilities.h"
#include "gl/GlError.h"
#include "passes/AutoExposurePass.h"
#include "passes/ConeTracePass.h"
#include "passes/DirectLightingPass.h"
#include "passes/FrameUniforms.h"
#include "passes/GBufferPass.h"
#include "passes/IndirectFallbackPass.h"
#include "passes/IndirectResolvePass.h"
#include "passes/LightSetup.h"
#include "passes/LightingTerms.h"
#include "passes/OverlayPass.h"
#include "passes/PostPass.h"
#include "passes/ShadowPass.h"
#include "passes/SheetPass.h"
#include "passes/SkyTexture.h"
#include "passes/TemporalAntialiasPass.h"
#include "passes/VoxelDebugPass.h"
#include "scene/Bvh.h"
#include "scene/Frustum.h"
#include "scene/GpuScene.h"
#include "scene/Scene.h"
#include "scene/SheenAlbedo.h"
#include "scene/Sky.h"

static_assert(lit::kMaxNearLevels == LIT_MAX_NEAR_LEVELS);

namespace lit {

namespace fs = std::filesystem;

namespace {

int toShaderView(View view) {
    switch (view) {
        case View::Final: return LIT_VIEW_FINAL;
        case View::DirectDiffuse: return LIT_VIEW_DIRECT_DIFFUSE;
        case View::IndirectDiffuse: return LIT_VIEW_INDIRECT_DIFFUSE;
        case View::DirectSpecular: return LIT_VIEW_DIRECT_SPECULAR;
        case View::IndirectSpecular: return LIT_VIEW_INDIRECT_SPECULAR;
        case View::Albedo: return LIT_VIEW_ALBEDO;
        case View::Normal: return LIT_VIEW_NORMAL;
        case View::ShadowMap: return LIT_VIEW_SHADOW_MAP;
        case View::Voxels: return LIT_VIEW_VOXELS;
        case View::RoughnessMetalness: return LIT_VIEW_ROUGHNESS_METALNESS;
        case View::VoxelSlice: return LIT_VIEW_VOXEL_SLICE;
        case View::VoxelLevels:
            return LIT_VIEW_VOXEL_LEVELS;
    }
    return LIT_VIEW_FINAL;
}

// What the shadow maps depend on; they are re-rendered only when it changes.
struct ShadowKey {
    std::uint64_t geometry = ~0ull, lights = ~0ull;
    std::uint64_t materials = ~0ull;  // Scene::materialRevision while sheets are or were in the maps, else 0
    const Scene* scene = nullptr;
    bool shadows = false;
    int size = 0;
    float depthBias = 0, slopeBias = 0;
    float sunIrradiance = 0, sunElevation = 0, sunAzimuth = 0;  // the default sun of a scene without lights
    bool cascades = false;                                      // directional lights get cascade slots
    bool operator==(const ShadowKey&) const = default;
};

// What the accumulated indirect history means; it is dropped when any of it changes.
struct IndirectKey {
    const Scene* scene = nullptr;
    int indirectScale = 0, specularSamples = 0, voxelResolution = 0;
    float smoothRoughness = 0, aperture = 0, maxTraceDistance = 0, stepScale = 0, footprint = 0;
    bool rgba8 = false, diffuse = false, specular = false, anisotropic = false;
    bool operator==(const IndirectKey&) const = default;
};

}  // namespace

struct Renderer::Impl {
    Impl(fs::path root, Log& log_)
        : log(log_),
          shaderRoot(std::move(root)),
          shadow(shaderRoot),
          gbuffer(shaderRoot),
          direct(shaderRoot),
          post(shaderRoot),
          gi(shaderRoot, profiler, log_),
          coneTrace(shaderRoot),
          resolve(shaderRoot),
          fallback(shaderRoot),
          overlayPass(shaderRoot),
          voxelDebug(shaderRoot),
          autoExposure(shaderRoot),
          sheets(shaderRoot),
          antialias(shaderRoot),
          frameUniforms("frame uniforms", sizeof(gpu::FrameUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT),
          lightBuffer("lights", sizeof(gpu::GpuLight) * LIT_MAX_LIGHTS, nullptr, GL_DYNAMIC_STORAGE_BIT) {}

    std::vector<Pass*> passes() {
        std::vector<Pass*> all{&shadow,   &gbuffer,     &direct,     &post,         &coneTrace, &resolve,
                               &fallback, &overlayPass, &voxelDebug, &autoExposure, &sheets,    &antialias};
        for (Pass* pass : gi.passes()) all.push_back(pass);
        for (const std::unique_ptr<VoxelGi>& level : nearGi)
            if (level)
                for (Pass* pass : level->passes()) all.push_back(pass);
        return all;
    }

    // The steps of a frame, in order (Renderer::render).
    void syncScene(const Scene& scene);                                     // materials, world bounds, BVH boxes
    bool updateLights(const Scene& scene, const RenderSettings& settings);  // true: the lights changed
    // `image`: the frame draws an image (render), not only GI work (advanceGi).
    gpu::FrameUniforms bindFrame(const Scene& scene, const CameraView& camera, const RenderSettings& settings,
                                 bool image);
    void drawShadowMaps(const Scene& scene, const RenderSettings& settings);
    void drawShadowCascades(const Scene& scene, const CameraView& camera, const RenderSettings& settings,
                            bool shadowsDirty);
    // What every frame does first, a GI-only one too: the scene's changes, the light table and
    // the frame's uniforms bound, the shadow maps when the lights changed (then shadowsDirty).
    struct SceneFrame {
        gpu::FrameUniforms uniforms;
        bool shadowsDirty = false;
    };
    SceneFrame beginScene(const Scene& scene, const CameraView& camera, const RenderSettings& settings, bool image);
    void drawGBuffer(const Scene& scene, const RenderSettings& settings, const gpu::FrameUniforms& frame);
    void updateGi(const Scene& scene, const CameraView& camera, const RenderSettings& settings, const GiBudget& budget,
                  bool shadowsDirty);
    // A near level's box around the camera (moved in eighths of its side), and the side of level
    // `level` (0 the finest: GiSettings::nearLevelSide, each next twice the last), metres.
    static Aabb nearLevelBox(const glm::vec3& eye, float side);
    static float nearLevelSide(const RenderSettings& settings, int level);
    // The volume the voxel views show (DebugViewSettings::voxelLevel).
    const VoxelGi& shownVoxelGi(const RenderSettings& settings) const;
    std::vector<const VoxelVolume*> voxelLevels(const RenderSettings& settings) const;
    // stats.voxelBytes and stats.nearLevels: the scene volume's and the near levels' memory.
    void recordGiMemory(const RenderSettings& settings);
    // `requested`, or a copy with fewer near levels: those at least half the scene's size across
    // are left out (the scene's volume is about as fine: they would cost without adding).
    const RenderSettings& withNearLevelFitted(const RenderSettings& requested);
    RenderSettings nearLevelFitted;  // withNearLevelFitted's copy
    void lightTerms(const Scene& scene, const RenderSettings& settings, const gpu::FrameUniforms& frame);
    void bindSheenAlbedo();
    // `layers`: whether the scene's materials have specular layers (GpuScene::hasMaterialLayers).
    void traceIndirect(const Scene& scene, const RenderSettings& settings, const gpu::FrameUniforms& frame,
                       bool layers);
    void composite(const Scene& scene, const RenderSettings& settings, const gpu::FrameUniforms& frame);
    // The transmissive sheets over the composite's image (SheetPass).
    void drawSheets(const Scene& scene, const RenderSettings& settings, const gpu::FrameUniforms& frame);
    void drawOverlay();

    // The sky image of settings.sky.hdrPath, loaded and uploaded when the path changes; nullptr
    // when the mode is not Hdr or the file could not be read (logged once per path).
    const SkyImage* updateSkyImage(const RenderSettings& settings);

    // On a software rasterizer (llvmpipe) draws are binned and run on the CPU when something
    // needs their result, so the CPU time of a pass that samples an earlier pass's output holds
    // the wait for it: the composite's "post" read seconds with GI at scale 1 (the cone trace), the
    // resolve read the low-resolution trace. Waiting before those passes in a scope of its own
    // gives that time an honest line, "GPU wait", and costs nothing there (the pass would wait at
    // the same point). Not on a GPU, where a glFinish would stall the pipeline.
    void waitForQueuedPasses() {
        if (!softwareRasterizer) return;
        Profiler::Scope scope(profiler, "GPU wait");
        glFinish();
    }

    Log& log;
    const bool softwareRasterizer = gl::softwareRasterizer();
    fs::path shaderRoot;
    Profiler profiler;
    ShadowPass shadow;
    GBufferPass gbuffer;
    DirectLightingPass direct;
    PostPass post;
    VoxelGi gi;
    // The cached mode's near levels (GiSettings::nearLevelCount()), the finest first, each made on
    // first use; and whether each one's update ran on after the last frame.
    std::vector<std::unique_ptr<VoxelGi>> nearGi;
    std::vector<bool> nearUpdating;
    ConeTracePass coneTrace;
    IndirectResolvePass resolve;
    IndirectFallbackPass fallback;
    OverlayPass overlayPass;
    VoxelDebugPass voxelDebug;
    AutoExposurePass autoExposure;
    SheetPass sheets;
    TemporalAntialiasPass antialias;
    std::chrono::steady_clock::time_point lastMetered{};  // when auto exposure last ran
    bool meteredLastFrame = false;
    SkyImage skyImage;
    std::string skyImagePath;  // the file skyImage (and skyTexture) came from; "" = none tried
    gl::Texture skyTexture;
    ViewportOverlay overlay;
    // What picking needs of the last frame: its camera (to unproject depth) and voxel volume.
    std::optional<gpu::FrameUniforms> lastFrame;
    // TemporalAntialiasPass: the frame's camera without the jitter (the overlay uses it), what the
    // last image was drawn from, and whether the GI's light changed in the last GI work (an
    // update's or a refinement's frame, rendered or not).
    glm::mat4 unjitteredViewProjection{1.0f};
    struct AntialiasKey {
        std::uint64_t geometryRevision = 0, materialRevision = 0, lightRevision = 0;
        RenderSettings settings;
        bool operator==(const AntialiasKey&) const = default;
    };
    std::optional<AntialiasKey> antialiasKey;
    // Each node's world transform when the last image was drawn, and whether nodes moved since with
    // the materials and the settings as they were (a node animation, a gizmo drag): that frame's
    // G-buffer writes each point's motion, and the anti-aliasing follows it.
    std::vector<glm::mat4> previousNodeWorld;
    bool nodesMoved = false;
    bool giLightChanging = false;
    float lastVoxelSize = 0.0f, lastVolumeSide = 0.0f;  // m; 0 when that frame had no GI
    LightingTerms terms;
    gl::Texture sheenAlbedo;  // E_s of KHR_materials_sheen (scene/SheenAlbedo.h), made for the first scene with layers
    gl::Buffer frameUniforms;
    gl::Buffer lightBuffer;
    std::unique_ptr<GpuScene> gpuScene;
    // Frustum culling: a BVH over gpuScene->items(), refit when transforms change.
    Bvh bvh;
    std::uint64_t bvhRevision = ~0ull;      // Scene::geometryRevision the BVH's boxes come from
    std::vector<std::uint32_t> cameraItems;  // the camera's culling result this frame
    // Fills `visible` with the items `viewProjection` may see (every item when culling is off)
    // and adds the view to the culling stats.
    void cullView(const glm::mat4& viewProjection, bool culling, std::vector<std::uint32_t>& visible);
    std::uint64_t uploadedMaterialRevision = 0;
    FrameStats stats;
    DrawCounters counters;  // this frame's

    Aabb bounds;
    std::uint64_t boundsRevision = ~0ull;
    LightSetup lights;
    ShadowKey shadowKey;
    // Temporal accumulation of the indirect terms: frames accumulated so far (drives the jitter
    // and cone rotation) and what its history means (IndirectResolvePass keeps the history's camera).
    std::uint64_t temporalFrame = 0;
    IndirectKey indirectKey;
};

const SkyImage* Renderer::Impl::updateSkyImage(const RenderSettings& settings) {
    if (settings.sky.mode != SkyMode::Hdr) return nullptr;
    if (settings.sky.hdrPath != skyImagePath) {
        skyImagePath = settings.sky.hdrPath;
        skyImage = {};
        skyTexture = {};
        try {
            skyImage = loadSkyImage(skyImagePath);
            skyTexture = makeSkyTexture(skyImage);
            log.info("sky " + skyImagePath + ": " + std::to_string(skyImage.width) + "x" +
                     std::to_string(skyImage.height));
        } catch (const SkyLoadError& e) {
            log.error(std::string(e.what()) + "; using the gradient sky");
            skyImage = {};
        }
    }
    return skyImage.texels.empty() ? nullptr : &skyImage;
}

void Renderer::Impl::cullView(const glm::mat4& viewProjection, bool culling, std::vector<std::uint32_t>& visible) {
    const auto start = std::chrono::steady_clock::now();
    if (culling) {
        bvh.cull(Frustum(viewProjection), visible);
    } else {
        visible.resize(gpuScene->items().size());
        std::iota(visible.begin(), visible.end(), 0u);
    }
    stats.cullMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    stats.drawsTotal += static_cast<int>(gpuScene->items().size());
    stats.drawsSubmitted += static_cast<int>(visible.size());
}

Renderer::Renderer(fs::path shaderRoot, Log& log) {
    gl::requireCapabilities();
    impl_ = std::make_unique<Impl>(std::move(shaderRoot), log);
    log.info("renderer ready on " + gl::contextDescription());
}

Renderer::~Renderer() = default;

void Renderer::setScene(const Scene& scene) {
    impl_->gpuScene = std::make_unique<GpuScene>(scene, impl_->log);
    impl_->bvh = Bvh(scene, impl_->gpuScene->items());
    impl_->bvhRevision = scene.geometryRevision;
    impl_->uploadedMaterialRevision = scene.materialRevision;
    impl_->boundsRevision = ~0ull;
    impl_->shadowKey = {};
    impl_->gi.invalidate();
    for (const std::unique_ptr<VoxelGi>& level : impl_->nearGi)
        if (level) level->invalidate();
    impl_->resolve.resetHistory();
    impl_->antialias.reset();
    impl_->previousNodeWorld.clear();
    impl_->meteredLastFrame = false;  // a new scene is metered afresh, not adapted to
    impl_->lastFrame.reset();  // the G-buffer's node IDs belong to the previous scene
}

// A frame (docs/ARCHITECTURE.md, "A frame"): the scene's changes, the lights and their shadow
// maps, the G-buffer, the GI update, the lighting terms, the composite and the overlay.
void Renderer::render(const Scene& scene, const CameraView& camera, const RenderSettings& requested,
                      const GiBudget& budget) {
    Impl& r = *impl_;
    if (requested.output.width <= 0 || requested.output.height <= 0) return;  // minimized window: nothing to draw
    if (!r.gpuScene) setScene(scene);
    r.profiler.beginFrame();
    r.gi.reportUpdate();
    for (const std::unique_ptr<VoxelGi>& level : r.nearGi)
        if (level) level->reportUpdate();
    r.stats = {};
    r.counters = {};

    const auto [frame, shadowsDirty] = r.beginScene(scene, camera, requested, true);
    const RenderSettings& settings = r.withNearLevelFitted(requested);
    r.drawGBuffer(scene, settings, frame);
    // GI: the voxel volume follows the scene; nothing is allocated while GI is off.
    if (settings.gi.enabled)
        r.updateGi(scene, camera, settings, budget, shadowsDirty);
    else
        r.giLightChanging = false;
    r.gbuffer.bindTargets();
    // The data and voxel views show no lighting term (the composite does not use them there), so
    // they skip lighting and cone tracing; the terms are redone by the next frame that shows them.
    if (!isDataView(settings.debug.view)) {
        r.lightTerms(scene, settings, frame);
    } else {
        r.resolve.resetHistory();  // no terms this frame: the next one starts afresh
    }
    r.composite(scene, settings, frame);
    r.drawOverlay();

    r.lastFrame = frame;
    r.lastVoxelSize = settings.gi.enabled ? r.gi.volume().voxelSize() : 0.0f;
    r.lastVolumeSide = settings.gi.enabled ? r.gi.volume().side() : 0.0f;
    r.recordGiMemory(settings);
    r.stats.shadowMapBytes = r.shadow.memoryBytes();
    r.profiler.endFrame();
    r.stats.drawCalls = r.counters.drawCalls;
}

void Renderer::advanceGi(const Scene& scene, const CameraView& camera, const RenderSettings& requested,
                         const GiBudget& budget) {
    Impl& r = *impl_;
    if (!requested.gi.enabled || !r.gpuScene) return;
    r.profiler.beginFrame();
    r.gi.reportUpdate();
    for (const std::unique_ptr<VoxelGi>& level : r.nearGi)
        if (level) level->reportUpdate();
    const bool shadowsDirty = r.beginScene(scene, camera, requested, false).shadowsDirty;
    const RenderSettings& settings = r.withNearLevelFitted(requested);
    r.updateGi(scene, camera, settings, budget, shadowsDirty);
    r.recordGiMemory(settings);
    r.profiler.endFrame();
}

Renderer::Impl::SceneFrame Renderer::Impl::beginScene(const Scene& scene, const CameraView& camera,
                                                      const RenderSettings& settings, bool image) {
    syncScene(scene);
    SceneFrame f;
    f.shadowsDirty = updateLights(scene, settings);
    f.uniforms = bindFrame(scene, camera, settings, image);
    if (f.shadowsDirty) drawShadowMaps(scene, settings);
    drawShadowCascades(scene, camera, settings, f.shadowsDirty);
    return f;
}

void Renderer::Impl::syncScene(const Scene& scene) {
    if (scene.materialRevision != uploadedMaterialRevision) {
        gpuScene->updateMaterials(scene);
        uploadedMaterialRevision = scene.materialRevision;
    }
    if (scene.geometryRevision != boundsRevision) {
        bounds = scene.worldBounds();
        boundsRevision = scene.geometryRevision;
    }
    if (scene.geometryRevision != bvhRevision) {  // transforms moved: new boxes, same tree
        const auto start = std::chrono::steady_clock::now();
        bvh.refit(scene);
        bvhRevision = scene.geometryRevision;
        stats.cullMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    }
}

// The light table: rebuilt only when the scene or the shadow settings change; the camera does
// not affect it or these maps (each directional light's map is fitted to the scene; the camera's
// cascades are drawShadowCascades').
bool Renderer::Impl::updateLights(const Scene& scene, const RenderSettings& settings) {
    // A material edit changes the maps only where sheets are or were (their transmittance layers).
    const std::uint64_t sheetMaterials = gpuScene->hasSheets() || lights.sheetShadows ? scene.materialRevision : 0;
    const ShadowKey key{scene.geometryRevision,
                        scene.lightRevision,
                        sheetMaterials,
                        &scene,
                        settings.shadows.enabled,
                        settings.shadows.mapSize,
                        settings.shadows.depthBias,
                        settings.shadows.slopeBias,
                        settings.sky.sunIrradiance,
                        settings.sky.sunElevation,
                        settings.sky.sunAzimuth,
                        settings.shadows.cascades > 0};
    if (key == shadowKey) return false;
    lights = buildLightSetup(scene, bounds, settings, log);
    lights.sheetShadows = gpuScene->hasSheets();
    glNamedBufferSubData(lightBuffer.id(), 0, static_cast<GLsizeiptr>(lights.lights.size() * sizeof(gpu::GpuLight)),
                         lights.lights.data());
    shadowKey = key;
    return true;
}

void Renderer::Impl::drawShadowMaps(const Scene& scene, const RenderSettings& settings) {
    Profiler::Scope scope(profiler, "shadow");
    const ItemCuller cullShadowView = [this, &settings](const glm::mat4& viewProjection,
                                                        std::vector<std::uint32_t>& visible) {
        cullView(viewProjection, settings.output.frustumCulling, visible);
    };
    shadow.execute(scene, *gpuScene, lights, settings, counters, cullShadowView);
}

// The camera's cascades of the directional lights: only those whose fit moved are drawn again.
void Renderer::Impl::drawShadowCascades(const Scene& scene, const CameraView& camera, const RenderSettings& settings,
                                        bool shadowsDirty) {
    stats.shadowCascadesDrawn = 0;
    if (lights.cascaded.empty() && !shadowsDirty) return;
    Profiler::Scope scope(profiler, "shadow cascades");
    const ItemCuller cullShadowView = [this, &settings](const glm::mat4& viewProjection,
                                                        std::vector<std::uint32_t>& visible) {
        cullView(viewProjection, settings.output.frustumCulling, visible);
    };
    const std::uint64_t drawnBefore = shadow.cascadesDrawn();
    shadow.executeCascades(scene, *gpuScene, lights, camera, bounds, settings, shadowsDirty, counters, cullShadowView);
    stats.shadowCascadesDrawn = static_cast<int>(shadow.cascadesDrawn() - drawnBefore);
}

// The frame's uniforms (camera, view, light count, sky) and the light table, bound for every pass.
gpu::FrameUniforms Renderer::Impl::bindFrame(const Scene& scene, const CameraView& camera,
                                             const RenderSettings& settings, bool image) {
    const Sky sky = resolveSky(scene, settings, updateSkyImage(settings));
    if (sky.mode == SkyMode::Hdr) skyTexture.bind(LIT_TEX_SKY);
    // A frame that draws an image is drawn and read through the jittered camera
    // (TemporalAntialiasPass); GI work alone (advanceGi) uses the camera as it is.
    CameraView drawn = camera;
    unjitteredViewProjection = camera.projection * camera.view;
    if (image) {
        const AntialiasKey key{scene.geometryRevision, scene.materialRevision, scene.lightRevision, settings};
        const bool changed = giLightChanging || !antialiasKey || !(*antialiasKey == key);
        nodesMoved = false;
        if (changed && antialiasKey && key.materialRevision == antialiasKey->materialRevision &&
            key.settings == antialiasKey->settings && previousNodeWorld.size() == scene.nodes.size())
            for (std::size_t i = 0; i < scene.nodes.size() && !nodesMoved; ++i)
                nodesMoved = scene.nodes[i].world != previousNodeWorld[i];
        antialiasKey = key;
        drawn.projection = TemporalAntialiasPass::jittered(
            camera.projection, antialias.begin(settings, {unjitteredViewProjection, changed, nodesMoved}),
            settings.output.width, settings.output.height);
    }
    const gpu::FrameUniforms frame = makeFrameUniforms(drawn, settings, toShaderView(settings.debug.view),
                                                       static_cast<int>(lights.lights.size()), &sky);
    frameUniforms.update(frame);
    frameUniforms.bindBase(GL_UNIFORM_BUFFER, LIT_UBO_FRAME);
    lightBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_LIGHTS);
    return frame;
}

void Renderer::Impl::drawGBuffer(const Scene& scene, const RenderSettings& settings, const gpu::FrameUniforms& frame) {
    gbuffer.resize(settings.output.width, settings.output.height);
    terms.resize(settings.output.width, settings.output.height);
    post.resize(settings.output.width, settings.output.height);
    cullView(frame.viewProjection, settings.output.frustumCulling, cameraItems);
    Profiler::Scope scope(profiler, "g-buffer");
    const std::size_t trianglesBefore = counters.triangles;  // the shadow pass counts its own
    gbuffer.execute(scene, *gpuScene, counters, &cameraItems, nodesMoved ? &previousNodeWorld : nullptr);
    stats.triangles = counters.triangles - trianglesBefore;
    previousNodeWorld.resize(scene.nodes.size());
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) previousNodeWorld[i] = scene.nodes[i].world;
}

Aabb Renderer::Impl::nearLevelBox(const glm::vec3& eye, float side) {
    // Snapped to eighths of the side, so that the level moves (and is voxelized again) only when
    // the camera has gone an eighth of it; the camera stays at least 3/8 of the side from a face.
    const float step = side / 8.0f;
    const glm::vec3 centre = glm::round(eye / step) * step;
    return {centre - 0.5f * side, centre + 0.5f * side};
}

void Renderer::Impl::updateGi(const Scene& scene, const CameraView& camera, const RenderSettings& settings,
                              const GiBudget& budget, bool shadowsDirty) {
    shadow.bindMaps();  // the injection lights the voxels with them
    // Sample pattern index 0 every frame without temporal accumulation: a pattern that moves
    // only adds flicker there, and a fixed one keeps each term image consistent with the final
    // image. With it, the pattern turns every frame and the history averages the patterns.
    const int frameIndex = settings.indirect.temporalAccumulation ? static_cast<int>(temporalFrame % 4096) : 0;
    // One budget for every volume's spread work, in this order: the updates from the scene volume
    // inwards (each near level's rays read the light of the volumes outside it), then the
    // refinements in the same order. A level whose update waits traces one voxel a frame.
    const int levels = settings.gi.nearLevelCount();
    nearGi.resize(static_cast<std::size_t>(levels));
    nearUpdating.resize(static_cast<std::size_t>(levels), false);
    const bool innerUpdating = std::find(nearUpdating.begin(), nearUpdating.end(), true) != nearUpdating.end();
    GiBudget sceneBudget = budget;
    if (innerUpdating) sceneBudget.refineVoxels = 0;
    stats.nearLevelsScrolled = 0;
    stats.nearVoxelizedVoxels = 0;
    GiFrameReport report = gi.update(
        {scene, *gpuScene, bounds, ShadowKinds::of(lights), shadowsDirty, frameIndex}, settings, sceneBudget, counters);
    bool updateWaits = report.updateDone < 1.0f, refinementWaits = report.refining || innerUpdating;
    bool outerCompleted = report.updateCompleted;
    const VoxelGi* outer = &gi;
    for (int k = levels - 1; k >= 0; --k) {
        std::unique_ptr<VoxelGi>& level = nearGi[static_cast<std::size_t>(k)];
        if (!level) level = std::make_unique<VoxelGi>(shaderRoot, profiler, log, VoxelGiLevel::Near);
        GiBudget levelBudget = budget;
        if (updateWaits)
            levelBudget = {1, 0, 0.0};  // the least a spread update takes: one voxel
        else if (refinementWaits)
            levelBudget.refineVoxels = 0;
        // An update of the volume outside that completed re-lights this level as a light edit does.
        const GiFrameReport near = level->update({scene, *gpuScene, nearLevelBox(camera.position, nearLevelSide(settings, k)),
                                                  ShadowKinds::of(lights), shadowsDirty || outerCompleted, frameIndex,
                                                  outer, &gi},
                                                 settings, levelBudget, counters);
        nearUpdating[static_cast<std::size_t>(k)] = near.updateDone < 1.0f;
        updateWaits = updateWaits || near.updateDone < 1.0f;
        refinementWaits = refinementWaits || near.refining;
        outerCompleted = near.updateCompleted;
        outer = level.get();
        report.voxelized = report.voxelized || near.voxelized;
        if (near.scrolled) ++stats.nearLevelsScrolled;
        if (near.voxelized) stats.nearVoxelizedVoxels += near.voxelizedVoxels;
        report.injected = report.injected || near.injected;
        report.lightChanged = report.lightChanged || near.lightChanged;
        if (near.updateDone < report.updateDone || (report.updateStage.empty() && !near.updateStage.empty())) {
            report.updateDone = std::min(report.updateDone, near.updateDone);
            report.updateStage = "near " + std::to_string(k + 1) + ": " + near.updateStage;
        }
        report.refining = report.refining || near.refining;
        report.refinedVoxels += near.refinedVoxels;
    }
    if (levels > 0) gi.volume().uniforms().bindBase(GL_UNIFORM_BUFFER, LIT_UBO_VOXEL);  // the scene volume's, for the frame's passes
    if (report.lightChanged) resolve.resetHistory();  // accumulated indirect light is stale
    giLightChanging = report.lightChanged || report.updateDone < 1.0f || report.refinedVoxels > 0;
    stats.voxelized = report.voxelized;
    stats.voxelizedBoxes = report.voxelizedBoxes;
    stats.giUpdateCompleted = report.updateCompleted;
    stats.injected = report.injected;
    stats.occupiedVoxels = report.occupiedVoxels;
    stats.giUpdateDone = report.updateDone;
    stats.giUpdateStage = report.updateStage;
    stats.refinedVoxels = report.refinedVoxels;
    stats.giRefining = report.refining;
    stats.giBounces = report.bounces;
    stats.giEveryBounce = report.everyBounce;
    stats.giShowingPrevious = report.showingPrevious;
}

float Renderer::Impl::nearLevelSide(const RenderSettings& settings, int level) {
    return std::ldexp(settings.gi.nearLevelSide, level);
}

const RenderSettings& Renderer::Impl::withNearLevelFitted(const RenderSettings& requested) {
    const int asked = requested.gi.nearLevelCount();
    if (asked == 0 || bounds.empty()) return requested;
    const glm::vec3 extent = bounds.max - bounds.min;
    const float across = std::max({extent.x, extent.y, extent.z});
    int levels = 0;
    while (levels < asked && nearLevelSide(requested, levels) < 0.5f * across) ++levels;
    if (levels == asked) return requested;
    nearLevelFitted = requested;
    nearLevelFitted.gi.nearLevels = levels;
    return nearLevelFitted;
}

void Renderer::Impl::recordGiMemory(const RenderSettings& settings) {
    stats.nearLevels.clear();
    if (!settings.gi.enabled) {
        stats.voxelBytes = 0;
        return;
    }
    stats.voxelBytes = gi.bytes();
    for (int k = 0; k < settings.gi.nearLevelCount() && k < static_cast<int>(nearGi.size()); ++k) {
        const std::unique_ptr<VoxelGi>& level = nearGi[static_cast<std::size_t>(k)];
        if (!level) continue;
        stats.nearLevels.push_back({nearLevelSide(settings, k), level->bytes()});
        stats.voxelBytes += level->bytes();
    }
}

// L_DD + L_DS from the lights and their shadow maps, then L_ID + L_IS from the voxel GI.
void Renderer::Impl::bindSheenAlbedo() {
    if (!sheenAlbedo) {
        sheenAlbedo = gl::Texture("sheen albedo", {GL_TEXTURE_2D, GL_R32F, kSheenAlbedoSize, kSheenAlbedoSize, 1, 1});
        glTextureSubImage2D(sheenAlbedo.id(), 0, 0, 0, kSheenAlbedoSize, kSheenAlbedoSize, GL_RED, GL_FLOAT,
                            sheenAlbedoTable().data());
        sheenAlbedo.setFilter(GL_LINEAR, GL_LINEAR);
        sheenAlbedo.setWrap(GL_CLAMP_TO_EDGE);
    }
    sheenAlbedo.bind(LIT_TEX_SHEEN_ALBEDO);
}

void Renderer::Impl::lightTerms(const Scene& scene, const RenderSettings& settings, const gpu::FrameUniforms& frame) {
    shadow.bindMaps();
    // The lighting passes read each pixel's specular layers from the material table (gbuffer.glsl).
    gpuScene->materials().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_MATERIALS);
    const bool layers = gpuScene->hasMaterialLayers();
    if (layers) bindSheenAlbedo();
    {
        Profiler::Scope scope(profiler, "lighting");
        direct.execute(terms, settings, {ShadowKinds::of(lights), {layers}});
    }
    if (settings.gi.enabled) {
        traceIndirect(scene, settings, frame, layers);
    } else {
        terms.clearIndirect();
        resolve.resetHistory();
    }
}

void Renderer::Impl::traceIndirect(const Scene& scene, const RenderSettings& settings,
                                   const gpu::FrameUniforms& frame, bool layers) {
    const VoxelVolume& volume = gi.volume();
    if (!ConeTracePass::reducedPath(settings)) {  // every pixel at full resolution
        Profiler::Scope scope(profiler, "cone trace");
        coneTrace.execute(terms, volume, settings, layers);
        resolve.resetHistory();
        return;
    }
    const ConeTracePass::Work work = ConeTracePass::workFor(settings);
    const IndirectKey key{&scene,
                          ConeTracePass::indirectScale(settings),
                          settings.indirect.specularSamples,
                          settings.gi.voxelResolution,
                          settings.indirect.specularFullResRoughness,
                          settings.gi.diffuseConeAperture,
                          settings.gi.maxTraceDistance,
                          settings.gi.coneStepScale,
                          settings.gi.footprintPerHeight(),
                          settings.gi.radianceRgba8,
                          work.diffuse,
                          work.specular,
                          settings.gi.anisotropicVoxels()};
    if (!(key == indirectKey)) resolve.resetHistory();
    indirectKey = key;
    const ConeTracePass::Sampling sampling =
        settings.indirect.temporalAccumulation
            ? ConeTracePass::samplingFor(temporalFrame, key.indirectScale, ConeTracePass::coneSubsets(settings))
            : ConeTracePass::Sampling{};
    {
        Profiler::Scope scope(profiler, "cone trace");
        gi.bindGather(settings);
        for (int k = 0; k < settings.gi.nearLevelCount() && k < static_cast<int>(nearGi.size()); ++k)
            nearGi[static_cast<std::size_t>(k)]->bindAsNearLevel(k);
        coneTrace.executeReduced(volume, settings, sampling, layers);
    }
    waitForQueuedPasses();  // the resolve samples the low-resolution trace
    {
        Profiler::Scope scope(profiler, "indirect resolve");
        gbuffer.bindTargets();
        resolve.execute(terms, coneTrace, volume, settings, sampling, frame.viewProjection, layers);
    }
    {
        Profiler::Scope scope(profiler, "indirect fallback");
        fallback.execute(resolve, ConeFeatures::of(settings, layers));
    }
    if (settings.indirect.temporalAccumulation) ++temporalFrame;
}

// The chosen view into the HDR image (the composite of the terms, or a debug view), auto
// exposure, tone mapping to the output.
void Renderer::Impl::drawSheets(const Scene& scene, const RenderSettings& settings, const gpu::FrameUniforms& frame) {
    if (!gpuScene->hasSheets() || !SheetPass::drawsView(settings)) return;
    Profiler::Scope scope(profiler, "sheets");
    // The shadow maps and the material table are bound since lightTerms (the views SheetPass draws
    // always light the terms); the sheen table only with material layers there.
    bindSheenAlbedo();
    const bool indirect = settings.gi.enabled && gi.valid() && gi.volume().radiance();
    if (indirect) {
        gi.volume().uniforms().bindBase(GL_UNIFORM_BUFFER, LIT_UBO_VOXEL);
        gi.volume().radiance().bind(LIT_TEX_VOXEL_RADIANCE);
        coneTrace.specularAlbedoTable().bind(LIT_TEX_SPECULAR_ALBEDO);
    }
    sheets.execute(scene, *gpuScene, {post.hdr(), gbuffer.depth(), gbuffer.nodeId()}, settings,
                   {ShadowKinds::of(lights), glm::vec3(frame.cameraPosition), &cameraItems, indirect}, counters);
}

void Renderer::Impl::composite(const Scene& scene, const RenderSettings& settings, const gpu::FrameUniforms& frame) {
    waitForQueuedPasses();  // the composite samples the lighting terms
    Profiler::Scope scope(profiler, "post");
    terms.bind();
    int shadowLayer = -1;
    for (const ShadowView& v : lights.shadows2d)
        if (v.light == settings.debug.shadowMapLight) shadowLayer = v.layer;
    if (settings.debug.view == View::VoxelLevels) {
        post.bindHdrTarget();
        const std::vector<const VoxelVolume*> volumes =
            settings.gi.enabled ? voxelLevels(settings) : std::vector<const VoxelVolume*>{};
        voxelDebug.executeLevels(volumes);
    } else if (isVoxelView(settings.debug.view)) {
        post.bindHdrTarget();
        const VoxelGi& shown = shownVoxelGi(settings);
        voxelDebug.execute(settings, settings.gi.enabled ? &shown.volume() : nullptr, shown.generation());
    } else {
        post.composite(settings, shadow.maps2d(), shadowLayer);
        drawSheets(scene, settings, frame);
    }
    if (TemporalAntialiasPass::applies(settings)) {
        Profiler::Scope antialiasScope(profiler, "anti-aliasing");
        antialias.execute(settings, post.hdr(), gbuffer.depth(), gbuffer.motion(), giLightChanging);
        stats.antialiasFrames = antialias.historyFrames();
    } else {
        antialias.reset();
    }
    if (settings.output.autoExposure && !isDataView(settings.debug.view)) {
        const auto now = std::chrono::steady_clock::now();
        // A pause (a still render, an idle editor) does not count as adaptation time.
        const float dt =
            meteredLastFrame ? std::min(std::chrono::duration<float>(now - lastMetered).count(), 0.25f) : 0.0f;
        if (!meteredLastFrame) autoExposure.reset();
        Profiler::Scope exposureScope(profiler, "auto exposure");
        autoExposure.execute(post.hdr(), settings, dt);
        autoExposure.bindExposure();
        lastMetered = now;
        meteredLastFrame = true;
    } else {
        meteredLastFrame = false;
    }
    post.tonemap(settings);
}

// The selection outline, gizmo lines and markers over the output image.
void Renderer::Impl::drawOverlay() {
    if (overlay.empty()) return;
    Profiler::Scope scope(profiler, "overlay");
    frameUniforms.bindBase(GL_UNIFORM_BUFFER, LIT_UBO_FRAME);
    // The outlined nodes' draw items' world boxes, as the BVH holds them for this frame.
    const std::vector<std::uint32_t> outlined = OverlayPass::outlineClasses(overlay);
    Aabb outlineBounds;
    const std::vector<DrawItem>& items = gpuScene->items();
    for (std::size_t i = 0; i < items.size(); ++i) {
        const auto id = static_cast<std::size_t>(items[i].node) + 1;
        if (items[i].node >= 0 && id < outlined.size() && outlined[id] != 0) outlineBounds.extend(bvh.itemBounds()[i]);
    }
    post.bindOutputTarget();
    // Lines stay put: the overlay is drawn without the frame's jitter.
    overlayPass.execute(overlay, gbuffer, outlineBounds, unjitteredViewProjection);
}

const gl::Texture& Renderer::outputTexture() const { return impl_->post.output(); }
const gl::Texture& Renderer::hdrTexture() const { return impl_->post.hdr(); }

std::vector<std::uint8_t> Renderer::readOutputRgba8() const {
    const gl::Texture& t = impl_->post.output();
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(t.desc().width) * t.desc().height * 4);
    if (pixels.empty()) return pixels;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(t.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(pixels.size()), pixels.data());
    return pixels;
}

std::vector<float> Renderer::readHdrRgb() const {
    const gl::Texture& t = impl_->post.hdr();
    std::vector<float> pixels(static_cast<std::size_t>(t.desc().width) * t.desc().height * 3);
    if (pixels.empty()) return pixels;
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(t.id(), 0, GL_RGB, GL_FLOAT, static_cast<GLsizei>(pixels.size() * sizeof(float)), pixels.data());
    return pixels;
}

std::vector<float> Renderer::readDepth() const {
    const gl::Texture& t = impl_->gbuffer.depth();
    std::vector<float> depth(static_cast<std::size_t>(t.desc().width) * t.desc().height);
    if (depth.empty() || !t) return depth;
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(t.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, static_cast<GLsizei>(depth.size() * sizeof(float)),
                      depth.data());
    return depth;
}

void Renderer::setOverlay(ViewportOverlay overlay) { impl_->overlay = std::move(overlay); }
const ViewportOverlay& Renderer::overlay() const { return impl_->overlay; }

namespace {
// Reads texel `pixel` (top-left origin) of a G-buffer target into `out`; false when out of range.
bool readTexel(const gl::Texture& texture, glm::ivec2 pixel, GLenum format, GLenum type, GLsizei bytes, void* out) {
    const int width = texture.desc().width, height = texture.desc().height;
    if (!texture || pixel.x < 0 || pixel.y < 0 || pixel.x >= width || pixel.y >= height) return false;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureSubImage(texture.id(), 0, pixel.x, height - 1 - pixel.y, 0, 1, 1, 1, format, type, bytes, out);
    return true;
}
}  // namespace

int Renderer::pickNode(glm::ivec2 pixel) const {
    const std::optional<PickedPrimitive> picked = pickPrimitive(pixel);
    return picked ? picked->node : -1;
}

std::optional<PickedPrimitive> Renderer::pickPrimitive(glm::ivec2 pixel) const {
    if (!impl_->lastFrame) return std::nullopt;
    GLuint id[2] = {0, 0};
    if (!readTexel(impl_->gbuffer.nodeId(), pixel, GL_RG_INTEGER, GL_UNSIGNED_INT, sizeof id, id) || id[0] == 0)
        return std::nullopt;
    return PickedPrimitive{static_cast<int>(id[0]) - 1, static_cast<int>(id[1])};
}

std::optional<SurfaceSample> Renderer::surfaceAt(glm::ivec2 pixel) const {
    const Impl& r = *impl_;
    const int node = pickNode(pixel);
    if (node < 0) return std::nullopt;
    float depth = 1.0f;
    glm::vec4 albedo(0.0f), normal(0.0f), material(0.0f);
    readTexel(r.gbuffer.albedo(), pixel, GL_RGBA, GL_FLOAT, sizeof albedo, &albedo);
    readTexel(r.gbuffer.depth(), pixel, GL_DEPTH_COMPONENT, GL_FLOAT, sizeof depth, &depth);
    readTexel(r.gbuffer.normal(), pixel, GL_RGBA, GL_FLOAT, sizeof normal, &normal);
    readTexel(r.gbuffer.material(), pixel, GL_RGBA, GL_FLOAT, sizeof material, &material);
    const int width = r.gbuffer.depth().desc().width, height = r.gbuffer.depth().desc().height;
    const glm::ivec2 glPixel(pixel.x, height - 1 - pixel.y);
    // As gbuffer.glsl's worldPositionFromDepth at the pixel centre.
    const glm::vec2 uv = (glm::vec2(glPixel) + 0.5f) / glm::vec2(width, height);
    const glm::vec4 clip(uv * 2.0f - 1.0f, depth * 2.0f - 1.0f, 1.0f);
    const glm::vec4 world = r.lastFrame->inverseViewProjection * clip;
    SurfaceSample s;
    s.position = glm::vec3(world) / world.w;
    s.normal = glm::length(glm::vec3(normal)) > 0.0f ? glm::normalize(glm::vec3(normal)) : glm::vec3(0, 1, 0);
    s.roughness = material.r;
    s.metalness = material.g;
    // Zero or not in either encoding (the albedo target is sRGB): as cone_trace.frag.glsl decides.
    s.diffuse = glm::any(glm::greaterThan(glm::vec3(albedo) * (1.0f - s.metalness), glm::vec3(0.0f)));
    s.node = node;
    s.glPixel = glPixel;
    s.voxelSize = r.lastVoxelSize;
    s.volumeSide = r.lastVolumeSide;
    return s;
}

bool Renderer::reloadChangedShaders() {
    bool any = false;
    for (Pass* pass : impl_->passes())
        for (gl::Program* program : pass->programs())
            if (program->sourcesChanged()) any |= program->reload(impl_->log);
    if (any) impl_->shadowKey = {};  // a new shadow shader must re-render the maps
    return any;
}

MipmapTimings Renderer::benchmarkMipmaps(int repetitions) { return impl_->gi.benchmarkMipmaps(repetitions); }

float Renderer::exposureEv(const RenderSettings& settings) const {
    return settings.output.autoExposure && impl_->meteredLastFrame ? impl_->autoExposure.readExposureEv()
                                                                   : settings.output.exposureEv;
}

const VoxelVolume* Renderer::voxels() const { return impl_->gi.valid() ? &impl_->gi.volume() : nullptr; }

const VoxelVolume* Renderer::shownVoxels(const RenderSettings& settings) const {
    const VoxelGi& shown = impl_->shownVoxelGi(settings);
    return shown.valid() ? &shown.volume() : nullptr;
}

std::vector<const VoxelVolume*> Renderer::voxelLevels(const RenderSettings& settings) const {
    return impl_->voxelLevels(settings);
}

std::vector<const VoxelVolume*> Renderer::Impl::voxelLevels(const RenderSettings& settings) const {
    std::vector<const VoxelVolume*> volumes;
    const int running = std::min(settings.gi.nearLevelCount(), static_cast<int>(nearGi.size()));
    for (int k = 0; k < running; ++k)
        if (const VoxelGi* level = nearGi[static_cast<std::size_t>(k)].get(); level && level->valid())
            volumes.push_back(&level->volume());
    if (gi.valid()) volumes.push_back(&gi.volume());
    return volumes;
}

const VoxelGi& Renderer::Impl::shownVoxelGi(const RenderSettings& settings) const {
    // nearGi holds the levels the last GI frame ran (fewer than asked in a small scene).
    const int running = std::min(settings.gi.nearLevelCount(), static_cast<int>(nearGi.size()));
    for (int k = std::min(settings.debug.voxelLevel, running); k >= 1; --k)
        if (const VoxelGi* level = nearGi[static_cast<std::size_t>(k - 1)].get(); level && level->valid())
            return *level;
    return gi;
}

Profiler& Renderer::profiler() { return impl_->profiler; }
const FrameStats& Renderer::stats() const { return impl_->stats; }
Log& Renderer::log() { return impl_->log; }

namespace {
// The folder of the running executable (Linux: /proc/self/exe); empty when it cannot be read.
fs::path executableFolder() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path() : exe.parent_path();
}

// $variable when set; else `installed` (relative to the executable: an installed program) when
// that folder exists; else the source tree the binary was built from (a build-tree run).
fs::path locateData(const char* variable, const char* installed, const char* sourceTree) {
    if (const char* value = std::getenv(variable); value && *value) return fs::path(value);
    if (const fs::path folder = executableFolder(); !folder.empty()) {
        std::error_code ec;
        const fs::path candidate = (folder / installed).lexically_normal();
        if (fs::is_directory(candidate, ec)) return candidate;
    }
    return fs::path(sourceTree);
}
}  // namespace

fs::path defaultShaderRoot() {
    return locateData("LIT_SHADER_DIR", LIT_INSTALL_DATA_FROM_BIN "/shaders", LIT_DEFAULT_SHADER_DIR);
}
fs::path defaultAssetRoot() {
    return locateData("LIT_ASSET_DIR", LIT_INSTALL_DATA_FROM_BIN "/assets", LIT_DEFAULT_ASSET_DIR);
}
fs::path defaultScenePath() { return defaultAssetRoot() / "cornell_box.gltf"; }

}  // namespace lit
