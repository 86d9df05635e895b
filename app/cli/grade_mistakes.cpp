#include "grade_mistakes.h"

#include "compare.h"
#include "grading_files.h"
#include "message_text.h"
#include "mistake_match.h"
#include "offscreen.h"
#include "program_route.h"
#include "work_check.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace lb {

namespace {

// "mistake 2 (normal matrix) vertex:19: message": the exercise's program, inline in its file.
QString mistakeText(int index, const ExerciseMistake &m, const Diagnostic &d)
{
    return exerciseProgramText(QString("mistake %1 (%2)").arg(index).arg(escapedName(m.name)), d);
}

} // namespace

GradeFailure useMistakeProgram(OffscreenRenderer &offscreen, const Exercise &exercise, int index,
                               const Scene &firstCase, const GradeStop &stop)
{
    GradeFailure out;
    const ExerciseMistake &m = exercise.mistakes[std::size_t(index)];
    const ExerciseReference &ref = exercise.reference;
    if (m.isBuiltIn()) {
        offscreen.renderer().clearUserProgram();
        return out;
    }
    // A stage the mistake leaves out is the reference's (a mistake in one stage is written
    // once).
    const QString vertex = m.vertex.isEmpty() ? ref.vertex : m.vertex;
    const QString fragment = m.fragment.isEmpty() ? ref.fragment : m.fragment;
    OffscreenProgramHost host(offscreen, firstCase);
    const ProgramVerdict verdict = buildAndTryWithin(
        host, {vertex, fragment, firstCase.bindings},
        {exercise.grading.size, exercise.grading.frameBudgetMs(), kGradingTrial},
        [&](const Diagnostic &d) { stop("mistake refused", mistakeText(index, m, d)); }, 0);
    if (const Diagnostic *refusal = verdict.refusal()) {
        out.status = "mistake refused";
        out.diagnostic = mistakeText(index, m, *refusal);
    } else if (!verdict.build.ok()) {
        const Diagnostic *first = verdict.build.firstError();
        out.status = "mistake does not build";
        out.diagnostic = first ? mistakeText(index, m, *first)
                               : QString("mistake %1 (%2): %3")
                                     .arg(index)
                                     .arg(escapedName(m.name), verdict.build.log());
    }
    return out;
}

QImage drawMistake(OffscreenRenderer &offscreen, const Exercise &exercise, int index,
                   const Scene &gradingCase)
{
    return offscreen.render(mistakeScene(referenceCase(gradingCase, exercise.reference),
                                         exercise.mistakes[std::size_t(index)]));
}

MistakeSearch findMistake(OffscreenRenderer &offscreen, const Exercise &exercise,
                          const std::vector<Scene> &cases, const std::vector<FailingCase> &failing,
                          const GradeStop &stop, const PreparedMistakeFrames &prepared)
{
    MistakeSearch out;
    const GradingSpec &spec = exercise.grading;
    if (failing.empty() || exercise.mistakes.empty())
        return out;
    double referenceShare = 0.0;
    std::vector<std::size_t> failingCases;
    for (const FailingCase &f : failing) {
        referenceShare += f.result.shareWithin;
        failingCases.push_back(f.index);
    }
    referenceShare /= double(failing.size());

    std::vector<MistakeShares> shares;
    for (int i = 0; i < int(exercise.mistakes.size()); ++i) {
        std::optional<std::vector<QImage>> frames =
            prepared ? prepared(i, failingCases) : std::nullopt;
        if (!frames) {
            out.failure = useMistakeProgram(offscreen, exercise, i, cases.front(), stop);
            if (out.failure)
                return out;
            frames.emplace();
            for (const FailingCase &f : failing)
                frames->push_back(drawMistake(offscreen, exercise, i, cases[f.index]));
            if (offscreen.wasReset()) {
                out.failure.status = "mistake refused";
                out.failure.diagnostic =
                    QString("mistake %1 (%2): the driver reset the context")
                        .arg(i)
                        .arg(escapedName(exercise.mistakes[std::size_t(i)].name));
                return out;
            }
        }
        double share = 0.0;
        SignatureAgreement signature;
        for (std::size_t k = 0; k < failing.size(); ++k) {
            const FailingCase &f = failing[k];
            const QImage &frame = (*frames)[k];
            share += measureCase(f.student, frame, kBackgroundPixel, spec.tolerance, spec.passShare)
                         .shareWithin;
            const SignatureAgreement a =
                signatureAgreement(f.student, f.reference, frame, spec.tolerance);
            signature.differing += a.differing;
            signature.agreeing += a.agreeing;
        }
        shares.push_back(
            {share / double(failing.size()),
             signature.differing ? double(signature.agreeing) / double(signature.differing) : 0.0,
             signature.differing});
    }
    if (const int best = bestMistake(referenceShare, shares); best >= 0) {
        const ExerciseMistake &m = exercise.mistakes[std::size_t(best)];
        out.match =
            MistakeMatch{best, m.name, localized(m.hint, "en"), shares[std::size_t(best)].share};
    }
    return out;
}

} // namespace lb
