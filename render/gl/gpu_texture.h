#pragma once
// A texture on the GPU with the mipmap Texture built (every level uploaded as it is, so GL
// and Texture::sample() read the same texels), and the sampling each draw asks for. Call with
// the context current.

#include "gl_object.h"
#include "texture.h"

#include <QOpenGLExtraFunctions>

namespace lb {

GlTexture uploadTexture(QOpenGLExtraFunctions &gl, const Texture &texture);
// Sets the bound GL_TEXTURE_2D's wrap and filters to `sampling`.
void applySampling(QOpenGLExtraFunctions &gl, const TextureSampling &sampling);

} // namespace lb
