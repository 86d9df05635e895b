#include "safe_write.h"

#include "png_encoder.h"

#include <QBuffer>
#include <QFileInfo>
#include <QImageWriter>
#include <QSaveFile>

#include <memory>

namespace lb {

QString unwritableTarget(const QString &path)
{
    const QFileInfo info(path);
    if (info.exists() && !info.isFile())
        return QString("%1: not a regular file (a device, a pipe or a folder); not replaced")
            .arg(path);
    return {};
}

QString writeFilesSafely(const std::vector<std::pair<QString, QByteArray>> &files)
{
    for (const auto &[path, bytes] : files)
        if (const QString why = unwritableTarget(path); !why.isEmpty())
            return why;
    std::vector<std::unique_ptr<QSaveFile>> saves;
    for (const auto &[path, bytes] : files) {
        saves.push_back(std::make_unique<QSaveFile>(path));
        QSaveFile &f = *saves.back();
        if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
            return QString("%1: %2").arg(path, f.errorString()); // the others are discarded
    }
    for (const std::unique_ptr<QSaveFile> &f : saves)
        if (!f->commit())
            return QString("%1: %2").arg(f->fileName(), f->errorString());
    return {};
}

QString writeFileSafely(const QString &path, const QByteArray &bytes)
{
    return writeFilesSafely({{path, bytes}});
}

QString writeImageSafely(const QString &path, const QImage &image, int quality)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix.isEmpty() || suffix == "png") {
        const QByteArray bytes = encodePng(image, pngLevelForQuality(quality));
        if (bytes.isEmpty())
            return QString("%1: %2").arg(path, image.isNull() ? "no image to write"
                                                              : "the PNG could not be encoded");
        return writeFileSafely(path, bytes);
    }
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    QImageWriter writer(&buffer, suffix.toLatin1());
    writer.setQuality(quality);
    if (!writer.write(image))
        return QString("%1: %2").arg(path, writer.errorString());
    return writeFileSafely(path, bytes);
}

} // namespace lb
