// --grade-one: one submission graded in the batch's child process (grade.h): the reference's
// frames, then the student's program built and tried within bounds, then its frames measured
// against the reference's, case by case. Whatever happens, one line of JSON on stdout says it.
#include "grade.h"
#include "standard_output.h"

#include "grade_frames.h"
#include "grade_mistakes.h"
#include "grading.h"
#include "grading_files.h"
#include "grading_report.h"
#include "message_text.h"
#include "mistake_match.h"
#include "offscreen.h"
#include "process_bounds.h"
#include "program_route.h"
#include "safe_write.h"
#include "submission.h"
#include "work_check.h"

#include <QFileInfo>
#include <QJsonDocument>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>

namespace lb {

namespace {

// "lighting.frag:26: message": the student's file and line. A link error belongs to no one
// stage; a scene file's program is text inside the file, so its stage is named.
QString diagnosticText(const Diagnostic &d, const Submission &s)
{
    const bool scene = s.vertexPath == s.fragmentPath;
    QString where;
    if (d.stage == ShaderStage::Link)
        where =
            scene ? escapedName(QFileInfo(s.vertexPath).fileName()) + " (link)" : QString("link");
    else
        where =
            escapedName(QFileInfo(d.stage == ShaderStage::Fragment ? s.fragmentPath : s.vertexPath)
                            .fileName()) +
            (scene ? QString(" (%1)").arg(stageName(d.stage)) : QString());
    return d.line > 0 ? QString("%1:%2: %3").arg(where, QString::number(d.line), d.message)
                      : QString("%1: %2").arg(where, d.message);
}

} // namespace

int runGradeOne(const CommandLine &cl)
{
    // Goes with the batch or the window that started it, even one killed with SIGKILL.
    platform::dieWithParent();
    GradingReport out;
    const auto finish = [&](const QString &status, const QString &diagnostic = {}) {
        out.status = status;
        out.diagnostic = diagnostic;
        // Read by the batch or the window from a pipe: what did not get there whole fails it.
        const QByteArray json =
            QJsonDocument(gradingReportJson(out)).toJson(QJsonDocument::Compact);
        return writeStandardOutput(json + '\n').isEmpty() ? 0 : 1;
    };
    const Submission s = readSubmission(cl.gradeOne);
    const QString name = cl.gradeName.isEmpty() ? s.name : cl.gradeName;
    out.submission = name;
    if (!s.error.isEmpty())
        return finish("unreadable", s.error);
    OffscreenRenderer offscreen;
    const GradingStart start = startGrading(cl, offscreen);
    if (start.failure)
        return finish(start.failure.status, start.failure.diagnostic);
    const Exercise &exercise = *start.exercise.file.exercise;
    const GradingSpec &spec = exercise.grading;
    const std::vector<Scene> &cases = start.cases;
    const GradeStop stop = [&](const QString &status, const QString &diagnostic) {
        finish(status, diagnostic);
    };

    // The reference's frames first, then the student's: one program build each. The batch's
    // frames, when it drew them (grade_frames.h), are the same frames, drawn once for all.
    const PreparedFrames prepared(cl.gradeFrames, start, cl.seed);
    std::vector<QImage> reference;
    if (std::optional<std::vector<QImage>> read = prepared.reference(cases.size())) {
        reference = std::move(*read);
    } else {
        if (const GradeFailure f = drawReference(offscreen, exercise, cases, stop, reference))
            return finish(f.status, f.diagnostic);
    }

    // The driver compiles and tries the student's program within bounds: past one, the
    // report says so and this process ends (the driver never returns to this thread). An
    // endless loop or a program far too slow is refused before its frames are drawn (the
    // batch's time limit ends one that hangs anyway); the frames below are that limit's.
    OffscreenProgramHost host(offscreen, cases.front());
    const ProgramVerdict verdict = buildAndTryWithin(
        host, {s.vertex, s.fragment, cases.front().bindings},
        {spec.size, spec.frameBudgetMs(), kGradingTrial},
        [&](const Diagnostic &d) { finish("refused", diagnosticText(d, s)); }, 0);
    if (const Diagnostic *refusal = verdict.refusal())
        return finish("refused", diagnosticText(*refusal, s));
    if (!verdict.build.ok()) {
        const Diagnostic *first = verdict.build.firstError();
        const bool compiled = !first || first->stage == ShaderStage::Link;
        return finish(compiled ? "does not link" : "does not compile",
                      first ? diagnosticText(*first, s) : verdict.build.log());
    }

    int worst = -1;
    CaseResult worstResult;
    QImage worstFrame;
    std::vector<FailingCase> failing; // the first ones, for the known mistakes
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const QImage frame = offscreen.render(cases[k]);
        // A driver that reset its context drew nothing worth grading (a real GPU stopping a
        // program that ran too long in this case).
        if (offscreen.wasReset())
            return finish("GPU reset", QString("the driver reset the context in case %1: a "
                                               "loop too long for this case?")
                                           .arg(k));
        const CaseResult r =
            measureCase(frame, reference[k], kBackgroundPixel, spec.tolerance, spec.passShare);
        out.cases.push_back(r);
        if (!r.passed && int(failing.size()) < kMaxMistakeCases)
            failing.push_back({k, frame, reference[k], r});
        const bool worse =
            worst < 0 || r.shareWithin < worstResult.shareWithin ||
            (r.shareWithin == worstResult.shareWithin && r.largest > worstResult.largest);
        if (worse) {
            worst = int(k);
            worstResult = r;
            worstFrame = frame;
        }
    }
    out.worstCase = worst;
    // Never a hint for a submission that passes: the mistakes are drawn only for failures.
    const MistakeSearch search =
        findMistake(offscreen, exercise, cases, failing, stop,
                    [&](int index, const std::vector<std::size_t> &failingCases) {
                        return prepared.mistake(index, failingCases);
                    });
    if (search.failure) {
        out.cases.clear();
        return finish(search.failure.status, search.failure.diagnostic);
    }
    out.mistake = search.match;
    if (!cl.sheetsDir.isEmpty()) {
        const QString path = gradingSheetPath(cl.sheetsDir, name);
        // A sheet is whole or not there; why not is the submission's diagnostic.
        out.sheetError =
            writeImageSafely(path, gradingSheet(name, worstFrame, reference[std::size_t(worst)],
                                                worstResult, worst));
        if (out.sheetError.isEmpty())
            out.sheet = path;
    }
    return finish("graded");
}

} // namespace lb
