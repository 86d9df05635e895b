#pragma once
// A texture as the texture switch puts it on the surface: the built-in checker or a mesh
// file's diffuse texture, with the same bilinear lookup GL does with GL_LINEAR and GL_REPEAT,
// so that the reference knows what the texture switch puts on a pixel.

#include <QImage>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace lb {

class Texture
{
public:
    static constexpr int kCheckerSize = 64;  // texels per side
    static constexpr int kCheckerSquare = 8; // texels per checker square
    static constexpr int kMaxSize = 4096;    // larger images are scaled down to this

    Texture(); // the checker
    // An image as a file stores it (row 0 at the top); texture coordinate t = 0 is its
    // bottom row, as in OpenGL and Assimp.
    static Texture fromImage(const QImage &image);

    const QImage &image() const { return m_image; } // RGBA8888, row 0 = t of 0
    glm::vec3 texel(int s, int t) const;            // wraps
    glm::vec3 sample(const glm::vec2 &uv) const;    // bilinear, repeat

private:
    QImage m_image;
};

} // namespace lb
