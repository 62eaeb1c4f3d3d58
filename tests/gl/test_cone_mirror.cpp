// tracedCones() (renderer/scene/OverlayShapes.cpp) repeats in C++ how cone.glsl chooses its cones.
// This runs cone.glsl's own functions (tangentFrame, the shared diffuse table, specularLobeCone with
// specularSample, sampleGgxHalfVector and ggxSampleWeight, specularConeAperture) in a compute
// shader for the same surfaces and compares: if the shader's sampling changes, the debug view's
// cones must follow.
#include "GlTestSupport.h"

#include "gl/Objects.h"
#include "gl/Shader.h"
#include "passes/ConeTracePass.h"
#include "scene/OverlayShapes.h"

#include <shared.h>

#include <algorithm>
#include <fstream>

namespace lit::test {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxSpecular = LIT_SPECULAR_MAX_SAMPLES;
constexpr int kResults = LIT_DIFFUSE_CONE_COUNT + kMaxSpecular + 1;

// Results: [0, 6) diffuse directions (xyz) and weights (w); [6, 6 + count) specular l (xyz) and
// weight (w, 0 = dropped); [14] x the specular aperture, y whether rough specular reuses the
// diffuse cones (1) or marches its own (0).
constexpr const char* kShader = R"(#version 450 core
layout(local_size_x = 1) in;
#include "cone.glsl"
layout(std430, binding = 0) buffer Results { vec4 result[]; };
uniform vec3 uNormal;
uniform vec3 uView;
uniform float uRoughness;
uniform int uCount;
uniform vec2 uFragCoord;
uniform float uDiffuseAperture;
void main() {
    mat3 basis = tangentFrame(uNormal);
    for (int i = 0; i < kDiffuseConeCount; ++i)
        result[i] = vec4(basis * kDiffuseConeDirections[i], kDiffuseConeWeights[i]);
    float alpha = alphaFromRoughness(uRoughness);
    for (int k = 0; k < uCount; ++k) {
        vec3 l;
        float w = specularLobeCone(k, uCount, uNormal, uView, basis, alpha, uFragCoord, 0, l);
        result[kDiffuseConeCount + k] = vec4(l, w);
    }
    result[kDiffuseConeCount + LIT_SPECULAR_MAX_SAMPLES] =
        vec4(specularConeAperture(alpha, uCount), specularCanReuseDiffuseCones(alpha, uDiffuseAperture) ? 1.0 : 0.0,
             0.0, 0.0);
}
)";

class ConeMirror : public ContextFixture {};

