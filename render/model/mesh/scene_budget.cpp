#include "scene_budget.h"

#include "mesh.h"
#include "message_text.h"
#include "resident_memory.h"

#include <QCoreApplication>
#include <QLocale>

#include <algorithm>

namespace lb {

namespace {

// The translation context of this file's messages.
struct SceneBudgetMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::SceneBudget)
};

// Whose tessellation counts: the shapes that have one, unless a loaded file is drawn instead.
bool hasTessellation(const ObjectSettings &object, const MeshFileSizes &files)
{
    if (!object.meshPath.isEmpty() && files.count(object.meshPath))
        return false;
    return object.shape != Shape::Cube;
}

MeshCost costOf(std::uint64_t vertices, std::uint64_t triangles, bool flatNormalsGenerated)
{
    // Flat normals split every corner that does not share its face's normal: on a curved
    // surface, all of them.
    if (flatNormalsGenerated)
        vertices = std::max(vertices, 3 * triangles);
    return {triangles, vertices * kBytesPerVertex + triangles * kBytesPerTriangle};
}

MeshCost operator+(MeshCost a, MeshCost b)
{
    return {a.triangles + b.triangles, a.bytes + b.bytes};
}

// The scene's cost with every object's tessellation held to at most `cap`.
MeshCost costCapped(const Scene &scene, const MeshFileSizes &files, int cap)
{
    MeshCost total;
    for (ObjectSettings object : scene.objects) {
        if (hasTessellation(object, files))
            object.tessellation = std::min(object.tessellation, cap);
        total = total + objectCost(object, files);
    }
    return total;
}

QString countText(std::uint64_t n)
{
    const QLocale english(QLocale::English);
    if (n >= 10'000'000)
        return SceneBudgetMessages::tr("%1 million").arg(english.toString(double(n) / 1e6, 'f', 0));
    if (n >= 1'000'000)
        return SceneBudgetMessages::tr("%1 million").arg(english.toString(double(n) / 1e6, 'f', 1));
    return english.toString(qulonglong(n));
}

QString fitMessage(const Scene &scene, const BudgetFit &fit, const MeshBudget &budget, int askedMax,
                   bool askedSame)
{
    QStringList names;
    for (const int i : fit.lowered)
        names << QString("%1 #%2").arg(echoedValue(displayName(scene.objects[std::size_t(i)]), 60),
                                       QString::number(i + 1));
    const char *context = "lb::SceneBudget";
    //: what a scene asks for; %n the objects in the scene
    const QString asked =
        countedText(context,
                    askedSame ? QT_TRANSLATE_N_NOOP("lb::SceneBudget",
                                                    "%n object(s) at tessellation %1 would make %2 "
                                                    "triangles (~%3)")
                              : QT_TRANSLATE_N_NOOP("lb::SceneBudget",
                                                    "%n object(s) at tessellation up to %1 would "
                                                    "make %2 triangles (~%3)"),
                    int(scene.objects.size()))
            .arg(QString::number(askedMax), countText(fit.asked.triangles),
                 byteSizeText(fit.asked.bytes));
    //: what was done about it; %n the objects lowered, %2 their names
    const QString lowered =
        countedText(context,
                    fit.fits
                        ? QT_TRANSLATE_N_NOOP("lb::SceneBudget",
                                              "tessellation lowered to %1 on %n object(s) (%2) "
                                              "to fit %3, the most a scene may take on this "
                                              "machine (%4 of memory): %5 triangles now")
                        : QT_TRANSLATE_N_NOOP("lb::SceneBudget",
                                              "tessellation lowered to %1 on %n object(s) (%2) "
                                              "and still over %3, the most a scene may take on "
                                              "this machine (%4 of memory): ~%5 (its mesh files "
                                              "count in full)"),
                    int(fit.lowered.size()))
            .arg(QString::number(fit.tessellation), summarisedList(names, ", ", 4),
                 byteSizeText(budget.bytes), byteSizeText(budget.machineBytes),
                 fit.fits ? countText(fit.fitted.triangles) : byteSizeText(fit.fitted.bytes));
    //: what a scene asked for (%1) and what was lowered to fit it in memory (%2)
    return SceneBudgetMessages::tr("%1; %2").arg(asked, lowered);
}

} // namespace

