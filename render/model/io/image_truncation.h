#pragma once
// Qt's JPEG and BMP readers decode a file that ends early without an error: the rows they
// did not get come out grey or black, and a texture would be drawn from that. These checks
// tell such a file by its own structure before it is decoded. (PNG and PPM readers refuse a
// short file themselves.)

#include <QByteArray>
#include <QString>

namespace lb {

// Why the image in `bytes`, in `format` as QImageReader names it ("jpeg", "bmp", "gif"), ends
// before its image does; empty when it is whole or the format is not one checked here.
QString truncatedImage(const QByteArray &bytes, const QByteArray &format);

} // namespace lb
