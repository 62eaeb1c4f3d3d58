#include "passes/SkyTexture.h"

namespace lit {

gl::Texture makeSkyTexture(const SkyImage& image) {
    gl::Texture texture("sky", {GL_TEXTURE_2D, GL_RGB32F, image.width, image.height, 1,
                                gl::Texture::mipCount(image.width, image.height)});
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGB, GL_FLOAT, image.texels.data());
    glGenerateTextureMipmap(texture.id());
    texture.setFilter(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);         // u wraps around the horizon
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);  // v stops at the poles
    return texture;
}

}  // namespace lit
