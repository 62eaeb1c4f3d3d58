#include "Renderer.h"

#include "gl/Capabilities.h"
#include "gl/GlError.h"
#include "passes/AutoExposurePass.h"
#include "passes/ConeTracePass.h"
#include "passes/DirectLightingPass.h"
#include "passes/FrameUniforms.h"
#include "passes/IndirectFallbackPass.h"
#include "passes/IndirectResolvePass.h"
#include "passes/InjectPass.h"
#include "passes/MipmapPass.h"
#include "passes/OverlayPass.h"
#include "passes/VoxelDebugPass.h"
#include "passes/VoxelVolume.h"
#include "passes/VoxelizePass.h"
#include "passes/GBufferPass.h"
#include "passes/LightSetup.h"
#include "passes/LightingTerms.h"
#include "passes/PostPass.h"
#include "passes/ShadowPass.h"
#include "passes/SkyTexture.h"
#include "scene/Bvh.h"
#include "scene/Frustum.h"
#include "scene/GpuScene.h"
#include "scene/Scene.h"
#include "scene/Sky.h"

#include <shared.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <string>
#include <tuple>

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
    }
    return LIT_VIEW_FINAL;
}

// What the shadow maps depend on; they are re-rendered only when it changes.
struct ShadowKey {
    std::uint64_t geometry = ~0ull, lights = ~0ull;
    const Scene* scene = nullptr;
    bool shadows = false;
    int size = 0;
    float depthBias = 0, slopeBias = 0;
    float sunIrradiance = 0, sunElevation = 0, sunAzimuth = 0;  // the default sun of a scene without lights
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

// What the voxel material volumes depend on; re-voxelized only when it changes.
struct VoxelKey {
    std::uint64_t geometry = ~0ull, materials = ~0ull;
    const Scene* scene = nullptr;
    bool operator==(const VoxelKey&) const = default;
};

std::string formatMs(double ms) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f ms", ms);
    return text;
}

}  // namespace

