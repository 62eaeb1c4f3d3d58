#include "Renderer.h"

#include "gl/Capabilities.h"
#include "gl/GlError.h"
#include "passes/DirectLightingPass.h"
#include "passes/GBufferPass.h"
#include "passes/LightSetup.h"
#include "passes/LightingTerms.h"
#include "passes/PostPass.h"
#include "passes/ShadowPass.h"
#include "scene/GpuScene.h"
#include "scene/Scene.h"

#include <shared.h>

#include <cstdlib>
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
    bool operator==(const ShadowKey&) const = default;
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
          frameUniforms("frame uniforms", sizeof(gpu::FrameUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT),
          lightBuffer("lights", sizeof(gpu::GpuLight) * LIT_MAX_LIGHTS, nullptr, GL_DYNAMIC_STORAGE_BIT) {}

    std::vector<Pass*> passes() { return {&shadow, &gbuffer, &direct, &post}; }

    Log& log;
    fs::path shaderRoot;
    Profiler profiler;
    ShadowPass shadow;
    GBufferPass gbuffer;
    DirectLightingPass direct;
    PostPass post;
    LightingTerms terms;
    gl::Buffer frameUniforms;
    gl::Buffer lightBuffer;
    std::unique_ptr<GpuScene> gpuScene;
    std::uint64_t uploadedMaterialRevision = 0;
    FrameStats stats;

    Aabb bounds;
    std::uint64_t boundsRevision = ~0ull;
    LightSetup lights;
    ShadowKey shadowKey;
};

Renderer::Renderer(fs::path shaderRoot, Log& log) {
    gl::requireCapabilities();
    impl_ = std::make_unique<Impl>(std::move(shaderRoot), log);
    log.info("renderer ready on " + gl::contextDescription());
}

Renderer::~Renderer() = default;

void Renderer::setScene(const Scene& scene) {
    impl_->gpuScene = std::make_unique<GpuScene>(scene, impl_->log);
    impl_->uploadedMaterialRevision = scene.materialRevision;
    impl_->boundsRevision = ~0ull;
    impl_->shadowKey = {};
}

void Renderer::render(const Scene& scene, const CameraView& camera, const RenderSettings& settings) {
    Impl& r = *impl_;
    if (settings.width <= 0 || settings.height <= 0) return;  // minimized window: nothing to draw
    if (!r.gpuScene) setScene(scene);

    r.profiler.beginFrame();
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

    // Lights and shadow maps: rebuilt only when the scene or shadow settings change; the camera
    // does not affect them (directional maps are fitted to the scene, not the view).
    const ShadowKey key{scene.geometryRevision, scene.lightRevision, &scene, settings.shadows, settings.shadowMapSize,
                        settings.shadowDepthBias, settings.shadowSlopeBias};
    const bool shadowsDirty = !(key == r.shadowKey);
    if (shadowsDirty) {
        r.lights = buildLightSetup(scene, r.bounds, settings, r.log);
        glNamedBufferSubData(r.lightBuffer.id(), 0,
                             static_cast<GLsizeiptr>(r.lights.lights.size() * sizeof(gpu::GpuLight)),
                             r.lights.lights.data());
    }

    gpu::FrameUniforms frame{};
    frame.view = camera.view;
    frame.projection = camera.projection;
    frame.viewProjection = camera.projection * camera.view;
    frame.inverseViewProjection = glm::inverse(frame.viewProjection);
    frame.cameraPosition = glm::vec4(camera.position, 1.0f);
    frame.viewport = glm::vec4(settings.width, settings.height, 1.0f / settings.width, 1.0f / settings.height);
    frame.exposure = glm::vec4(settings.exposure, settings.shadowPcfRadius, 0.0f, 0.0f);
    frame.counts = glm::ivec4(static_cast<int>(r.lights.lights.size()), toShaderView(settings.view), 0, 0);
    r.frameUniforms.update(frame);
    r.frameUniforms.bindBase(GL_UNIFORM_BUFFER, LIT_UBO_FRAME);
    r.lightBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_LIGHTS);

    if (shadowsDirty) {
        Profiler::Scope scope(r.profiler, "shadow");
        r.shadow.execute(scene, *r.gpuScene, r.lights, settings, counters);
        r.shadowKey = key;
    }

    r.gbuffer.resize(settings.width, settings.height);
    r.terms.resize(settings.width, settings.height);
    r.post.resize(settings.width, settings.height);
    {
        Profiler::Scope scope(r.profiler, "g-buffer");
        const int before = counters.drawCalls;
        r.gbuffer.execute(scene, *r.gpuScene, counters);
        r.stats.triangles = counters.triangles;
        (void)before;
    }
    r.gbuffer.bindTargets();
    r.shadow.bindMaps();
    {
        Profiler::Scope scope(r.profiler, "lighting");
        r.direct.execute(r.terms, settings);
    }
    // Indirect terms: written by the cone-tracing pass when GI is on; zero otherwise.
    r.terms.clearIndirect();
    {
        Profiler::Scope scope(r.profiler, "post");
        r.terms.bind();
        int shadowLayer = -1;
        for (const ShadowView& v : r.lights.shadows2d)
            if (v.light == settings.shadowDebugLight) shadowLayer = v.layer;
        r.post.composite(settings, r.shadow.maps2d(), shadowLayer);
        r.post.tonemap(settings);
    }
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

bool Renderer::reloadChangedShaders() {
    bool any = false;
    for (Pass* pass : impl_->passes())
        for (gl::Program* program : pass->programs())
            if (program->sourcesChanged()) any |= program->reload(impl_->log);
    if (any) impl_->shadowKey = {};  // a new shadow shader must re-render the maps
    return any;
}

Profiler& Renderer::profiler() { return impl_->profiler; }
const FrameStats& Renderer::stats() const { return impl_->stats; }
Log& Renderer::log() { return impl_->log; }

namespace {
fs::path fromEnvOr(const char* variable, const char* fallback) {
    if (const char* value = std::getenv(variable); value && *value) return fs::path(value);
    return fs::path(fallback);
}
}  // namespace

fs::path defaultShaderRoot() { return fromEnvOr("LIT_SHADER_DIR", LIT_DEFAULT_SHADER_DIR); }
fs::path defaultAssetRoot() { return fromEnvOr("LIT_ASSET_DIR", LIT_DEFAULT_ASSET_DIR); }
fs::path defaultScenePath() { return defaultAssetRoot() / "cornell_box.gltf"; }

}  // namespace lit
