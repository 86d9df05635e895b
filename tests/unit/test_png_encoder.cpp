// The PNG writer of --render and of the window's exports (libpng, one row filter): every pixel
// comes back as it went in, alpha and all; the file is no bigger than QImageWriter's at the same
// zlib level; formats other than PNG still go through Qt; a null image is refused by name.
#include "png_encoder.h"
#include "safe_write.h"

#include <QBuffer>
#include <QFile>
#include <QImageReader>
#include <QImageWriter>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace lb;

namespace {

// A frame like --render's: a flat background, a shaded disc, a little noise on it.
QImage renderedLike(QSize size)
{
    QImage image(size, QImage::Format_RGB32);
    QRandomGenerator random(7);
    const QPointF centre(size.width() / 2.0, size.height() / 2.0);
    const double radius = 0.4 * std::min(size.width(), size.height());
    for (int y = 0; y < size.height(); ++y)
        for (int x = 0; x < size.width(); ++x) {
            const double d = std::hypot(x - centre.x(), y - centre.y()) / radius;
            if (d > 1.0) {
                image.setPixel(x, y, qRgb(38, 41, 46));
                continue;
            }
            const int shade = int(255 * (1.0 - d * d)) - int(random.bounded(2));
            image.setPixel(x, y, qRgb(std::max(shade, 0), std::max(shade / 2, 0), 40));
        }
    return image;
}

QImage decoded(const QByteArray &bytes)
{
    QImage image;
    image.loadFromData(bytes, "PNG");
    return image;
}

bool samePixels(const QImage &a, const QImage &b)
{
    if (a.size() != b.size())
        return false;
    const QImage x = a.convertToFormat(QImage::Format_ARGB32);
    const QImage y = b.convertToFormat(QImage::Format_ARGB32);
    for (int row = 0; row < x.height(); ++row)
        if (std::memcmp(x.constScanLine(row), y.constScanLine(row), size_t(x.width()) * 4) != 0)
            return false;
    return true;
}

} // namespace

class TestPngEncoder : public QObject
{
    Q_OBJECT

private slots:
    void pixelsComeBackAsTheyWent_data()
    {
        QTest::addColumn<QImage>("image");
        QTest::addColumn<int>("level");
        QTest::newRow("frame, level 1") << renderedLike({320, 200}) << 1;
        QTest::newRow("frame, default level") << renderedLike({320, 200}) << -1;
        QTest::newRow("frame, stored") << renderedLike({64, 48}) << 0;
        QTest::newRow("frame, level 9") << renderedLike({64, 48}) << 9;
        QTest::newRow("one pixel") << renderedLike({1, 1}) << 1;
        QTest::newRow("one row, odd width") << renderedLike({1001, 1}) << 1;
        QImage noise(97, 61, QImage::Format_RGB32);
        QRandomGenerator random(3);
        for (int y = 0; y < noise.height(); ++y)
            for (int x = 0; x < noise.width(); ++x)
                noise.setPixel(x, y, random.generate() | 0xff000000u);
        QTest::newRow("noise") << noise << 1;
        QImage translucent(50, 30, QImage::Format_ARGB32);
        for (int y = 0; y < translucent.height(); ++y)
            for (int x = 0; x < translucent.width(); ++x)
                translucent.setPixel(x, y, qRgba(5 * x, 8 * y, 200, (x * 37 + y * 11) % 256));
        QTest::newRow("alpha") << translucent << 1;
        QImage gray(40, 20, QImage::Format_Grayscale8);
        for (int y = 0; y < gray.height(); ++y)
            for (int x = 0; x < gray.width(); ++x)
                gray.setPixel(x, y, qRgb(6 * x, 6 * x, 6 * x));
        QTest::newRow("grayscale") << gray << 1;
        QTest::newRow("premultiplied")
            << translucent.convertToFormat(QImage::Format_ARGB32_Premultiplied) << 1;
    }

    void pixelsComeBackAsTheyWent()
    {
        QFETCH(QImage, image);
        QFETCH(int, level);
        const QByteArray bytes = encodePng(image, level);
        QVERIFY(bytes.startsWith("\x89PNG\r\n\x1a\n"));
        const QImage back = decoded(bytes);
        QCOMPARE(back.size(), image.size());
        QCOMPARE(back.hasAlphaChannel(), image.hasAlphaChannel());
        QVERIFY(samePixels(back, image));
    }

    void noBiggerThanQtsWriterAtTheSameLevel()
    {
        // Qt's quality 80 is zlib level 1, as --render writes; its writer tries every row
        // filter, this one keeps to Sub: on a rendered frame the file stays the same size.
        const QImage frame = renderedLike({960, 540});
        QByteArray qt;
        QBuffer buffer(&qt);
        QVERIFY(buffer.open(QIODevice::WriteOnly));
        QImageWriter writer(&buffer, "png");
        writer.setQuality(80);
        QVERIFY(writer.write(frame));
        const QByteArray ours = encodePng(frame, pngLevelForQuality(80));
        QVERIFY2(ours.size() <= qt.size() * 11 / 10,
                 qPrintable(QString("%1 bytes against Qt's %2").arg(ours.size()).arg(qt.size())));
        QVERIFY(encodePng(frame, 9).size() < encodePng(frame, 0).size() / 4);
    }

    void qualityMapsAsQtMapsIt()
    {
        QCOMPARE(pngLevelForQuality(-1), -1);
        QCOMPARE(pngLevelForQuality(0), 9);
        QCOMPARE(pngLevelForQuality(80), 1);
        QCOMPARE(pngLevelForQuality(100), 0);
        QCOMPARE(pngLevelForQuality(500), 0);
    }

    void nullImagesAreRefusedAndOtherFormatsGoThroughQt()
    {
        QVERIFY(encodePng(QImage()).isEmpty());
        QTemporaryDir dir;
        const QString png = dir.filePath("frame.png");
        QCOMPARE(writeImageSafely(png, QImage()), png + ": no image to write");
        QVERIFY(!QFile::exists(png));

        const QImage frame = renderedLike({64, 48});
        QCOMPARE(writeImageSafely(png, frame), QString());
        QVERIFY(samePixels(QImage(png), frame));
        const QString bare = dir.filePath("frame"); // no suffix: PNG
        QCOMPARE(writeImageSafely(bare, frame), QString());
        QCOMPARE(QImageReader(bare).format(), QByteArray("png"));
        const QString jpeg = dir.filePath("frame.jpg");
        QCOMPARE(writeImageSafely(jpeg, frame, 90), QString());
        QCOMPARE(QImageReader(jpeg).format(), QByteArray("jpeg"));
    }
};

QTEST_GUILESS_MAIN(TestPngEncoder)
#include "test_png_encoder.moc"
