#pragma once
// The GPU copy of an equirectangular sky image (scene/Sky.h) as sky.glsl samples it at
// LIT_TEX_SKY: RGB32F with a full mip chain (wide cones read blurred levels), u repeating around
// the horizon, v clamped at the poles, trilinear filtering.

#include "gl/Objects.h"
#include "scene/Sky.h"

namespace lit {

gl::Texture makeSkyTexture(const SkyImage& image);

}  // namespace lit
