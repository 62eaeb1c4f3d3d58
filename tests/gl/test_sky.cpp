// The sky model is written twice, in C++ (scene/Sky.cpp, used by the reference renderer and
// tools) and GLSL (shaders/include/sky.glsl, used by the background and the cones): evaluate
// both for the same directions and require them to agree, for every mode.
#include "GlTestSupport.h"

#include "gl/Objects.h"
#include "gl/Shader.h"
#include "passes/FrameUniforms.h"
#include "passes/SkyTexture.h"
#include "scene/Sky.h"

#include <shared.h>

#include <cstdio>
#include <fstream>
#include <random>

namespace lit::test {
namespace {

class SkyTwin : public ContextFixture {
protected:
    // Runs skyRadiance (sky.glsl) for each direction on the GPU.
    std::vector<glm::vec3> gpuRadiance(const Sky& sky, const gl::Texture* image, const std::vector<glm::vec3>& directions) {
        // A shader root of its own with the real include folder, so the probe includes sky.glsl
        // exactly as the passes do.
        const std::filesystem::path root = outputDir() / "sky_probe";
        std::filesystem::create_directories(root);
        std::error_code ignored;
        std::filesystem::remove(root / "include", ignored);
        std::filesystem::create_directory_symlink(sourceDir() / "shaders" / "include", root / "include");
        std::ofstream(root / "sky_probe.comp.glsl") << R"(#version 450 core
#include "sky.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 6) readonly buffer Directions { vec4 directions[]; };
layout(std430, binding = 7) writeonly buffer Radiance { vec4 radiance[]; };
uniform int uCount;
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < uint(uCount)) radiance[i] = vec4(skyRadiance(directions[i].xyz), 1.0);
}
)";
        gl::Program program(root, "sky probe", {{GL_COMPUTE_SHADER, "sky_probe.comp.glsl"}});
        std::vector<glm::vec4> in;
        for (const glm::vec3& d : directions) in.emplace_back(d, 0.0f);
        gl::Buffer inBuffer("directions", in.size() * sizeof(glm::vec4), in.data(), 0);
        gl::Buffer outBuffer("radiance", in.size() * sizeof(glm::vec4), nullptr, 0);
        RenderSettings settings;
        const gpu::FrameUniforms frame = makeFrameUniforms(CameraView{}, settings, 0, 0, &sky);
        gl::Buffer frameBuffer("frame", sizeof frame, &frame, 0);
        frameBuffer.bindBase(GL_UNIFORM_BUFFER, LIT_UBO_FRAME);
        inBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, 6);
        outBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, 7);
        if (image) image->bind(LIT_TEX_SKY);
        program.use();
        program.set("uCount", static_cast<int>(in.size()));
        glDispatchCompute(static_cast<GLuint>((in.size() + 63) / 64), 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::vector<glm::vec4> out(in.size());
        glGetNamedBufferSubData(outBuffer.id(), 0, static_cast<GLsizeiptr>(out.size() * sizeof(glm::vec4)), out.data());
        std::vector<glm::vec3> result;
        for (const glm::vec4& v : out) result.emplace_back(v);
        return result;
    }

    static std::vector<glm::vec3> directions() {
        std::mt19937 random(13);
        std::normal_distribution<float> normal;
        // Not the exact poles: there u (the azimuth) is undefined, and atan(0, −0) may give any
        // column of the image's first row on either side.
        std::vector<glm::vec3> out = {{0, 0.999f, 0.01f}, {1, 0, 0}, {0, 0, -1}, {0, 0, 1}, {0.001f, 0.2f, 1.0f}};
        while (out.size() < 512) {
            const glm::vec3 d(normal(random), normal(random), normal(random));
            if (glm::length(d) > 1e-3f) out.push_back(d * 3.0f);  // any length: both normalise
        }
        return out;
    }
};

TEST_F(SkyTwin, UniformAndGradientAgree) {
    RenderSettings settings;
    settings.sky.intensity = 1.7f;
    for (SkyMode mode : {SkyMode::None, SkyMode::Uniform, SkyMode::Gradient}) {
        settings.sky.mode = mode;
        const Sky sky = resolveSky(Scene{}, settings, nullptr);
        const std::vector<glm::vec3> dirs = directions();
        const std::vector<glm::vec3> gpu = gpuRadiance(sky, nullptr, dirs);
        float worst = 0.0f;
        for (std::size_t i = 0; i < dirs.size(); ++i) worst = std::max(worst, glm::length(gpu[i] - skyRadiance(sky, dirs[i])));
        EXPECT_LT(worst, 1e-5f) << toString(mode);  // float rounding of the same formula
    }
}

// The image mode: bilinear lookup at full resolution. GPUs filter with a few bits of sub-texel
// precision (8 on llvmpipe and most GPUs), so the difference is bounded by about 1/256 of the
// largest step between neighbouring texels (here up to 4): 0.04 = 1 % of the brightest texel.
TEST_F(SkyTwin, EquirectangularImageAgrees) {
    SkyImage image;
    image.width = 32;
    image.height = 16;
    std::mt19937 random(7);
    std::uniform_real_distribution<float> value(0.0f, 4.0f);
    for (int i = 0; i < image.width * image.height; ++i) image.texels.emplace_back(value(random), value(random), value(random));
    RenderSettings settings;
    settings.sky.mode = SkyMode::Hdr;
    const Sky sky = resolveSky(Scene{}, settings, &image);
    const gl::Texture texture = makeSkyTexture(image);
    const std::vector<glm::vec3> dirs = directions();
    const std::vector<glm::vec3> gpu = gpuRadiance(sky, &texture, dirs);
    float worst = 0.0f;
    for (std::size_t i = 0; i < dirs.size(); ++i) worst = std::max(worst, glm::length(gpu[i] - skyRadiance(sky, dirs[i])));
    std::printf("sky image: largest C++/GLSL difference %.5f (texels up to 4)\n", worst);
    EXPECT_LT(worst, 0.04f);
}

}  // namespace
}  // namespace lit::test
