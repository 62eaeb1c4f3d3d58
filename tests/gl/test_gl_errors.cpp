// GL errors must not go unseen: the debug output that lit-render and lit-editor install
// (gl::installDebugOutput) turns a GL error into an error line of the log, in every build type.
// The programs' reactions (lit-render exits 1 writing nothing, the editor logs it) are checked
// end to end by lit_render_cli and editor_gl_error through the same injected error.
#include "GlTestSupport.h"

#include "gl/Capabilities.h"
#include "scene/GpuScene.h"
#include "scene/Scene.h"

#include <epoxy/gl.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace lit::test {
namespace {

class GlErrors : public ContextFixture {
protected:
    void SetUp() override {
        ContextFixture::SetUp();
        if (HasFatalFailure()) return;
        log_.setSink([this](const LogMessage& m) { messages_.push_back(m); });
        gl::installDebugOutput(log_);
    }

    std::vector<std::string> glErrorLines() const {
        std::vector<std::string> lines;
        for (const LogMessage& m : messages_)
            if (m.level == LogLevel::Error && m.text.starts_with("GL ")) lines.push_back(m.text);
        return lines;
    }

    Log log_;
    std::vector<LogMessage> messages_;
};

TEST_F(GlErrors, AnInvalidCallIsAnErrorInTheLog) {
    GLuint buffer = 0;
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, 16, nullptr, 0);
    EXPECT_TRUE(glErrorLines().empty()) << "valid calls logged a GL error: " << glErrorLines().front();
    // Immutable storage cannot be respecified: GL_INVALID_OPERATION (GL 4.5 §6.2).
    glNamedBufferStorage(buffer, 16, nullptr, 0);
    glDeleteBuffers(1, &buffer);
    const std::vector<std::string> lines = glErrorLines();
    ASSERT_EQ(lines.size(), 1u) << "expected one GL error line in the log";
    EXPECT_TRUE(lines[0].starts_with("GL error (api")) << lines[0];
}

// The seam the end-to-end tests use makes exactly one GL error, and only when asked.
TEST_F(GlErrors, InjectedErrorOnlyWhenRequested) {
    ::unsetenv("LIT_TEST_GL_ERROR");
    EXPECT_FALSE(gl::injectGlErrorIfRequested());
    EXPECT_TRUE(glErrorLines().empty());
    ::setenv("LIT_TEST_GL_ERROR", "1", 1);
    EXPECT_TRUE(gl::injectGlErrorIfRequested());
    ::unsetenv("LIT_TEST_GL_ERROR");
    EXPECT_EQ(glErrorLines().size(), 1u);
}

// An image larger than GL_MAX_TEXTURE_SIZE (glTextureStorage2D would fail with a GL error) is
// refused before the upload with a warning that names it, and the texture falls back to the
// neutral one.
TEST_F(GlErrors, AnImageOverTheTextureLimitIsAWarningNotAGlError) {
    GLint maxSide = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSide);
    ASSERT_GT(maxSide, 0);
    Scene scene;
    Image wide;
    wide.name = "too wide";
    wide.width = maxSide + 1;  // one row: (max + 1) × 4 bytes, 64 kB on llvmpipe (16384)
    wide.height = 1;
    wide.rgba.assign(static_cast<std::size_t>(wide.width) * 4, 128);
    scene.images.push_back(wide);
    Texture texture;
    texture.image = 0;
    scene.textures.push_back(texture);
    const GpuScene gpuScene(scene, log_);
    EXPECT_TRUE(glErrorLines().empty()) << glErrorLines().front();
    bool warned = false;
    for (const LogMessage& m : messages_)
        warned = warned || (m.level == LogLevel::Warning && m.text.find("'too wide'") != std::string::npos &&
                            m.text.find("larger than this GL's limit of " + std::to_string(maxSide)) != std::string::npos);
    EXPECT_TRUE(warned) << "no warning names the image and the limit";
}

}  // namespace
}  // namespace lit::test
