#include "grade.h"

#include "grading.h"
#include "import_process.h"
#include "offscreen.h"
#include "submission.h"
#include "texture_file.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSaveFile>
#include <QThread>
#include <QTimer>

#include <cstdio>
#include <memory>

namespace lb {

namespace {

constexpr QRgb kBackground = qRgb(41, 43, 48); // the renderer's clear colour
constexpr double kTrialBudgetMs = 2000.0;      // one frame at the grading size, at most

void printLine(const QString &line, FILE *stream)
{
    std::fputs(qPrintable(line + "\n"), stream);
    std::fflush(stream);
}

// The exercise file, checked: "PATH: why" when it cannot be graded against.
struct ExerciseFile
{
    SceneFile file;
    QString error;
};

ExerciseFile readExerciseFile(const QString &path)
{
    ExerciseFile e;
    const SceneFileRead read = readSceneFile(path);
    if (!read.file)
        e.error = read.error;
    else if (!read.exerciseError.isEmpty())
        e.error = QString("%1: %2").arg(path, read.exerciseError);
    else if (!read.file->exercise)
        e.error =
            QString("%1: not an exercise (the scene file has no \"exercise\" section)").arg(path);
    else
        e.file = *read.file;
    return e;
}

QString diagnosticText(const Diagnostic &d, const Submission &s)
{
    const QString file =
        QFileInfo(d.stage == ShaderStage::Fragment ? s.fragmentPath : s.vertexPath).fileName();
    return d.line > 0 ? QString("%1:%2: %3").arg(file).arg(d.line).arg(d.message)
                      : QString("%1: %2").arg(file, d.message);
}

// What one child said, or what became of it.
struct Graded
{
    QString name;
    QString status; // "graded", "does not compile", "does not link", "refused", "timed out", ...
    QString diagnostic;
    int cases = 0, passed = 0, worst = 0;
    double meanShare = 0.0;
};

Graded fromJson(const QJsonObject &o)
{
    Graded g;
    g.name = o["submission"].toString();
    g.status = o["status"].toString();
    g.diagnostic = o["diagnostic"].toString();
    const QJsonArray cases = o["cases"].toArray();
    g.cases = int(cases.size());
    double share = 0.0;
    for (const QJsonValue &c : cases) {
        g.passed += c["passed"].toBool();
        g.worst = std::max(g.worst, c["largest"].toInt());
        share += c["shareWithin"].toDouble();
    }
    g.meanShare = g.cases ? share / g.cases : 0.0;
    return g;
}

QString summaryLine(const Graded &g)
{
    if (g.status != "graded")
        return QString("%1: %2%3")
            .arg(g.name, g.status, g.diagnostic.isEmpty() ? QString() : ": " + g.diagnostic);
    return QString("%1: %2 %3/%4 cases, largest difference %5/255, %6% of pixels within "
                   "tolerance")
        .arg(g.name, g.passed == g.cases ? "passed" : "failed")
        .arg(g.passed)
        .arg(g.cases)
        .arg(g.worst)
        .arg(100.0 * g.meanShare, 0, 'f', 1);
}

QString csvField(QString s)
{
    if (s.contains(',') || s.contains('"') || s.contains('\n')) {
        s.replace('"', "\"\"");
        s = '"' + s + '"';
    }
    return s;
}

QString csv(const std::vector<Graded> &rows)
{
    QString out = "submission,status,cases_passed,cases,worst_difference,mean_share_within,"
                  "first_diagnostic\n";
    for (const Graded &g : rows)
        out += QStringList{csvField(g.name),
                           csvField(g.status),
                           QString::number(g.passed),
                           QString::number(g.cases),
                           QString::number(g.worst),
                           QString::number(g.meanShare, 'f', 4),
                           csvField(g.diagnostic.section('\n', 0, 0))}
                   .join(',') +
               "\n";
    return out;
}

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
        if (!o.textureFile.isEmpty() && !done.contains(o.textureFile)) {
            const TextureFileRead read = readTextureFile(o.textureFile);
            if (!read.texture)
                return read.error;
            offscreen.addTextureFile(o.textureFile, read.texture);
            done << o.textureFile;
        }
    }
    return {};
}

} // namespace

