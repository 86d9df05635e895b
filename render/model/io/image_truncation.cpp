#include "image_truncation.h"

#include <QCoreApplication>
#include <QtEndian>

namespace lb {

namespace {

// The translation context of this file's messages.
struct ImageTruncationMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::ImageTruncation)
};

quint32 le32(const QByteArray &b, int at)
{
    return qFromLittleEndian<quint32>(b.constData() + at);
}

quint16 le16(const QByteArray &b, int at)
{
    return qFromLittleEndian<quint16>(b.constData() + at);
}

// The main image's last scan (SOS, FF DA) must be followed by the end-of-image marker
// (FF D9). Scan data never holds FF DA or FF D9 (a data byte FF is written FF 00), and an
// EXIF thumbnail's own markers come before the main image's scans.
QString truncatedJpeg(const QByteArray &bytes)
{
    const qsizetype scan = bytes.lastIndexOf(QByteArrayLiteral("\xFF\xDA"));
    if (scan < 0)
        return ImageTruncationMessages::tr("no image data (no scan)");
    if (bytes.indexOf(QByteArrayLiteral("\xFF\xD9"), scan) < 0)
        return ImageTruncationMessages::tr(
            "the file ends inside the image data (no end-of-image marker): cut short?");
    return {};
}

// An uncompressed bitmap's rows take a known number of bytes after the header's offset.
QString truncatedBmp(const QByteArray &bytes)
{
    if (bytes.size() < 26)
        return ImageTruncationMessages::tr("the file ends inside its header");
    const quint32 offset = le32(bytes, 10), header = le32(bytes, 14);
    qint64 width = 0, height = 0, bits = 0, compression = 0;
    if (header == 12) { // OS/2's BITMAPCOREHEADER
        width = le16(bytes, 18);
        height = le16(bytes, 20);
        bits = le16(bytes, 24);
    } else if (header >= 40 && bytes.size() >= 34) {
        width = qint32(le32(bytes, 18));
        height = qint32(le32(bytes, 22));
        bits = le16(bytes, 28);
        compression = le32(bytes, 30);
    } else {
        return {}; // a header Qt may not read either: its reader says so
    }
    qint64 needed = 0;
    if (compression == 0 || compression == 3) { // BI_RGB, BI_BITFIELDS: whole rows of 4 bytes
        const qint64 stride = (std::abs(width) * bits + 31) / 32 * 4;
        needed = qint64(offset) + stride * std::abs(height);
    } else if (bytes.size() >= 38) { // run-length and others: the size the header gives
        needed = qint64(offset) + le32(bytes, 34);
    }
    if (needed > bytes.size())
        return ImageTruncationMessages::tr(
                   "the file ends inside the image data (%1 of %2 bytes): cut short?")
            .arg(bytes.size())
            .arg(needed);
    return {};
}

} // namespace

QString truncatedImage(const QByteArray &bytes, const QByteArray &format)
{
    if (format == "jpeg" || format == "jpg")
        return truncatedJpeg(bytes);
    if (format == "bmp")
        return truncatedBmp(bytes);
    return {};
}

} // namespace lb
