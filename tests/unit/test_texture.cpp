// Texture lookups worked by hand: the nearest and linear filters at and between texel
// centres, repeat and clamp outside 0 to 1, the mipmap's 2x2 means, GL's level of detail and
// level selection for both mipmap filters.
#include "texture.h"

#include <QTest>

using namespace lb;

namespace {

// 4 x 2 texels, bottom row (t = 0) first as Texture stores them: grey levels 0, 40, 80, 120
// and 160, 200, 240, 255 above.
Texture fourByTwo()
{
    QImage file(4, 2, QImage::Format_RGB32);
    const int top[4] = {160, 200, 240, 255}, bottom[4] = {0, 40, 80, 120};
    for (int s = 0; s < 4; ++s) {
        file.setPixel(s, 0, qRgb(top[s], top[s], top[s])); // row 0 of a file is its top
        file.setPixel(s, 1, qRgb(bottom[s], bottom[s], bottom[s]));
    }
    return Texture::fromImage(file);
}

float grey(const glm::vec3 &c)
{
    return c.r * 255.0f;
}

constexpr TextureSampling kNearest{TextureWrap::Repeat, TextureFilter::Nearest, false};
constexpr TextureSampling kLinear{TextureWrap::Repeat, TextureFilter::Linear, false};

} // namespace

class TestTexture : public QObject
{
    Q_OBJECT
private slots:
    void nearestReadsTheTexelUnderTheCoordinate()
    {
        const Texture t = fourByTwo();
        QCOMPARE(grey(t.sample({0.125f, 0.25f}, kNearest)), 0.0f);   // texel (0, 0)'s centre
        QCOMPARE(grey(t.sample({0.49f, 0.25f}, kNearest)), 40.0f);   // still texel 1
        QCOMPARE(grey(t.sample({0.51f, 0.25f}, kNearest)), 80.0f);   // texel 2
        QCOMPARE(grey(t.sample({0.875f, 0.75f}, kNearest)), 255.0f); // top right
    }

    void linearWeighsTheFourAround()
    {
        const Texture t = fourByTwo();
        // At a texel centre, that texel; halfway between texels 1 and 2 of the bottom row,
        // their mean; at the middle of the four bottom-left texels, the mean of 0, 40, 160, 200.
        QCOMPARE(grey(t.sample({0.375f, 0.25f}, kLinear)), 40.0f);
        QVERIFY(std::abs(grey(t.sample({0.5f, 0.25f}, kLinear)) - 60.0f) < 1e-3f);
        QVERIFY(std::abs(grey(t.sample({0.25f, 0.5f}, kLinear)) - 100.0f) < 1e-3f);
    }

    void repeatAndClampOutsideTheImage()
    {
        const Texture t = fourByTwo();
        TextureSampling clamp = kNearest;
        clamp.wrap = TextureWrap::Clamp;
        // u = 1.125 is texel 0 again when repeating, the last texel when clamping.
        QCOMPARE(grey(t.sample({1.125f, 0.25f}, kNearest)), 0.0f);
        QCOMPARE(grey(t.sample({1.125f, 0.25f}, clamp)), 120.0f);
        QCOMPARE(grey(t.sample({-0.125f, 0.25f}, kNearest)), 120.0f);
        QCOMPARE(grey(t.sample({-0.125f, 0.25f}, clamp)), 0.0f);
        // Linear at u = 0 (the left edge) mixes the last texel in when repeating, not when
        // clamping: (0 + 120) / 2 against 0.
        TextureSampling linearClamp = kLinear;
        linearClamp.wrap = TextureWrap::Clamp;
        QVERIFY(std::abs(grey(t.sample({0.0f, 0.25f}, kLinear)) - 60.0f) < 1e-3f);
        QCOMPARE(grey(t.sample({0.0f, 0.25f}, linearClamp)), 0.0f);
    }

