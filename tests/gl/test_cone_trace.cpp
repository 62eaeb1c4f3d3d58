// The cone-tracing pass (L_ID, L_IS) on its own: the radiance volume is filled directly on the
// CPU (and its mips made with glGenerateTextureMipmap, a plain 2×2×2 average, i.e. the
// premultiplied convention cone.glsl expects), and the G-buffer comes from simple scenes drawn
// through GBufferPass. No voxelization, injection or Renderer is involved, so a failure here is
// the tracer's.
#include <shared.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>

#include "GlTestSupport.h"
#include "gi/VoxelVolume.h"
#include "passes/ConeTracePass.h"
#include "passes/FrameUniforms.h"
#include "passes/GBufferPass.h"
#include "passes/LightingTerms.h"
#include "scene/GpuScene.h"
#include "scene/RadicalInverse.h"
#include "scene/SceneBuilder.h"

namespace lit::test {
namespace {

// Premultiplied radiance (rgb = a·L) and opacity of the volume at a voxel centre (world, m).
using RadianceField = std::function<glm::vec4(const glm::vec3& world)>;

// The cube every test traces in: [−1, 1]³ plus VoxelVolume's padding.
const Aabb kTestBounds{glm::vec3(-1.0f), glm::vec3(1.0f)};

struct TraceImages {
    int width = 0, height = 0;
    std::vector<glm::vec4> diffuse, specular;  // L_ID, L_IS, rows bottom-up
    std::vector<float> depth;                  // window-space depth (1 = background)
    glm::mat4 inverseViewProjection{1.0f};

    std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
    bool surface(int x, int y) const { return depth[index(x, y)] < 1.0f; }
    glm::vec3 world(int x, int y) const {
        const glm::vec4 ndc((x + 0.5f) / width * 2.0f - 1.0f, (y + 0.5f) / height * 2.0f - 1.0f,
                            depth[index(x, y)] * 2.0f - 1.0f, 1.0f);
        const glm::vec4 w = inverseViewProjection * ndc;
        return glm::vec3(w) / w.w;
    }
};

// Summary of one term over the pixels that `keep` accepts.
struct TermStats {
    int count = 0;
    glm::vec3 mean{0.0f}, min{1e30f}, max{-1e30f};
};

TermStats statsOf(const TraceImages& images, const std::vector<glm::vec4>& term,
                  const std::function<bool(int, int)>& keep) {
    TermStats s;
    glm::dvec3 sum(0.0);
    for (int y = 0; y < images.height; ++y)
        for (int x = 0; x < images.width; ++x) {
            if (!keep(x, y)) continue;
            const glm::vec3 v(term[images.index(x, y)]);
            sum += glm::dvec3(v);
            s.min = glm::min(s.min, v);
            s.max = glm::max(s.max, v);
            ++s.count;
        }
    if (s.count) s.mean = glm::vec3(sum / double(s.count));
    return s;
}

CameraView lookAt(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up, float aspect = 1.0f) {
    CameraView c;
    c.position = eye;
    c.yfov = 0.8f;
    c.znear = 0.05f;
    c.zfar = 20.0f;
    c.view = glm::lookAt(eye, target, up);
    c.projection = glm::perspective(c.yfov, aspect, c.znear, c.zfar);
    return c;
}

// A scene with one square plane of side `size` at height `y`, normal +Y, one material.
Scene planeScene(float y, float size, const glm::vec3& baseColor, float roughness, float metallic) {
    Scene scene;
    const int material = addMaterial(scene, baseColor, roughness, metallic, "plane");
    addMeshNode(scene, makePlaneMesh("plane", size, material), {0.0f, y, 0.0f});
    return scene;
}

class ConeTrace : public ContextFixture {
protected:
    void SetUp() override {
        ContextFixture::SetUp();
        if (HasFatalFailure()) return;
        const auto shaders = sourceDir() / "shaders";
        gbuffer_ = std::make_unique<GBufferPass>(shaders);
        cone_ = std::make_unique<ConeTracePass>(shaders);
        terms_ = std::make_unique<LightingTerms>();
        volume_ = std::make_unique<VoxelVolume>();
        frameUniforms_ = std::make_unique<gl::Buffer>("frame uniforms", sizeof(gpu::FrameUniforms), nullptr,
                                                      GL_DYNAMIC_STORAGE_BIT);
        settings_.output.width = 96;
        settings_.output.height = 96;
        settings_.gi.voxelResolution = 64;
        // The fast mode's tracer (isotropic mips, unbounded cones): this fixture fills only the
        // isotropic volume (glGenerateTextureMipmap); the accurate mode reads the directional
        // volumes MipmapPass builds, and is tested through the whole pipeline (test_gi_accuracy.cpp).
        settings_.gi.mode = GiMode::Fast;
    }

