#pragma once
// PNG bytes of an image, written with libpng and one fixed row filter (Sub) instead of
// QImageWriter's choice per row: Qt lets libpng try all five filters on every row, which
// took two thirds of the time of a 1920x1080 frame's PNG (31 ms against 10 at zlib level 1),
// for a file of the same size on rendered frames (a flat background and smooth shading).

#include <QByteArray>
#include <QImage>

namespace lb {

// `zlibLevel` 0 (stored) to 9 (smallest); -1 is zlib's default (6). Opaque images are written
// as RGB, others as RGBA (not premultiplied). Empty for a null image or when libpng fails.
QByteArray encodePng(const QImage &image, int zlibLevel = -1);

// The zlib level QImageWriter's PNG quality (0-100, -1 for the default) stands for.
int pngLevelForQuality(int quality);

} // namespace lb