struct Renderer::Impl {
    Impl(fs::path root, Log& log_)
        : log(log_),
          shaderRoot(std::move(root)),
          shadow(shaderRoot),
          gbuffer(shaderRoot),
          direct(shaderRoot),
          post(shaderRoot),
          voxelize(shaderRoot),
          inject(shaderRoot),
          mipmap(shaderRoot),
          coneTrace(shaderRoot),
          resolve(shaderRoot),
          fallback(shaderRoot),
          overlayPass(shaderRoot),
          voxelDebug(shaderRoot),
          autoExposure(shaderRoot),
          frameUniforms("frame uniforms", sizeof(gpu::FrameUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT),
          lightBuffer("lights", sizeof(gpu::GpuLight) * LIT_MAX_LIGHTS, nullptr, GL_DYNAMIC_STORAGE_BIT) {}

    std::vector<Pass*> passes() {
        return {&shadow,    &gbuffer, &direct,   &post,        &voxelize,   &inject,      &mipmap,
                &coneTrace, &resolve, &fallback, &overlayPass, &voxelDebug, &autoExposure};
    }

    // The sky image of settings.sky.hdrPath, loaded and uploaded when the path changes; nullptr
    // when the mode is not Hdr or the file could not be read (logged once per path).
    const SkyImage* updateSkyImage(const RenderSettings& settings);

    // Voxelize / inject / mipmaps when what they depend on changed. Returns whether it ran.
    void updateVoxels(const Scene& scene, const RenderSettings& settings, const GiBudget& budget, bool shadowsDirty,
                      DrawCounters& counters);
    // Whether the cached mode's update runs over several frames (voxelIrradianceVoxelsPerFrame
    // entries each) rather than all in the edit's frame: only over a complete list longer than that.
    // Voxels that replay their rays' recorded hits take kReplayVoxelsPerFrameFactor times as many.
    std::uint32_t voxelsPerFrame(const RenderSettings& settings, const GiBudget& budget) const {
        const std::uint32_t perFrame = budget.updateVoxels == GiBudget::kAll ? 0u : std::max(budget.updateVoxels, 1u);
        return replaysRayHits(settings) ? static_cast<std::uint32_t>(std::min<std::uint64_t>(std::uint64_t{perFrame} * kReplayVoxelsPerFrameFactor,
                                                                          std::numeric_limits<std::uint32_t>::max()))
                      : perFrame;
    }
    bool spreadOverFrames(const RenderSettings& settings, const GiBudget& budget) const {
        const std::uint32_t perFrame = voxelsPerFrame(settings, budget);
        return settings.gi.voxelIrradiance() && perFrame > 0 && perFrame < occupiedCount && occupiedListComplete;
    }
    // Logs what the last GI update did and what it cost, once its GPU timings are in.
    void reportGiUpdate();

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
    VoxelizePass voxelize;
    InjectPass inject;
    MipmapPass mipmap;
    ConeTracePass coneTrace;
    IndirectResolvePass resolve;
    IndirectFallbackPass fallback;
    OverlayPass overlayPass;
    VoxelDebugPass voxelDebug;
    AutoExposurePass autoExposure;
    std::chrono::steady_clock::time_point lastMetered{};  // when auto exposure last ran
    bool meteredLastFrame = false;
    SkyImage skyImage;
    std::string skyImagePath;  // the file skyImage (and skyTexture) came from; "" = none tried
    gl::Texture skyTexture;
    ViewportOverlay overlay;
    // What picking needs of the last frame: its camera (to unproject depth) and voxel volume.
    std::optional<gpu::FrameUniforms> lastFrame;
    float lastVoxelSize = 0.0f, lastVolumeSide = 0.0f;  // m; 0 when that frame had no GI
    VoxelVolume voxels;
    LightingTerms terms;
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

    Aabb bounds;
    std::uint64_t boundsRevision = ~0ull;
    LightSetup lights;
    ShadowKey shadowKey;
    VoxelKey voxelKey;
    float injectedRadianceRange = 0.0f;
    // What the last injection's bounces were traced with (bounces > 1 depend on the cone settings).
    int injectedBounces = 0;
    int pendingBounces = 1;  // bounces of the GI update waiting to be logged
    bool injectedIrradiance = false;  // the voxel irradiance volumes hold this light (diffuseFromVoxelIrradiance)
    // The voxel irradiance update under way (voxelIrradianceVoxelsPerFrame > 0), round robin over
    // the occupied-voxel list: the next entry to trace, and how many entries are still to be traced
    // since the last edit (0: every voxel holds the current light).
    std::uint32_t irradianceNext = 0;
    std::uint32_t irradianceRemaining = 0;
    // The refinement after it (voxelIrradianceRefineVoxelsPerFrame > 0): the set offset of the
    // round under way (1..kConeSets − 1; kConeSets: done) and its next list entry.
    int irradianceRefineRound = 0;
    std::uint32_t irradianceRefineNext = 0;
    static constexpr int kConeSets = LIT_CONE_STRATA * LIT_CONE_STRATA;
    // Refinement rounds are left to run with `settings`, after the update (or the one under way).
    bool refinementLeft(const RenderSettings& settings) const {
        return settings.gi.voxelIrradiance() && irradianceRefineRound < kConeSets && occupiedListComplete &&
               occupiedCount > 0;
    }
    // Bounces 2..N spread over frames as the irradiance update is (the cached mode with
    // voxelIrradianceVoxelsPerFrame > 0): the bounce under way (0: none; the irradiance update waits
    // for the last one) and its next list entry.
    int bounceUnderWay = 0;
    std::uint32_t bounceNext = 0;
    // A light edit came while a spread update ran on: one more update follows it (updateVoxels).
    bool updateAgain = false;
    // The voxel rays' hit cache (InjectPass::ensureRayHits): valid once a trace over the whole
    // list recorded every hit since the last voxelization, for rayHitsRays rays per voxel.
    bool rayHitsValid = false;
    int rayHitsRays = 0;
    // What a voxel-ray trace of the list does with the cache now: replay when valid, else record.
    RayHits rayHitsFor(const RenderSettings& settings) {
        const int rays = ConeFeatures::of(settings).voxelRays;
        if (rays <= 0 || !occupiedListComplete) return RayHits::Off;
        const std::size_t before = inject.rayHitBytes();
        if (!inject.ensureRayHits(rays, occupiedCount)) {
            rayHitsValid = false;
            return RayHits::Off;
        }
        if (inject.rayHitBytes() != before) {
            rayHitsValid = false;
            char text[160];
            std::snprintf(text, sizeof text, "voxel ray hits: %.1f MiB (%u occupied voxels × 2 sides × %d rays)",
                          static_cast<double>(inject.rayHitBytes()) / (1024.0 * 1024.0), occupiedCount, rays);
            log.info(text);
        }
        if (rays != rayHitsRays) rayHitsValid = false;
        rayHitsRays = rays;
        return replaysRayHits(settings) ? RayHits::Replay : RayHits::Record;
    }
    // Whether a trace with `settings` replays the recorded hits (the cache holds its rays' hits).
    bool replaysRayHits(const RenderSettings& settings) const {
        return rayHitsValid && rayHitsRays > 0 && rayHitsRays == ConeFeatures::of(settings).voxelRays;
    }
    // The irradiance update starts again over the whole list (from where it stands), its
    // refinement rounds after it.
    void restartIrradianceUpdate() {
        irradianceRemaining = std::max(occupiedCount, 1u);
        irradianceRefineRound = 1;
        irradianceRefineNext = 0;
    }
    // A trace over the whole list ended: what it recorded is the cache now.
    void listTraced(RayHits hits) {
        if (hits == RayHits::Record) rayHitsValid = true;
    }
    bool injectedAnisotropic = true;
    int injectedVoxelRays = 0;
    float injectedFootprint = 0.0f, injectedAperture = 0.0f, injectedStepScale = 0.0f, injectedTraceDistance = 0.0f,
          injectedIntensity = 0.0f;
    bool voxelsValid = false;
    std::uint64_t voxelGeneration = 0;  // counts voxelizations (the voxel debug views cache by it)
    // Temporal accumulation of the indirect terms: frames accumulated so far (drives the jitter
    // and cone rotation) and what its history means (IndirectResolvePass keeps the history's camera).
    std::uint64_t temporalFrame = 0;
    IndirectKey indirectKey;
    // The GI update waiting for its GPU timings to be logged: what ran, why, in which frame.
    std::string pendingGiReason;
    std::uint64_t pendingGiFrame = 0;
    bool pendingVoxelize = false;
    std::uint32_t occupiedCount = 0;    // voxels the last voxelization occupied
    bool occupiedListComplete = false;  // the list holds all of them (else inject runs over N³)
};

void Renderer::Impl::updateVoxels(const Scene& scene, const RenderSettings& settings, const GiBudget& budget,
                                  bool shadowsDirty, DrawCounters& counters) {
    std::string reason;
    const bool reallocated = voxels.ensure(settings.gi.voxelResolution, settings.gi.radianceRgba8, log);
    const bool moved = voxels.fitTo(bounds);
    // Sample pattern index 0 every frame without temporal accumulation: a pattern that moves
    // only adds flicker there, and a fixed one keeps each term image consistent with the final
    // image. With it, the pattern turns every frame and the history averages the patterns.
    voxels.updateUniforms(settings,
                          settings.indirect.temporalAccumulation ? static_cast<int>(temporalFrame % 4096) : 0);
    const VoxelKey key{scene.geometryRevision, scene.materialRevision, &scene};
    bool voxelDirty = !voxelsValid || reallocated || moved || !(key == voxelKey);
    if (!voxelsValid) reason = "first GI frame";
    else if (reallocated) reason = "voxel resolution or format changed";
    else if (moved || key.geometry != voxelKey.geometry || key.scene != voxelKey.scene) reason = "geometry changed";
    else if (key.materials != voxelKey.materials) reason = "materials changed";
    // Bounces and the voxel irradiance trace cones through the volume: their settings change what
    // is injected.
    const bool bounceSettingsChanged =
        std::clamp(settings.gi.bounces, 1, kMaxBounces) != injectedBounces ||
        settings.gi.voxelIrradiance() != injectedIrradiance ||
        // The cached mode's voxel irradiance is traced with the same cone settings as the bounces.
        ((injectedBounces > 1 || injectedIrradiance) &&
         (settings.gi.anisotropicVoxels() != injectedAnisotropic ||
          ConeFeatures::of(settings).voxelRays != injectedVoxelRays ||
          settings.gi.footprintPerHeight() != injectedFootprint ||
          settings.gi.diffuseConeAperture != injectedAperture || settings.gi.coneStepScale != injectedStepScale ||
          settings.gi.maxTraceDistance != injectedTraceDistance || settings.gi.indirectIntensity != injectedIntensity));
    // The six directional mip chains are built only while anisotropic voxels are on (they cost
    // ~10× the isotropic chain on llvmpipe): switching them on rebuilds them.
    const bool directionalMissing = settings.gi.anisotropicVoxels() && !injectedAnisotropic;
    const bool injectDirty = voxelDirty || shadowsDirty || settings.gi.radianceRange != injectedRadianceRange ||
                             bounceSettingsChanged || directionalMissing;
    // Switched off: the directional volumes' memory goes back (0.6-1.3 GiB at 512³); switching on
    // again makes and rebuilds them (directionalMissing, from injectedAnisotropic).
    if (!settings.gi.anisotropicVoxels() && voxels.directional(0)) {
        voxels.releaseDirectionalVolumes();
        injectedAnisotropic = false;
    }
    if (!voxelDirty && injectDirty)
        reason = bounceSettingsChanged  ? "bounce settings changed"
                 : directionalMissing ? "anisotropic voxels switched on"
                                      : "lights or shadows changed";
    if (voxelDirty) {
        {
            Profiler::Scope scope(profiler, "voxelize");
            voxelize.execute(scene, *gpuScene, voxels, counters);
        }
        {
            // Once per voxelization: the mip chain is then built over these (light edits too).
            Profiler::Scope scope(profiler, "mip lists");
            mipmap.listOccupiedParents(voxels);
        }
        voxelKey = key;
        voxelsValid = true;
        ++voxelGeneration;
        rayHitsValid = false;  // other voxels: other hits
        // One uint read back per voxelization (which is rare and slow anyway): the count is
        // reported, and a list that overflowed is grown for the next voxelization while this
        // one injects the whole grid.
        occupiedCount = voxels.readOccupiedCount();
        occupiedListComplete = occupiedCount <= voxels.occupiedCapacity();
        if (!occupiedListComplete) {
            voxels.setParentListsValid(false);  // listed from an incomplete list: mipmaps over the whole grid
            log.warning("occupied-voxel list overflowed (" + std::to_string(occupiedCount) + " voxels, room for " +
                        std::to_string(voxels.occupiedCapacity()) + "); injecting the whole grid until the next voxelization");
            voxels.growOccupiedList(occupiedCount + occupiedCount / 4);
        }
    }
    if (injectDirty) {
        shadow.bindMaps();
        const int bounces = std::clamp(settings.gi.bounces, 1, kMaxBounces);
        // Before the injection, which then writes the bounces' direct radiance beside level 0.
        if (bounces > 1) voxels.ensureBounceVolumes();
        // When only the light changed and the bounces gather with voxel rays, level 0 and its mips
        // keep the last update's light until the last bounce replaces them: the second bounce's rays
        // take the direct volume's light where they end (InjectPass::traceBounce) and, while they
        // march, only the mips' occupancy (alpha), which the voxels set, not the light. (Cones read
        // the mips' light; after a voxelization the mips must hold the new occupancy; one bounce
        // has no later rebuild.) So the direct light's own mip build is saved (Sponza 256³ with
        // anisotropic voxels: 120-155 ms of the edit's frame; docs/PERFORMANCE.md), the specular
        // cones and the gathered diffuse show the same (last) update meanwhile, and a spread update
        // need not start again at each edit: see updateAgain below.
        const bool onlyLightChanged = !voxelDirty && !bounceSettingsChanged && !directionalMissing &&
                                      settings.gi.radianceRange == injectedRadianceRange;
        const bool keepLastUpdate = onlyLightChanged && bounces > 1 && ConeFeatures::of(settings).voxelRays > 0;
        {
            Profiler::Scope scope(profiler, "inject");
            inject.execute(voxels, occupiedListComplete, !keepLastUpdate, bounces > 1, ShadowKinds::of(lights));
        }
        if (!keepLastUpdate) {
            Profiler::Scope scope(profiler, "mipmap");
            mipmap.execute(voxels, settings.gi.anisotropicVoxels(), occupiedListComplete);
        }
        // A light edit while a spread update runs (a light dragged in the editor: an edit every
        // frame) lets it run on, the voxels not traced yet taking the new direct light, and asks
        // for another update after it. Starting again at each edit, as other edits do, would keep
        // a drag's update from ever reaching the irradiance: the indirect light stood still until
        // the drag ended (with two bounces, the default since the thirteenth session).
        const bool updateRunning = bounceUnderWay > 0 || (injectedIrradiance && irradianceRemaining > 0);
        const bool runOn = keepLastUpdate && updateRunning && spreadOverFrames(settings, budget) &&
                           settings.gi.voxelIrradiance() == injectedIrradiance;
        updateAgain = runOn;
        if (!runOn) {
            // Bounces 2..N: each re-injects the voxels' traced indirect light (docs/GI.md). In the
            // cached mode with the update spread over frames, they are spread too (below): a light
            // dragged in the editor would otherwise stall every frame of the drag for whole bounces.
            bounceUnderWay = 0;
            if (bounces > 1) {
                Profiler::Scope scope(profiler, "bounces");
                if (spreadOverFrames(settings, budget)) {
                    bounceUnderWay = 2;
                    bounceNext = 0;
                } else {
                    for (int b = 2; b <= bounces; ++b) {
                        const RayHits hits = rayHitsFor(settings);
                        inject.executeBounce(voxels, ConeFeatures::of(settings), b == 2, occupiedListComplete, hits);
                        listTraced(hits);
                        mipmap.execute(voxels, settings.gi.anisotropicVoxels(), occupiedListComplete);
                    }
                }
            }
            if (settings.gi.voxelIrradiance()) {
                // A new edit asks for the whole list again, from where the update stands (a new list
                // after a voxelization: from its start), so that a light dragged over many frames keeps
                // refreshing every voxel in turn, and once the update has gone round the list every
                // voxel was traced after the last edit (no trace of the old light).
                inject.prepareIrradiance(voxels, voxelDirty);
                if (voxelDirty || irradianceNext >= occupiedCount) irradianceNext = 0;
                restartIrradianceUpdate();
            }
        }
        injectedIrradiance = settings.gi.voxelIrradiance();
        injectedBounces = bounces;
        pendingBounces = bounces;
        injectedAnisotropic = settings.gi.anisotropicVoxels();
        injectedVoxelRays = ConeFeatures::of(settings).voxelRays;
        injectedFootprint = settings.gi.footprintPerHeight();
        injectedAperture = settings.gi.diffuseConeAperture;
        injectedStepScale = settings.gi.coneStepScale;
        injectedTraceDistance = settings.gi.maxTraceDistance;
        injectedIntensity = settings.gi.indirectIntensity;
        injectedRadianceRange = settings.gi.radianceRange;
        pendingGiReason = reason;
        pendingGiFrame = profiler.currentFrame();
        pendingVoxelize = voxelDirty;
        resolve.resetHistory();  // the scene's light changed: accumulated indirect light is stale
    }
    // The voxel irradiance (diffuseFromVoxelIrradiance): all of the list in the edit's frame, or
    // voxelIrradianceVoxelsPerFrame entries per frame, wrapping round the list, until every entry
    // has been traced since the last edit. An overflowed list (whole-grid dispatch) is done at once.
    // The list ranges traced this frame, and whether the frame completed an update or a refinement
    // round (or traced everything at once): then the filter runs over the whole list, else only over
    // the ranges traced (the filter over all occupied voxels costs ~150 ms a frame at 256³ on
    // Sponza here, as much as a third of the trace it follows; docs/PERFORMANCE.md).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> tracedRanges;
    bool filterAll = false;
    if (bounceUnderWay > 0) {
        // A spread bounce: voxelIrradianceVoxelsPerFrame entries a frame (all that is left if the
        // setting went to 0 meanwhile); the last entry ends the bounce (level 0 and its mips), and
        // the last bounce lets the irradiance update start in the next frame.
        Profiler::Scope scope(profiler, "bounces");
        const std::uint32_t perFrame = voxelsPerFrame(settings, budget);
        const std::uint32_t left = occupiedCount - std::min(bounceNext, occupiedCount);
        const std::uint32_t count = perFrame == 0 ? left : std::min(perFrame, left);
        const RayHits hits = rayHitsFor(settings);
        inject.traceBounce(voxels, ConeFeatures::of(settings), bounceUnderWay == 2, true, bounceNext, count, hits);
        bounceNext += count;
        if (bounceNext >= occupiedCount) {
            listTraced(hits);  // the pass ran over the whole list from 0
            inject.endBounce(voxels, true);
            mipmap.execute(voxels, settings.gi.anisotropicVoxels(), occupiedListComplete);
            bounceNext = 0;
            bounceUnderWay = bounceUnderWay < injectedBounces ? bounceUnderWay + 1 : 0;
        }
    } else if (settings.gi.voxelIrradiance() && irradianceRemaining > 0) {
        Profiler::Scope scope(profiler, "voxel irradiance");
        const std::uint32_t perFrame = voxelsPerFrame(settings, budget);
        if (!spreadOverFrames(settings, budget)) {
            const RayHits hits = rayHitsFor(settings);
            inject.executeIrradiance(voxels, ConeFeatures::of(settings), occupiedListComplete, 0, 0, 0, hits);
            listTraced(hits);
            irradianceRemaining = 0;
        } else {
            std::uint32_t left = std::min(perFrame, irradianceRemaining);
            irradianceRemaining -= left;
            const RayHits hits = rayHitsFor(settings);
            while (left > 0) {  // at most twice: up to the list's end, then from its start
                const std::uint32_t count = std::min(left, occupiedCount - irradianceNext);
                inject.executeIrradiance(voxels, ConeFeatures::of(settings), true, irradianceNext, count, 0, hits);
                tracedRanges.emplace_back(irradianceNext, count);
                irradianceNext = (irradianceNext + count) % occupiedCount;
                left -= count;
            }
            // The accumulated indirect light holds the frames of the update (old light in the
            // voxels not reached yet): the first frame after it starts the history afresh. Every
            // entry was traced once since the edit: recorded, if that is what the update did.
            if (irradianceRemaining == 0) {
                resolve.resetHistory();
                listTraced(hits);
                if (updateAgain) {
                    // Light edits came while this update ran: another one, with the light as it is now.
                    updateAgain = false;
                    bounceUnderWay = injectedBounces > 1 ? 2 : 0;
                    bounceNext = 0;
                    restartIrradianceUpdate();
                }
            }
        }
        filterAll = irradianceRemaining == 0;
    }
    // The refinement once the update is done, in the same frame when the budget allows (a still
    // converges in its one frame).
    const bool refine =
        bounceUnderWay == 0 && irradianceRemaining == 0 && refinementLeft(settings) && budget.refineVoxels > 0;
    if (refine) {
        // Round k traces every voxel's set + k once over the list, budget entries a frame; each
        // voxel then averages k + 1 sets. The light is right throughout: only its sampling improves.
        Profiler::Scope scope(profiler, "voxel irradiance");
        std::uint32_t left = budget.refineVoxels;
        while (left > 0 && irradianceRefineRound < kConeSets) {
            const std::uint32_t count = std::min(left, occupiedCount - irradianceRefineNext);
            inject.executeIrradiance(voxels, ConeFeatures::of(settings), true, irradianceRefineNext, count,
                                     irradianceRefineRound);
            tracedRanges.emplace_back(irradianceRefineNext, count);
            stats.refinedVoxels += count;
            left -= count;
            irradianceRefineNext += count;
            if (irradianceRefineNext >= occupiedCount) {
                irradianceRefineNext = 0;
                ++irradianceRefineRound;
                filterAll = true;
            }
        }
    }
    if (filterAll || !tracedRanges.empty()) {
        // The voxels traced see their new values (and, once the update is complete, every voxel
        // its neighbours' new values: the result is then the all-at-once filter's exactly).
        Profiler::Scope filterScope(profiler, "voxel irradiance filter");
        if (filterAll) {
            inject.filterIrradiance(voxels, occupiedListComplete);
        } else {
            for (const auto& [first, count] : tracedRanges) inject.filterIrradiance(voxels, true, first, count);
        }
    }

    stats.voxelized = voxelDirty;
    stats.injected = injectDirty;
    stats.giRefining = refinementLeft(settings);
    stats.occupiedVoxels = occupiedCount;
    // Progress of the spread update: passes over the list (bounces 2..N, then the irradiance).
    const double listLength = std::max(occupiedCount, 1u);
    const int passes = (injectedBounces - 1) + (injectedIrradiance ? 1 : 0);
    if (bounceUnderWay > 0) {
        stats.giUpdateDone = static_cast<float>(((bounceUnderWay - 2) * listLength + bounceNext) / (passes * listLength));
        stats.giUpdateStage = "bounce " + std::to_string(bounceUnderWay);
    } else if (injectedIrradiance && irradianceRemaining > 0) {
        stats.giUpdateDone = static_cast<float>(((passes - 1) * listLength + (listLength - irradianceRemaining)) /
                                                (passes * listLength));
        stats.giUpdateStage = "irradiance";
    } else if (refine && irradianceRefineRound < kConeSets) {
        stats.giUpdateStage = "refining " + std::to_string(irradianceRefineRound) + "/" + std::to_string(kConeSets - 1);
    }
}

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

void Renderer::Impl::reportGiUpdate() {
    if (pendingGiFrame == 0) return;
    const PassTiming* injectTiming = profiler.lastRun("inject");
    if (!injectTiming || injectTiming->frame < pendingGiFrame) return;
    const PassTiming* voxelizeTiming = profiler.lastRun("voxelize");
    const PassTiming* mipTiming = profiler.lastRun("mipmap");
    std::string text = pendingVoxelize ? "re-voxelized " : "re-injected ";
    text += std::to_string(voxels.resolution()) + "³ (" + pendingGiReason + "): ";
    if (pendingVoxelize && voxelizeTiming) text += "voxelize " + formatMs(voxelizeTiming->gpuMs) + ", ";
    const PassTiming* listsTiming = profiler.lastRun("mip lists");
    if (pendingVoxelize && listsTiming && listsTiming->frame >= pendingGiFrame)
        text += "mip lists " + formatMs(listsTiming->gpuMs) + ", ";
    const double n = voxels.resolution();
    char occupancy[96];
    std::snprintf(occupancy, sizeof occupancy, "inject %s over %u occupied voxels (%.2f %% of the grid%s)",
                  formatMs(injectTiming->gpuMs).c_str(), occupiedCount, 100.0 * occupiedCount / (n * n * n),
                  occupiedListComplete ? "" : ", list overflowed: whole grid");
    text += occupancy;
    if (mipTiming) text += ", mipmap " + formatMs(mipTiming->gpuMs);
    const PassTiming* bounceTiming = profiler.lastRun("bounces");
    if (bounceTiming && bounceTiming->frame >= pendingGiFrame)
        text += ", " + std::to_string(pendingBounces - 1) + " more bounce" + (pendingBounces > 2 ? "s " : " ") +
                formatMs(bounceTiming->gpuMs);
    const PassTiming* irradianceTiming = profiler.lastRun("voxel irradiance");
    if (irradianceTiming && irradianceTiming->frame >= pendingGiFrame)
        text += ", voxel irradiance " + formatMs(irradianceTiming->gpuMs);
    const PassTiming* filterTiming = profiler.lastRun("voxel irradiance filter");
    if (filterTiming && filterTiming->frame >= pendingGiFrame) text += " + filter " + formatMs(filterTiming->gpuMs);
    // Every frame of a gizmo drag re-voxelizes: one folded line with a count, not one per frame.
    log.info(text, Fold::IgnoringNumbers);
    pendingGiFrame = 0;
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
    impl_->voxelsValid = false;
    impl_->resolve.resetHistory();
    impl_->meteredLastFrame = false;  // a new scene is metered afresh, not adapted to
    impl_->lastFrame.reset();  // the G-buffer's node IDs belong to the previous scene
}

void Renderer::render(const Scene& scene, const CameraView& camera, const RenderSettings& settings,
                      const GiBudget& budget) {
    Impl& r = *impl_;
    if (settings.output.width <= 0 || settings.output.height <= 0) return;  // minimized window: nothing to draw
    if (!r.gpuScene) setScene(scene);

    r.profiler.beginFrame();
    r.reportGiUpdate();
    r.stats = {};
    DrawCounters counters;

    if (scene.materialRevision != r.uploadedMaterialRevision) {
        r.gpuScene->updateMaterials(scene);
        r.uploadedMaterialRevision = scene.materialRevision;
    }
    if (scene.geometryRevision != r.boundsRevision) {
        r.bounds = scene.worldBounds();
        r.boundsRevision = scene.geometryRevision;
    }
    if (scene.geometryRevision != r.bvhRevision) {  // transforms moved: new boxes, same tree
        const auto start = std::chrono::steady_clock::now();
        r.bvh.refit(scene);
        r.bvhRevision = scene.geometryRevision;
        r.stats.cullMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    }

    // Lights and shadow maps: rebuilt only when the scene or shadow settings change; the camera
    // does not affect them (directional maps are fitted to the scene, not the view).
    const ShadowKey key{scene.geometryRevision,     scene.lightRevision,        &scene,
                        settings.shadows.enabled,   settings.shadows.mapSize,   settings.shadows.depthBias,
                        settings.shadows.slopeBias, settings.sky.sunIrradiance, settings.sky.sunElevation,
                        settings.sky.sunAzimuth};
    const bool shadowsDirty = !(key == r.shadowKey);
    if (shadowsDirty) {
        r.lights = buildLightSetup(scene, r.bounds, settings, r.log);
        glNamedBufferSubData(r.lightBuffer.id(), 0,
                             static_cast<GLsizeiptr>(r.lights.lights.size() * sizeof(gpu::GpuLight)),
                             r.lights.lights.data());
    }

    const Sky sky = resolveSky(scene, settings, r.updateSkyImage(settings));
    if (sky.mode == SkyMode::Hdr) r.skyTexture.bind(LIT_TEX_SKY);
    const gpu::FrameUniforms frame = makeFrameUniforms(camera, settings, toShaderView(settings.debug.view),
                                                       static_cast<int>(r.lights.lights.size()), &sky);
    r.frameUniforms.update(frame);
    r.frameUniforms.bindBase(GL_UNIFORM_BUFFER, LIT_UBO_FRAME);
    r.lightBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_LIGHTS);

