#include "probe_equation_words.h"

#include "choice_labels.h"

#include <QCoreApplication>
#include <QStringList>

namespace lb {

namespace {

constexpr const char *kContext = "lb::ProbeEquation";

QString partForDisplay(const EquationPart &part)
{
    QString text = part.text;
    if (part.kind == EquationPart::Kind::Phrase)
        text = QCoreApplication::translate(kContext, part.text.toUtf8().constData());
    else if (part.kind == EquationPart::Kind::ShowChoice)
        if (const std::optional<ShowChoice> show = parseShowChoice(part.text))
            text = showLabel(*show);
    return part.beside(text);
}

} // namespace

QString equationForDisplay(const std::vector<EquationLine> &lines)
{
    QStringList shown;
    for (const EquationLine &line : lines) {
        QStringList parts;
        for (const EquationPart &part : line.parts)
            parts << partForDisplay(part);
        const QString pattern = line.words ? QCoreApplication::translate(kContext, line.pattern)
                                           : QString::fromUtf8(line.pattern);
        shown << fillPattern(pattern, parts);
    }
    return shown.join('\n');
}

} // namespace lb
