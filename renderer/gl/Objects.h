#pragma once
// Thin RAII types over GL objects, created with Direct State Access (GL 4.5).
// They add the few operations Lit uses; anything else calls GL with .id().

#include "gl/Handle.h"

#include <cstddef>
#include <initializer_list>
#include <span>
#include <string_view>

namespace lit::gl {

class Buffer {
public:
    Buffer() = default;
    // Immutable storage (glNamedBufferStorage). flags: e.g. GL_DYNAMIC_STORAGE_BIT.
    Buffer(std::string_view label, std::size_t bytes, const void* data, GLbitfield flags);

    template <typename T>
    static Buffer fromSpan(std::string_view label, std::span<const T> data, GLbitfield flags = 0) {
        return Buffer(label, data.size_bytes(), data.data(), flags);
    }

    // Needs GL_DYNAMIC_STORAGE_BIT.
    void update(std::size_t offset, std::size_t bytes, const void* data);
    template <typename T>
    void update(const T& value) { update(0, sizeof(T), &value); }

    void bindBase(GLenum target, GLuint index) const { glBindBufferBase(target, index, handle_.id()); }
    GLuint id() const { return handle_.id(); }
    std::size_t size() const { return size_; }
    explicit operator bool() const { return static_cast<bool>(handle_); }

private:
    BufferHandle handle_;
    std::size_t size_ = 0;
};

struct TextureDesc {
    GLenum target = GL_TEXTURE_2D;  // GL_TEXTURE_2D, _2D_ARRAY, _3D, _CUBE_MAP, _CUBE_MAP_ARRAY
    GLenum format = GL_RGBA8;       // sized internal format
    int width = 1, height = 1;
    int depth = 1;                  // 3D depth, array layers, or cube-array layer-faces (6 × cubes)
    int levels = 1;
};

class Texture {
public:
    Texture() = default;
    Texture(std::string_view label, const TextureDesc& desc);

    const TextureDesc& desc() const { return desc_; }
    GLuint id() const { return handle_.id(); }
    explicit operator bool() const { return static_cast<bool>(handle_); }
    void bind(GLuint unit) const { glBindTextureUnit(unit, handle_.id()); }
    void setFilter(GLenum minFilter, GLenum magFilter) const;
    void setWrap(GLenum wrap) const;

    static int mipCount(int w, int h = 1, int d = 1);

private:
    TextureHandle handle_;
    TextureDesc desc_;
};

class Framebuffer {
public:
    Framebuffer() = default;
    explicit Framebuffer(std::string_view label);
    // A complete framebuffer drawing to `colours` (level 0) as colour attachments 0, 1, ... in
    // order; throws GlError naming `label` when incomplete.
    static Framebuffer withColours(std::string_view label, std::initializer_list<const Texture*> colours);

    void attach(GLenum attachment, const Texture& texture, int level = 0);
    void attachLayer(GLenum attachment, const Texture& texture, int layer, int level = 0);
    // Sets glNamedFramebufferDrawBuffers for `count` colour attachments (0 = depth only).
    void setDrawBuffers(int count);
    // Colour attachment i is drawn when written[i], else GL_NONE (at most 8).
    void setDrawBuffers(std::initializer_list<bool> written);
    // Throws GlError naming the status when incomplete.
    void checkComplete(std::string_view what) const;
    void bind() const { glBindFramebuffer(GL_FRAMEBUFFER, handle_.id()); }
    GLuint id() const { return handle_.id(); }

private:
    FramebufferHandle handle_;
};

class VertexArray {
public:
    VertexArray() = default;
    explicit VertexArray(std::string_view label);
    GLuint id() const { return handle_.id(); }
    void bind() const { glBindVertexArray(handle_.id()); }

private:
    VertexArrayHandle handle_;
};

class Sampler {
public:
    Sampler() = default;
    explicit Sampler(std::string_view label);
    GLuint id() const { return handle_.id(); }
    void set(GLenum pname, GLint value) const { glSamplerParameteri(handle_.id(), pname, value); }
    void bind(GLuint unit) const { glBindSampler(unit, handle_.id()); }

private:
    SamplerHandle handle_;
};

}  // namespace lit::gl
