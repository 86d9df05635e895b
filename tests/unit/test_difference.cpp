// The difference view's numbers, measured on frames made here: the largest channel
// difference, where it is (GL's bottom-up rows turned top-left) and the share that differs.
#include "compare.h"
#include "grading.h"

#include <QImage>
#include <QRandomGenerator>
#include <QTest>

#include <vector>

using namespace lb;

class TestDifference : public QObject
{
    Q_OBJECT
private slots:
    void identicalFramesDifferNowhere()
    {
        const std::vector<std::uint8_t> a(5 * 3 * 4, 77);
        const DifferenceStats d = measureDifference(a.data(), a.data(), QSize(5, 3));
        QVERIFY(d.valid);
        QCOMPARE(d.largest, 0);
        QCOMPARE(d.differing, 0.0);
    }

    void largestDifferenceAndWhere()
    {
        const QSize size(5, 3);
        std::vector<std::uint8_t> a(5 * 3 * 4, 100), b = a;
        auto at = [&](int x, int rowFromBottom, int channel) -> std::uint8_t & {
            return b[std::size_t((rowFromBottom * size.width() + x) * 4 + channel)];
        };
        at(1, 0, 0) = 110; // 10 in red, bottom row
        at(3, 2, 2) = 60;  // 40 in blue, top row: the largest
        at(4, 2, 1) = 60;  // 40 again later: the first one is reported
        at(0, 1, 3) = 0;   // alpha is not compared
        const DifferenceStats d = measureDifference(a.data(), b.data(), size);
        QCOMPARE(d.largest, 40);
        QCOMPARE(d.at, QPoint(3, 0)); // top-left origin: the top row is y = 0
        QCOMPARE(d.differing, 3.0 / 15.0);
    }

    // The view's share within the tolerance is Check My Work's for a case (grading.h): the
    // same pixels (drawn by either side: the background on both is not counted), the same
    // tolerance, the same share, on random frames with background between the surfaces.
    void theViewCountsAsGradingDoes()
    {
        const QSize size(37, 23);
        QRandomGenerator random(11);
        QImage a(size, QImage::Format_RGB32), b(size, QImage::Format_RGB32);
        for (int y = 0; y < size.height(); ++y)
            for (int x = 0; x < size.width(); ++x) {
                const bool background = random.bounded(3) == 0;
                const QRgb p = background ? kBackgroundPixel
                                          : qRgb(random.bounded(256), random.bounded(256), 90);
                const int shift = random.bounded(5); // 0..4: some within 2, some not
                a.setPixel(x, y, p);
                b.setPixel(x, y,
                           random.bounded(4) == 0
                               ? kBackgroundPixel
                               : qRgb(std::min(255, qRed(p) + shift), qGreen(p), qBlue(p)));
            }
        // As glReadPixels gives them: RGBA bytes, rows bottom-up.
        const auto bytes = [&](const QImage &image) {
            std::vector<std::uint8_t> out;
            for (int y = size.height() - 1; y >= 0; --y)
                for (int x = 0; x < size.width(); ++x) {
                    const QRgb p = image.pixel(x, y);
                    out.insert(out.end(), {std::uint8_t(qRed(p)), std::uint8_t(qGreen(p)),
                                           std::uint8_t(qBlue(p)), 255});
                }
            return out;
        };
        const std::vector<std::uint8_t> ba = bytes(a), bb = bytes(b);
        for (int tolerance : {0, 2, 3}) {
            const DifferenceStats view = measureDifference(ba.data(), bb.data(), size, tolerance);
            const CaseResult graded = measureCase(a, b, kBackgroundPixel, tolerance, 0.99);
            QCOMPARE(view.drawn, qint64(graded.compared));
            QCOMPARE(view.shareWithin, graded.shareWithin);
            QCOMPARE(view.largest, graded.largest);
            QVERIFY2(view.shareWithin > 0.05 && view.shareWithin < 0.95,
                     qPrintable(QString::number(view.shareWithin)));
        }
    }

    // Issue 36: grading reads frames by the row; what it counts is what QImage::pixel gives,
    // in every format a frame may come in (translucent pixels included), counted here pixel by
    // pixel as grading counted before.
    void gradingReadsEveryFormatAsPixelDoes_data()
    {
        QTest::addColumn<int>("format");
        for (QImage::Format f :
             {QImage::Format_RGB32, QImage::Format_ARGB32, QImage::Format_ARGB32_Premultiplied,
              QImage::Format_RGBA8888, QImage::Format_RGBA8888_Premultiplied,
              QImage::Format_RGBX8888, QImage::Format_RGB888, QImage::Format_RGBA64,
              QImage::Format_RGBA64_Premultiplied, QImage::Format_Indexed8, QImage::Format_RGB16,
              QImage::Format_ARGB8565_Premultiplied, QImage::Format_A2BGR30_Premultiplied})
            QTest::newRow(qPrintable(QString::number(int(f)))) << int(f);
    }

    void gradingReadsEveryFormatAsPixelDoes()
    {
        QFETCH(int, format);
        QRandomGenerator random(36);
        const auto frame = [&] {
            QImage image(37, 23, QImage::Format_ARGB32);
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x)
                    image.setPixel(x, y, (x + y) % 5 ? random.generate() : kBackgroundPixel);
            return image.convertToFormat(QImage::Format(format));
        };
        const QImage student = frame(), reference = frame(), mistake = frame();
        const auto difference = [](QRgb a, QRgb b) {
            return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                             std::abs(qBlue(a) - qBlue(b))});
        };
        const int tolerance = 60;
        int compared = 0, within = 0, differing = 0, agreeing = 0;
        for (int y = 0; y < reference.height(); ++y)
            for (int x = 0; x < reference.width(); ++x) {
                const QRgb s = student.pixel(x, y), r = reference.pixel(x, y),
                           m = mistake.pixel(x, y);
                if (difference(s, kBackgroundPixel) > 1 || difference(r, kBackgroundPixel) > 1) {
                    ++compared;
                    within += difference(s, r) <= tolerance;
                }
                if (difference(m, r) > tolerance) {
                    ++differing;
                    agreeing += difference(s, m) <= tolerance;
                }
            }
        const CaseResult graded = measureCase(student, reference, kBackgroundPixel, tolerance, 0.5);
        QCOMPARE(graded.compared, compared);
        QCOMPARE(graded.shareWithin, double(within) / double(compared));
        const SignatureAgreement a = signatureAgreement(student, reference, mistake, tolerance);
        QCOMPARE(a.differing, long(differing));
        QCOMPARE(a.agreeing, long(agreeing));
        QVERIFY(differing > 100 && agreeing > 10); // the frames differ, and not everywhere
    }

    void emptyFrame()
    {
        const DifferenceStats d = measureDifference(nullptr, nullptr, QSize(0, 0));
        QVERIFY(d.valid);
        QCOMPARE(d.largest, 0);
    }
};

QTEST_GUILESS_MAIN(TestDifference)
#include "test_difference.moc"