    void TearDown() override {
        // GL objects go before the context.
        gpuScene_.reset();
        frameUniforms_.reset();
        volume_.reset();
        terms_.reset();
        cone_.reset();
        gbuffer_.reset();
        context_.reset();
    }

    // Allocates the volume around `bounds` and fills level 0 from `field` at voxel centres, then
    // builds the mips with glGenerateTextureMipmap.
    void fillVolume(const RadianceField& field, const Aabb& bounds = kTestBounds) {
        volume_->ensure(settings_.gi.voxelResolution, false, log_);
        volume_->fitTo(bounds);
        const int n = volume_->resolution();
        std::vector<glm::vec4> voxels(static_cast<std::size_t>(n) * n * n);
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const glm::vec3 centre = volume_->minCorner() + (glm::vec3(x, y, z) + 0.5f) * volume_->voxelSize();
                    voxels[(static_cast<std::size_t>(z) * n + y) * n + x] = field(centre);
                }
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTextureSubImage3D(volume_->radiance().id(), 0, 0, 0, 0, n, n, n, GL_RGBA, GL_FLOAT, voxels.data());
        glGenerateTextureMipmap(volume_->radiance().id());
    }

    // Draws `scene` into the G-buffer from `camera` and runs the cone-tracing pass.
    TraceImages trace(const Scene& scene, const CameraView& camera) {
        const int w = settings_.output.width, h = settings_.output.height;
        gpuScene_ = std::make_unique<GpuScene>(scene, log_);
        const gpu::FrameUniforms frame = makeFrameUniforms(camera, settings_, LIT_VIEW_FINAL, 0);
        frameUniforms_->update(frame);
        frameUniforms_->bindBase(GL_UNIFORM_BUFFER, LIT_UBO_FRAME);

        gbuffer_->resize(w, h);
        terms_->resize(w, h);
        DrawCounters counters;
        gbuffer_->execute(scene, *gpuScene_, counters);
        gbuffer_->bindTargets();
        volume_->updateUniforms(settings_, 0);
        cone_->execute(*terms_, *volume_, settings_);

        TraceImages images;
        images.width = w;
        images.height = h;
        images.inverseViewProjection = frame.inverseViewProjection;
        images.diffuse = readRgba(terms_->texture(Term::IndirectDiffuse));
        images.specular = readRgba(terms_->texture(Term::IndirectSpecular));
        images.depth.resize(static_cast<std::size_t>(w) * h);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glGetTextureImage(gbuffer_->depth().id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                          static_cast<GLsizei>(images.depth.size() * sizeof(float)), images.depth.data());
        return images;
    }

    static std::vector<glm::vec4> readRgba(const gl::Texture& texture) {
        std::vector<glm::vec4> pixels(static_cast<std::size_t>(texture.desc().width) * texture.desc().height);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(pixels.size() * sizeof(glm::vec4)),
                          pixels.data());
        return pixels;
    }

    Log log_;
    RenderSettings settings_;
    std::unique_ptr<GBufferPass> gbuffer_;
    std::unique_ptr<ConeTracePass> cone_;
    std::unique_ptr<LightingTerms> terms_;
    std::unique_ptr<VoxelVolume> volume_;
    std::unique_ptr<gl::Buffer> frameUniforms_;
    std::unique_ptr<GpuScene> gpuScene_;
};

RadianceField uniformField(float radiance, float opacity = 1.0f) {
    return [=](const glm::vec3&) { return glm::vec4(glm::vec3(radiance * opacity), opacity); };
}

// A white Lambertian plane (albedo 1, roughness 1, metal 0) seen from above at an angle, with
// part of the image left as background.
Scene furnaceScene() { return planeScene(0.0f, 1.2f, glm::vec3(1.0f), 1.0f, 0.0f); }
CameraView furnaceCamera() { return lookAt({0.0f, 1.2f, 1.6f}, {0.0f, 0.0f, 0.0f}, {0, 1, 0}); }

