#pragma once
// The built-in checker texture, and the same bilinear lookup GL does with GL_LINEAR and
// GL_REPEAT, so that the reference knows what the texture switch puts on a pixel.

#include <QImage>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace lb {

class CheckerTexture
{
public:
    static constexpr int kSize = 64;  // texels per side
    static constexpr int kSquare = 8; // texels per checker square
    CheckerTexture();

    const QImage &image() const { return m_image; } // RGBA8888, row 0 = t of 0
    glm::vec3 texel(int s, int t) const;            // wraps
    glm::vec3 sample(const glm::vec2 &uv) const;    // bilinear, repeat

private:
    QImage m_image;
};

} // namespace lb
