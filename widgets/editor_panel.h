#pragma once
// The shader editor dock: a tab for the vertex and one for the fragment shader of the program
// on screen, recompiled while typing (after a pause, 150 ms by default), at once on
// Ctrl+Enter, or only on demand; the diagnostics in a list below (click to jump); presets.

#include "glsl/program.h"

#include <QTimer>
#include <QWidget>

class QCheckBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QMenu;
class QSpinBox;
class QTabWidget;

namespace lb {

class ShaderEditor;
struct Preset;

class EditorPanel : public QWidget
{
    Q_OBJECT
public:
    explicit EditorPanel(QWidget *parent = nullptr);

    ShaderEditor *editor(ShaderStage stage) const;
    QString source(ShaderStage stage) const;
    QListWidget *diagnosticsList() const { return m_list; }
    QMenu *presetsMenu() const { return m_presets; }
    QCheckBox *liveCheck() const { return m_live; }
    QSpinBox *delayBox() const { return m_delay; }
    QLabel *statusLabel() const { return m_status; }

    // Replaces both sources (no compile pause: the new program is asked for at once).
    void setSources(const QString &vertex, const QString &fragment);
    void loadPreset(const Preset &preset);
    // While the editor shows a built-in program untouched, it follows the Shading panel's
    // Gouraud/Phong choice; once edited it is the user's program and stays.
    void followShading(bool gouraud);

public slots:
    void compileNow();
    void showBuild(const lb::ProgramBuild &build);

signals:
    void compileRequested(const QString &vertex, const QString &fragment);

private:
    void onEdited();
    void jumpTo(int row);

    QTabWidget *m_tabs;
    ShaderEditor *m_vertex;
    ShaderEditor *m_fragment;
    QListWidget *m_list;
    QMenu *m_presets;
    QCheckBox *m_live;
    QSpinBox *m_delay;
    QLabel *m_status;
    QLineEdit *m_find;
    QTimer m_pause;
    std::vector<Diagnostic> m_shown;
    QString m_builtInVertex, m_builtInFragment; // the built-in shown, while untouched
    bool m_builtInIsGouraud = false;
    bool m_loading = false;
};

} // namespace lb
