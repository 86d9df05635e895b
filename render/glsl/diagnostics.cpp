#include "diagnostics.h"

#include <QRegularExpression>

#include <algorithm>

namespace lb {

namespace {

struct LogForm
{
    QRegularExpression pattern; // captures: severity word, line, column (optional), message
    int severity, line, column, message;
};

const std::vector<LogForm> &logForms()
{
    static const std::vector<LogForm> forms{
        // Mesa: 0:13(2): error: message
        // (also "preprocessor error" and the like)
        {QRegularExpression(R"(^\s*\d+:(\d+)\((\d+)\):\s*(?:\w+\s+)?(error|warning)\s*:\s*(.*)$)",
                            QRegularExpression::CaseInsensitiveOption),
         3, 1, 2, 4},
        // NVIDIA: 0(13) : error C1008: message
        {QRegularExpression(R"(^\s*\d+\((\d+)\)\s*:\s*(error|warning)\s*(?:[A-Z]\d+)?\s*:\s*(.*)$)",
                            QRegularExpression::CaseInsensitiveOption),
         2, 1, 0, 3},
        // AMD / Apple / ANGLE: ERROR: 0:13: message
        {QRegularExpression(R"(^\s*(error|warning)\s*:\s*\d+:(\d+):\s*(.*)$)",
                            QRegularExpression::CaseInsensitiveOption),
         1, 2, 0, 3},
    };
    return forms;
}

const QRegularExpression &placelessForm()
{
    // "error: message" with no place, or any other non-empty line (a link log). Mesa's link
    // log joins repeated messages with a "." at the start of the next: ".warning: ...".
    static const QRegularExpression form(R"(^[\s.]*(error|warning)\s*:?\s*(.*)$)",
                                         QRegularExpression::CaseInsensitiveOption);
    return form;
}

// NVIDIA's link log repeats the stage logs under "Vertex info" and a rule of dashes.
const QRegularExpression &heading()
{
    static const QRegularExpression form(R"(^(-+|(vertex|fragment|geometry) info)$)",
                                         QRegularExpression::CaseInsensitiveOption);
    return form;
}

Diagnostic::Severity severityOf(const QString &word)
{
    return word.compare("warning", Qt::CaseInsensitive) == 0 ? Diagnostic::Severity::Warning
                                                             : Diagnostic::Severity::Error;
}

} // namespace

QString stageName(ShaderStage stage)
{
    switch (stage) {
    case ShaderStage::Vertex:
        return "vertex";
    case ShaderStage::Fragment:
        return "fragment";
    case ShaderStage::Link:
        return "link";
    }
    return {};
}

std::vector<Diagnostic> parseDriverLog(const QString &log, ShaderStage stage, int linesAdded)
{
    std::vector<Diagnostic> out;
    for (const QString &raw : log.split('\n')) {
        const QString line = raw.trimmed();
        if (line.isEmpty() || line == ".") // Mesa ends a link log with a lone "."
            continue;
        Diagnostic d;
        d.stage = stage;
        bool placed = false;
        for (const LogForm &form : logForms()) {
            const QRegularExpressionMatch m = form.pattern.match(line);
            if (!m.hasMatch())
                continue;
            d.severity = severityOf(m.captured(form.severity));
            // A line inside the workbench's own prefix maps to the user's first line.
            d.line = std::max(1, m.captured(form.line).toInt() - linesAdded);
            d.column = form.column ? m.captured(form.column).toInt() : 0;
            d.message = m.captured(form.message).trimmed();
            placed = true;
            break;
        }
        if (!placed) {
            const QRegularExpressionMatch m = placelessForm().match(line);
            if (m.hasMatch()) {
                d.severity = severityOf(m.captured(1));
                d.message = m.captured(2).trimmed();
            } else if (heading().match(line).hasMatch()) {
                continue;
            } else {
                d.message = line;
            }
        }
        if (d.message.isEmpty())
            d.message = line;
        // Mesa repeats a link warning once per use; once is enough in the list.
        const bool repeated = std::any_of(out.begin(), out.end(), [&](const Diagnostic &o) {
            return o.severity == d.severity && o.line == d.line && o.column == d.column &&
                   o.message == d.message;
        });
        if (!repeated)
            out.push_back(d);
    }
    return out;
}

} // namespace lb