    if (shadowsDirty) {
        Profiler::Scope scope(r.profiler, "shadow");
        const ItemCuller cullShadowView = [&r, &settings](const glm::mat4& viewProjection,
                                                          std::vector<std::uint32_t>& visible) {
            r.cullView(viewProjection, settings.output.frustumCulling, visible);
        };
        r.shadow.execute(scene, *r.gpuScene, r.lights, settings, counters, cullShadowView);
        r.shadowKey = key;
    }

    r.gbuffer.resize(settings.output.width, settings.output.height);
    r.terms.resize(settings.output.width, settings.output.height);
    r.post.resize(settings.output.width, settings.output.height);
    r.cullView(frame.viewProjection, settings.output.frustumCulling, r.cameraItems);
    {
        Profiler::Scope scope(r.profiler, "g-buffer");
        const std::size_t trianglesBefore = counters.triangles;  // the shadow pass counts its own
        r.gbuffer.execute(scene, *r.gpuScene, counters, &r.cameraItems);
        r.stats.triangles = counters.triangles - trianglesBefore;
    }
    // GI: the voxel volume follows the scene; nothing is allocated while GI is off.
    const bool giWanted = settings.gi.enabled;
    if (giWanted) r.updateVoxels(scene, settings, budget, shadowsDirty, counters);
    r.gbuffer.bindTargets();
    // The data and voxel views show no lighting term (the composite does not use them there), so
    // they skip lighting and cone tracing; the terms are redone by the next frame that shows them.
    if (!isDataView(settings.debug.view)) {
        r.shadow.bindMaps();
        {
            Profiler::Scope scope(r.profiler, "lighting");
            r.direct.execute(r.terms, settings, ShadowKinds::of(r.lights));
        }
        if (giWanted && ConeTracePass::reducedPath(settings)) {
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
            if (!(key == r.indirectKey)) r.resolve.resetHistory();
            r.indirectKey = key;
            const ConeTracePass::Sampling sampling =
                settings.indirect.temporalAccumulation
                    ? ConeTracePass::samplingFor(r.temporalFrame, key.indirectScale,
                                                 ConeTracePass::coneSubsets(settings))
                    : ConeTracePass::Sampling{};
            {
                Profiler::Scope scope(r.profiler, "cone trace");
                if (settings.gi.voxelIrradiance()) r.inject.bindIrradiance();
                r.coneTrace.executeReduced(r.voxels, settings, sampling);
            }
            r.waitForQueuedPasses();  // the resolve samples the low-resolution trace
            {
                Profiler::Scope scope(r.profiler, "indirect resolve");
                r.gbuffer.bindTargets();
                r.resolve.execute(r.terms, r.coneTrace, r.voxels, settings, sampling, frame.viewProjection);
            }
            {
                Profiler::Scope scope(r.profiler, "indirect fallback");
                r.fallback.execute(r.resolve, ConeFeatures::of(settings));
            }
            if (settings.indirect.temporalAccumulation) ++r.temporalFrame;
        } else if (giWanted) {
            Profiler::Scope scope(r.profiler, "cone trace");
            r.coneTrace.execute(r.terms, r.voxels, settings);
            r.resolve.resetHistory();
        } else {
            r.terms.clearIndirect();
            r.resolve.resetHistory();
        }
    } else {
        r.resolve.resetHistory();  // no terms this frame: the next one starts afresh
    }
    r.stats.voxelBytes = giWanted ? r.voxels.totalBytes() : 0;
    r.waitForQueuedPasses();  // the composite samples the lighting terms
    {
        Profiler::Scope scope(r.profiler, "post");
        r.terms.bind();
        int shadowLayer = -1;
        for (const ShadowView& v : r.lights.shadows2d)
            if (v.light == settings.debug.shadowMapLight) shadowLayer = v.layer;
        if (isVoxelView(settings.debug.view)) {
            r.post.bindHdrTarget();
            r.voxelDebug.execute(settings, giWanted ? &r.voxels : nullptr, r.voxelGeneration);
        } else {
            r.post.composite(settings, r.shadow.maps2d(), shadowLayer);
        }
        if (settings.output.autoExposure && !isDataView(settings.debug.view)) {
            const auto now = std::chrono::steady_clock::now();
            // A pause (a still render, an idle editor) does not count as adaptation time.
            const float dt = r.meteredLastFrame ? std::min(std::chrono::duration<float>(now - r.lastMetered).count(), 0.25f)
                                                : 0.0f;
            if (!r.meteredLastFrame) r.autoExposure.reset();
            Profiler::Scope exposureScope(r.profiler, "auto exposure");
            r.autoExposure.execute(r.post.hdr(), settings, dt);
            r.autoExposure.bindExposure();
            r.lastMetered = now;
            r.meteredLastFrame = true;
        } else {
            r.meteredLastFrame = false;
        }
        r.post.tonemap(settings);
    }
    if (!r.overlay.empty()) {
        Profiler::Scope scope(r.profiler, "overlay");
        r.frameUniforms.bindBase(GL_UNIFORM_BUFFER, LIT_UBO_FRAME);
        // The outlined nodes' draw items' world boxes, as the BVH holds them for this frame.
        const std::vector<std::uint32_t> outlined = OverlayPass::outlineClasses(r.overlay);
        Aabb outlineBounds;
        const std::vector<DrawItem>& items = r.gpuScene->items();
        for (std::size_t i = 0; i < items.size(); ++i) {
            const auto id = static_cast<std::size_t>(items[i].node) + 1;
            if (items[i].node >= 0 && id < outlined.size() && outlined[id] != 0) outlineBounds.extend(r.bvh.itemBounds()[i]);
        }
        r.post.bindOutputTarget();
        r.overlayPass.execute(r.overlay, r.gbuffer, outlineBounds, frame.viewProjection);
    }
    r.lastFrame = frame;
    r.lastVoxelSize = giWanted ? r.voxels.voxelSize() : 0.0f;
    r.lastVolumeSide = giWanted ? r.voxels.side() : 0.0f;
    r.profiler.endFrame();
    r.stats.drawCalls = counters.drawCalls;
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
    if (!impl_->lastFrame) return -1;
    GLuint id = 0;
    if (!readTexel(impl_->gbuffer.nodeId(), pixel, GL_RED_INTEGER, GL_UNSIGNED_INT, sizeof id, &id)) return -1;
    return static_cast<int>(id) - 1;
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

MipmapTimings Renderer::benchmarkMipmaps(int repetitions) {
    if (!impl_->voxelsValid) return {};
    return lit::benchmarkMipmaps(impl_->mipmap, impl_->voxels, repetitions, impl_->injectedAnisotropic);
}

float Renderer::exposureEv(const RenderSettings& settings) const {
    return settings.output.autoExposure && impl_->meteredLastFrame ? impl_->autoExposure.readExposureEv()
                                                                   : settings.output.exposureEv;
}

const VoxelVolume* Renderer::voxels() const { return impl_->voxelsValid ? &impl_->voxels : nullptr; }

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