// Builds a compute program from `source`, written to a temporary file outside shaders/: its
// #include "cone.glsl" (and the others) resolve in shaders/include as the renderer's own do.
gl::Program testComputeProgram(const std::string& name, const char* source) {
    const fs::path dir = fs::temp_directory_path() / ("lit_cone_mirror_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path file = dir / "test.comp.glsl";
    std::ofstream(file) << source;
    gl::Program program(sourceDir() / "shaders", name, {{GL_COMPUTE_SHADER, file.string()}});
    fs::remove_all(dir);
    return program;
}

TEST_F(ConeMirror, TracedConesMatchTheShader) {
    if (HasFatalFailure()) return;
    gl::Program program = testComputeProgram("cone mirror", kShader);
    gl::Buffer results("cone mirror results", kResults * sizeof(glm::vec4), nullptr, GL_DYNAMIC_STORAGE_BIT);

    struct Case {
        glm::vec3 normal, view;
        float roughness;
        int count;
        glm::ivec2 glPixel;
    };
    const Case cases[] = {
        {{0, 1, 0}, {0.3f, 0.8f, 0.5f}, 0.0f, 2, {37, 81}},
        {{0, 1, 0}, {0.3f, 0.8f, 0.5f}, 0.5f, 2, {38, 81}},
        {{1, 0, 0}, {0.6f, 0.2f, -0.7f}, 0.3f, 8, {120, 5}},
        {{0, 0, -1}, {0.2f, 0.1f, -0.9f}, 0.8f, 4, {0, 0}},  // n.z < 0: the other branch of tangentFrame
        {glm::normalize(glm::vec3(-0.4f, 0.5f, 0.3f)), {0.1f, 0.9f, 0.3f}, 0.9f, 8, {255, 254}},
        {{0, 1, 0}, {0.95f, 0.05f, 0.0f}, 1.0f, 3, {17, 200}},  // grazing: samples fall below the horizon
        // One cone: the lobe's dominant direction, smooth, rough (reuses the diffuse cones) and grazing.
        {{0, 1, 0}, {0.3f, 0.8f, 0.5f}, 0.35f, 1, {37, 81}},
        {glm::normalize(glm::vec3(-0.4f, 0.5f, 0.3f)), {0.1f, 0.9f, 0.3f}, 0.9f, 1, {255, 254}},
        {{0, 1, 0}, {0.95f, 0.05f, 0.0f}, 0.5f, 1, {17, 200}},
        {{0, 1, 0}, {0.3f, 0.8f, 0.5f}, 0.6f, 1, {37, 81}},  // one cone wider than a diffuse one, still marched
    };
    for (const Case& c : cases) {
        const glm::vec3 n = glm::normalize(c.normal), v = glm::normalize(c.view);
        ASSERT_GE(glm::dot(n, v), 0.0f) << "tracedCones bends back-facing normals; keep the cases front-facing";
        const glm::vec2 fragCoord = glm::vec2(c.glPixel) + 0.5f;
        glProgramUniform3fv(program.id(), program.location("uNormal"), 1, &n.x);
        glProgramUniform3fv(program.id(), program.location("uView"), 1, &v.x);
        glProgramUniform1f(program.id(), program.location("uRoughness"), c.roughness);
        glProgramUniform1i(program.id(), program.location("uCount"), c.count);
        glProgramUniform2fv(program.id(), program.location("uFragCoord"), 1, &fragCoord.x);
        const RenderSettings defaults;
        glProgramUniform1f(program.id(), program.location("uDiffuseAperture"), defaults.gi.diffuseConeAperture);
        const std::vector<glm::vec4> zero(kResults, glm::vec4(0.0f));
        results.update(0, zero.size() * sizeof(glm::vec4), zero.data());
        results.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
        program.use();
        glDispatchCompute(1, 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::vector<glm::vec4> gpu(kResults);
        glGetNamedBufferSubData(results.id(), 0, kResults * sizeof(glm::vec4), gpu.data());

        SurfaceSample s;
        s.position = glm::vec3(0.0f);
        s.normal = n;
        s.roughness = c.roughness;
        s.glPixel = c.glPixel;
        RenderSettings settings;
        settings.gi.mode = GiMode::Fast;  // the fixed six-cone set the shader above traces
        settings.indirect.specularSamples = c.count;
        const std::vector<TracedCone> cones = tracedCones(s, v * 3.0f, settings);

        std::vector<glm::vec4> specular;  // the shader's kept samples, in order
        float weightSum = 0.0f;
        for (int k = 0; k < c.count; ++k) {
            const glm::vec4 r = gpu[static_cast<std::size_t>(LIT_DIFFUSE_CONE_COUNT + k)];
            if (r.w > 0.0f) specular.push_back(r), weightSum += r.w;
        }
        const std::size_t expectedCones = LIT_DIFFUSE_CONE_COUNT + std::max<std::size_t>(specular.size(), 1);
        ASSERT_EQ(cones.size(), expectedCones) << "roughness " << c.roughness << ", " << c.count << " samples";
        for (int i = 0; i < LIT_DIFFUSE_CONE_COUNT; ++i) {
            const TracedCone& cone = cones[static_cast<std::size_t>(i)];
            EXPECT_FALSE(cone.specular);
            EXPECT_LT(glm::length(cone.direction - glm::vec3(gpu[static_cast<std::size_t>(i)])), 1e-5f) << "diffuse " << i;
            EXPECT_FLOAT_EQ(cone.weight, gpu[static_cast<std::size_t>(i)].w);
        }
        const float aperture = gpu[LIT_DIFFUSE_CONE_COUNT + kMaxSpecular].x;
        const bool reuses = gpu[LIT_DIFFUSE_CONE_COUNT + kMaxSpecular].y > 0.5f;
        for (std::size_t k = LIT_DIFFUSE_CONE_COUNT; k < cones.size(); ++k)
            EXPECT_EQ(cones[k].marched, !reuses) << "roughness " << c.roughness << ", " << c.count << " samples";
        if (specular.empty()) {
            // All below the horizon: the shader traces the mirror direction.
            EXPECT_LT(glm::length(cones.back().direction - glm::reflect(-v, n)), 1e-5f);
            EXPECT_NEAR(cones.back().aperture, aperture, 1e-6f);
        }
        for (std::size_t k = 0; k < specular.size(); ++k) {
            const TracedCone& cone = cones[LIT_DIFFUSE_CONE_COUNT + k];
            EXPECT_TRUE(cone.specular);
            // Loose enough for FMA and transcendental differences of the GPU's float math.
            EXPECT_LT(glm::length(cone.direction - glm::normalize(glm::vec3(specular[k]))), 1e-3f)
                << "specular " << k << ", roughness " << c.roughness << ", pixel " << c.glPixel.x << "," << c.glPixel.y;
            EXPECT_NEAR(cone.weight, specular[k].w / weightSum, 1e-3f);
            EXPECT_NEAR(cone.aperture, aperture, 1e-5f);
        }
    }
}

// The accurate mode (footprint-bounded cones) traces a stratified set per low-resolution texel
// (cone_strata.glsl); the cone directions view must draw the set of the picked pixel's texel.
// The shader computes, for each pixel, the set the resolve's fallback computes for it
// (coneSetIndex((pixel − jitter) / scale), jitter 0) and that set's six world directions.
constexpr int kStrataPixels = 24;
constexpr const char* kStrataShader = R"(#version 450 core
layout(local_size_x = 1) in;
#include "cone.glsl"
#include "cone_strata.glsl"
layout(std430, binding = 0) buffer Results { vec4 result[]; };
uniform vec3 uNormal;
uniform int uScale;
uniform ivec2 uPixels[24];
void main() {
    mat3 basis = tangentFrame(uNormal);
    for (int p = 0; p < 24; ++p) {
        int set = coneSetIndex(uPixels[p] / uScale);
        for (int i = 0; i < kDiffuseConeCount; ++i)
            result[p * kDiffuseConeCount + i] = vec4(basis * stratifiedDiffuseConeDirection(i, set), float(set));
    }
}
)";

TEST_F(ConeMirror, AccurateModeTracedConesAreThePixelsStratifiedSet) {
    if (HasFatalFailure()) return;
    gl::Program program = testComputeProgram("cone strata mirror", kStrataShader);
    constexpr std::size_t kCount = std::size_t(kStrataPixels) * LIT_DIFFUSE_CONE_COUNT;
    gl::Buffer results("cone strata mirror results", kCount * sizeof(glm::vec4), nullptr, GL_DYNAMIC_STORAGE_BIT);

    // A 4 × 4 block (every set once at scale 1), then pixels far out and on block edges.
    std::vector<glm::ivec2> pixels;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) pixels.push_back({x, y});
    for (const glm::ivec2 p : {glm::ivec2(37, 81), glm::ivec2(38, 81), glm::ivec2(120, 5), glm::ivec2(255, 254),
                               glm::ivec2(7, 8), glm::ivec2(1279, 719), glm::ivec2(17, 200), glm::ivec2(64, 3)})
        pixels.push_back(p);
    ASSERT_EQ(pixels.size(), std::size_t(kStrataPixels));
    glProgramUniform2iv(program.id(), program.location("uPixels[0]"), kStrataPixels, &pixels[0].x);

    for (const int scale : {1, 2, 4})
        for (const glm::vec3 normal : {glm::vec3(0, 1, 0), glm::vec3(0, 0, -1), glm::normalize(glm::vec3(-0.4f, 0.5f, 0.3f))}) {
            RenderSettings settings;
            settings.gi.coneFootprintPerHeight = kAccurateGiFootprint;
            settings.indirect.scale = scale;
            ASSERT_EQ(ConeTracePass::indirectScale(settings), scale);
            glProgramUniform3fv(program.id(), program.location("uNormal"), 1, &normal.x);
            glProgramUniform1i(program.id(), program.location("uScale"), scale);
            const std::vector<glm::vec4> zero(kCount, glm::vec4(-1.0f));
            results.update(0, zero.size() * sizeof(glm::vec4), zero.data());
            results.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
            program.use();
            glDispatchCompute(1, 1, 1);
            glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
            std::vector<glm::vec4> gpu(kCount);
            glGetNamedBufferSubData(results.id(), 0, GLsizeiptr(kCount * sizeof(glm::vec4)), gpu.data());

            std::vector<int> setsOfBlock;
            for (std::size_t p = 0; p < pixels.size(); ++p) {
                SurfaceSample s;
                s.normal = normal;
                s.glPixel = pixels[p];
                s.voxelSize = 0.05f;
                s.volumeSide = 3.2f;
                // Seen from straight above the surface: no shading-normal bend.
                const std::vector<TracedCone> cones = tracedCones(s, normal * 3.0f, settings);
                ASSERT_GE(cones.size(), std::size_t(LIT_DIFFUSE_CONE_COUNT));
                const int gpuSet = static_cast<int>(gpu[p * LIT_DIFFUSE_CONE_COUNT].w);
                EXPECT_EQ(coneSetOfPixel(pixels[p], settings), gpuSet) << "pixel " << pixels[p].x << "," << pixels[p].y;
                if (p < 16) setsOfBlock.push_back(gpuSet);
                for (int i = 0; i < LIT_DIFFUSE_CONE_COUNT; ++i) {
                    const TracedCone& cone = cones[static_cast<std::size_t>(i)];
                    const glm::vec4 g = gpu[p * LIT_DIFFUSE_CONE_COUNT + std::size_t(i)];
                    EXPECT_FALSE(cone.specular);
                    EXPECT_EQ(cone.coneSet, gpuSet);
                    EXPECT_LT(glm::length(cone.direction - glm::vec3(g)), 1e-4f)
                        << "cone " << i << ", pixel " << pixels[p].x << "," << pixels[p].y << ", scale " << scale;
                    // Bounded from √3 voxels above the surface, rising at n·d.
                    EXPECT_FLOAT_EQ(cone.footprintPerHeight, kAccurateGiFootprint);
                    EXPECT_NEAR(cone.heightPerDistance, glm::dot(cone.direction, normal), 1e-5f);
                }
            }
            // At scale 1 the 4 × 4 block holds all 16 sets (the pattern the strata filter averages).
            if (scale == 1) {
                std::sort(setsOfBlock.begin(), setsOfBlock.end());
                EXPECT_TRUE(std::adjacent_find(setsOfBlock.begin(), setsOfBlock.end()) == setsOfBlock.end());
                EXPECT_EQ(setsOfBlock.size(), std::size_t(LIT_CONE_STRATA * LIT_CONE_STRATA));
            }
        }
    // The fast mode keeps the fixed set (TracedConesMatchTheShader checks its directions).
    SurfaceSample s;
    s.glPixel = {5, 6};
    RenderSettings fast;
    fast.gi.mode = GiMode::Fast;
    for (const TracedCone& cone : tracedCones(s, {0, 3, 0}, fast)) {
        EXPECT_EQ(cone.coneSet, -1);
        EXPECT_EQ(cone.footprintPerHeight, 0.0f);
    }
}

