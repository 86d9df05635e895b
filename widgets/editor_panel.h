#pragma once
// The shader editor dock: a tab for the vertex and one for the fragment shader of the program
// on screen, recompiled while typing (after a pause, 150 ms by default), at once on
// Ctrl+Enter, or only on demand; the diagnostics in a list below (click to jump); presets.

#include "program_build.h"
#include "scene_file.h"

#include <QFileSystemWatcher>
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

    // Files: a pair NAME.vert + NAME.frag. open() takes one or both; the missing partner of a
    // single file is looked for beside it. Returns an empty string, or what went wrong.
    QString openFiles(const QStringList &paths);
    QString save();                         // to the files the pair came from
    QString saveAs(const QString &anyPath); // NAME.vert/NAME.frag (or NAME) -> both files
    QString filePath(ShaderStage stage) const;
    // What is in the editor, in words: a preset's name, the file, "edited" when changed.
    QString programName() const;
    // Changed since it came from its preset, file or scene (or saved in a scene as edited).
    bool isEdited() const;
    bool showsBuiltIn() const; // an untouched built-in program, following the Shading panel
    // The program for a scene file: none while the built-in one shows untouched.
    std::optional<ProgramText> program() const;
    // A scene file's program; none: the built-in program of the shading mode.
    void setProgram(const std::optional<ProgramText> &program, bool gouraud);
    bool isModified() const;
    bool isModified(ShaderStage stage) const;

    // The sources, their files and modified flags; written within half a second of every
    // edit, so that a crash or a kill loses nothing, and read back at the next start.
    void saveState(QSettings &settings) const;
    bool restoreState(QSettings &settings); // false when there was nothing to restore

public slots:
    void compileNow();
    void showBuild(const lb::ProgramBuild &build);

signals:
    void compileRequested(const QString &vertex, const QString &fragment);
    void edited(); // the text changed: time to autosave

private:
    void onEdited();
    void jumpTo(int row);
    void updateTitles();
    void watch();
    void fileChangedOnDisk(const QString &path);
    QString writeFile(ShaderStage stage, const QString &path);

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
    QString m_paths[2];          // vertex, fragment; empty when not from a file
    QString m_origin;            // the preset or file the text came from (a name: data, not words)
    bool m_originEdited = false; // it was already edited there (a scene file said so)
    // Unsaved edits restored from the last session (Scintilla can only clear its own flag).
    bool m_restoredUnsaved[2] = {false, false};
    QFileSystemWatcher m_watcher;
};

} // namespace lb
