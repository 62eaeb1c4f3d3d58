// Shader loading: #include expansion, errors that name file:line, keeping the last good program,
// and the std140/std430 layouts of shared.h matching C++.
#include "GlTestSupport.h"

#include "gl/GlError.h"
#include "gl/Shader.h"

#include <shared.h>

#include <chrono>
#include <cstddef>
#include <fstream>
#include <thread>

namespace lit::test {
namespace {

namespace fs = std::filesystem;

void writeFile(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
}

class Shaders : public GlFixture {
protected:
    void SetUp() override {
        GlFixture::SetUp();
        root_ = fs::temp_directory_path() / ("lit_shader_test_" + std::to_string(::getpid()) + "_" +
                                             ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root_);
        writeFile(root_ / "include" / "colour.glsl", "vec4 colour() { return vec4(1.0, 0.5, 0.25, 1.0); }\n");
        writeFile(root_ / "quad.vert.glsl",
                  "#version 450 core\nvoid main() { gl_Position = vec4(0.0, 0.0, 0.0, 1.0); }\n");
        writeFile(root_ / "good.frag.glsl",
                  "#version 450 core\n#include \"colour.glsl\"\nout vec4 o;\nvoid main() { o = colour(); }\n");
    }
    void TearDown() override { fs::remove_all(root_); }
    fs::path root_;
};

TEST_F(Shaders, IncludesExpandOnceWithLineDirectives) {
    std::vector<fs::path> files;
    writeFile(root_ / "twice.frag.glsl",
              "#version 450 core\n#include \"colour.glsl\"\n#include \"colour.glsl\"\nout vec4 o;\nvoid main() { o = colour(); }\n");
    const std::string source = gl::expandIncludes(root_, "twice.frag.glsl", "", files);
    ASSERT_EQ(files.size(), 2u);
    EXPECT_EQ(files[1].filename(), "colour.glsl");
    std::size_t count = 0, at = 0;
    while ((at = source.find("vec4 colour()", at)) != std::string::npos) ++count, ++at;
    EXPECT_EQ(count, 1u) << source;
    EXPECT_NE(source.find("#line 1 1"), std::string::npos) << source;
}

TEST_F(Shaders, MissingIncludeNamesFileAndLine) {
    writeFile(root_ / "bad_include.frag.glsl", "#version 450 core\n\n#include \"nope.glsl\"\nvoid main() {}\n");
    std::vector<fs::path> files;
    try {
        gl::expandIncludes(root_, "bad_include.frag.glsl", "", files);
        FAIL() << "expected a GlError";
    } catch (const gl::GlError& e) {
        EXPECT_NE(std::string(e.what()).find("bad_include.frag.glsl:3"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("nope.glsl"), std::string::npos) << e.what();
    }
}

TEST_F(Shaders, CompileErrorInIncludedFileReportsThatFileAndLine) {
    writeFile(root_ / "include" / "broken.glsl", "// line 1\n// line 2\nfloat broken() { return undefinedThing; }\n");
    writeFile(root_ / "uses_broken.frag.glsl",
              "#version 450 core\n#include \"broken.glsl\"\nout vec4 o;\nvoid main() { o = vec4(broken()); }\n");
    try {
        gl::Program program(root_, "broken", {{GL_VERTEX_SHADER, "quad.vert.glsl"}, {GL_FRAGMENT_SHADER, "uses_broken.frag.glsl"}});
        FAIL() << "expected a GlError";
    } catch (const gl::GlError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find((root_ / "include" / "broken.glsl").string() + ":3:"), std::string::npos) << message;
    }
}

TEST_F(Shaders, FailedReloadKeepsTheLastGoodProgram) {
    gl::Program program(root_, "good", {{GL_VERTEX_SHADER, "quad.vert.glsl"}, {GL_FRAGMENT_SHADER, "good.frag.glsl"}});
    const GLuint before = program.id();
    ASSERT_NE(before, 0u);
    EXPECT_FALSE(program.sourcesChanged());
    // File times have a coarse resolution on some file systems: make sure the change is seen.
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    writeFile(root_ / "good.frag.glsl", "#version 450 core\nout vec4 o;\nvoid main() { o = vec4(oops); }\n");
    fs::last_write_time(root_ / "good.frag.glsl", fs::last_write_time(root_ / "good.frag.glsl") + std::chrono::seconds(2));
    EXPECT_TRUE(program.sourcesChanged());
    EXPECT_FALSE(program.reload(log_));
    EXPECT_EQ(program.id(), before) << "the last good program must stay";
    EXPECT_TRUE(glIsProgram(program.id()));
    EXPECT_FALSE(program.sourcesChanged()) << "a failed build is not retried until the file changes again";
    const auto messages = log_.recent();
    ASSERT_FALSE(messages.empty());
    EXPECT_EQ(messages.back().level, LogLevel::Error);
    EXPECT_NE(messages.back().text.find("good.frag.glsl:3:"), std::string::npos) << messages.back().text;

    writeFile(root_ / "good.frag.glsl", "#version 450 core\nout vec4 o;\nvoid main() { o = vec4(0.5); }\n");
    fs::last_write_time(root_ / "good.frag.glsl", fs::last_write_time(root_ / "good.frag.glsl") + std::chrono::seconds(4));
    EXPECT_TRUE(program.reload(log_));
    EXPECT_NE(program.id(), 0u);
}

// The GLSL side of shared.h must lay its blocks out exactly like the C++ side.
TEST_F(GlFixture, SharedHeaderLayoutsMatchCpp) {
    gl::Program program(sourceDir() / "shaders", "direct lighting",
                        {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "direct_lighting.frag.glsl"}});
    const auto offsetOf = [&](GLenum interface, const char* name) {
        const GLuint index = glGetProgramResourceIndex(program.id(), interface, name);
        EXPECT_NE(index, GL_INVALID_INDEX) << name;
        const GLenum property = GL_OFFSET;
        GLint offset = -1;
        glGetProgramResourceiv(program.id(), interface, index, 1, &property, 1, nullptr, &offset);
        return offset;
    };
    EXPECT_EQ(offsetOf(GL_UNIFORM, "frame.inverseViewProjection"), GLint(offsetof(gpu::FrameUniforms, inverseViewProjection)));
    EXPECT_EQ(offsetOf(GL_UNIFORM, "frame.cameraPosition"), GLint(offsetof(gpu::FrameUniforms, cameraPosition)));
    EXPECT_EQ(offsetOf(GL_UNIFORM, "frame.counts"), GLint(offsetof(gpu::FrameUniforms, counts)));
    EXPECT_EQ(offsetOf(GL_BUFFER_VARIABLE, "lights[0].shadowViewProjection"), GLint(offsetof(gpu::GpuLight, shadowViewProjection)));
    EXPECT_EQ(offsetOf(GL_BUFFER_VARIABLE, "lights[0].shadowParams"), GLint(offsetof(gpu::GpuLight, shadowParams)));
    const GLuint lights = glGetProgramResourceIndex(program.id(), GL_BUFFER_VARIABLE, "lights[0].positionRange");
    const GLenum stride = GL_TOP_LEVEL_ARRAY_STRIDE;
    GLint arrayStride = 0;
    glGetProgramResourceiv(program.id(), GL_BUFFER_VARIABLE, lights, 1, &stride, 1, nullptr, &arrayStride);
    EXPECT_EQ(arrayStride, GLint(sizeof(gpu::GpuLight)));
}

}  // namespace
}  // namespace lit::test