// White furnace: every cone of a surface inside a uniformly radiant, opaque field L sees L, and
// the diffuse weights integrate the cosine lobe to exactly π, so L_ID = albedo · L = L.
TEST_F(ConeTrace, FurnaceGivesAlbedoTimesRadiance) {
    const float L = 0.5f;
    fillVolume(uniformField(L));
    const TraceImages images = trace(furnaceScene(), furnaceCamera());
    const auto onSurface = [&](int x, int y) { return images.surface(x, y); };
    const TermStats d = statsOf(images, images.diffuse, onSurface);
    ASSERT_GT(d.count, images.width * images.height / 8) << "the plane must cover part of the image";
    // 5 %: the weights sum to π in exact arithmetic; RGBA16F storage of L (±0.05 %) and the
    // sRGB8 G-buffer albedo (1.0 is exact) add far less.
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(d.min[c], L, 0.05f * L) << "channel " << c;
        EXPECT_NEAR(d.max[c], L, 0.05f * L) << "channel " << c;
    }
    // Background pixels are written as exactly 0 (no surface, nothing to light).
    const auto background = [&](int x, int y) { return !images.surface(x, y); };
    const TermStats bd = statsOf(images, images.diffuse, background);
    const TermStats bs = statsOf(images, images.specular, background);
    ASSERT_GT(bd.count, 0) << "the test needs background pixels";
    EXPECT_EQ(bd.max, glm::vec3(0.0f));
    EXPECT_EQ(bs.max, glm::vec3(0.0f));
    // The dielectric's specular reflectance (F0 = 0.04, rough) is small but not zero.
    const TermStats s = statsOf(images, images.specular, onSurface);
    EXPECT_GT(s.mean.g, 0.005f * L);
    EXPECT_LT(s.max.g, 0.5f * L);
}

TEST_F(ConeTrace, FurnaceIsLinearInRadiance) {
    const Scene scene = furnaceScene();
    fillVolume(uniformField(0.0f));
    const TraceImages dark = trace(scene, furnaceCamera());
    fillVolume(uniformField(0.5f));
    const TraceImages once = trace(scene, furnaceCamera());
    fillVolume(uniformField(1.0f));
    const TraceImages twice = trace(scene, furnaceCamera());
    const auto onSurface = [&](int x, int y) { return once.surface(x, y); };
    EXPECT_EQ(statsOf(dark, dark.diffuse, onSurface).max, glm::vec3(0.0f));
    EXPECT_EQ(statsOf(dark, dark.specular, onSurface).max, glm::vec3(0.0f));
    float worst = 0.0f;
    for (int y = 0; y < once.height; ++y)
        for (int x = 0; x < once.width; ++x) {
            if (!onSurface(x, y)) continue;
            const std::size_t i = once.index(x, y);
            worst = std::max(worst, std::abs(twice.diffuse[i].g / (2.0f * once.diffuse[i].g) - 1.0f));
        }
    // 1 %: RGBA16F rounding of the stored values and of the output.
    EXPECT_LT(worst, 0.01f) << "L_ID(2L) / (2 L_ID(L)) − 1, worst pixel";
}

// Indirect intensity and the material's ambient occlusion (G-buffer albedo.a) scale both terms.
TEST_F(ConeTrace, IntensityAndOcclusionScaleBothTerms) {
    const float L = 0.5f;
    fillVolume(uniformField(L));
    Scene scene = furnaceScene();
    const TraceImages plain = trace(scene, furnaceCamera());
    // A 1×1 occlusion texture of 128/255: occlusion = 1 + strength·(0.502 − 1) = 0.502.
    Image image;
    image.name = "occlusion";
    image.width = image.height = 1;
    image.rgba = {128, 128, 128, 255};
    scene.images.push_back(image);
    Texture texture;
    texture.image = 0;
    scene.textures.push_back(texture);
    scene.materials[0].occlusionTexture = 0;
    ++scene.materialRevision;
    settings_.gi.indirectIntensity = 0.25f;
    const TraceImages scaled = trace(scene, furnaceCamera());
    const float expected = 0.25f * 128.0f / 255.0f;
    const auto onSurface = [&](int x, int y) { return plain.surface(x, y); };
    const TermStats d0 = statsOf(plain, plain.diffuse, onSurface), d1 = statsOf(scaled, scaled.diffuse, onSurface);
    const TermStats s0 = statsOf(plain, plain.specular, onSurface), s1 = statsOf(scaled, scaled.specular, onSurface);
    ASSERT_GT(d0.mean.g, 0.0f);
    ASSERT_GT(s0.mean.g, 0.0f);
    // 1 %: the occlusion is stored in 8 bits and both outputs in RGBA16F.
    EXPECT_NEAR(d1.mean.g / d0.mean.g, expected, 0.01f * expected);
    EXPECT_NEAR(s1.mean.g / s0.mean.g, expected, 0.01f * expected);
}

