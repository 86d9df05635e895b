#include "headless.h"

#include "diagnostics.h"
#include "heap_warmer.h"
#include "message_text.h"
#include "offscreen.h"
#include "plot_output.h"
#include "program_route.h"
#include "resident_memory.h"
#include "safe_write.h"
#include "scene_budget.h"
#include "standard_output.h"
#include "view_coverage.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>

namespace lb {

namespace {

// Qt maps PNG quality 80 to zlib level 1: about three times faster than the default level
// on a 1920x1080 frame, for a file a few percent larger (mostly flat background).
constexpr int kPngQuality = 80;

double rounded(float v)
{
    return std::round(double(v) * 1e6) / 1e6;
}

QJsonArray array(const glm::vec3 &v)
{
    return QJsonArray{rounded(v.x), rounded(v.y), rounded(v.z)};
}

QJsonArray bytes(const glm::vec3 &v)
{
    return QJsonArray{int(std::lround(v.x * 255.0f)), int(std::lround(v.y * 255.0f)),
                      int(std::lround(v.z * 255.0f))};
}

// The end of a headless run that went well: what it used (the mesh, the driver's copies of
// it, the context) is the system's to free, at once; tearing it all down took about 50 ms of
// a 1M-triangle --render (issue 14). The sanitizer build tears down as usual, so that its leak
// check sees the whole run. A helper still running when this process ends is killed by the
// system (platform::dieWithParent() in import_main.cpp; Linux only), as ~ImportProcess would have
// done.
int leave(int code)
{
#ifdef LIGHTBENCH_SANITIZE
    return code;
#else
    std::fflush(nullptr);
    std::_Exit(code);
#endif
}

void printLine(const QByteArray &line, FILE *stream)
{
    std::fputs(line.constData(), stream);
    std::fputc('\n', stream);
    std::fflush(stream);
}

// A run's result as a JSON line on standard output; false, with the reason on stderr, when
// it did not get there whole (a closed stdout, a full disk).
bool printResult(const QJsonObject &o)
{
    const QString why = writeStandardOutput(QJsonDocument(o).toJson(QJsonDocument::Compact) + '\n');
    if (!why.isEmpty())
        printLine(("lightbench: " + why).toUtf8(), stderr);
    return why.isEmpty();
}

// With LIGHTBENCH_PHASES set, a run's parts as one JSON line on stderr: for each, the
// milliseconds since the run began when it ended, and as PHASE + "MB" this process's resident
// memory then (bench/mesh.sh's breakdown).
class PhaseLog
{
public:
    PhaseLog() { m_clock.start(); }
    void mark(const char *phase)
    {
        if (m_on) {
            m_marks[phase] = std::round(double(m_clock.nsecsElapsed()) * 1e-5) / 10.0;
            m_marks[QString(phase) + "MB"] = qint64(residentKB() / 1024); // resident then
        }
    }
    void print() const
    {
        if (m_on)
            printLine("phases: " + QJsonDocument(m_marks).toJson(QJsonDocument::Compact), stderr);
    }

private:
    bool m_on = qEnvironmentVariableIsSet("LIGHTBENCH_PHASES");
    QElapsedTimer m_clock;
    QJsonObject m_marks;
};

} // namespace

QJsonObject probeJson(const ProbeResult &probe, const glm::ivec3 &gpu, QPoint pixel,
                      const Scene &scene)
{
    QJsonObject o;
    o["pixel"] = QJsonArray{pixel.x(), pixel.y()};
    o["hit"] = probe.hit;
    o["gpu"] = QJsonArray{gpu.r, gpu.g, gpu.b};
    o["shading"] = toName(scene.shading.shading);
    o["specularModel"] = toName(scene.shading.specular);
    const TermSwitches &on = scene.shading.terms;
    QJsonArray terms;
    for (const auto &[name, enabled] :
         {std::pair{"ambient", on.ambient}, {"diffuse", on.diffuse}, {"specular", on.specular}})
        if (enabled)
            terms.append(name);
    o["terms"] = terms; // those switched on; each light below lists all three
    o["show"] = toName(scene.shading.show);
    if (!probe.hit)
        return o;
    const QJsonArray ref = bytes(probe.reference);
    o["reference"] = ref;
    int worst = 0;
    for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(o["gpu"].toArray()[c].toInt() - ref[c].toInt()));
    o["maxDifference"] = worst;
    o["object"] = probe.object;
    o["triangle"] = qint64(probe.triangle);
    o["position"] = array(probe.position);
    o["normal"] = array(probe.normal);
    o["V"] = array(viewVector(probe.position, scene.shading.projection));
    // Each enabled light's vectors and terms; the sums below are what the pixel shows.
    QJsonArray lights;
    for (const ProbeLight &light : probe.lights) {
        const LightingTerms &t = light.terms;
        QJsonObject l;
        l["light"] = light.index + 1;
        l["L"] = array(t.L);
        l["H"] = array(t.H);
        l["R"] = array(t.R);
        l["NdotL"] = rounded(t.nDotL);
        l[QLatin1String(specularModel(scene.shading.specular).angleKey)] = rounded(t.specularAngle);
        l["distance"] = rounded(t.distance); // 0 for a directional light
        l["attenuation"] = rounded(t.attenuation);
        l["spot"] = rounded(t.spot);
        l["ambient"] = array(t.ambient); // with attenuation and spot, switched on or not
        l["diffuse"] = array(t.diffuse);
        l["specular"] = array(t.specular);
        lights.append(l);
    }
    o["lights"] = lights;
    o["ambient"] = array(probe.total.ambient); // the sums: the terms switched on

