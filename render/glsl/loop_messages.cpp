#include "loop_messages.h"

#include <QCoreApplication>

namespace lb {

namespace {

// The translation context of these messages.
struct LoopMessages
{
    Q_DECLARE_TR_FUNCTIONS(lb::Loops)
};

// [refusal][vertex][wraps]: the stage and the counter's note change the sentence, so each
// combination is a sentence of its own. %1: the steps.
const char *const kCountedLoop[2][2][2] = {
    {{QT_TRANSLATE_NOOP("lb::Loops",
                        "this loop runs %1 times for every fragment: a frame would take seconds "
                        "or more on any GPU (llvmpipe stops it after 65,535 steps and draws a "
                        "wrong picture)"),
      QT_TRANSLATE_NOOP("lb::Loops",
                        "this loop runs %1 times for every fragment (its counter moves away from "
                        "its bound: only wrapping around ends it): a frame would take seconds or "
                        "more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong "
                        "picture)")},
     {QT_TRANSLATE_NOOP("lb::Loops",
                        "this loop runs %1 times for every vertex: a frame would take seconds or "
                        "more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong "
                        "picture)"),
      QT_TRANSLATE_NOOP("lb::Loops",
                        "this loop runs %1 times for every vertex (its counter moves away from "
                        "its bound: only wrapping around ends it): a frame would take seconds or "
                        "more on any GPU (llvmpipe stops it after 65,535 steps and draws a wrong "
                        "picture)")}},
    {{QT_TRANSLATE_NOOP("lb::Loops",
                        "this program never finishes a frame: the loop here runs %1 times for "
                        "every fragment: a frame would take seconds or more on any GPU (llvmpipe "
                        "stops it after 65,535 steps and draws a wrong picture)"),
      QT_TRANSLATE_NOOP("lb::Loops",
                        "this program never finishes a frame: the loop here runs %1 times for "
                        "every fragment (its counter moves away from its bound: only wrapping "
                        "around ends it): a frame would take seconds or more on any GPU "
                        "(llvmpipe stops it after 65,535 steps and draws a wrong picture)")},
     {QT_TRANSLATE_NOOP("lb::Loops",
                        "this program never finishes a frame: the loop here runs %1 times for "
                        "every vertex: a frame would take seconds or more on any GPU (llvmpipe "
                        "stops it after 65,535 steps and draws a wrong picture)"),
      QT_TRANSLATE_NOOP("lb::Loops",
                        "this program never finishes a frame: the loop here runs %1 times for "
                        "every vertex (its counter moves away from its bound: only wrapping "
                        "around ends it): a frame would take seconds or more on any GPU "
                        "(llvmpipe stops it after 65,535 steps and draws a wrong picture)")}}};

} // namespace

LoopTexts countedLoopTexts(const QString &steps, ShaderStage stage, bool wraps)
{
    const int vertex = stage == ShaderStage::Vertex ? 1 : 0;
    const auto text = [&](int refusal) {
        return QCoreApplication::translate("lb::Loops", kCountedLoop[refusal][vertex][wraps])
            .arg(steps);
    };
    return {text(0), text(1)};
}

LoopTexts unconditionalLoopTexts(bool noCondition)
{
    return {noCondition
                ? LoopMessages::tr("this loop never ends: it has no condition and nothing in it "
                                   "breaks, returns or discards (the driver may drop it and draw "
                                   "garbage, or hang)")
                : LoopMessages::tr("this loop never ends: its condition is always true and "
                                   "nothing in it breaks, returns or discards (the driver may "
                                   "drop it and draw garbage, or hang)"),
            LoopMessages::tr(
                "this program never finishes a frame: the loop here has no condition (or an "
                "always-true one) and no break, return or discard")};
}

QString unchangedConditionWarning(const QStringList &names)
{
    //: %1 the names the loop's condition reads, as the shader spells them ("i, n")
    return names.size() == 1
               ? LoopMessages::tr("this loop never ends once it starts: its condition reads "
                                  "%1, and nothing in the loop changes it")
                     .arg(names.front())
               : LoopMessages::tr("this loop never ends once it starts: its condition reads "
                                  "%1, and nothing in the loop changes them")
                     .arg(names.join(", "));
}

QString withMacroNote(const QString &text, const QString &macro)
{
    //: %1 a message about a loop, %2 the name of the macro that writes the loop
    return LoopMessages::tr("%1 (the loop comes from macro %2, used on this line)")
        .arg(text, macro);
}

} // namespace lb