// A term that is switched off and not shown is written as 0 without being traced; showing it in
// its debug view traces it even when it is off in the final image.
TEST_F(ConeTrace, SwitchedOffTermsAreZero) {
    fillVolume(uniformField(0.5f));
    const auto onSurface = [](const TraceImages& images) { return [&](int x, int y) { return images.surface(x, y); }; };
    settings_.terms.indirectSpecular = false;
    const TraceImages noSpecular = trace(furnaceScene(), furnaceCamera());
    EXPECT_GT(statsOf(noSpecular, noSpecular.diffuse, onSurface(noSpecular)).min.g, 0.0f);
    EXPECT_EQ(statsOf(noSpecular, noSpecular.specular, onSurface(noSpecular)).max, glm::vec3(0.0f));
    settings_.debug.view = View::IndirectSpecular;
    const TraceImages shown = trace(furnaceScene(), furnaceCamera());
    EXPECT_GT(statsOf(shown, shown.specular, onSurface(shown)).min.g, 0.0f);
    EXPECT_EQ(statsOf(shown, shown.diffuse, onSurface(shown)).max, glm::vec3(0.0f)) << "not shown, not traced";
    settings_.debug.view = View::Final;
    settings_.gi.enabled = false;
    const TraceImages off = trace(furnaceScene(), furnaceCamera());
    EXPECT_EQ(statsOf(off, off.diffuse, onSurface(off)).max, glm::vec3(0.0f));
    EXPECT_EQ(statsOf(off, off.specular, onSurface(off)).max, glm::vec3(0.0f));
}

// A white metal mirror in the same furnace reflects L: F = 1, G ≈ 1 and the GGX sample weight
// F·G·(v·h)/((n·h)(n·v)) is ≈ 1 for a sharp lobe.
TEST_F(ConeTrace, MirrorFurnaceReflectsRadiance) {
    const float L = 0.5f;
    fillVolume(uniformField(L));
    const TraceImages images = trace(planeScene(0.0f, 1.2f, glm::vec3(1.0f), 0.05f, 1.0f), furnaceCamera());
    const auto onSurface = [&](int x, int y) { return images.surface(x, y); };
    const TermStats s = statsOf(images, images.specular, onSurface);
    ASSERT_GT(s.count, 0);
    EXPECT_NEAR(s.min.g, L, 0.05f * L);
    EXPECT_NEAR(s.max.g, L, 0.05f * L);
    // A pure metal has no diffuse albedo.
    EXPECT_EQ(statsOf(images, images.diffuse, onSurface).max, glm::vec3(0.0f));
}

// A rough white metal in the furnace: the split-sum estimator has no weight noise, so L_IS is
// E·L everywhere, E being the lobe's directional albedo (0.79-0.9 for F0 = 1 and roughness 0.6
// with height-correlated Smith G: single scattering loses the rest), and neighbouring pixels
// agree even with 2 samples.
TEST_F(ConeTrace, RoughMetalFurnaceIsNoiseFree) {
    const float L = 0.5f;
    fillVolume(uniformField(L));
    const TraceImages images = trace(planeScene(0.0f, 1.2f, glm::vec3(1.0f), 0.6f, 1.0f), furnaceCamera());
    const auto onSurface = [&](int x, int y) { return images.surface(x, y); };
    const TermStats s = statsOf(images, images.specular, onSurface);
    ASSERT_GT(s.count, 0);
    EXPECT_GT(s.min.g, 0.75f * L);
    EXPECT_LT(s.max.g, 0.95f * L);
    float worst = 0.0f;
    for (int y = 0; y < images.height; ++y)
        for (int x = 0; x + 1 < images.width; ++x)
            if (onSurface(x, y) && onSurface(x + 1, y))
                worst = std::max(worst, std::abs(images.specular[images.index(x + 1, y)].g -
                                                  images.specular[images.index(x, y)].g));
    EXPECT_LT(worst, 0.01f * L) << "largest jump between horizontal neighbours";
}

