#include "shader_document.h"

#include "bounded_read.h"
#include "dialect.h"
#include "presets.h"
#include "safe_write.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSettings>

namespace lb {

ShaderFileRead readShaderFile(const QString &path)
{
    // UTF-8 takes at least a byte a character: a longer file is over the characters' limit.
    const BoundedRead read =
        readBounded(path, {QT_TRANSLATE_NOOP("lb::FileLimit", "a shader"), kMaxSourceCharacters});
    ShaderFileRead r;
    r.error = read.error;
    if (r.error.isEmpty())
        r.text = QString::fromUtf8(read.bytes);
    return r;
}

namespace {

constexpr ShaderStage kStages[] = {ShaderStage::Vertex, ShaderStage::Fragment};

QString partnerOf(const QString &path)
{
    const QFileInfo info(path);
    const QString other = info.suffix() == "vert" ? "frag" : "vert";
    return info.dir().filePath(info.completeBaseName() + "." + other);
}

ShaderStage stageOfFile(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    return suffix == "frag" || suffix == "fs" || suffix == "fsh" ? ShaderStage::Fragment
                                                                 : ShaderStage::Vertex;
}

// The settings' words for an origin's kind: data, never translated.
const char *const kKindNames[] = {"text", "preset", "files", "scene"};

QString kindName(ShaderOrigin::Kind kind)
{
    return kKindNames[int(kind)];
}

ShaderOrigin::Kind kindNamed(const QString &name)
{
    for (int i = 0; i < 4; ++i)
        if (name == kKindNames[i])
            return ShaderOrigin::Kind(i);
    return ShaderOrigin::Kind::Text;
}

} // namespace

ShaderDocument::ShaderDocument(QObject *parent) : QObject(parent)
{
    connect(&m_watcher, &QFileSystemWatcher::fileChanged, this, &ShaderDocument::fileChangedOnDisk);
}

QString ShaderDocument::source(ShaderStage s) const
{
    return stage(s).text;
}

void ShaderDocument::setSource(ShaderStage s, const QString &text)
{
    if (stage(s).text == text)
        return;
    stage(s).text = text;
    emit sourceChanged(s);
    if (m_replaced && m_stages[0].text == m_replaced->stages[0].text &&
        m_stages[1].text == m_replaced->stages[1].text)
        restoreReplaced();
    announceFiles();
    emit changed();
}

ShaderDocument::Snapshot ShaderDocument::snapshot() const
{
    return {m_stages, m_origin, m_builtInGouraud, m_builtInText};
}

bool ShaderDocument::otherStageAwaitsUndo(ShaderStage s) const
{
    if (!m_replaced)
        return false;
    const int i = s == ShaderStage::Fragment ? 1 : 0;
    const std::size_t self = std::size_t(i), other = std::size_t(1 - i);
    return m_stages[self].text == m_replaced->stages[self].text &&
           m_stages[other].text == m_replacement[other] &&
           m_replacement[other] != m_replaced->stages[other].text;
}

void ShaderDocument::restoreReplaced()
{
    m_stages = m_replaced->stages;
    m_origin = m_replaced->origin;
    m_builtInGouraud = m_replaced->builtInGouraud;
    m_builtInText = m_replaced->builtInText;
    m_replaced.reset();
    watch();
}

void ShaderDocument::take(Stage &stage, const QString &text, const QString &path)
{
    stage.text = stage.saved = text;
    stage.path = path;
    stage.unsaved = false;
}

void ShaderDocument::loaded(const Snapshot &before, const ShaderOrigin &origin,
                            std::optional<bool> builtInGouraud)
{
    // Only text worth bringing back is remembered (not the empty editor before a start).
    if (!before.stages[0].text.isEmpty() || !before.stages[1].text.isEmpty()) {
        m_replaced = before;
        m_replacement = {m_stages[0].text, m_stages[1].text};
    }
    m_origin = origin;
    m_builtInGouraud = builtInGouraud;
    if (builtInGouraud)
        m_builtInText = {m_stages[0].text, m_stages[1].text};
    watch();
    for (ShaderStage s : kStages)
        emit sourceChanged(s);
    announceFiles();
    emit changed();
    requestCompile();
}

void ShaderDocument::setSources(const QString &vertex, const QString &fragment)
{
    const Snapshot before = snapshot();
    take(m_stages[0], vertex, {});
    take(m_stages[1], fragment, {});
    loaded(before, {});
}

void ShaderDocument::loadPreset(const Preset &preset)
{
    const Snapshot before = snapshot();
    take(m_stages[0], preset.vertexSource(), {});
    take(m_stages[1], preset.fragmentSource(), {});
    std::optional<bool> builtIn;
    for (bool gouraud : {false, true})
        if (&builtInPreset(gouraud) == &preset)
            builtIn = gouraud;
    loaded(before, {ShaderOrigin::Kind::Preset, preset.name, false}, builtIn);
}

void ShaderDocument::followShading(bool gouraud)
{
    if (showsBuiltIn() && gouraud != *m_builtInGouraud)
        loadPreset(builtInPreset(gouraud));
}

bool ShaderDocument::showsBuiltIn() const
{
    return m_builtInGouraud && m_stages[0].text == m_builtInText[0] &&
           m_stages[1].text == m_builtInText[1];
}

ShaderDocument::FixedModel ShaderDocument::fixedModel() const
{
    if (showsBuiltIn())
        return {};
    if (m_builtInGouraud)
        return {m_builtInGouraud, std::nullopt};
    if (m_origin.kind == ShaderOrigin::Kind::Preset)
        if (const Preset *p = presetNamed(m_origin.name))
            return {p->gouraud,
                    p->specular ? parseSpecularModel(QString::fromLatin1(p->specular))
                                : std::nullopt,
                    p->parallelView};
    return {};
}

ShaderOrigin ShaderDocument::origin() const
{
    ShaderOrigin o = m_origin;
    o.edited = o.edited || isModified();
    return o;
}

QString ShaderDocument::filePath(ShaderStage s) const
{
    return stage(s).path;
}

bool ShaderDocument::isModified(ShaderStage s) const
{
    return stage(s).modified();
}

bool ShaderDocument::isModified() const
{
    return m_stages[0].modified() || m_stages[1].modified();
}

QString ShaderDocument::openFiles(const QStringList &paths)
{
    QString chosen[2];
    for (const QString &p : paths)
        chosen[stageOfFile(p) == ShaderStage::Fragment] = p;
    for (int i = 0; i < 2; ++i) // a single file brings its partner when there is one
        if (chosen[i].isEmpty() && !chosen[1 - i].isEmpty() &&
            QFileInfo::exists(partnerOf(chosen[1 - i])))
            chosen[i] = partnerOf(chosen[1 - i]);
    QString text[2];
    for (int i = 0; i < 2; ++i) {
        if (chosen[i].isEmpty())
            continue;
        const ShaderFileRead read = readShaderFile(chosen[i]);
        if (!read.ok())
            return tr("Cannot open %1").arg(read.error);
        text[i] = read.text;
    }
    // A stage with no file chosen keeps its text, its file and its unsaved edits.
    const Snapshot before = snapshot();
    for (int i = 0; i < 2; ++i)
        if (!chosen[i].isEmpty())
            take(m_stages[std::size_t(i)], text[i], QFileInfo(chosen[i]).absoluteFilePath());
    const QString named = m_stages[0].path.isEmpty() ? m_stages[1].path : m_stages[0].path;
    loaded(before, {ShaderOrigin::Kind::Files, QFileInfo(named).completeBaseName(), false});
    return {};
}

QString ShaderDocument::writeFiles(const QString &vertexPath, const QString &fragmentPath)
{
    QString error;
    const QString paths[2] = {vertexPath, fragmentPath};
    // As a pair: neither file is replaced unless both are written.
    if (const QString why = writeFilesSafely(
            {{paths[0], m_stages[0].text.toUtf8()}, {paths[1], m_stages[1].text.toUtf8()}});
        !why.isEmpty())
        error = tr("Cannot save %1").arg(why);
    for (int i = 0; i < 2 && error.isEmpty(); ++i) {
        Stage &s = m_stages[std::size_t(i)];
        s.path = QFileInfo(paths[i]).absoluteFilePath();
        s.saved = s.text;
        s.unsaved = false;
    }
    if (error.isEmpty()) { // the text is now the pair's, no longer a preset's or a built-in
        m_origin = {ShaderOrigin::Kind::Files, QFileInfo(vertexPath).completeBaseName(), false};
        m_builtInGouraud.reset();
    }
    // Our own writes come back as changes from outside; they read as what was saved.
    watch();
    announceFiles();
    emit changed();
    return error;
}

QString ShaderDocument::save()
{
    if (m_stages[0].path.isEmpty() || m_stages[1].path.isEmpty())
        return tr("The shaders have no files yet: use Save As");
    return writeFiles(m_stages[0].path, m_stages[1].path);
}

QString ShaderDocument::saveAs(const QString &anyPath)
{
    const QFileInfo info(anyPath);
    const QString base = info.suffix() == "vert" || info.suffix() == "frag"
                             ? info.dir().filePath(info.completeBaseName())
                             : info.absoluteFilePath();
    return writeFiles(base + ".vert", base + ".frag");
}

void ShaderDocument::watch()
{
    if (!m_watcher.files().isEmpty())
        m_watcher.removePaths(m_watcher.files());
    for (const Stage &s : m_stages)
        if (!s.path.isEmpty() && QFileInfo::exists(s.path))
            m_watcher.addPath(s.path);
}

void ShaderDocument::fileChangedOnDisk(const QString &path)
{
    for (ShaderStage st : kStages) {
        Stage &s = stage(st);
        if (s.path != path)
            continue;
        const ShaderFileRead read = readShaderFile(path);
        if (!read.ok()) { // gone, or no longer something to read (a huge file, a FIFO)
            emit diskChanged(st, DiskChange::Gone, path);
            continue;
        }
        const QString text = read.text;
        if (text == s.saved) // nothing new: our own save, or a touch
            continue;
        if (s.modified()) {
            emit diskChanged(st, DiskChange::KeptEdits, path);
            continue;
        }
        s.text = s.saved = text;
        emit sourceChanged(st);
        emit changed();
        requestCompile();
        emit diskChanged(st, DiskChange::Reloaded, path);
    }
    watch(); // editors that save by renaming replace the watched file
}

std::optional<ProgramText> ShaderDocument::program() const
{
    if (showsBuiltIn())
        return std::nullopt;
    const ShaderOrigin o = origin();
    return ProgramText{o.names.isEmpty() ? plainText(o.name) : o.names, m_stages[0].text,
                       m_stages[1].text, o.edited};
}

void ShaderDocument::setProgram(const std::optional<ProgramText> &program, bool gouraud)
{
    if (!program) {
        loadPreset(builtInPreset(gouraud));
        return;
    }
    const Snapshot before = snapshot();
    take(m_stages[0], program->vertex, {});
    take(m_stages[1], program->fragment, {});
    loaded(before, {ShaderOrigin::Kind::Scene, localized(program->name, "en"), program->edited,
                    program->name.size() > 1 || !program->name.contains("en") ? program->name
                                                                              : LocalizedText{}});
}

void ShaderDocument::saveState(QSettings &settings) const
{
    settings.beginGroup("editor");
    settings.setValue("vertex", m_stages[0].text);
    settings.setValue("fragment", m_stages[1].text);
    settings.setValue("vertexPath", m_stages[0].path);
    settings.setValue("fragmentPath", m_stages[1].path);
    settings.setValue("vertexModified", m_stages[0].modified());
    settings.setValue("fragmentModified", m_stages[1].modified());
    const bool builtIn = showsBuiltIn();
    settings.setValue("builtIn", builtIn ? (*m_builtInGouraud ? "gouraud" : "phong") : "");
    const ShaderOrigin o = origin();
    settings.setValue("originKind", kindName(o.kind));
    settings.setValue("origin", o.name);
    settings.setValue("originNames",
                      o.names.isEmpty()
                          ? QString()
                          : QString::fromUtf8(QJsonDocument(localizedTextJson(o.names).toObject())
                                                  .toJson(QJsonDocument::Compact)));
    settings.setValue("edited", o.edited);
    settings.endGroup();
}

bool ShaderDocument::restoreState(QSettings &settings)
{
    settings.beginGroup("editor");
    const bool saved = settings.contains("vertex");
    const QString builtIn = settings.value("builtIn").toString();
    Stage stages[2];
    const char *keys[2][3] = {{"vertex", "vertexPath", "vertexModified"},
                              {"fragment", "fragmentPath", "fragmentModified"}};
    for (int i = 0; i < 2; ++i) {
        take(stages[i], settings.value(keys[i][0]).toString(),
             settings.value(keys[i][1]).toString());
        stages[i].unsaved = settings.value(keys[i][2]).toBool();
    }
    // Sessions from before "originKind" kept no origin: their text reads as nameless.
    const ShaderOrigin origin{
        kindNamed(settings.value("originKind").toString()), settings.value("origin").toString(),
        settings.value("edited").toBool(),
        readLocalizedText(
            QJsonDocument::fromJson(settings.value("originNames").toString().toUtf8()).object(),
            "originNames", limits::kMaxNameCharacters, [](const QString &, const QString &) {})};
    settings.endGroup(); // before anything is announced: a listener may write settings
    if (saved && !builtIn.isEmpty()) {
        loadPreset(builtInPreset(builtIn == "gouraud"));
    } else if (saved) {
        const Snapshot before = snapshot();
        m_stages = {stages[0], stages[1]};
        loaded(before, origin);
    }
    return saved;
}

void ShaderDocument::requestCompile()
{
    emit compileRequested(m_stages[0].text, m_stages[1].text);
}

void ShaderDocument::announceFiles()
{
    Announced now;
    for (std::size_t i = 0; i < 2; ++i) {
        now.paths[i] = m_stages[i].path;
        now.modified[i] = m_stages[i].modified();
    }
    if (now == m_announced)
        return;
    m_announced = now;
    emit filesChanged();
}

} // namespace lb