    o["diffuse"] = array(probe.total.diffuse);
    o["specular"] = array(probe.total.specular);
    o["base"] = array(probe.base);
    // Where the texture is read and at which level of detail (as the GPU picks its mipmap).
    o["uv"] = QJsonArray{rounded(probe.uv.x), rounded(probe.uv.y)};
    o["levelOfDetail"] = rounded(probe.lod);
    return o;
}

QString formatDiagnostic(const Diagnostic &d, const CommandLine &cl)
{
    // Link messages belong to both files; they are given on the vertex shader's name.
    const QString &file = d.stage == ShaderStage::Fragment ? cl.fragmentPath : cl.vertexPath;
    const QString prefix = d.stage == ShaderStage::Link ? "link: " : "";
    return QString("%1:%2:%3: %4: %5%6")
        .arg(file, QString::number(d.line), QString::number(d.column),
             d.severity == Diagnostic::Severity::Error ? "error" : "warning", prefix, d.message);
}

namespace {

// How much of the heap to warm for these mesh files (heap_warmer.h): two and a half times
// their size, what a binary mesh's arrays take in this process at once (a 19 MB PLY of 1M
// triangles without normals: the received mesh 19 MB, then normal generation's arrays and the
// driver's copies 24 MB more, LIGHTBENCH_PHASES' resident memory); never more than an eighth
// of the machine's memory. Four times (until issue 36) ended the same phases no sooner and
// peaked 22 MB higher (196 against 174 MB): what is warmed and not used stays resident; twice
// was as fast and peaked at 178 MB (the heap's layout decides the last few MB). A text
// format's file is bigger than its mesh: more is warmed than used. Once the mesh is in the
// driver's buffers the freed heap is given back (HeapWarmer::giveBack): 174 -> 164 MB, for
// ~20 ms of the frame faulting its own pages in.
// Files of more than kMostWarmedFileBytes get none. The heap is warmed while the helper
// reads, which is when the helper is at its own peak (Assimp's whole scene, about 3.4 times a
// binary PLY): a 10M-triangle scan (190 MB) warmed 508 MB, and the two processes peaked
// together at 1.26 GB instead of 0.85, for a gain lost in the noise of 5 runs (4.5-8.7 s
// either way; 0.3 s in the best runs); warming it less kept the allocator's tuning and
// peaked at 0.92 GB (bench/README.md, issue 36).
constexpr qint64 kMostWarmedFileBytes = 128ll << 20;
std::size_t warmingBytes(const QStringList &paths)
{
    qint64 bytes = 0;
    for (const QString &path : paths)
        bytes += QFileInfo(path).size();
    if (bytes > kMostWarmedFileBytes)
        return 0;
    const qint64 cap = ImportLimits::machineMemoryMB() << 17; // MB / 8, in bytes
    return std::size_t(std::clamp<qint64>(5 * bytes / 2, 0, cap));
}

} // namespace

