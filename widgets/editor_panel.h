#pragma once
// The shader editor dock: a view of the ShaderDocument, with a tab for the vertex and one for
// the fragment shader of the program on screen, recompiled while typing (after a pause, 150 ms
// by default), at once on Ctrl+Enter, or only on demand; the diagnostics in a list below
// (click to jump); presets.

#include "program.h"
#include "shader_document.h"

#include <QTimer>
#include <QWidget>

class QCheckBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QMenu;
class QSettings;
class QSpinBox;
class QTabWidget;
class QToolButton;

namespace lb {

class ShaderEditor;
struct Preset;

// What the program is called where the user reads it ("Toon (edited)"): words made from the
// origin's data at display time, never stored.
QString programDisplayName(const ShaderOrigin &origin);

class EditorPanel : public QWidget
{
    Q_OBJECT
public:
    // The panel shows and edits `document`, which must live while the panel is in use (the
    // window's member document goes before the window's child widgets: see the destructor).
    explicit EditorPanel(ShaderDocument *document, QWidget *parent = nullptr);
    ~EditorPanel() override;

    ShaderDocument *document() const { return m_document; }
    ShaderEditor *editor(ShaderStage stage) const;
    QListWidget *diagnosticsList() const { return m_list; }
    QMenu *presetsMenu() const { return m_presets; }
    QCheckBox *liveCheck() const { return m_live; }
    QSpinBox *delayBox() const { return m_delay; }
    QLabel *statusLabel() const { return m_status; }
    QString programName() const { return programDisplayName(m_document->origin()); }

    // The document's, as the panel shows it (what tests and the window reach through it).
    QString source(ShaderStage stage) const { return m_document->source(stage); }
    void loadPreset(const Preset &preset) { m_document->loadPreset(preset); }
    QString openFiles(const QStringList &paths) { return m_document->openFiles(paths); }
    QString save() { return m_document->save(); }
    QString saveAs(const QString &anyPath) { return m_document->saveAs(anyPath); }
    QString filePath(ShaderStage stage) const { return m_document->filePath(stage); }
    std::optional<ProgramText> program() const { return m_document->program(); }
    bool isModified() const { return m_document->isModified(); }

    // The editor's zoom, in steps of one point (View > Zoom In Editor, Ctrl++), kept with the
    // settings, and the UI scale (1.0 to 2.5), which grows the text in proportion on top.
    static constexpr int kMinZoom = -6, kMaxZoom = 20;
    int zoom() const { return m_zoom; }
    void setZoom(int steps);
    void setUiScale(double scale);
    // The text size of the editors in points, zoom and scale included.
    double fontPointSize() const;
    // Whether restoreState() brought back edits that were never saved (a crash, a kill).
    bool restoredUnsavedEdits() const { return m_restoredUnsaved; }
    // Typed text waiting for the live compile's pause to end.
    bool isCompilePending() const { return m_pause.isActive(); }

    // The live switch and its pause, the zoom, and the document's state
    // (ShaderDocument::saveState), in the settings' "editor" group.
    void saveState(QSettings &settings) const;
    bool restoreState(QSettings &settings); // false when there was no document to restore

public slots:
    void compileNow();
    void startFind(); // Edit > Find in Shader (Ctrl+F), from anywhere in the window
    void undo();      // in the stage shown (Edit > Undo in the Editor)
    void redo();
    void showBuild(const lb::ProgramBuild &build);

signals:
    void compileRequested(const QString &vertex, const QString &fragment);

protected:
    // Esc in the find field; the stage tabs' width (fitPresetButton)
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void typed(ShaderStage stage);
    void showSource(ShaderStage stage);
    void showDiskChange(ShaderStage stage, ShaderDocument::DiskChange change, const QString &path);
    void jumpTo(int row);
    void updateTitles();
    void fitPresetButton();
    void applyZoom();
    void fitMessages();
    int scaleShare() const; // the points the UI scale adds

    ShaderDocument *m_document;
    QTabWidget *m_tabs;
    ShaderEditor *m_vertex;
    ShaderEditor *m_fragment;
    QListWidget *m_list;
    QMenu *m_presets;
    QToolButton *m_presetButton;
    QCheckBox *m_live;
    QSpinBox *m_delay;
    QLabel *m_status;
    QLineEdit *m_find;
    QTimer m_pause;
    std::vector<Diagnostic> m_shown;
    bool m_typing = false;  // the user's text is on its way to the document
    bool m_showing = false; // the document's text is on its way to an editor
    int m_zoom = 0;
    double m_uiScale = 1.0;
    bool m_restoredUnsaved = false;
};

} // namespace lb
