#pragma once
// A texture as the texture switch puts it on the surface: the built-in checker, a mesh
// file's diffuse texture or an image file, with its mipmap (each level half the one before,
// a 2x2 box average, built here and uploaded as it is so the GPU reads the same texels), and
// the lookup GL does for each TextureSampling, so that the reference knows what the texture
// puts on a pixel.

#include "texture_sampling.h"

#include <QImage>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

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

    const QImage &image() const { return m_levels.front(); } // RGBA8888, row 0 = t of 0
    int levelCount() const { return int(m_levels.size()); }  // down to 1 x 1
    const QImage &level(int i) const { return m_levels[std::size_t(i)]; }

    glm::vec3 texel(int level, int s, int t, TextureWrap wrap) const;
    // What GL returns for coordinate `uv` at level of detail `lod` (see levelOfDetail).
    glm::vec3 sample(const glm::vec2 &uv, const TextureSampling &sampling, float lod = 0.0f) const;
    // GL's level of detail: log2 of the most texels (of level 0) that one pixel step in x or
    // in y crosses; `dx`, `dy` are the texture coordinate's change over those steps.
    float levelOfDetail(const glm::vec2 &dx, const glm::vec2 &dy) const;
    // The mipmap level(s) a lookup at `lod` reads and the weight of the second: what GL's
    // level selection does for the sampling's filter (one level without mipmaps).
    struct Levels
    {
        int first = 0, second = 0;
        float weight = 0.0f; // of `second`
    };
    Levels levelsAt(float lod, const TextureSampling &sampling) const;

private:
    explicit Texture(QImage level0); // and the levels below it
    glm::vec3 sampleLevel(int level, const glm::vec2 &uv, const TextureSampling &sampling) const;
    void buildLevels();

    std::vector<QImage> m_levels; // never empty
};

} // namespace lb
