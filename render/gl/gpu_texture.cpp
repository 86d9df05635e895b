#include "gpu_texture.h"

namespace lb {

GlTexture uploadTexture(QOpenGLExtraFunctions &gl, const Texture &texture)
{
    GlTexture id = GlTexture::create();
    gl.glBindTexture(GL_TEXTURE_2D, id.id());
    gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int level = 0; level < texture.levelCount(); ++level) {
        const QImage &image = texture.level(level);
        gl.glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA8, image.width(), image.height(), 0, GL_RGBA,
                        GL_UNSIGNED_BYTE, image.constBits());
    }
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, texture.levelCount() - 1);
    applySampling(gl, TextureSampling{});
    gl.glBindTexture(GL_TEXTURE_2D, 0);
    return id;
}

void applySampling(QOpenGLExtraFunctions &gl, const TextureSampling &sampling)
{
    const bool nearest = sampling.filter == TextureFilter::Nearest;
    const GLint mag = nearest ? GL_NEAREST : GL_LINEAR;
    const GLint min = !sampling.mipmaps ? mag
                      : nearest         ? GL_NEAREST_MIPMAP_NEAREST
                                        : GL_LINEAR_MIPMAP_LINEAR;
    const GLint wrap = sampling.wrap == TextureWrap::Repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
}

} // namespace lb
