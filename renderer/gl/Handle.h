#pragma once
// Move-only ownership of one OpenGL object name.
//
// Every GL object in Lit is owned by exactly one Handle; moving leaves the source empty (name 0),
// so the object is deleted once. Objects are created with Direct State Access (glCreate*), which
// makes them fully initialised at creation and lets us label them before first use.

#include <epoxy/gl.h>

#include <string_view>
#include <utility>

namespace lit::gl {

template <typename Traits>
class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint name) : name_(name) {}
    ~Handle() { reset(); }

    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }

    GLuint id() const { return name_; }
    explicit operator bool() const { return name_ != 0; }

    void reset() {
        if (name_ != 0) Traits::destroy(name_);
        name_ = 0;
    }

    // Names the object for debuggers (RenderDoc, apitrace) and KHR_debug messages.
    void label(std::string_view text) const {
        if (name_ != 0)
            glObjectLabel(Traits::kLabelType, name_, static_cast<GLsizei>(text.size()), text.data());
    }

private:
    GLuint name_ = 0;
};

struct BufferTraits {
    static constexpr GLenum kLabelType = GL_BUFFER;
    static void destroy(GLuint n) { glDeleteBuffers(1, &n); }
};
struct TextureTraits {
    static constexpr GLenum kLabelType = GL_TEXTURE;
    static void destroy(GLuint n) { glDeleteTextures(1, &n); }
};
struct FramebufferTraits {
    static constexpr GLenum kLabelType = GL_FRAMEBUFFER;
    static void destroy(GLuint n) { glDeleteFramebuffers(1, &n); }
};
struct VertexArrayTraits {
    static constexpr GLenum kLabelType = GL_VERTEX_ARRAY;
    static void destroy(GLuint n) { glDeleteVertexArrays(1, &n); }
};
struct SamplerTraits {
    static constexpr GLenum kLabelType = GL_SAMPLER;
    static void destroy(GLuint n) { glDeleteSamplers(1, &n); }
};
struct QueryTraits {
    static constexpr GLenum kLabelType = GL_QUERY;
    static void destroy(GLuint n) { glDeleteQueries(1, &n); }
};
struct ProgramTraits {
    static constexpr GLenum kLabelType = GL_PROGRAM;
    static void destroy(GLuint n) { glDeleteProgram(n); }
};
struct ShaderTraits {
    static constexpr GLenum kLabelType = GL_SHADER;
    static void destroy(GLuint n) { glDeleteShader(n); }
};

using BufferHandle = Handle<BufferTraits>;
using TextureHandle = Handle<TextureTraits>;
using FramebufferHandle = Handle<FramebufferTraits>;
using VertexArrayHandle = Handle<VertexArrayTraits>;
using SamplerHandle = Handle<SamplerTraits>;
using QueryHandle = Handle<QueryTraits>;
using ProgramHandle = Handle<ProgramTraits>;
using ShaderHandle = Handle<ShaderTraits>;

}  // namespace lit::gl
