#include "texture.h"

#include <cmath>

namespace lb {

Texture::Texture() : m_image(kCheckerSize, kCheckerSize, QImage::Format_RGBA8888)
{
    const QColor light(235, 235, 225), dark(70, 80, 95);
    for (int t = 0; t < kCheckerSize; ++t)
        for (int s = 0; s < kCheckerSize; ++s)
            m_image.setPixelColor(s, t,
                                  ((s / kCheckerSquare + t / kCheckerSquare) % 2) ? dark : light);
}

Texture Texture::fromImage(const QImage &image)
{
    QImage flipped = image.convertToFormat(QImage::Format_RGBA8888).mirrored();
    if (flipped.width() > kMaxSize || flipped.height() > kMaxSize)
        flipped = flipped.scaled(kMaxSize, kMaxSize, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    Texture t;
    if (!flipped.isNull())
        t.m_image = flipped;
    return t;
}

glm::vec3 Texture::texel(int s, int t) const
{
    const int w = m_image.width(), h = m_image.height();
    s = ((s % w) + w) % w;
    t = ((t % h) + h) % h;
    const QRgb c = m_image.pixel(s, t);
    return glm::vec3(qRed(c), qGreen(c), qBlue(c)) / 255.0f;
}

glm::vec3 Texture::sample(const glm::vec2 &uv) const
{
    // Texel centres sit at (i + 0.5) / size, as in the GL specification's linear filter.
    const float x = uv.x * float(m_image.width()) - 0.5f;
    const float y = uv.y * float(m_image.height()) - 0.5f;
    const int s0 = int(std::floor(x));
    const int t0 = int(std::floor(y));
    const float fx = x - float(s0);
    const float fy = y - float(t0);
    const glm::vec3 bottom = texel(s0, t0) * (1 - fx) + texel(s0 + 1, t0) * fx;
    const glm::vec3 top = texel(s0, t0 + 1) * (1 - fx) + texel(s0 + 1, t0 + 1) * fx;
    return bottom * (1 - fy) + top * fy;
}

} // namespace lb