// The bounce pass of the accurate mode gives each voxel a stratified set (cone_strata.glsl,
// voxelConeSetIndex, used by bounce.comp.glsl) by its coordinates along its surface: every 4 × 4
// patch of voxels of a floor, wall or slanted surface must hold all 16 sets once, whatever the
// normal's sign, so that the mip levels the pixels' cones read average every direction. A hash
// of the coordinates, or a pattern over the wrong axes (a wall's voxels all in one set), fails.
constexpr int kPatch = 8;
constexpr const char* kVoxelSetShader = R"(#version 450 core
layout(local_size_x = 8, local_size_y = 8) in;
#include "cone.glsl"
#include "cone_strata.glsl"
layout(std430, binding = 0) buffer Results { int result[]; };
uniform vec3 uNormal;
uniform ivec3 uOrigin;
uniform ivec3 uU;  // unit steps of the patch's two axes in voxels
uniform ivec3 uV;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    result[p.y * 8 + p.x] = voxelConeSetIndex(uOrigin + p.x * uU + p.y * uV, uNormal);
}
)";

TEST_F(ConeMirror, BounceVoxelSetsCoverEverySetOnEachSurfacePatch) {
    if (HasFatalFailure()) return;
    gl::Program program = testComputeProgram("voxel cone sets", kVoxelSetShader);
    constexpr std::size_t kCount = std::size_t(kPatch) * kPatch;
    gl::Buffer results("voxel cone sets", kCount * sizeof(int), nullptr, GL_DYNAMIC_STORAGE_BIT);
    struct Case {
        glm::vec3 normal;
        glm::ivec3 u, v;  // the voxel axes along the surface
    };
    const Case cases[] = {
        {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},   // floor
        {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},  // ceiling
        {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},   // walls
        {{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},
        {glm::normalize(glm::vec3(0.3f, 0.9f, -0.2f)), {1, 0, 0}, {0, 0, 1}},  // a slope, mostly up
    };
    for (const Case& c : cases)
        for (const glm::ivec3 origin : {glm::ivec3(0, 0, 0), glm::ivec3(13, 7, 42), glm::ivec3(63, 1, 2)}) {
            glProgramUniform3fv(program.id(), program.location("uNormal"), 1, &c.normal.x);
            glProgramUniform3iv(program.id(), program.location("uOrigin"), 1, &origin.x);
            glProgramUniform3iv(program.id(), program.location("uU"), 1, &c.u.x);
            glProgramUniform3iv(program.id(), program.location("uV"), 1, &c.v.x);
            const std::vector<int> fill(kCount, -1);
            results.update(0, kCount * sizeof(int), fill.data());
            results.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
            program.use();
            glDispatchCompute(1, 1, 1);
            glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
            std::vector<int> sets(kCount);
            glGetNamedBufferSubData(results.id(), 0, GLsizeiptr(kCount * sizeof(int)), sets.data());
            // Every 4 × 4 window of the 8 × 8 patch (aligned or not).
            for (int wy = 0; wy + LIT_CONE_STRATA <= kPatch; ++wy)
                for (int wx = 0; wx + LIT_CONE_STRATA <= kPatch; ++wx) {
                    std::vector<int> seen(LIT_CONE_STRATA * LIT_CONE_STRATA, 0);
                    for (int y = wy; y < wy + LIT_CONE_STRATA; ++y)
                        for (int x = wx; x < wx + LIT_CONE_STRATA; ++x) {
                            const int set = sets[static_cast<std::size_t>(y * kPatch + x)];
                            ASSERT_GE(set, 0);
                            ASSERT_LT(set, LIT_CONE_STRATA * LIT_CONE_STRATA);
                            ++seen[static_cast<std::size_t>(set)];
                        }
                    for (std::size_t k = 0; k < seen.size(); ++k)
                        EXPECT_EQ(seen[k], 1) << "set " << k << ", normal " << c.normal.x << "," << c.normal.y << ","
                                              << c.normal.z << ", window " << wx << "," << wy;
                }
        }
}

}  // namespace
}  // namespace lit::test