int runGradeOne(const CommandLine &cl)
{
    QJsonObject out;
    const auto finish = [&](const QString &status, const QString &diagnostic = {}) {
        out["status"] = status;
        if (!diagnostic.isEmpty())
            out["diagnostic"] = diagnostic;
        printLine(QString::fromUtf8(QJsonDocument(out).toJson(QJsonDocument::Compact)), stdout);
        return 0;
    };
    const Submission s = readSubmission(cl.gradeOne);
    out["submission"] = s.name;
    if (!s.error.isEmpty())
        return finish("unreadable", s.error);
    const ExerciseFile e = readExerciseFile(cl.exercisePath);
    if (!e.error.isEmpty())
        return finish("no exercise", e.error);
    const Exercise &exercise = *e.file.exercise;
    const GradingSpec &spec = exercise.grading;

    OffscreenRenderer offscreen;
    if (const QString error = offscreen.initialize(spec.size); !error.isEmpty())
        return finish("no OpenGL", error);
    if (const QString error = loadSceneFiles(offscreen, e.file.scene); !error.isEmpty())
        return finish("exercise files", error);
    const std::vector<Scene> cases = gradingCases(e.file.scene, spec, cl.seed);

    // The reference's frames first, then the student's: one program build each.
    std::vector<QImage> reference;
    if (exercise.reference.builtIn()) {
        offscreen.renderer().clearUserProgram();
        for (Scene c : cases) {
            c.shading.shading = exercise.reference.shading;
            c.shading.specular = exercise.reference.specular;
            reference.push_back(offscreen.render(c));
        }
    } else {
        const ProgramBuild build =
            offscreen.useProgram(exercise.reference.vertex, exercise.reference.fragment);
        if (!build.ok())
            return finish("reference does not link", build.log());
        for (const Scene &c : cases)
            reference.push_back(offscreen.render(c));
    }

    const ProgramBuild build = offscreen.useProgram(s.vertex, s.fragment);
    if (!build.ok()) {
        const auto first = std::find_if(
            build.diagnostics.begin(), build.diagnostics.end(),
            [](const Diagnostic &d) { return d.severity == Diagnostic::Severity::Error; });
        const bool compiled = first == build.diagnostics.end() || first->stage == ShaderStage::Link;
        return finish(compiled ? "does not link" : "does not compile",
                      first == build.diagnostics.end() ? build.log() : diagnosticText(*first, s));
    }
    // An endless loop or a program far too slow is refused before its frames are drawn
    // (the batch's time limit ends one that hangs anyway).
    const TrialResult trial = offscreen.tryUserProgram(
        cases.front(), s.vertex, s.fragment, spec.size, kTrialBudgetMs, kCommandLineTrial);
    if (trial.refusal)
        return finish("refused", diagnosticText(*trial.refusal, s));

    QJsonArray results;
    int worst = -1;
    CaseResult worstResult;
    QImage worstFrame;
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const QImage frame = offscreen.render(cases[k]);
        const CaseResult r =
            measureCase(frame, reference[k], kBackground, spec.tolerance, spec.passShare);
        results.append(QJsonObject{{"case", int(k)},
                                   {"largest", r.largest},
                                   {"at", QJsonArray{r.at.x(), r.at.y()}},
                                   {"shareWithin", r.shareWithin},
                                   {"compared", r.compared},
                                   {"passed", r.passed}});
        const bool worse =
            worst < 0 || r.shareWithin < worstResult.shareWithin ||
            (r.shareWithin == worstResult.shareWithin && r.largest > worstResult.largest);
        if (worse) {
            worst = int(k);
            worstResult = r;
            worstFrame = frame;
        }
    }
    out["cases"] = results;
    out["worstCase"] = worst;
    if (!cl.sheetsDir.isEmpty()) {
        const QString path = QDir(cl.sheetsDir).filePath(s.name + ".png");
        if (!gradingSheet(s.name, worstFrame, reference[std::size_t(worst)], worstResult, worst)
                 .save(path))
            out["sheetError"] = QString("%1: cannot write").arg(path);
        else
            out["sheet"] = path;
    }
    return finish("graded");
}

