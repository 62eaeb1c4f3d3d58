#include "gl/Objects.h"

#include "gl/GlError.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <string>

namespace lit::gl {

namespace {
GLuint createBuffer() {
    GLuint n = 0;
    glCreateBuffers(1, &n);
    return n;
}
}  // namespace

Buffer::Buffer(std::string_view label, std::size_t bytes, const void* data, GLbitfield flags)
    : handle_(createBuffer()), size_(bytes) {
    handle_.label(label);
    // Zero-sized storage is an error in GL; keep one byte so empty scenes still bind something.
    glNamedBufferStorage(handle_.id(), static_cast<GLsizeiptr>(std::max<std::size_t>(bytes, 1)),
                         bytes > 0 ? data : nullptr, flags);
}

void Buffer::update(std::size_t offset, std::size_t bytes, const void* data) {
    assert(offset + bytes <= size_ && "Buffer::update past the end: allocate a larger buffer");
    glNamedBufferSubData(handle_.id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

Texture::Texture(std::string_view label, const TextureDesc& desc) : desc_(desc) {
    GLuint n = 0;
    glCreateTextures(desc.target, 1, &n);
    handle_ = TextureHandle(n);
    handle_.label(label);
    switch (desc.target) {
        case GL_TEXTURE_2D:
        case GL_TEXTURE_CUBE_MAP:
            glTextureStorage2D(n, desc.levels, desc.format, desc.width, desc.height);
            break;
        case GL_TEXTURE_2D_ARRAY:
        case GL_TEXTURE_3D:
        case GL_TEXTURE_CUBE_MAP_ARRAY:
            glTextureStorage3D(n, desc.levels, desc.format, desc.width, desc.height, desc.depth);
            break;
        default:
            assert(false && "Texture: unsupported target; add it to the switch");
    }
    const bool mipmapped = desc.levels > 1;
    setFilter(mipmapped ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR, GL_LINEAR);
    setWrap(GL_CLAMP_TO_EDGE);
}

void Texture::setFilter(GLenum minFilter, GLenum magFilter) const {
    glTextureParameteri(handle_.id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
    glTextureParameteri(handle_.id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
}

void Texture::setWrap(GLenum wrap) const {
    glTextureParameteri(handle_.id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
    glTextureParameteri(handle_.id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
    glTextureParameteri(handle_.id(), GL_TEXTURE_WRAP_R, static_cast<GLint>(wrap));
}

int Texture::mipCount(int w, int h, int d) {
    const unsigned largest = static_cast<unsigned>(std::max({w, h, d, 1}));
    return static_cast<int>(std::bit_width(largest));
}

Framebuffer::Framebuffer(std::string_view label) {
    GLuint n = 0;
    glCreateFramebuffers(1, &n);
    handle_ = FramebufferHandle(n);
    handle_.label(label);
}

void Framebuffer::attach(GLenum attachment, const Texture& texture, int level) {
    glNamedFramebufferTexture(handle_.id(), attachment, texture.id(), level);
}

void Framebuffer::attachLayer(GLenum attachment, const Texture& texture, int layer, int level) {
    glNamedFramebufferTextureLayer(handle_.id(), attachment, texture.id(), level, layer);
}

void Framebuffer::setDrawBuffers(int count) {
    if (count == 0) {
        glNamedFramebufferDrawBuffer(handle_.id(), GL_NONE);
        glNamedFramebufferReadBuffer(handle_.id(), GL_NONE);
        return;
    }
    GLenum buffers[8];
    assert(count <= 8);
    for (int i = 0; i < count; ++i) buffers[i] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
    glNamedFramebufferDrawBuffers(handle_.id(), count, buffers);
}

void Framebuffer::setDrawBuffers(std::initializer_list<bool> written) {
    GLenum buffers[8];
    assert(written.size() <= 8);
    GLsizei count = 0;
    for (const bool w : written) {
        buffers[count] = w ? GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(count) : GL_NONE;
        ++count;
    }
    glNamedFramebufferDrawBuffers(handle_.id(), count, buffers);
}

Framebuffer Framebuffer::withColours(std::string_view label, std::initializer_list<const Texture*> colours) {
    Framebuffer framebuffer(label);
    int index = 0;
    for (const Texture* colour : colours) framebuffer.attach(static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + index++), *colour);
    framebuffer.setDrawBuffers(index);
    framebuffer.checkComplete(label);
    return framebuffer;
}

void Framebuffer::checkComplete(std::string_view what) const {
    const GLenum status = glCheckNamedFramebufferStatus(handle_.id(), GL_FRAMEBUFFER);
    if (status == GL_FRAMEBUFFER_COMPLETE) return;
    throw GlError("framebuffer '" + std::string(what) + "' is incomplete (status 0x" +
                  [&] {
                      char hex[16];
                      std::snprintf(hex, sizeof hex, "%04X", status);
                      return std::string(hex);
                  }() +
                  ")");
}

VertexArray::VertexArray(std::string_view label) {
    GLuint n = 0;
    glCreateVertexArrays(1, &n);
    handle_ = VertexArrayHandle(n);
    handle_.label(label);
}

Sampler::Sampler(std::string_view label) {
    GLuint n = 0;
    glCreateSamplers(1, &n);
    handle_ = SamplerHandle(n);
    handle_.label(label);
}

}  // namespace lit::gl