    void theMipmapHalvesByTwoByTwoMeans()
    {
        const Texture t = fourByTwo();
        QCOMPARE(t.levelCount(), 3); // 4 x 2, 2 x 1, 1 x 1
        QCOMPARE(t.level(1).size(), QSize(2, 1));
        QCOMPARE(t.level(2).size(), QSize(1, 1));
        // Level 1's left texel: (0 + 40 + 160 + 200) / 4 = 100; its right: (80 + 120 + 240
        // + 255) / 4 = 173.75, rounded to 174; level 2: (100 + 174) / 2 = 137 (its single row
        // is used twice).
        QCOMPARE(grey(t.texel(1, 0, 0, TextureWrap::Repeat)), 100.0f);
        QCOMPARE(grey(t.texel(1, 1, 0, TextureWrap::Repeat)), 174.0f);
        QCOMPARE(grey(t.texel(2, 0, 0, TextureWrap::Repeat)), 137.0f);
        // The checker's 8-texel squares are grey from level 4 (4 x 4) on.
        const Texture checker;
        QCOMPARE(checker.levelCount(), 7);
        const glm::vec3 a = checker.texel(4, 0, 0, TextureWrap::Repeat),
                        b = checker.texel(4, 1, 0, TextureWrap::Repeat);
        QVERIFY(a == b);
    }

    void levelOfDetailIsLog2OfTexelsPerPixel()
    {
        const Texture t = fourByTwo(); // 4 texels across, 2 up
        // One texel per pixel step in x: 0; four: 2; the larger of x and y counts.
        QCOMPARE(t.levelOfDetail({0.25f, 0.0f}, {0.0f, 0.5f}), 0.0f);
        QCOMPARE(t.levelOfDetail({1.0f, 0.0f}, {0.0f, 0.5f}), 2.0f);
        QCOMPARE(t.levelOfDetail({0.25f, 0.0f}, {0.0f, 2.0f}), 2.0f);
        // A diagonal step: its length, sqrt(3^2 + 4^2) = 5 texels.
        QVERIFY(std::abs(t.levelOfDetail({0.75f, 2.0f}, {0.0f, 0.0f}) - std::log2(5.0f)) < 1e-5f);
    }

    void levelSelection()
    {
        const Texture t = fourByTwo();
        TextureSampling nearestMip = kNearest, trilinear = kLinear;
        nearestMip.mipmaps = trilinear.mipmaps = true;
        // Nearest mipmap: level 0 up to 0.5, then the nearest level (GL's ceil(lod + 0.5) - 1),
        // never past the last.
        QCOMPARE(t.levelsAt(0.4f, nearestMip).first, 0);
        QCOMPARE(t.levelsAt(0.6f, nearestMip).first, 1);
        QCOMPARE(t.levelsAt(1.4f, nearestMip).first, 1);
        QCOMPARE(t.levelsAt(1.6f, nearestMip).first, 2);
        QCOMPARE(t.levelsAt(9.0f, nearestMip).first, 2);
        // Trilinear: the two levels around, weighted by the fraction.
        const Texture::Levels l = t.levelsAt(1.25f, trilinear);
        QCOMPARE(l.first, 1);
        QCOMPARE(l.second, 2);
        QCOMPARE(l.weight, 0.25f);
        QVERIFY(std::abs(grey(t.sample({0.25f, 0.5f}, trilinear, 1.25f)) -
                         (0.75f * 100.0f + 0.25f * 137.0f)) < 1e-3f);
        // Magnified, or without mipmaps: level 0 only.
        QCOMPARE(t.levelsAt(-1.0f, trilinear).first, 0);
        QCOMPARE(t.levelsAt(3.0f, kLinear).first, 0);
        QCOMPARE(grey(t.sample({0.375f, 0.25f}, kLinear, 3.0f)), 40.0f);
    }

    // Images larger than Texture::kMaxSize are drawn scaled down, keeping their shape.
    void bigImagesAreScaledDown()
    {
        QImage wide(8192, 16, QImage::Format_RGB32);
        wide.fill(Qt::white);
        const Texture t = Texture::fromImage(wide);
        QCOMPARE(t.image().size(), QSize(4096, 8));
        QCOMPARE(t.levelCount(), 13); // 4096 wide: log2(4096) + 1 levels
    }
};

QTEST_MAIN(TestTexture)
#include "test_texture.moc"