// CPU reference for one texel of the specular albedo table: the same estimator as
// specular_albedo.frag.glsl (GGX sampling, height-correlated Smith G), with many more samples.
glm::vec2 specularAlbedoReference(float NdotV, float roughness) {
    const float r = std::clamp(roughness, 0.03f, 1.0f);
    const float alpha = r * r, a2 = alpha * alpha;
    const glm::vec3 v(std::sqrt(1.0f - NdotV * NdotV), 0.0f, NdotV);
    const int samples = 1 << 16;
    glm::dvec2 sum(0.0);
    for (int k = 0; k < samples; ++k) {
        const float ux = (k + 0.5f) / samples;
        const float uy = radicalInverse(static_cast<std::uint32_t>(k));
        const float cos2 = (1.0f - ux) / (1.0f + (a2 - 1.0f) * ux);
        const float sinTheta = std::sqrt(std::max(1.0f - cos2, 0.0f)), phi = 2.0f * glm::pi<float>() * uy;
        const glm::vec3 h(sinTheta * std::cos(phi), sinTheta * std::sin(phi), std::sqrt(cos2));
        const float VdotH = glm::dot(v, h);
        const glm::vec3 l = 2.0f * VdotH * h - v;
        if (VdotH <= 0.0f || l.z <= 0.0f) continue;
        const float lambdaV = l.z * std::sqrt(NdotV * NdotV * (1.0f - a2) + a2);
        const float lambdaL = NdotV * std::sqrt(l.z * l.z * (1.0f - a2) + a2);
        const float g = 2.0f * l.z * NdotV / (lambdaV + lambdaL);
        const float w = g * VdotH / (h.z * NdotV);
        const float fc = std::pow(1.0f - VdotH, 5.0f);
        sum += glm::dvec2(w * (1.0f - fc), w * fc);
    }
    return glm::vec2(sum / double(samples));
}

TEST_F(ConeTrace, SpecularAlbedoTableMatchesCpuIntegration) {
    constexpr int size = LIT_SPECULAR_ALBEDO_SIZE;
    const gl::Texture& table = cone_->specularAlbedoTable();
    ASSERT_EQ(table.desc().width, size);
    std::vector<glm::vec2> texels(size * size);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(table.id(), 0, GL_RG, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(glm::vec2)),
                      texels.data());
    for (const glm::ivec2 t : {glm::ivec2(0, 0), glm::ivec2(3, 31), glm::ivec2(16, 16), glm::ivec2(31, 8),
                               glm::ivec2(31, 31), glm::ivec2(8, 24)}) {
        const float NdotV = (t.x + 0.5f) / size, roughness = (t.y + 0.5f) / size;
        const glm::vec2 expected = specularAlbedoReference(NdotV, roughness);
        const glm::vec2 got = texels[t.y * size + t.x];
        // 1 % of the albedo + RG16F rounding: the GPU integrates with 1024 samples, the reference 65536.
        EXPECT_NEAR(got.x, expected.x, 0.01f * (expected.x + expected.y) + 1e-3f) << "A at n·v " << NdotV << ", roughness " << roughness;
        EXPECT_NEAR(got.y, expected.y, 0.01f * (expected.x + expected.y) + 1e-3f) << "B at n·v " << NdotV << ", roughness " << roughness;
    }
    // Energy: a white (F0 = 1) lobe reflects at most what arrives, and a mirror all of it.
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const glm::vec2 ab = texels[y * size + x];
            EXPECT_LE(ab.x + ab.y, 1.005f) << "texel " << x << ", " << y;
        }
    EXPECT_NEAR(texels[size - 1].x + texels[size - 1].y, 1.0f, 0.005f) << "mirror at normal incidence";
}

