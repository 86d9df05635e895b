#pragma once
// Test support: a rendered frame against the CPU reference, pixel by pixel.
#include "offscreen.h"
#include "probe.h"

#include <QImage>
#include <QPoint>
#include <QString>

namespace lb::test {

constexpr int kTolerance = 2; // per channel, out of 255
inline const QSize kSize(320, 240);

struct Comparison
{
    int compared = 0;
    int withSpecular = 0; // samples where the highlight contributes visibly
    int worst = 0;
    QPoint worstAt;
    QString worstText;
};

// The largest channel difference between a pixel and a reference colour (0-1), in 1/255.
int channelDifference(QRgb gpu, const glm::vec3 &reference);

// The pixel with the most green: the middle of a red material's white highlight.
QPoint brightestGreen(const QImage &frame);

// The largest channel difference between two frames of one size, in 1/255.
int largestDifference(const QImage &a, const QImage &b);

// Under the sanitizers (CI's last pass) the grids below are this many times coarser each way:
// the sanitizers watch the code paths, which a row's pixels all take alike, and comparing every
// fifth pixel of every row is the first pass's work. Under AddressSanitizer the full grids
// took 2 of the pass's 7 minutes (bench/README.md, "Build and CI").
#ifdef LIGHTBENCH_SANITIZE
inline constexpr int kGridCoarsening = 2;
#else
inline constexpr int kGridCoarsening = 1;
#endif
// A count of pixels that a test asks of a full grid (compared, with a highlight), for the
// grid this build compares.
inline int ofThisGrid(int fullGridCount)
{
    constexpr int share = kGridCoarsening * kGridCoarsening;
    return (fullGridCount + share - 1) / share;
}

// Under the sanitizers the long tables of cases (every shading x specular model x frame x w x
// projection) run every third row: the row's number is not a multiple of any column's count,
// so every value of every column still comes, in fewer of the combinations, which the first
// pass runs in full.
#ifdef LIGHTBENCH_SANITIZE
inline constexpr int kCaseStride = 3;
#else
inline constexpr int kCaseStride = 1;
#endif
// Whether the `row`th case (0, 1, 2... in the order they are made) runs in this build.
inline bool inThisBuildsCases(int row)
{
    return row % kCaseStride == 0;
}

// Compares a grid of pixels (every `step`th each way, times kGridCoarsening). Pixels on a
// silhouette or a crease (a neighbour two pixels away misses the object or sees a surface turned by
// more than ~11 degrees) are skipped: there the rasteriser and the ray may rightly pick different
// triangles; so are pixels by the edge of a spotlight's cone (a neighbour on its other side), and
// by a nearest-filtered texture's texel edges and level switches.
Comparison compareWithReference(OffscreenRenderer &offscreen, const Scene &scene,
                                const QImage &frame, int step = 5);

// Renders `scene` and compares it; returns an empty string, or what failed (the frame is then
// saved for inspection and its path is part of the message). minSpecular: how many compared
// pixels must show the highlight, so that a case whose highlight is out of view cannot pass
// by testing only ambient and diffuse.
QString checkAgainstReference(OffscreenRenderer &offscreen, const Scene &scene, const QString &name,
                              int minCompared, int minSpecular, int tolerance = kTolerance);

// Writes the frame to LB_TEST_OUTPUT/NAME.png (CMake's build/tests/test-output) for a person to
// look at; returns the path.
QString saveForInspection(const QImage &frame, const QString &name);

// A scene where the normal matrix matters: rotated and scaled non-uniformly, no light marker.
Scene testScene();

} // namespace lb::test
