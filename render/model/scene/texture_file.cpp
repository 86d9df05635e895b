#include "texture_file.h"

#include "bounded_read.h"
#include "image_truncation.h"
#include "message_text.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QImageIOHandler>
#include <QImageReader>

#include <mutex>

namespace lb {

namespace {
// The translation context of this file's messages.
struct TextureFileMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::TextureFile)
};
} // namespace

TextureFileRead readTextureFile(const QString &path)
{
    TextureFileRead read;
    // Messages name the path as the user gave it, like those of unreadableFile().
    const QString name = echoedPath(path);
    read.error = unreadableFile(
        path, {QT_TRANSLATE_NOOP("lb::FileLimit", "an image"), kMaxTextureFileBytes});
    if (!read.error.isEmpty())
        return read;
    if (QFileInfo(path).size() == 0) {
        read.error = TextureFileMessages::tr("%1: an empty file, not an image").arg(name);
        return read;
    }
    QImageReader reader(path);
    reader.setAutoTransform(true); // a photo's EXIF orientation, as viewers show it
    if (!reader.canRead()) {
        read.error = TextureFileMessages::tr("%1: not an image (%2)")
                         .arg(name, reader.error() == QImageReader::UnsupportedFormatError
                                        ? TextureFileMessages::tr("the formats read are %1")
                                              .arg(QString::fromLatin1(
                                                  QImageReader::supportedImageFormats().join(", ")))
                                        : reader.errorString());
        return read;
    }
    const QSize size = reader.size(); // from the header, before anything is decoded
    if (size.width() > kMaxTextureFileSide || size.height() > kMaxTextureFileSide) {
        read.error =
            TextureFileMessages::tr("%1: %2 x %3 texels is more than a texture may have (%4 x %4)")
                .arg(name, QString::number(size.width()), QString::number(size.height()),
                     QString::number(kMaxTextureFileSide));
        return read;
    }
    // The largest image allowed decodes to 1 GiB of RGBA; Qt refuses more than 256 MiB unless
    // told (a process-wide setting: set once, before the first image is read here).
    static std::once_flag limitSet;
    std::call_once(limitSet, [] {
        QImageReader::setAllocationLimit(
            int((qint64(kMaxTextureFileSide) * kMaxTextureFileSide * 4) >> 20) + 64);
    });
    // Bigger ones are decoded at the size drawn where the format can (JPEG); a thin one keeps
    // at least one texel across.
    if (size.isValid() && (size.width() > Texture::kMaxSize || size.height() > Texture::kMaxSize))
        reader.setScaledSize(size.scaled(Texture::kMaxSize, Texture::kMaxSize, Qt::KeepAspectRatio)
                                 .expandedTo(QSize(1, 1)));
    // The size as shown: a photo's EXIF rotation by 90 degrees swaps it.
    const QSize shown = reader.transformation() & QImageIOHandler::TransformationRotate90
                            ? size.transposed()
                            : size;
    // A file cut short is refused before it is decoded (its missing rows would be drawn grey).
    if (QFile file(path); file.open(QIODevice::ReadOnly)) {
        const uchar *mapped = file.map(0, file.size());
        const QByteArray bytes =
            mapped ? QByteArray::fromRawData(reinterpret_cast<const char *>(mapped),
                                             qsizetype(file.size()))
                   : QByteArray();
        if (const QString why = truncatedImage(bytes, reader.format()); mapped && !why.isEmpty()) {
            read.error =
                TextureFileMessages::tr("%1: could not be read as an image: %2").arg(name, why);
            return read;
        }
    }
    const QImage image = reader.read();
    if (image.isNull()) {
        read.error = TextureFileMessages::tr("%1: could not be read as an image: %2")
                         .arg(name, reader.errorString());
        return read;
    }
    auto texture = std::make_shared<Texture>(Texture::fromImage(image));
    const QImage &drawn = texture->image();
    const QString fileName = QFileInfo(path).fileName();
    if (shown.isValid() && shown != drawn.size())
        //: %1 a file's name, %2 x %3 the texels drawn, %4 x %5 the image's own size
        read.summary =
            TextureFileMessages::tr("%1: %2 x %3 texels (scaled from %4 x %5)")
                .arg(fileName, QString::number(drawn.width()), QString::number(drawn.height()),
                     QString::number(shown.width()), QString::number(shown.height()));
    else
        read.summary =
            TextureFileMessages::tr("%1: %2 x %3 texels")
                .arg(fileName, QString::number(drawn.width()), QString::number(drawn.height()));
    read.texture = std::move(texture);
    return read;
}

} // namespace lb
