#pragma once
// The program being edited, apart from any widget: the vertex and fragment sources, the files
// they came from (NAME.vert + NAME.frag, watched for changes made elsewhere), where the text
// came from, which stage has unsaved edits, and the built-in program that follows the shading
// choice while untouched. The editor panel shows it, the scene files and the session settings
// store it, and tests drive it without a window.

#include "diagnostics.h"
#include "scene_file.h"

#include <QFileSystemWatcher>
#include <QObject>
#include <QString>
#include <QStringList>

#include <array>
#include <optional>

class QSettings;

namespace lb {

struct Preset;

// A shader file's text, or why it was not read: anything that is not a regular file (a
// device such as /dev/zero, a FIFO, a folder) or is larger than a shader may be is refused
// before a byte of it is read, with a message naming the path and the limit.
struct ShaderFileRead
{
    QString text;
    QString error; // "PATH: ..." when not read
    bool ok() const { return error.isEmpty(); }
};
ShaderFileRead readShaderFile(const QString &path);

// Where the text came from, as data. Words for it are the view's business (translated when
// shown, never stored).
struct ShaderOrigin
{
    enum class Kind {
        Text,   // handed over as text (setSources): no name
        Preset, // the Presets menu; `name` is the preset's
        Files,  // a NAME.vert/NAME.frag pair; `name` is NAME
        Scene,  // a scene file's program; `name` as the file has it (may be empty)
    };
    Kind kind = Kind::Text;
    QString name;
    bool edited = false; // changed since it came from there
    // A scene's program: its name in each language its file gives (`name` is the English);
    // the editor shows the one of the lessons' language.
    LocalizedText names{};
    bool operator==(const ShaderOrigin &o) const
    {
        return kind == o.kind && name == o.name && edited == o.edited && names == o.names;
    }
};

class ShaderDocument : public QObject
{
    Q_OBJECT
public:
    // What a change of a watched file did.
    enum class DiskChange {
        Reloaded,  // the stage had no unsaved edits: it now holds the disk's text
        KeptEdits, // the stage has unsaved edits: they stay, the disk's text is not taken
        Gone,      // the file cannot be read any more: the text stays
    };
    Q_ENUM(DiskChange)

    explicit ShaderDocument(QObject *parent = nullptr);

    QString source(ShaderStage stage) const;
    // The user's edit of one stage: marks it modified (no compile is asked for; the view
    // decides when, e.g. after a pause in typing).
    void setSource(ShaderStage stage, const QString &text);
    // Replaces both sources with text of no file and no name; compiles at once.
    void setSources(const QString &vertex, const QString &fragment);
    void loadPreset(const Preset &preset);
    // While the document holds a built-in program untouched, it follows the Shading panel's
    // Gouraud/Phong choice; once edited it is the user's program and stays.
    void followShading(bool gouraud);
    bool showsBuiltIn() const;
    // The built-in program the text started from (Gouraud: true), edited or not; none for a
    // file, a scene's program or text handed over. An edited built-in keeps its shading.
    std::optional<bool> builtInBase() const { return m_builtInGouraud; }
    // The course model the text computes where it fixes it (Preset::gouraud, ::specular): an
    // edited built-in keeps its shading, the slides' presets their shading and N.H. Empty
    // while the untouched built-in program follows the panel, and for text of unknown origin.
    struct FixedModel
    {
        std::optional<bool> gouraud;
        std::optional<SpecularModel> specular;
        bool parallelView = false; // V = (0,0,1) whatever the projection
    };
    FixedModel fixedModel() const;

    ShaderOrigin origin() const; // `edited` also when there are unsaved edits now

    // Files: a pair NAME.vert + NAME.frag. openFiles() takes one or both; the missing partner
    // of a single file is looked for beside it. Each returns an empty string, or what went
    // wrong (then nothing changed but what was written).
    QString openFiles(const QStringList &paths);
    QString save();                         // to the files the pair came from
    QString saveAs(const QString &anyPath); // NAME.vert/NAME.frag (or NAME) -> both files
    QString filePath(ShaderStage stage) const;
    bool isModified() const;
    bool isModified(ShaderStage stage) const; // edits not in its file (or not as loaded)

    // The program for a scene file: none while the built-in one shows untouched.
    std::optional<ProgramText> program() const;
    // A scene file's program; none: the built-in program of the shading mode.
    void setProgram(const std::optional<ProgramText> &program, bool gouraud);

    // The sources, files, origin and unsaved-edit flags, in the settings' "editor" group;
    // restoreState() returns false when there was nothing to restore.
    void saveState(QSettings &settings) const;
    bool restoreState(QSettings &settings);

    // Asks for the program to be built from the current sources.
    void requestCompile();

    // Undoing a replacement (a preset, an example, a reset, files opened over the text): when
    // the user's undo has brought `stage` back to its text from before, while the other stage
    // still shows what replaced it, the view should undo the other stage too. Once both are
    // back, the document is again what it was: origin, files and built-in included.
    bool otherStageAwaitsUndo(ShaderStage stage) const;

signals:
    void sourceChanged(lb::ShaderStage stage); // edited or replaced
    void filesChanged();                       // a file path or a modified flag changed
    void changed();                            // anything above, or the origin: show, autosave
    void compileRequested(const QString &vertex, const QString &fragment);
    void diskChanged(lb::ShaderStage stage, lb::ShaderDocument::DiskChange change,
                     const QString &path);

private:
    struct Stage
    {
        QString text;
        QString saved;        // the text as its file (or its origin) has it
        QString path;         // absolute; empty when not from a file
        bool unsaved = false; // unsaved edits restored from the last session
        bool modified() const { return unsaved || text != saved; }
    };
    Stage &stage(ShaderStage s) { return m_stages[s == ShaderStage::Fragment ? 1 : 0]; }
    const Stage &stage(ShaderStage s) const { return m_stages[s == ShaderStage::Fragment ? 1 : 0]; }
    static void take(Stage &stage, const QString &text, const QString &path);
    // What a replacement can bring back.
    struct Snapshot
    {
        std::array<Stage, 2> stages;
        ShaderOrigin origin;
        std::optional<bool> builtInGouraud;
        std::array<QString, 2> builtInText;
    };
    Snapshot snapshot() const;
    // Takes `origin` and the built-in shown (the caller has set the stages, `before` is the
    // document before that), announces it all and asks for a compile.
    void loaded(const Snapshot &before, const ShaderOrigin &origin,
                std::optional<bool> builtInGouraud = std::nullopt);
    void restoreReplaced(); // both stages are back at the texts from before the replacement
    void announceFiles();   // filesChanged() when a path or a modified flag differs from before
    void watch();
    void fileChangedOnDisk(const QString &path);
    QString writeFiles(const QString &vertexPath, const QString &fragmentPath);

    std::array<Stage, 2> m_stages;        // vertex, fragment
    ShaderOrigin m_origin;                // `edited`: already edited when it was loaded
    std::optional<bool> m_builtInGouraud; // the built-in program loaded, Gouraud or Phong
    std::array<QString, 2> m_builtInText; // its sources
    std::optional<Snapshot> m_replaced;   // the document before the last replacement
    std::array<QString, 2> m_replacement; // the texts that replacement put in
    struct Announced
    {
        QString paths[2];
        bool modified[2] = {false, false};
        bool operator==(const Announced &o) const
        {
            return paths[0] == o.paths[0] && paths[1] == o.paths[1] &&
                   modified[0] == o.modified[0] && modified[1] == o.modified[1];
        }
    } m_announced;
    QFileSystemWatcher m_watcher;
};

} // namespace lb
