#include "shader_editor.h"

#include "glsl_lexer.h"

#include <Qsci/qscicommand.h>
#include <Qsci/qscicommandset.h>
#include <Qsci/qscistyle.h>
#include <Qsci/qscistyledtext.h>

#include <QFontDatabase>
#include <QRegularExpression>
#include <QSet>
#include <QWheelEvent>

#include <algorithm>
#include <map>

namespace lb {

namespace {
enum Marker { kErrorMarker = 0, kWarningMarker = 1 };
enum Indicator { kErrorSquiggle = 0, kWarningSquiggle = 1 };
const QColor kErrorColour("#c62828"), kWarningColour("#b26a00");
} // namespace

ShaderEditor::ShaderEditor(QWidget *parent) : QsciScintilla(parent)
{
    setLexer(new GlslLexer(this));

    setUtf8(true);
    setMarginType(0, NumberMargin);
    setMarginWidth(0, "0000");
    setMarginType(1, SymbolMargin);
    setMarginWidth(1, 14);
    setMarginSensitivity(1, false);
    setBraceMatching(SloppyBraceMatch);
    setAutoIndent(true);
    setIndentationsUseTabs(false);
    setIndentationWidth(4);
    setTabWidth(4);
    setCaretLineVisible(true);
    setCaretLineBackgroundColor(QColor("#f3f6fb"));
    // Completion from the GLSL words and every name already in the file (its declarations).
    setAutoCompletionSource(AcsNone);
    connect(this, &QsciScintillaBase::SCN_CHARADDED, this, &ShaderEditor::offerCompletion);
    connect(this, &QsciScintilla::userListActivated, this, &ShaderEditor::acceptCompletion);

    markerDefine(Circle, kErrorMarker);
    setMarkerBackgroundColor(kErrorColour, kErrorMarker);
    setMarkerForegroundColor(kErrorColour, kErrorMarker);
    markerDefine(RightTriangle, kWarningMarker);
    setMarkerBackgroundColor(kWarningColour, kWarningMarker);
    setMarkerForegroundColor(kWarningColour, kWarningMarker);
    indicatorDefine(SquiggleIndicator, kErrorSquiggle);
    setIndicatorForegroundColor(kErrorColour, kErrorSquiggle);
    indicatorDefine(SquiggleIndicator, kWarningSquiggle);
    setIndicatorForegroundColor(kWarningColour, kWarningSquiggle);
    setAnnotationDisplay(AnnotationBoxed);

    // Zoom belongs to the window's View menu (Ctrl++, Ctrl+=, Ctrl+-, Ctrl+0), which zooms
    // both stages and keeps the zoom. Scintilla's own keys would zoom one stage only, and it
    // types the keys it does not bind (Ctrl+= wrote "=" into the shader).
    for (QsciCommand::Command c : {QsciCommand::ZoomIn, QsciCommand::ZoomOut}) {
        QsciCommand *command = standardCommands()->find(c);
        command->setKey(0);
        command->setAlternateKey(0);
    }
}

void ShaderEditor::setZoom(int points)
{
    zoomTo(points);
    setMarginWidth(0, "0000"); // measured at the new size, so big line numbers fit
}

void ShaderEditor::wheelEvent(QWheelEvent *event)
{
    if (!(event->modifiers() & Qt::ControlModifier)) {
        QsciScintilla::wheelEvent(event);
        return;
    }
    // Scintilla would zoom this stage alone and past the panel's knowledge.
    const int y = event->angleDelta().y();
    if (y != 0)
        emit zoomRequested(y > 0 ? 1 : -1);
    event->accept();
}

void ShaderEditor::replaceText(const QString &text)
{
    if (text == this->text())
        return;
    if (length() == 0) { // nothing to bring back: a plain load
        setText(text);
        return;
    }
    // One undo step, so Ctrl+Z brings back what a preset, an example or a reset replaced.
    beginUndoAction();
    selectAll();
    replaceSelectedText(text);
    endUndoAction();
    setCursorPosition(0, 0); // a new program is read from its first line
    setFirstVisibleLine(0);
}

void ShaderEditor::clearDiagnostics()
{
    markerDeleteAll();
    clearAnnotations();
    const int last = lines() - 1;
    clearIndicatorRange(0, 0, last, lineLength(last), kErrorSquiggle);
    clearIndicatorRange(0, 0, last, lineLength(last), kWarningSquiggle);
    m_markedLines = 0;
}

void ShaderEditor::showDiagnostics(const std::vector<Diagnostic> &diagnostics)
{
    clearDiagnostics();
    static const QFont small = [] {
        QFont f = QFontDatabase::systemFont(QFontDatabase::FixedFont);
        f.setPointSizeF(f.pointSizeF() * 0.9);
        return f;
    }();
    static const QsciStyle errorStyle(-1, "error", kErrorColour, QColor("#fdecea"), small);
    static const QsciStyle warningStyle(-1, "warning", kWarningColour, QColor("#fff4e0"), small);

    // Several messages on one line share one annotation.
    std::map<int, std::pair<QString, bool>> notes; // line -> text, has an error
    for (const Diagnostic &d : diagnostics) {
        if (d.line < 1 || d.line > lines())
            continue;
        const int line = d.line - 1;
        const bool error = d.severity == Diagnostic::Severity::Error;
        auto &[text, hasError] = notes[line];
        //: a compiler's message under its line in the editor; %1 the message
        const QString said =
            error ? tr("error: %1").arg(d.message) : tr("warning: %1").arg(d.message);
        text += (text.isEmpty() ? "" : "\n") + said;
        hasError = hasError || error;
        if (d.column > 0) {
            // Underline from the column to the end of the word there.
            const QString lineText = this->text(line);
            int end = d.column - 1;
            while (end < lineText.size() &&
                   (lineText[end].isLetterOrNumber() || lineText[end] == '_'))
                ++end;
            end = std::max(end, d.column);
            fillIndicatorRange(line, d.column - 1, line, end,
                               error ? kErrorSquiggle : kWarningSquiggle);
        }
    }
    for (const auto &[line, note] : notes) {
        markerAdd(line, note.second ? kErrorMarker : kWarningMarker);
        annotate(line, QsciStyledText(note.first, note.second ? errorStyle : warningStyle));
    }
    m_markedLines = int(notes.size());
}

namespace {
constexpr int kCompletionList = 1;
constexpr int kMinPrefix = 2;

bool isIdentifierCharacter(QChar c)
{
    return c.isLetterOrNumber() || c == '_';
}
} // namespace

void ShaderEditor::offerCompletion(int character)
{
    if (!isIdentifierCharacter(QChar(character)))
        return;
    const QString prefix = wordBeforeCursor().text;
    if (prefix.size() < kMinPrefix || prefix[0].isDigit())
        return;

    static const QRegularExpression identifier(R"(\b[A-Za-z_]\w*\b)");
    QSet<QString> seen;
    QStringList candidates;
    auto consider = [&](const QString &word) {
        if (word.size() > prefix.size() && word.startsWith(prefix) && !seen.contains(word)) {
            seen.insert(word);
            candidates << word;
        }
    };
    for (const QString &word : GlslLexer::completionWords())
        consider(word);
    auto it = identifier.globalMatch(text());
    while (it.hasNext())
        consider(it.next().captured());
    if (candidates.isEmpty())
        return;
    candidates.sort();
    showUserList(kCompletionList, candidates);
}

void ShaderEditor::acceptCompletion(int id, const QString &word)
{
    if (id != kCompletionList)
        return;
    const WordBeforeCursor w = wordBeforeCursor();
    setSelection(w.line, w.start, w.line, w.end);
    replaceSelectedText(word);
}

ShaderEditor::WordBeforeCursor ShaderEditor::wordBeforeCursor() const
{
    WordBeforeCursor w;
    getCursorPosition(&w.line, &w.end);
    const QString lineText = text(w.line);
    w.start = w.end;
    while (w.start > 0 && isIdentifierCharacter(lineText[w.start - 1]))
        --w.start;
    w.text = lineText.mid(w.start, w.end - w.start);
    return w;
}

void ShaderEditor::goTo(int line, int column)
{
    const int l = std::max(0, line - 1);
    setCursorPosition(l, std::max(0, column - 1));
    ensureLineVisible(l);
    setFocus();
}

} // namespace lb
