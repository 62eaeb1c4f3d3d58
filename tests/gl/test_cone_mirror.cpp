// tracedCones() (renderer/scene/OverlayShapes.cpp) repeats in C++ how cone.glsl chooses its cones.
// This runs cone.glsl's own functions (tangentFrame, the shared diffuse table, specularSample,
// sampleGgxHalfVector, ggxSampleWeight, specularConeAperture) in a compute shader for the same
// surfaces and compares: if the shader's sampling changes, the debug view's cones must follow.
#include "GlTestSupport.h"

#include "gl/Objects.h"
#include "gl/Shader.h"
#include "scene/OverlayShapes.h"

#include <shared.h>

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
        vec3 h = basis * sampleGgxHalfVector(specularSample(k, uCount, uFragCoord, 0), alpha);
        vec3 l;
        float w = ggxSampleWeight(uNormal, uView, h, alpha, l);
        result[kDiffuseConeCount + k] = vec4(l, w);
    }
    result[kDiffuseConeCount + LIT_SPECULAR_MAX_SAMPLES] =
        vec4(specularConeAperture(alpha, uCount), specularCanReuseDiffuseCones(alpha, uCount, uDiffuseAperture) ? 1.0 : 0.0,
             0.0, 0.0);
}
)";

class ConeMirror : public ContextFixture {};

TEST_F(ConeMirror, TracedConesMatchTheShader) {
    if (HasFatalFailure()) return;
    const fs::path dir = fs::temp_directory_path() / ("lit_cone_mirror_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path file = dir / "cone_mirror.comp.glsl";
    std::ofstream(file) << kShader;
    // The shader lives outside shaders/; its #include "cone.glsl" resolves in shaders/include.
    gl::Program program(sourceDir() / "shaders", "cone mirror", {{GL_COMPUTE_SHADER, file.string()}});
    fs::remove_all(dir);
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
        glProgramUniform1f(program.id(), program.location("uDiffuseAperture"), defaults.diffuseConeAperture);
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
        settings.specularSamples = c.count;
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

}  // namespace
}  // namespace lit::test
