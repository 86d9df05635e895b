// The difference view's numbers, measured on frames made here: the largest channel
// difference, where it is (GL's bottom-up rows turned top-left) and the share that differs.
#include "compare.h"

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

    void emptyFrame()
    {
        const DifferenceStats d = measureDifference(nullptr, nullptr, QSize(0, 0));
        QVERIFY(d.valid);
        QCOMPARE(d.largest, 0);
    }
};

QTEST_GUILESS_MAIN(TestDifference)
#include "test_difference.moc"
