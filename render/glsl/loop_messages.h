#pragma once
// The words of the endless-loop diagnostics (loops.h): a warning on the loop's line and, for a
// loop that never ends once it is reached, the reason the whole program is refused (the
// trial's, program_trial.h). Whole sentences, translated in the context lb::Loops, so that
// neither is made by cutting the other apart.

#include "diagnostics.h"

#include <QString>
#include <QStringList>

namespace lb {

struct LoopTexts
{
    QString warning; // "this loop runs ..."
    QString refusal; // "this program never finishes a frame: the loop here runs ..."
};

// A counted loop of `steps` steps ("2,000,000,000", as English writes it) for every vertex
// or fragment; `wraps`: its counter moves away from its bound, so only wrapping ends it.
LoopTexts countedLoopTexts(const QString &steps, ShaderStage stage, bool wraps);
// A loop with no condition (`noCondition`) or an always-true one, and no way out of its body.
LoopTexts unconditionalLoopTexts(bool noCondition);
// A loop whose condition reads only `names`, which nothing in the loop changes (a warning
// only: the condition may be false the first time).
QString unchangedConditionWarning(const QStringList &names);
// `text` with the note that the loop comes from `macro`, used on the line named.
QString withMacroNote(const QString &text, const QString &macro);

} // namespace lb