int runGrade(const CommandLine &cl)
{
    const ExerciseFile e = readExerciseFile(cl.exercisePath);
    if (!e.error.isEmpty()) {
        printLine("lightbench: --exercise: " + e.error, stderr);
        return 2;
    }
    if (!cl.sheetsDir.isEmpty() && !QDir().mkpath(cl.sheetsDir)) {
        printLine(QString("lightbench: --sheets: %1: cannot make the folder").arg(cl.sheetsDir),
                  stderr);
        return 2;
    }
    const int cases = e.file.exercise->grading.cases;
    // Time for one submission: its frames and its process; a hang ends here.
    const int limitMs = 30000 + 1500 * cases;

    std::vector<Graded> rows(std::size_t(cl.submissions.size()));
    bool anyUnreadable = false;
    std::vector<int> toRun;
    for (int i = 0; i < int(cl.submissions.size()); ++i) {
        const Submission s = readSubmission(cl.submissions[i]);
        rows[std::size_t(i)].name = s.name.isEmpty() ? cl.submissions[i] : s.name;
        if (!s.error.isEmpty()) {
            printLine("lightbench: " + s.error, stderr);
            rows[std::size_t(i)].status = "unreadable";
            rows[std::size_t(i)].diagnostic = s.error;
            anyUnreadable = true;
        } else {
            toRun.push_back(i);
        }
    }

    // Both cores (or as many as there are, up to 4): each submission in a process of its own.
    // LIGHTBENCH_GRADE_PROCESSES sets how many run at once (bench/grade.sh compares).
    const int asked = qEnvironmentVariableIntValue("LIGHTBENCH_GRADE_PROCESSES");
    const int parallel =
        asked > 0 ? std::min(asked, 16) : std::max(1, std::min(QThread::idealThreadCount(), 4));
    QEventLoop loop;
    QObject children; // owns the processes: each goes with it, whatever the loop left undone
    std::size_t next = 0;
    int running = 0;
    std::function<void()> startMore = [&] {
        while (running < parallel && next < toRun.size()) {
            const int i = toRun[next++];
            auto *p = new QProcess(&children);
            QStringList args{"--grade-one",   cl.submissions[i], "--exercise",
                             cl.exercisePath, "--seed",          QString::number(cl.seed)};
            if (!cl.sheetsDir.isEmpty())
                args << "--sheets" << cl.sheetsDir;
            auto *timer = new QTimer(p);
            timer->setSingleShot(true);
            QObject::connect(timer, &QTimer::timeout, p, [&rows, i, p] {
                rows[std::size_t(i)].status = "timed out";
                p->kill();
            });
            QObject::connect(
                p, &QProcess::finished, &loop, [&, i, p](int code, QProcess::ExitStatus status) {
                    Graded &row = rows[std::size_t(i)];
                    const QByteArray out = p->readAllStandardOutput();
                    const QJsonObject json =
                        QJsonDocument::fromJson(out.trimmed().split('\n').last()).object();
                    if (row.status == "timed out") {
                        row.diagnostic = QString("more than %1 s").arg(limitMs / 1000);
                    } else if (status == QProcess::CrashExit || json.isEmpty()) {
                        row.status = "crashed";
                        row.diagnostic = QString::fromUtf8(p->readAllStandardError())
                                             .trimmed()
                                             .section('\n', -1);
                        if (row.diagnostic.isEmpty())
                            row.diagnostic = QString("exit code %1").arg(code);
                    } else {
                        const QString name = row.name;
                        row = fromJson(json);
                        row.name = name;
                    }
                    p->deleteLater();
                    --running;
                    if (next >= toRun.size() && running == 0)
                        loop.quit();
                    else
                        startMore();
                });
            QObject::connect(p, &QProcess::errorOccurred, p, [p](QProcess::ProcessError error) {
                if (error == QProcess::FailedToStart) // no finished() follows: say it ended
                    emit p->finished(-1, QProcess::CrashExit);
            });
            ++running;
            p->start(QCoreApplication::applicationFilePath(), args);
            timer->start(limitMs);
        }
    };
    if (!toRun.empty()) {
        startMore();
        loop.exec();
    }

    for (const Graded &g : rows)
        printLine(summaryLine(g), stdout);
    if (!cl.reportPath.isEmpty()) {
        QSaveFile file(cl.reportPath);
        const QByteArray bytes = csv(rows).toUtf8();
        if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() ||
            !file.commit()) {
            printLine(QString("lightbench: --report: %1: cannot write").arg(cl.reportPath), stderr);
            return 1;
        }
    }
    return anyUnreadable ? 2 : 0;
}

} // namespace lb
