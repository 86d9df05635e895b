#include "grade_frames.h"
#include "standard_output.h"

#include "grade.h"
#include "grading.h"
#include "import_process.h"
#include "message_text.h"
#include "offscreen.h"
#include "process_bounds.h"
#include "program_route.h"
#include "scene_budget.h"
#include "scene_file.h"
#include "work_check.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStorageInfo>

#include <algorithm>

namespace lb {

namespace {

// Meshes and images the exercise's scene names, read into `offscreen`; "" or why not.
QString loadSceneFiles(OffscreenRenderer &offscreen, const Scene &scene)
{
    QStringList done;
    for (const ObjectSettings &o : scene.objects) {
        if (!o.meshPath.isEmpty() && !done.contains(o.meshPath)) {
            const ImportResult r = ImportProcess::import(o.meshPath);
            if (!r.ok())
                return r.error;
            offscreen.addMeshFile(r.file);
            done << o.meshPath;
        }
    }
    return offscreen.readTextureFiles(scene);
}

QString referenceName(std::size_t gradingCase)
{
    return QString("reference-%1.rgb32").arg(gradingCase);
}

QString mistakeName(int index, std::size_t gradingCase)
{
    return QString("mistake-%1-%2.rgb32").arg(index).arg(gradingCase);
}

const char *const kKeyName = "key";

// What the frames were drawn from: the exercise as this process parsed it (written out again:
// the same text for the same exercise), the seed and the size. An exercise file changed
// while the batch runs parses into another key, and its children draw their own frames. (The
// meshes and images it names are keyed by their names only.)
QByteArray framesKey(const SceneFile &exercise, std::uint32_t seed, QSize size)
{
    QCryptographicHash hash(QCryptographicHash::Sha256);
    hash.addData(sceneFileBytes(exercise, QDir::root()));
    hash.addData(
        QString("seed %1 size %2x%3").arg(seed).arg(size.width()).arg(size.height()).toUtf8());
    return hash.result().toHex();
}

// The frame's pixels as they are in memory (QImage's RGB32 rows, 4 bytes a pixel, no
// padding): read back by PreparedFrames::read on this machine only.
bool writeFrame(const QString &path, const QImage &frame)
{
    QFile file(path);
    if (frame.format() != QImage::Format_RGB32 || !file.open(QIODevice::WriteOnly))
        return false;
    for (int y = 0; y < frame.height(); ++y) {
        const qint64 bytes = qint64(frame.width()) * 4;
        if (file.write(reinterpret_cast<const char *>(frame.constScanLine(y)), bytes) != bytes)
            return false;
    }
    return file.flush() && file.error() == QFileDevice::NoError;
}

bool writeBytes(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size() && file.flush();
}

} // namespace

GradingStart startGrading(const CommandLine &cl, OffscreenRenderer &offscreen)
{
    GradingStart start;
    start.exercise = readExerciseFile(cl.exercisePath);
    if (!start.exercise.error.isEmpty()) {
        start.failure = {"no exercise", start.exercise.error};
        return start;
    }
    const GradingSpec &spec = start.exercise.file.exercise->grading;
    if (const QString error = offscreen.initialize(spec.size); !error.isEmpty()) {
        start.failure = {"no OpenGL", error};
        return start;
    }
    if (const QString error = loadSceneFiles(offscreen, start.exercise.file.scene);
        !error.isEmpty()) {
        start.failure = {"exercise files", error};
        return start;
    }
    // An exercise is a scene someone handed out: held to the scene budget as the window and
    // --render hold it (the same lowered scene for the reference and the student's program).
    Scene base = start.exercise.file.scene;
    fitToBudget(base, {}, meshBudget());
    start.cases = gradingCases(base, spec, cl.seed);
    return start;
}

GradeFailure drawReference(OffscreenRenderer &offscreen, const Exercise &exercise,
                           const std::vector<Scene> &cases, const GradeStop &stop,
                           std::vector<QImage> &frames)
{
    frames.clear();
    if (exercise.reference.builtIn()) {
        offscreen.renderer().clearUserProgram();
        for (const Scene &c : cases)
            frames.push_back(offscreen.render(referenceCase(c, exercise.reference)));
        return {};
    }
    // The teacher's program is a stranger's too (an exercise handed on): tried as every
    // submission is. One that loops or is over the budget stops the batch, on its line.
    const QString &vertex = exercise.reference.vertex, &fragment = exercise.reference.fragment;
    OffscreenProgramHost host(offscreen, cases.front());
    const ProgramVerdict verdict = buildAndTryWithin(
        host, {vertex, fragment, cases.front().bindings},
        {exercise.grading.size, exercise.grading.frameBudgetMs(), kGradingTrial},
        [&](const Diagnostic &d) {
            stop("reference refused", exerciseProgramText("reference", d));
        },
        0);
    if (const Diagnostic *refusal = verdict.refusal())
        return {"reference refused", exerciseProgramText("reference", *refusal)};
    if (!verdict.build.ok())
        return {"reference does not build", verdict.build.log()};
    for (const Scene &c : cases)
        frames.push_back(offscreen.render(c));
    return {};
}

PreparedFrames::PreparedFrames(const QString &dir, const GradingStart &start, std::uint32_t seed)
    : m_dir(dir), m_size(start.exercise.file.exercise->grading.size)
{
    if (dir.isEmpty())
        return;
    // Regular files only: a FIFO in their place would block the read (the batch's own
    // folder holds none; the option is hidden, not guarded).
    QFile key(QDir(dir).filePath(kKeyName));
    const QByteArray expected = framesKey(start.exercise.file, seed, m_size);
    m_usable = QFileInfo(key).isFile() && key.open(QIODevice::ReadOnly) &&
               key.read(expected.size() + 1) == expected;
}

std::optional<QImage> PreparedFrames::read(const QString &name) const
{
    QFile file(QDir(m_dir).filePath(name));
    const qint64 rowBytes = qint64(m_size.width()) * 4;
    if (!m_usable || !QFileInfo(file).isFile() || !file.open(QIODevice::ReadOnly) ||
        file.size() != rowBytes * m_size.height())
        return std::nullopt;
    QImage frame(m_size, QImage::Format_RGB32);
    for (int y = 0; y < frame.height(); ++y)
        if (file.read(reinterpret_cast<char *>(frame.scanLine(y)), rowBytes) != rowBytes)
            return std::nullopt;
    return frame;
}

std::optional<std::vector<QImage>> PreparedFrames::reference(std::size_t cases) const
{
    std::vector<QImage> frames;
    for (std::size_t k = 0; k < cases; ++k) {
        std::optional<QImage> frame = read(referenceName(k));
        if (!frame)
            return std::nullopt;
        frames.push_back(std::move(*frame));
    }
    return frames;
}

std::optional<std::vector<QImage>>
PreparedFrames::mistake(int index, const std::vector<std::size_t> &cases) const
{
    std::vector<QImage> frames;
    for (std::size_t k : cases) {
        std::optional<QImage> frame = read(mistakeName(index, k));
        if (!frame)
            return std::nullopt;
        frames.push_back(std::move(*frame));
    }
    return frames;
}

int preparationTimeLimitMs(const GradingSpec &spec, int mistakes)
{
    const int asked = qEnvironmentVariableIntValue("LIGHTBENCH_GRADE_TIME_LIMIT_MS");
    // A trial and a frame of every case for the reference and for each mistake.
    const double frames = double(1 + mistakes) * double(spec.cases + 1);
    return asked > 0 ? asked : int(std::min(30000 + spec.frameBudgetMs() * frames, 3600000.0));
}

bool preparationWorthIt(const GradingSpec &spec, int mistakes, std::size_t submissions,
                        int parallel)
{
    const qint64 bytes = qint64(1 + mistakes) * qint64(spec.cases) * qint64(spec.size.width()) *
                         qint64(spec.size.height()) * 4;
    return submissions > std::size_t(std::max(parallel, 1)) && bytes <= kMostPreparedBytes &&
           bytes <= QStorageInfo(QDir::tempPath()).bytesAvailable() / 2;
}

void startPreparation(QProcess &preparation, const CommandLine &cl, const QString &dir)
{
    preparation.setStandardErrorFile(QProcess::nullDevice());
    // This program, never LIGHTBENCH_GRADE_PROGRAM's stand-in (the tests' children): the
    // frames are the real program's whatever plays the children.
    preparation.start(QCoreApplication::applicationFilePath(),
                      {"--grade-prepare", dir, "--exercise", cl.exercisePath, "--seed",
                       QString::number(cl.seed)});
}

bool preparedFrames(QProcess &preparation, int exitCode, QProcess::ExitStatus status)
{
    const QJsonObject said =
        QJsonDocument::fromJson(preparation.readAllStandardOutput().trimmed()).object();
    return status == QProcess::NormalExit && exitCode == 0 &&
           said["status"].toString() == "prepared";
}

int runGradePrepare(const CommandLine &cl)
{
    // Goes with the batch that started it, even one killed with SIGKILL.
    platform::dieWithParent();
    const auto finish = [](const QString &status, const QString &diagnostic = {}) {
        QJsonObject o{{"status", status}};
        if (!diagnostic.isEmpty())
            o["diagnostic"] = diagnostic;
        // Read by the batch from a pipe: what did not get there whole fails this child.
        return writeStandardOutput(QJsonDocument(o).toJson(QJsonDocument::Compact) + '\n').isEmpty()
                   ? 0
                   : 1;
    };
    OffscreenRenderer offscreen;
    const GradingStart start = startGrading(cl, offscreen);
    if (start.failure)
        return finish(start.failure.status, start.failure.diagnostic);
    const Exercise &exercise = *start.exercise.file.exercise;
    const QDir dir(cl.gradePrepare);
    const auto written = [&](const QString &name, const QImage &frame) {
        return writeFrame(dir.filePath(name), frame);
    };
    const GradeStop stop = [&](const QString &status, const QString &diagnostic) {
        finish(status, diagnostic);
    };

    std::vector<QImage> frames;
    if (const GradeFailure f = drawReference(offscreen, exercise, start.cases, stop, frames))
        return finish(f.status, f.diagnostic);
    for (std::size_t k = 0; k < frames.size(); ++k)
        if (!written(referenceName(k), frames[k]))
            return finish("not written", dir.filePath(referenceName(k)));
    for (int i = 0; i < int(exercise.mistakes.size()); ++i) {
        if (const GradeFailure f =
                useMistakeProgram(offscreen, exercise, i, start.cases.front(), stop))
            return finish(f.status, f.diagnostic);
        for (std::size_t k = 0; k < start.cases.size(); ++k)
            if (!written(mistakeName(i, k), drawMistake(offscreen, exercise, i, start.cases[k])))
                return finish("not written", dir.filePath(mistakeName(i, k)));
    }
    if (offscreen.wasReset())
        return finish("GPU reset", "the driver reset the context");
    if (!writeBytes(dir.filePath(kKeyName),
                    framesKey(start.exercise.file, cl.seed, exercise.grading.size)))
        return finish("not written", dir.filePath(kKeyName));
    return finish("prepared");
}

} // namespace lb
