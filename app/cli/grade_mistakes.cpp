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

MistakeSearch findMistake(OffscreenRenderer &offscreen, const Exercise &exercise,
                          const std::vector<Scene> &cases, const std::vector<FailingCase> &failing,
                          const std::function<void(const QString &, const QString &)> &stop)
{
    MistakeSearch out;
    const GradingSpec &spec = exercise.grading;
    const ExerciseReference &ref = exercise.reference;
    if (failing.empty() || exercise.mistakes.empty())
        return out;
    double referenceShare = 0.0;
    for (const FailingCase &f : failing)
        referenceShare += f.result.shareWithin;
    referenceShare /= double(failing.size());

    std::vector<MistakeShares> shares;
    for (int i = 0; i < int(exercise.mistakes.size()); ++i) {
        const ExerciseMistake &m = exercise.mistakes[std::size_t(i)];
        if (m.isBuiltIn()) {
            offscreen.renderer().clearUserProgram();
        } else {
            // A stage the mistake leaves out is the reference's (a mistake in one stage is
            // written once).
            const QString vertex = m.vertex.isEmpty() ? ref.vertex : m.vertex;
            const QString fragment = m.fragment.isEmpty() ? ref.fragment : m.fragment;
            OffscreenProgramHost host(offscreen, cases.front());
            const ProgramVerdict verdict = buildAndTryWithin(
                host, {vertex, fragment}, {spec.size, kGradingTrialBudgetMs},
                [&](const Diagnostic &d) { stop("mistake refused", mistakeText(i, m, d)); }, 0);
            if (const Diagnostic *refusal = verdict.refusal()) {
                out.failure = "mistake refused";
                out.diagnostic = mistakeText(i, m, *refusal);
                return out;
            }
            if (!verdict.build.ok()) {
                const Diagnostic *first = verdict.build.firstError();
                out.failure = "mistake does not build";
                out.diagnostic = first ? mistakeText(i, m, *first)
                                       : QString("mistake %1 (%2): %3")
                                             .arg(i)
                                             .arg(escapedName(m.name), verdict.build.log());
                return out;
            }
        }
        double share = 0.0;
        SignatureAgreement signature;
        for (const FailingCase &f : failing) {
            const QImage frame =
                offscreen.render(mistakeScene(referenceCase(cases[f.index], ref), m));
            share += measureCase(f.student, frame, kBackgroundPixel, spec.tolerance, spec.passShare)
                         .shareWithin;
            const SignatureAgreement a =
                signatureAgreement(f.student, f.reference, frame, spec.tolerance);
            signature.differing += a.differing;
            signature.agreeing += a.agreeing;
        }
        if (offscreen.wasReset()) {
            out.failure = "mistake refused";
            out.diagnostic = QString("mistake %1 (%2): the driver reset the context")
                                 .arg(i)
                                 .arg(escapedName(m.name));
            return out;
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
