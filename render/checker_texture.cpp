#include "checker_texture.h"

#include <cmath>

namespace lb {

CheckerTexture::CheckerTexture() : m_image(kSize, kSize, QImage::Format_RGBA8888)
{
    const QColor light(235, 235, 225), dark(70, 80, 95);
    for (int t = 0; t < kSize; ++t)
        for (int s = 0; s < kSize; ++s)
            m_image.setPixelColor(s, t, ((s / kSquare + t / kSquare) % 2) ? dark : light);
}

glm::vec3 CheckerTexture::texel(int s, int t) const
{
    s = ((s % kSize) + kSize) % kSize;
    t = ((t % kSize) + kSize) % kSize;
    const QRgb c = m_image.pixel(s, t);
    return glm::vec3(qRed(c), qGreen(c), qBlue(c)) / 255.0f;
}

glm::vec3 CheckerTexture::sample(const glm::vec2 &uv) const
{
    // Texel centres sit at (i + 0.5) / size, as in the GL specification's linear filter.
    const float x = uv.x * kSize - 0.5f;
    const float y = uv.y * kSize - 0.5f;
    const int s0 = int(std::floor(x));
    const int t0 = int(std::floor(y));
    const float fx = x - float(s0);
    const float fy = y - float(t0);
    const glm::vec3 bottom = texel(s0, t0) * (1 - fx) + texel(s0 + 1, t0) * fx;
    const glm::vec3 top = texel(s0, t0 + 1) * (1 - fx) + texel(s0 + 1, t0 + 1) * fx;
    return bottom * (1 - fy) + top * fy;
}

} // namespace lb
