#include "gpu_texture.h"

namespace lb {

GlTexture uploadTexture(QOpenGLExtraFunctions &gl, const Texture &texture)
{
    const QImage &image = texture.image();
    GlTexture id = GlTexture::create();
    gl.glBindTexture(GL_TEXTURE_2D, id.id());
    gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl.glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width(), image.height(), 0, GL_RGBA,
                    GL_UNSIGNED_BYTE, image.constBits());
    // Plain bilinear without mipmaps: Texture::sample() repeats exactly this lookup.
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    gl.glBindTexture(GL_TEXTURE_2D, 0);
    return id;
}

} // namespace lb
