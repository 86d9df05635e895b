#pragma once
// One shader's source: GLSL highlighting, line numbers, brace matching, auto-indent,
// completion (GLSL words and the names in the file), and the driver's diagnostics shown where
// the user looks: a margin marker, the message under the line, a squiggle at the column.

#include "diagnostics.h"

#include <Qsci/qsciscintilla.h>

#include <vector>

namespace lb {

class ShaderEditor : public QsciScintilla
{
    Q_OBJECT
public:
    explicit ShaderEditor(QWidget *parent = nullptr);

    void showDiagnostics(const std::vector<Diagnostic> &diagnostics);
    void clearDiagnostics();
    int markedLineCount() const { return m_markedLines; } // lines carrying a marker
    void goTo(int line, int column);                      // 1-based; column 0 = start of the line
    // Shows `text` as one undoable step (Ctrl+Z brings the old text back), unlike setText(),
    // which empties the undo history.
    void replaceText(const QString &text);
    // Points added to every font size (Scintilla's zoom), the line numbers' margin following.
    void setZoom(int points);

signals:
    // Ctrl+wheel: one step in (+1) or out (-1), for the panel to zoom both stages and keep it.
    void zoomRequested(int steps);

protected:
    void wheelEvent(QWheelEvent *event) override;

private:
    // Completion without QsciAPIs: its preparation runs on a thread that crashes when the
    // editor is destroyed first. The candidates are few; the GUI thread finds them at once.
    void offerCompletion(int character);
    void acceptCompletion(int id, const QString &word);
    struct WordBeforeCursor
    {
        int line = 0, start = 0, end = 0; // end is the cursor
        QString text;
    };
    WordBeforeCursor wordBeforeCursor() const;

    int m_markedLines = 0;
};

} // namespace lb