// A mirror on the floor, looked at from the front; a red radiant block stands behind it on the
// left (x < 0, z < −0.6) and the rest of the volume is empty. The left half of the mirror
// reflects the block; the right half reflects empty space.
TEST_F(ConeTrace, MirrorReflectsRedRegionOnlyWhereItLooks) {
    const float L = 0.8f;
    fillVolume([&](const glm::vec3& p) {
        return (p.x < 0.0f && p.z < -0.6f) ? glm::vec4(L, 0.0f, 0.0f, 1.0f) : glm::vec4(0.0f);
    });
    const Scene scene = planeScene(-0.5f, 1.0f, glm::vec3(1.0f), 0.05f, 1.0f);
    const TraceImages images = trace(scene, lookAt({0.0f, 0.5f, 1.5f}, {0.0f, -0.5f, 0.0f}, {0, 1, 0}));
    // Pixels whose mirror point is well inside each half (0.1 m from the boundary at x = 0).
    const auto left = [&](int x, int y) { return images.surface(x, y) && images.world(x, y).x < -0.1f; };
    const auto right = [&](int x, int y) { return images.surface(x, y) && images.world(x, y).x > 0.1f; };
    const TermStats l = statsOf(images, images.specular, left);
    const TermStats r = statsOf(images, images.specular, right);
    ASSERT_GT(l.count, 100);
    ASSERT_GT(r.count, 100);
    // 10 %: a white metal's F = 1 and G ≈ 1; the cone meets the block's face through one voxel of
    // trilinear ramp, which the premultiplied accumulation keeps at full radiance.
    EXPECT_NEAR(l.mean.r, L, 0.1f * L);
    EXPECT_GT(l.min.r, 0.7f * L) << "every left pixel sees the block";
    EXPECT_LT(l.max.g, 0.01f * L);
    EXPECT_LT(l.max.b, 0.01f * L);
    EXPECT_LT(r.max.r, 0.02f * L) << "the right half sees empty space";
}

// Radiance only in the upper half (y > 0): a surface below it facing up sees it, the same
// surface seen from below (its back face, shaded with the normal flipped to −Y) sees nothing.
TEST_F(ConeTrace, DiffuseDependsOnNormalDirection) {
    const float L = 0.5f;
    fillVolume([&](const glm::vec3& p) { return p.y > 0.0f ? glm::vec4(glm::vec3(L), 1.0f) : glm::vec4(0.0f); });
    const Scene scene = planeScene(-0.25f, 0.8f, glm::vec3(1.0f), 1.0f, 0.0f);
    const TraceImages up = trace(scene, lookAt({0.0f, 1.0f, 1.0f}, {0.0f, -0.25f, 0.0f}, {0, 1, 0}));
    const TraceImages down = trace(scene, lookAt({0.0f, -1.5f, 1.0f}, {0.0f, -0.25f, 0.0f}, {0, 1, 0}));
    const TermStats u = statsOf(up, up.diffuse, [&](int x, int y) { return up.surface(x, y); });
    const TermStats d = statsOf(down, down.diffuse, [&](int x, int y) { return down.surface(x, y); });
    ASSERT_GT(u.count, 100);
    ASSERT_GT(d.count, 100);
    // Exactly, the up-facing plane would get ≈ 0.97 L: only rays within ~10° of the horizon leave
    // the 2.1 m volume through its sides before they reach y = 0. The five side cones, 60° from
    // the normal, cross the radiant half for only ~0.9 m before their axis leaves the volume, with
    // footprints (mip 4-5, 0.5-1 m voxels) half in the empty half, so they end partly transparent
    // and the tracer gives 0.72-0.78 L (docs/GI.md, "Known limits"). Reading the premultiplied
    // volume as straight colour would give 0.43-0.48 L.
    EXPECT_GT(u.min.g, 0.65f * L);
    EXPECT_LT(u.max.g, 1.0f * L);
    // Facing away, the cones see only empty space, apart from the coarsest mips (one or two
    // voxels for the whole volume) that average the two halves: ~2 % of L.
    EXPECT_LT(d.max.g, 0.05f * L) << "the down-facing side";
    EXPECT_GT(u.mean.g, 20.0f * d.mean.g);
}

