#include "texture.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace lb {

namespace {

QImage checkerImage()
{
    QImage image(Texture::kCheckerSize, Texture::kCheckerSize, QImage::Format_RGBA8888);
    const QColor light(235, 235, 225), dark(70, 80, 95);
    for (int t = 0; t < Texture::kCheckerSize; ++t)
        for (int s = 0; s < Texture::kCheckerSize; ++s)
            image.setPixelColor(
                s, t,
                ((s / Texture::kCheckerSquare + t / Texture::kCheckerSquare) % 2) ? dark : light);
    return image;
}

// The next mipmap level: half as wide and high (at least 1), each texel the rounded mean of
// the 2x2 texels it covers (a last odd row or column is left out, as a box filter does).
QImage halved(const QImage &source)
{
    const int w = std::max(1, source.width() / 2), h = std::max(1, source.height() / 2);
    QImage next(w, h, QImage::Format_RGBA8888);
    const int sx = source.width() > 1 ? 1 : 0, sy = source.height() > 1 ? 1 : 0;
    for (int y = 0; y < h; ++y) {
        const uchar *row0 = source.constScanLine(2 * y * sy);
        const uchar *row1 = source.constScanLine((2 * y + 1) * sy);
        uchar *out = next.scanLine(y);
        for (int x = 0; x < w; ++x) {
            const int a = 4 * 2 * x * sx, b = 4 * (2 * x + 1) * sx;
            for (int c = 0; c < 4; ++c)
                out[4 * x + c] =
                    uchar((row0[a + c] + row0[b + c] + row1[a + c] + row1[b + c] + 2) / 4);
        }
    }
    return next;
}

int wrapped(int i, int size, TextureWrap wrap)
{
    return wrap == TextureWrap::Repeat ? ((i % size) + size) % size : std::clamp(i, 0, size - 1);
}

} // namespace

Texture::Texture() : Texture(checkerImage()) {}

Texture::Texture(QImage level0) : m_levels{std::move(level0)}
{
    buildLevels();
}

Texture Texture::fromImage(const QImage &image)
{
    QImage flipped = image.convertToFormat(QImage::Format_RGBA8888).mirrored();
    if (flipped.width() > kMaxSize || flipped.height() > kMaxSize)
        flipped = flipped.scaled(kMaxSize, kMaxSize, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    return flipped.isNull() ? Texture() : Texture(std::move(flipped));
}

void Texture::buildLevels()
{
    m_levels.resize(1);
    while (m_levels.back().width() > 1 || m_levels.back().height() > 1)
        m_levels.push_back(halved(m_levels.back()));
}

glm::vec3 Texture::texel(int level, int s, int t, TextureWrap wrap) const
{
    const QImage &image = m_levels[std::size_t(level)];
    const uchar *p =
        image.constScanLine(wrapped(t, image.height(), wrap)) + 4 * wrapped(s, image.width(), wrap);
    return glm::vec3(p[0], p[1], p[2]) / 255.0f;
}

glm::vec3 Texture::sampleLevel(int level, const glm::vec2 &uv,
                               const TextureSampling &sampling) const
{
    const QImage &image = m_levels[std::size_t(level)];
    // Texel centres sit at (i + 0.5) / size, as in the GL specification's filters.
    const float x = uv.x * float(image.width()), y = uv.y * float(image.height());
    if (sampling.filter == TextureFilter::Nearest)
        return texel(level, int(std::floor(x)), int(std::floor(y)), sampling.wrap);
    const int s0 = int(std::floor(x - 0.5f)), t0 = int(std::floor(y - 0.5f));
    const float fx = x - 0.5f - float(s0), fy = y - 0.5f - float(t0);
    const TextureWrap w = sampling.wrap;
    const glm::vec3 bottom = texel(level, s0, t0, w) * (1 - fx) + texel(level, s0 + 1, t0, w) * fx;
    const glm::vec3 top =
        texel(level, s0, t0 + 1, w) * (1 - fx) + texel(level, s0 + 1, t0 + 1, w) * fx;
    return bottom * (1 - fy) + top * fy;
}

float Texture::levelOfDetail(const glm::vec2 &dx, const glm::vec2 &dy) const
{
    const glm::vec2 size(float(image().width()), float(image().height()));
    const glm::vec2 x = dx * size, y = dy * size;
    const float rho = std::sqrt(std::max(x.x * x.x + x.y * x.y, y.x * y.x + y.y * y.y));
    return rho > 0.0f ? std::log2(rho) : -1000.0f;
}

Texture::Levels Texture::levelsAt(float lod, const TextureSampling &sampling) const
{
    const int last = levelCount() - 1;
    if (std::isnan(lod))
        lod = 0.0f;
    lod = std::min(lod, float(last) + 1.0f); // far past the last level (an edge-on plane)
    if (!sampling.mipmaps || lod <= 0.0f)    // magnified, or one level only
        return {};
    if (sampling.filter == TextureFilter::Nearest) {
        const int d = lod <= 0.5f ? 0 : int(std::ceil(lod + 0.5f)) - 1;
        return {std::min(d, last), std::min(d, last), 0.0f};
    }
    if (lod >= float(last))
        return {last, last, 0.0f};
    const int d = int(std::floor(lod));
    return {d, d + 1, lod - float(d)};
}

glm::vec3 Texture::sample(const glm::vec2 &uv, const TextureSampling &sampling, float lod) const
{
    const Levels l = levelsAt(lod, sampling);
    const glm::vec3 first = sampleLevel(l.first, uv, sampling);
    if (l.weight == 0.0f)
        return first;
    return first * (1.0f - l.weight) + sampleLevel(l.second, uv, sampling) * l.weight;
}

} // namespace lb
