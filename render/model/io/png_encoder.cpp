#include "png_encoder.h"

#include <png.h>

#include <algorithm>
#include <csetjmp>

namespace lb {

namespace {

void append(png_structp png, png_bytep data, png_size_t length)
{
    static_cast<QByteArray *>(png_get_io_ptr(png))
        ->append(reinterpret_cast<const char *>(data), qsizetype(length));
}

void flush(png_structp) {}

// Only plain data lives in this frame: libpng reports errors with longjmp, which must not
// skip a destructor. Returns false when libpng gave up.
bool writeRows(png_structp png, png_infop info, const QImage &image, bool alpha, int level)
{
    if (setjmp(png_jmpbuf(png)))
        return false;
    png_set_IHDR(png, info, png_uint_32(image.width()), png_uint_32(image.height()), 8,
                 alpha ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    png_set_compression_level(png, level);
    png_write_info(png, info);
    // QImage's 0xAARRGGBB words are the bytes B, G, R, A on a little-endian machine.
    static_assert(Q_BYTE_ORDER == Q_LITTLE_ENDIAN, "rows are read as B, G, R, A bytes");
    png_set_bgr(png);
    if (!alpha)
        png_set_filler(png, 0, PNG_FILLER_AFTER); // the A byte of RGB32 is dropped
    for (int y = 0; y < image.height(); ++y)
        png_write_row(png, image.constScanLine(y));
    png_write_end(png, info);
    return true;
}

} // namespace

int pngLevelForQuality(int quality)
{
    // As Qt's PNG handler maps it: 100 stores, 0 compresses most.
    return quality < 0 ? -1 : (100 - std::min(quality, 100)) * 9 / 91;
}

QByteArray encodePng(const QImage &image, int zlibLevel)
{
    if (image.isNull())
        return {};
    const bool alpha = image.hasAlphaChannel();
    const QImage::Format format = alpha ? QImage::Format_ARGB32 : QImage::Format_RGB32;
    const QImage rows = image.format() == format ? image : image.convertToFormat(format);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    QByteArray bytes;
    bool ok = false;
    if (info) {
        bytes.reserve(qsizetype(rows.sizeInBytes() / 16)); // grows when the frame is busier
        png_set_write_fn(png, &bytes, append, flush);
        ok = writeRows(png, info, rows, alpha, std::clamp(zlibLevel, -1, 9));
    }
    png_destroy_write_struct(&png, &info);
    return ok ? bytes : QByteArray();
}

} // namespace lb