// The opacity correction makes a half-transparent slab block the same share of a cone whatever
// the step scale: a 4× shorter step samples each voxel 4× as often. Measured: with the
// correction (and midpoint sampling) step scales 0.125..1 agree within 3 %; without it, 0.25
// gives 2.4× the result of 1.0.
TEST_F(ConeTrace, ResultDoesNotDependOnStepScale) {
    const float L = 0.5f;
    const float opacity = 0.3f;  // per voxel
    fillVolume([&](const glm::vec3& p) {
        const bool slab = p.y > 0.0f && p.y < 0.25f;
        return slab ? glm::vec4(glm::vec3(opacity * L), opacity) : glm::vec4(0.0f);
    });
    const Scene scene = planeScene(-0.25f, 0.8f, glm::vec3(1.0f), 1.0f, 0.0f);
    const CameraView camera = lookAt({0.0f, 1.0f, 1.0f}, {0.0f, -0.25f, 0.0f}, {0, 1, 0});
    settings_.gi.coneStepScale = 0.25f;
    const TraceImages fine = trace(scene, camera);
    settings_.gi.coneStepScale = 1.0f;
    const TraceImages coarse = trace(scene, camera);
    const auto onSurface = [&](int x, int y) { return fine.surface(x, y); };
    const float a = statsOf(fine, fine.diffuse, onSurface).mean.g;
    const float b = statsOf(coarse, coarse.diffuse, onSurface).mean.g;
    ASSERT_GT(a, 0.1f * L) << "the slab must be visible";
    ASSERT_LT(a, 0.9f * L) << "the slab must be see-through, or every step scale gives L";
    EXPECT_NEAR(b / a, 1.0f, 0.05f) << "step 0.25: " << a << ", step 1.0: " << b;
}

// Timings (docs/PERFORMANCE.md, "What each benchmark prints"; not a test: run with
// --gtest_also_run_disabled_tests). The Cornell
// box G-buffer; the volume is filled with the world boxes of its meshes (walls and blocks opaque,
// radiance 0.3), a stand-in for a voxelized scene with the same cone lengths. Once with the
// box's materials (roughness 0.9: wide specular cones), once with every surface a mirror
// (roughness 0.05: the narrowest cones, half-voxel steps), the worst case for L_IS.
TEST_F(ConeTrace, DISABLED_Benchmark) {
    Scene scene = loadGltf(sourceDir() / "assets" / "cornell_box.gltf", log_);
    scene.updateWorldTransforms();
    std::vector<Aabb> boxes;
    for (const Node& node : scene.nodes)
        if (node.mesh >= 0)
            for (const Primitive& p : scene.meshes[node.mesh].primitives) boxes.push_back(p.bounds.transformed(node.world));
    const CameraView camera = sceneCameraView(scene, 0, 1.0f);
    for (const float roughness : {0.9f, 0.05f}) {
        for (Material& m : scene.materials) m.roughness = roughness;
        for (const int resolution : {64, 128}) {
            for (const int size : {128, 256}) {
                settings_.gi.voxelResolution = resolution;
                settings_.output.width = size;
                settings_.output.height = size;
                const float margin = scene.worldBounds().size().x / static_cast<float>(resolution);  // ~1 voxel
                fillVolume(
                    [&](const glm::vec3& p) {
                        for (const Aabb& b : boxes)
                            if (glm::all(glm::greaterThanEqual(p, b.min - margin)) &&
                                glm::all(glm::lessThanEqual(p, b.max + margin)))
                                return glm::vec4(glm::vec3(0.3f), 1.0f);
                        return glm::vec4(0.0f);
                    },
                    scene.worldBounds());
                trace(scene, camera);  // warm up: llvmpipe compiles the shader variant on first use
                glFinish();
                const int frames = 3;
                double total = 0.0;
                for (int i = 0; i < frames; ++i) {
                    const auto start = std::chrono::steady_clock::now();
                    volume_->updateUniforms(settings_, i);
                    cone_->execute(*terms_, *volume_, settings_);
                    glFinish();
                    total += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
                }
                std::printf("cone trace, roughness %.2f, %d³ volume, %dx%d image, %d specular samples: %.1f ms\n",
                            roughness, resolution, size, size, settings_.indirect.specularSamples, total / frames);
            }
        }
    }
}

}  // namespace
}  // namespace lit::test
