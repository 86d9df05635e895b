// Compare views: each side of a split or a wipe is its own program's picture, as the
// reference says; the difference view is zero for one program on both sides and shows
// Gouraud against Phong at the highlight.
#include "reference_compare.h"

#include <QGuiApplication>
#include <QTest>

using namespace lb;
using namespace lb::test;

class TestCompare : public QObject
{
    Q_OBJECT
private:
    OffscreenRenderer m_offscreen;

private slots:
    void initTestCase()
    {
        const QString error = m_offscreen.initialize(kSize);
        QVERIFY2(error.isEmpty(), qPrintable(error));
    }

    void eachSideMatchesItsReference_data()
    {
        QTest::addColumn<int>("mode");
        QTest::addColumn<float>("wipe");
        QTest::newRow("side by side") << int(CompareMode::SideBySide) << 0.5f;
        QTest::newRow("wipe 0.3") << int(CompareMode::Wipe) << 0.3f;
        QTest::newRow("wipe 0.7") << int(CompareMode::Wipe) << 0.7f;
    }

    void eachSideMatchesItsReference()
    {
        QFETCH(int, mode);
        QFETCH(float, wipe);
        Scene s = testScene();
        s.compare.mode = CompareMode(mode);
        s.compare.wipe = wipe;
        s.shading.shading = Shading::Phong;
        s.compare.shading = Shading::Gouraud;
        s.compare.specular = SpecularModel::Phong;
        const QString failure =
            checkAgainstReference(m_offscreen, s, QTest::currentDataTag(), 100, 3);
        QVERIFY2(failure.isEmpty(), qPrintable(failure));

        // And the two sides really are two programs: a side alone differs from the frame.
        const QImage frame = m_offscreen.render(s);
        Scene one = s;
        one.compare.mode = CompareMode::Off;
        QVERIFY(largestDifference(frame, m_offscreen.render(one)) > 20);
    }

    void differenceIsZeroForOneProgramOnBothSides()
    {
        Scene s;
        s.showLight = false;
        s.compare.mode = CompareMode::Difference;
        s.compare.shading = s.shading.shading;
        s.compare.specular = s.shading.specular;
        const QImage frame = m_offscreen.render(s);
        const DifferenceStats &d = m_offscreen.renderer().difference();
        QVERIFY(d.valid);
        QCOMPARE(d.largest, 0);
        QCOMPARE(d.differing, 0.0);
        // The picture is black but for the colour scale at the right edge.
        const QRgb middle = frame.pixel(kSize.width() / 2, kSize.height() / 2);
        QCOMPARE(qRed(middle) + qGreen(middle) + qBlue(middle), 0);
        const QRgb scaleTop = frame.pixel(kSize.width() - 20, int(kSize.height() * 0.12));
        QVERIFY(qRed(scaleTop) > 200 && qGreen(scaleTop) > 200); // white: the top of the scale
    }

    void differenceShowsGouraudAgainstPhongAtTheHighlight()
    {
        Scene s; // the window's coarse sphere, where the two differ most
        s.showLight = false;
        const QPoint peak = brightestGreen(m_offscreen.render(s));
        s.compare.mode = CompareMode::Difference;
        s.compare.shading = Shading::Gouraud;
        s.compare.specular = s.shading.specular;
        const QImage frame = m_offscreen.render(s);
        const DifferenceStats &d = m_offscreen.renderer().difference();
        QVERIFY2(d.largest >= 20, qPrintable(QString("largest %1/255").arg(d.largest)));
        QVERIFY(d.differing > 0.05);
        const QRgb atPeak = frame.pixel(peak);
        QVERIFY2(qRed(atPeak) + qGreen(atPeak) + qBlue(atPeak) > 150,
                 qPrintable(saveForInspection(frame, "difference")));
        // The largest difference is where the two programs' own pictures say it is.
        s.compare.mode = CompareMode::Off;
        const QImage phong = m_offscreen.render(s);
        s.shading.shading = Shading::Gouraud;
        const QImage gouraud = m_offscreen.render(s);
        const QRgb p = phong.pixel(d.at), g = gouraud.pixel(d.at);
        const int there = std::max({std::abs(qRed(p) - qRed(g)), std::abs(qGreen(p) - qGreen(g)),
                                    std::abs(qBlue(p) - qBlue(g))});
        QVERIFY(std::abs(there - d.largest) <= 1);
    }
};

int main(int argc, char **argv)
{
    setDefaultGlFormat();
    QGuiApplication app(argc, argv);
    TestCompare test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_compare.moc"
