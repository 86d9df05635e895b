#pragma once
// An image file read as a texture (any format QImageReader reads: PNG, JPEG, BMP, ...). The
// file is checked before it is decoded: not a regular file, bigger than kMaxTextureFileBytes,
// not an image, or more than kMaxTextureFileSide texels on a side gives a message and no
// texture. Safe to call off the GUI thread (the object loader decodes on a worker).

#include "texture.h"

#include <QString>

#include <memory>

namespace lb {

constexpr int kMaxTextureFileSide = 16384;
constexpr qint64 kMaxTextureFileBytes = 512ll << 20;

struct TextureFileRead
{
    std::shared_ptr<const Texture> texture; // null on failure
    QString error;                          // "FILE: what went wrong"; empty on success
    // "brick.png: 512 x 512 texels" (and "(scaled from 8192 x 4096)" where it was).
    QString summary;
};

TextureFileRead readTextureFile(const QString &path);

} // namespace lb
