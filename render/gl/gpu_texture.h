#pragma once
// A texture on the GPU, sampled exactly as Texture::sample() samples it on the CPU: bilinear,
// repeat, no mipmaps. Call with the context current.

#include "gl_object.h"
#include "texture.h"

#include <QOpenGLExtraFunctions>

namespace lb {

GlTexture uploadTexture(QOpenGLExtraFunctions &gl, const Texture &texture);

} // namespace lb
