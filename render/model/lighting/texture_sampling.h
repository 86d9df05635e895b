#pragma once
// How a texture is looked up: what GL's wrap and filter parameters say, as the Object panel,
// the scene file and the command line name them. The renderer sets exactly these on the GL
// texture and Texture::sample() repeats the lookup on the CPU.

namespace lb {

// Outside [0, 1]: the image repeats (GL_REPEAT) or its edge texels stretch (GL_CLAMP_TO_EDGE).
enum class TextureWrap { Repeat, Clamp };
// The texel nearest the coordinate, or the four around it weighted (GL_NEAREST, GL_LINEAR).
enum class TextureFilter { Nearest, Linear };

struct TextureSampling
{
    TextureWrap wrap = TextureWrap::Repeat;
    TextureFilter filter = TextureFilter::Linear;
    // Minified surfaces read smaller copies of the image (a mipmap), chosen by the level of
    // detail: GL_NEAREST_MIPMAP_NEAREST with the nearest filter, GL_LINEAR_MIPMAP_LINEAR
    // (trilinear) with the linear one.
    bool mipmaps = false;

    bool operator==(const TextureSampling &o) const
    {
        return wrap == o.wrap && filter == o.filter && mipmaps == o.mipmaps;
    }
    bool operator!=(const TextureSampling &o) const { return !(*this == o); }
};

} // namespace lb