std::uint64_t machineMemoryBytes()
{
    if (const std::uint64_t bytes = physicalMemoryBytes())
        return bytes;
    return 8ull << 30; // unknown (the portable layer): a laptop's
}

MeshBudget meshBudget(std::uint64_t machineBytes)
{
    return {std::min(machineBytes / 4, kMeshBudgetCap), machineBytes};
}

MeshCost objectCost(const ObjectSettings &object, const MeshFileSizes &files)
{
    const bool flat = object.normals == NormalMode::Flat;
    if (!object.meshPath.isEmpty())
        if (const auto file = files.find(object.meshPath); file != files.end()) {
            const MeshFileSize &f = file->second;
            // The file's own normals drawn: the mesh is used as it is.
            const bool generated = object.normals != NormalMode::File || !f.hasNormals;
            return costOf(f.vertices, f.triangles, generated && flat);
        }
    return costOf(shapeVertexCount(object.shape, object.tessellation),
                  shapeTriangleCount(object.shape, object.tessellation), flat);
}

MeshCost sceneCost(const Scene &scene, const MeshFileSizes &files)
{
    return costCapped(scene, files, limits::kMaxTessellation);
}

BudgetFit fitToBudget(Scene &scene, const MeshFileSizes &files, const MeshBudget &budget)
{
    BudgetFit fit;
    fit.asked = fit.fitted = sceneCost(scene, files);
    int askedMax = 0, askedMin = limits::kMaxTessellation;
    for (const ObjectSettings &o : scene.objects)
        if (hasTessellation(o, files)) {
            askedMax = std::max(askedMax, o.tessellation);
            askedMin = std::min(askedMin, o.tessellation);
        }
    if (fit.asked.bytes <= budget.bytes)
        return fit;
    fit.fits = false; // until lowered
    // The highest cap that fits (the cost only grows with the cap): binary search.
    int lo = limits::kMinTessellation, hi = std::max(lo, askedMax - 1);
    if (costCapped(scene, files, lo).bytes > budget.bytes)
        hi = lo; // over even at the least: the files or the object count alone
    while (lo < hi) {
        const int mid = lo + (hi - lo + 1) / 2;
        if (costCapped(scene, files, mid).bytes <= budget.bytes)
            lo = mid;
        else
            hi = mid - 1;
    }
    fit.tessellation = lo;
    for (int i = 0; i < int(scene.objects.size()); ++i) {
        ObjectSettings &o = scene.objects[std::size_t(i)];
        if (hasTessellation(o, files) && o.tessellation > lo) {
            o.tessellation = lo;
            fit.lowered.push_back(i);
        }
    }
    fit.fitted = sceneCost(scene, files);
    fit.fits = fit.fitted.bytes <= budget.bytes;
    if (fit.lowered.empty()) // nothing left to lower: said when it was lowered, not again
        return fit;
    fit.message = fitMessage(scene, fit, budget, askedMax, askedMin == askedMax);
    return fit;
}

int highestTessellation(const Scene &scene, int index, const MeshFileSizes &files,
                        const MeshBudget &budget)
{
    if (index < 0 || index >= int(scene.objects.size()) ||
        !hasTessellation(scene.objects[std::size_t(index)], files))
        return limits::kMaxTessellation;
    Scene trial = scene;
    const auto fitsAt = [&](int t) {
        trial.objects[std::size_t(index)].tessellation = t;
        return sceneCost(trial, files).bytes <= budget.bytes;
    };
    int lo = limits::kMinTessellation, hi = limits::kMaxTessellation;
    if (fitsAt(hi))
        return hi;
    while (lo < hi) {
        const int mid = lo + (hi - lo + 1) / 2;
        if (fitsAt(mid))
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

QString byteSizeText(std::uint64_t bytes)
{
    const QLocale english(QLocale::English);
    const double mb = double(bytes) / double(1 << 20);
    if (mb >= 1024.0)
        return SceneBudgetMessages::tr("%1 GB").arg(english.toString(mb / 1024.0, 'f', 1));
    return SceneBudgetMessages::tr("%1 MB").arg(english.toString(mb, 'f', 0));
}

} // namespace lb