int runHeadless(const CommandLine &cl, const Scene &requested)
{
    PhaseLog phases;
    Scene scene = requested;
    // The helper reads the mesh file while this process sets up OpenGL.
    ImportProcess import;
    ImportResult imported;
    QEventLoop waiting;
    QObject::connect(&import, &ImportProcess::finished, &waiting, [&](const ImportResult &r) {
        imported = r;
        waiting.quit();
    });
    // Each file once, however many objects draw it.
    QStringList paths;
    for (const ObjectSettings &o : scene.objects)
        if (!o.meshPath.isEmpty() && !paths.contains(o.meshPath))
            paths << o.meshPath;
    if (!paths.isEmpty())
        import.start(paths.front(), cl.importLimits());

    OffscreenRenderer offscreen;
    if (const QString error = offscreen.initialize(cl.size); !error.isEmpty()) {
        printLine("lightbench: " + error.toUtf8(), stderr);
        return 1;
    }
    phases.mark("openGl");
    // The heap the mesh will be put in, touched while the helper reads; handed over when
    // Assimp is done reading (the stages after "reading": converting, receiving) or the
    // import ends.
    HeapWarmer heap(cl.check ? 0 : warmingBytes(paths)); // --check draws no frame
    QObject::connect(&import, &ImportProcess::progress, &waiting,
                     [&heap](double, const QString &stage) {
                         if (stage != QLatin1String("reading"))
                             heap.stop();
                     });
    double loadSeconds = 0.0;
    qint64 helperPeakKB = 0;
    QStringList readers;     // who read each file: "assimp", "ply", "stl"
    MeshFileSizes fileSizes; // for the scene budget
    for (int i = 0; i < int(paths.size()); ++i) {
        if (i > 0)
            import.start(paths[i], cl.importLimits());
        if (import.isRunning())
            waiting.exec();
        heap.stop();
        if (!imported.ok()) {
            printLine("lightbench: " + imported.error.toUtf8(), stderr);
            return 1;
        }
        offscreen.addMeshFile(imported.file);
        for (ObjectSettings &o : scene.objects)
            if (o.meshPath == imported.file->path && o.adoptFileMaterial)
                o.material = adoptMaterial(o.material, imported.file->material);
        loadSeconds += imported.file->seconds;
        const Mesh &m = *imported.file->mesh;
        fileSizes[imported.file->path] = {m.vertexCount(), m.triangleCount(), !m.normals.empty()};
        helperPeakKB = std::max(helperPeakKB, imported.file->helperPeakKB);
        readers << imported.file->reader;
    }
    if (!paths.isEmpty())
        phases.mark("import");
    // What the scene asks of this machine's memory, before any mesh is built (issue 29): a
    // scene over the budget is drawn with its tessellation lowered, and says so.
    if (const QString lowered = fitToBudget(scene, fileSizes, meshBudget()).message;
        !lowered.isEmpty())
        printLine(("lightbench: " +
                   (cl.scenePath.isEmpty() ? QString() : escapedName(cl.scenePath) + ": ") +
                   lowered)
                      .toUtf8(),
                  stderr);
    if (const QString error = offscreen.readTextureFiles(scene); !error.isEmpty()) {
        printLine("lightbench: " + error.toUtf8(), stderr);
        return 1;
    }
    if (cl.hasUserProgram()) {
        FILE *out = cl.check ? stdout : stderr;
        // The driver compiles, links and tries a stranger's program within bounds (one that
        // makes it take too much memory or time ends the process with a message on its line:
        // a driver stuck in a draw or a compile never returns to this thread), on small
        // frames before a frame at --size: a program that would take longer than the budget,
        // or hangs, exits 1 with a message on its loop's line.
        OffscreenProgramHost host(offscreen, scene);
        bool said = false; // the build's diagnostics, said once it linked (before the trial)
        const auto sayBuild = [&](const ProgramBuild &build) {
            for (const Diagnostic &d : build.diagnostics)
                printLine(formatDiagnostic(d, cl).toUtf8(), out);
            said = true;
        };
        const ProgramVerdict verdict = buildAndTryWithin(
            host, {cl.vertexSource, cl.fragmentSource, scene.bindings},
            {cl.size, cl.frameBudgetSeconds * 1000.0},
            [&](const Diagnostic &d) { printLine(formatDiagnostic(d, cl).toUtf8(), out); }, 1,
            sayBuild);
        if (!said)
            sayBuild(verdict.build);
        if (const Diagnostic *refusal = verdict.refusal())
            printLine(formatDiagnostic(*refusal, cl).toUtf8(), out);
        if (!verdict.accepted())
            return 1;
        if (cl.check)
            return 0;
    }

    for (const QString &turned : offscreen.facesRemarks(scene))
        printLine("lightbench: " + turned.toUtf8(), stderr);
    // A file that loads but draws nothing in view, or only its back, says why.
    for (int i = 0; i < int(scene.objects.size()); ++i) {
        const ObjectSettings &o = scene.objects[std::size_t(i)];
        if (o.meshPath.isEmpty())
            continue;
        if (const QString why = viewProblem(scene, i, offscreen.objectMesh(scene, i), cl.size);
            !why.isEmpty())
            printLine(("lightbench: " + escapedName(QFileInfo(o.meshPath).fileName()) + " " + why)
                          .toUtf8(),
                      stderr);
    }

    // Past here only pixels are needed, except by the probe: a big mesh's frame holds one
    // copy of it (the driver's) instead of three.
    if (!cl.probe) {
        imported.file.reset(); // the offscreen renderer's hold is the last: it lets go first
        offscreen.dropCpuMeshes(scene);
        heap.giveBack();
    }
    phases.mark("meshToGpu");

    if (cl.benchFrames > 0) {
        offscreen.renderFrames(scene, 3); // warm-up: uploads, shader variants
        QElapsedTimer timer;
        timer.start();
        offscreen.renderFrames(scene, cl.benchFrames);
        const double seconds = double(timer.nsecsElapsed()) * 1e-9;
        QJsonObject o;
        o["frames"] = cl.benchFrames;
        o["seconds"] = seconds;
        o["fps"] = double(cl.benchFrames) / seconds;
        o["triangles"] = qint64(offscreen.objectTriangleCount());
        o["size"] = QString("%1x%2").arg(cl.size.width()).arg(cl.size.height());
        o["peakMB"] = double(peakResidentKB()) / 1024.0; // this process, not the helper
        if (!paths.isEmpty()) {
            o["loadSeconds"] = loadSeconds;
            o["helperPeakMB"] = double(helperPeakKB) / 1024.0;
            o["readers"] = readers.join(',');
        }
        if (!printResult(o))
            return leave(1);
    }

    if (cl.probe) // its pixel is read as the frame is drawn, before the light's marker
        offscreen.renderer().setProbe({}, *cl.probe);
    if (cl.hasUserProgram()) // a frame that shows nothing is said, not only saved
        offscreen.renderer().lookAtNextFrame();
    const QImage frame = offscreen.render(scene);
    phases.mark("frame");
    if (const std::optional<FrameLook> look = offscreen.renderer().takeFrameLook();
        look && *look != FrameLook::Drawn)
        printLine(("lightbench: warning: " + frameLookWarning(*look)).toUtf8(), stderr);
    if (offscreen.wasReset()) { // a GPU's recovery: the frame is no picture
        const QString why = "the driver reset the OpenGL context while it drew this frame";
        if (cl.hasUserProgram())
            printLine(formatDiagnostic(refusalAt(cl.vertexSource, cl.fragmentSource,
                                                 why + ": an endless or very long loop?"),
                                       cl)
                          .toUtf8(),
                      stderr);
        else
            printLine("lightbench: " + why.toUtf8(), stderr);
        return 1;
    }
    if (!cl.renderPath.isEmpty() && !cl.plot) // --plot's picture is the plot, written below
        if (const QString error = writeImageSafely(cl.renderPath, frame, kPngQuality);
            !error.isEmpty()) {
            printLine("lightbench: --render: cannot write " + error.toUtf8(), stderr);
            return 1;
        }
    phases.mark("png");
    phases.print();
    if (scene.compare.mode == CompareMode::Difference) {
        const DifferenceStats &d = offscreen.renderer().difference();
        QJsonObject o;
        o["largestDifference"] = d.largest;
        o["at"] = QJsonArray{d.at.x(), d.at.y()};
        o["differing"] = std::round(d.differing * 1e6) / 1e6;
        o["shareWithin"] = std::round(d.shareWithin * 1e6) / 1e6; // of the pixels drawn
        o["tolerance"] = d.tolerance;
        if (!printResult(o))
            return leave(1);
    }
    if (cl.probe) {
        PixelView view;
        const ProbeResult probe =
            probeFramePixel(scene, offscreen.probedObjects(scene), cl.size, *cl.probe, &view);
        const QRgb drawn = frame.pixel(*cl.probe); // the difference view's: no surface read
        QJsonObject o = probeJson(probe,
                                  offscreen.renderer().probedColour().value_or(
                                      glm::ivec3(qRed(drawn), qGreen(drawn), qBlue(drawn))),
                                  *cl.probe, sceneOfSide(scene, view.sideB));
        if (scene.compare.mode != CompareMode::Off)
            o["side"] = view.sideB ? "B" : "A";
        if (!printResult(o))
            return leave(1);
        if (cl.plot) // the curves with the probed point marked (in the scene of its side)
            return leave(writePlotOutputs(cl, sceneOfSide(scene, view.sideB), &probe));
    }
    return leave(0);
}

} // namespace lb
