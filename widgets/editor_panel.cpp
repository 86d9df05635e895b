#include "editor_panel.h"

#include "presets.h"
#include "shader_editor.h"

#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QSaveFile>
#include <QSettings>
#include <QShortcut>
#include <QSpinBox>
#include <QSplitter>
#include <QTabWidget>
#include <QToolButton>
#include <QVBoxLayout>

namespace lb {

namespace {
constexpr int kDefaultPauseMs = 150;

int index(ShaderStage stage)
{
    return stage == ShaderStage::Fragment ? 1 : 0;
}

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
} // namespace

EditorPanel::EditorPanel(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);

    auto *bar = new QHBoxLayout;
    auto *presetButton = new QToolButton(this);
    presetButton->setText(tr("Presets"));
    presetButton->setPopupMode(QToolButton::InstantPopup);
    m_presets = new QMenu(presetButton);
    for (const Preset &p : presets())
        m_presets->addAction(p.name, this, [this, &p] { loadPreset(p); });
    presetButton->setMenu(m_presets);
    presetButton->setToolTip(tr("The built-in programs, the slides' shaders as printed, toon"));
    bar->addWidget(presetButton);

    auto *compile = new QToolButton(this);
    compile->setText(tr("Compile"));
    compile->setToolTip(tr("Compile and link now (Ctrl+Enter)"));
    connect(compile, &QToolButton::clicked, this, &EditorPanel::compileNow);
    bar->addWidget(compile);

    m_live = new QCheckBox(tr("Live"), this);
    m_live->setChecked(true);
    m_live->setToolTip(tr("Recompile after a pause in typing; off: only on Ctrl+Enter"));
    bar->addWidget(m_live);
    m_delay = new QSpinBox(this);
    m_delay->setRange(0, 5000);
    m_delay->setSingleStep(50);
    m_delay->setSuffix(tr(" ms"));
    m_delay->setValue(kDefaultPauseMs);
    m_delay->setToolTip(tr("The pause after the last key before a live recompile"));
    connect(m_live, &QCheckBox::toggled, m_delay, &QSpinBox::setEnabled);
    bar->addWidget(m_delay);

    m_find = new QLineEdit(this);
    m_find->setPlaceholderText(tr("Find (Ctrl+F)"));
    m_find->setClearButtonEnabled(true);
    connect(m_find, &QLineEdit::returnPressed, this, [this] {
        auto *e = static_cast<ShaderEditor *>(m_tabs->currentWidget());
        e->findFirst(m_find->text(), false, false, false, true);
    });
    bar->addWidget(m_find, 1);
    layout->addLayout(bar);

    m_tabs = new QTabWidget(this);
    m_vertex = new ShaderEditor(this);
    m_fragment = new ShaderEditor(this);
    m_tabs->addTab(m_vertex, tr("Vertex"));
    m_tabs->addTab(m_fragment, tr("Fragment"));
    m_list = new QListWidget(this);
    m_list->setToolTip(tr("Click a message to go to its line"));
    // The status line sits above the messages; its text never widens the dock (a dock that
    // grew on an error would shrink the viewport under the user's eyes).
    m_status = new QLabel(this);
    m_status->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    auto *messages = new QWidget(this);
    auto *messagesLayout = new QVBoxLayout(messages);
    messagesLayout->setContentsMargins(0, 0, 0, 0);
    messagesLayout->addWidget(m_status);
    messagesLayout->addWidget(m_list);
    auto *split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_tabs);
    split->addWidget(messages);
    split->setStretchFactor(0, 5);
    split->setStretchFactor(1, 1);
    layout->addWidget(split, 1);

    m_pause.setSingleShot(true);
    connect(&m_pause, &QTimer::timeout, this, &EditorPanel::compileNow);
    for (ShaderEditor *e : {m_vertex, m_fragment}) {
        connect(e, &ShaderEditor::textChanged, this, &EditorPanel::onEdited);
        connect(e, &ShaderEditor::modificationChanged, this, &EditorPanel::updateTitles);
    }
    connect(&m_watcher, &QFileSystemWatcher::fileChanged, this, &EditorPanel::fileChangedOnDisk);
    connect(m_list, &QListWidget::itemActivated, this,
            [this](QListWidgetItem *item) { jumpTo(m_list->row(item)); });
    connect(m_list, &QListWidget::itemClicked, this,
            [this](QListWidgetItem *item) { jumpTo(m_list->row(item)); });

    for (const char *key : {"Ctrl+Return", "Ctrl+Enter"}) {
        auto *s = new QShortcut(QKeySequence(tr(key)), this, this, &EditorPanel::compileNow);
        s->setContext(Qt::WidgetWithChildrenShortcut);
    }
    auto *find = new QShortcut(QKeySequence::Find, this);
    find->setContext(Qt::WidgetWithChildrenShortcut);
    connect(find, &QShortcut::activated, this, [this] {
        m_find->setFocus();
        m_find->selectAll();
    });
}

ShaderEditor *EditorPanel::editor(ShaderStage stage) const
{
    return stage == ShaderStage::Fragment ? m_fragment : m_vertex;
}

QString EditorPanel::source(ShaderStage stage) const
{
    return editor(stage)->text();
}

void EditorPanel::setSources(const QString &vertex, const QString &fragment)
{
    m_loading = true;
    m_vertex->setText(vertex);
    m_fragment->setText(fragment);
    m_vertex->setModified(false);
    m_fragment->setModified(false);
    m_restoredUnsaved[0] = m_restoredUnsaved[1] = false;
    m_loading = false;
    m_builtInVertex.clear();
    m_builtInFragment.clear();
    m_origin = tr("your shaders");
    m_originEdited = false;
    m_paths[0].clear();
    m_paths[1].clear();
    watch();
    updateTitles();
    compileNow();
    emit edited();
}

void EditorPanel::loadPreset(const Preset &preset)
{
    setSources(preset.vertexSource(), preset.fragmentSource());
    m_origin = preset.name;
    for (bool gouraud : {false, true}) {
        if (&builtInPreset(gouraud) == &preset) {
            m_builtInVertex = source(ShaderStage::Vertex);
            m_builtInFragment = source(ShaderStage::Fragment);
            m_builtInIsGouraud = gouraud;
        }
    }
    emit edited(); // again, now that the name and the built-in are known
}

bool EditorPanel::showsBuiltIn() const
{
    return !m_builtInVertex.isEmpty() && source(ShaderStage::Vertex) == m_builtInVertex &&
           source(ShaderStage::Fragment) == m_builtInFragment;
}

bool EditorPanel::isEdited() const
{
    if (showsBuiltIn())
        return false;
    return m_originEdited || isModified() || !m_builtInVertex.isEmpty();
}

QString EditorPanel::programName() const
{
    // Words for the user only: scene files and settings keep the name and the flag as data.
    return isEdited() ? tr("%1 (edited)").arg(m_origin) : m_origin;
}

std::optional<ProgramText> EditorPanel::program() const
{
    if (showsBuiltIn())
        return std::nullopt;
    return ProgramText{m_origin, source(ShaderStage::Vertex), source(ShaderStage::Fragment),
                       isEdited()};
}

void EditorPanel::setProgram(const std::optional<ProgramText> &program, bool gouraud)
{
    if (!program) {
        loadPreset(builtInPreset(gouraud));
        return;
    }
    setSources(program->vertex, program->fragment);
    m_origin = program->name.isEmpty() ? tr("the scene's shaders") : program->name;
    m_originEdited = program->edited; // an edit saved in the scene is still an edit
    updateTitles();
    emit edited();
}

void EditorPanel::followShading(bool gouraud)
{
    if (showsBuiltIn() && gouraud != m_builtInIsGouraud)
        loadPreset(builtInPreset(gouraud));
}

void EditorPanel::onEdited()
{
    if (m_loading)
        return;
    if (m_live->isChecked())
        m_pause.start(m_delay->value());
    emit edited();
}

QString EditorPanel::filePath(ShaderStage stage) const
{
    return m_paths[index(stage)];
}

bool EditorPanel::isModified(ShaderStage stage) const
{
    return editor(stage)->isModified() || m_restoredUnsaved[index(stage)];
}

bool EditorPanel::isModified() const
{
    return isModified(ShaderStage::Vertex) || isModified(ShaderStage::Fragment);
}

void EditorPanel::updateTitles()
{
    for (ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment}) {
        const int i = index(stage);
        QString title = i ? tr("Fragment") : tr("Vertex");
        if (!m_paths[i].isEmpty())
            title += " - " + QFileInfo(m_paths[i]).fileName();
        if (isModified(stage) && !m_paths[i].isEmpty())
            title += " *";
        if (editor(stage)->markedLineCount() > 0)
            title += " \u25cf";
        m_tabs->setTabText(i, title);
        m_tabs->setTabToolTip(i, m_paths[i]);
    }
}

void EditorPanel::watch()
{
    if (!m_watcher.files().isEmpty())
        m_watcher.removePaths(m_watcher.files());
    for (const QString &p : m_paths)
        if (!p.isEmpty() && QFileInfo::exists(p))
            m_watcher.addPath(p);
}

QString EditorPanel::openFiles(const QStringList &paths)
{
    QString chosen[2];
    for (const QString &p : paths)
        chosen[index(stageOfFile(p))] = p;
    for (int i = 0; i < 2; ++i) // a single file brings its partner when there is one
        if (chosen[i].isEmpty() && !chosen[1 - i].isEmpty() &&
            QFileInfo::exists(partnerOf(chosen[1 - i])))
            chosen[i] = partnerOf(chosen[1 - i]);
    QString text[2] = {source(ShaderStage::Vertex), source(ShaderStage::Fragment)};
    for (int i = 0; i < 2; ++i) {
        if (chosen[i].isEmpty())
            continue;
        QFile f(chosen[i]);
        if (!f.open(QIODevice::ReadOnly))
            return tr("Cannot open %1: %2").arg(chosen[i], f.errorString());
        text[i] = QString::fromUtf8(f.readAll());
    }
    const QString keep[2] = {m_paths[0], m_paths[1]};
    setSources(text[0], text[1]);
    for (int i = 0; i < 2; ++i)
        m_paths[i] = chosen[i].isEmpty() ? keep[i] : QFileInfo(chosen[i]).absoluteFilePath();
    m_origin = QFileInfo(m_paths[0].isEmpty() ? m_paths[1] : m_paths[0]).completeBaseName();
    m_originEdited = false;
    watch();
    updateTitles();
    emit edited();
    return {};
}

QString EditorPanel::writeFile(ShaderStage stage, const QString &path)
{
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(source(stage).toUtf8()) < 0 || !f.commit())
        return tr("Cannot save %1: %2").arg(path, f.errorString());
    m_paths[index(stage)] = QFileInfo(path).absoluteFilePath();
    editor(stage)->setModified(false);
    m_restoredUnsaved[index(stage)] = false;
    return {};
}

QString EditorPanel::save()
{
    if (m_paths[0].isEmpty() || m_paths[1].isEmpty())
        return tr("The shaders have no files yet: use Save As");
    m_watcher.blockSignals(true); // our own write is no change from outside
    QString error = writeFile(ShaderStage::Vertex, m_paths[0]);
    if (error.isEmpty())
        error = writeFile(ShaderStage::Fragment, m_paths[1]);
    watch();
    m_watcher.blockSignals(false);
    updateTitles();
    emit edited();
    return error;
}

QString EditorPanel::saveAs(const QString &anyPath)
{
    const QFileInfo info(anyPath);
    const QString base = info.suffix() == "vert" || info.suffix() == "frag"
                             ? info.dir().filePath(info.completeBaseName())
                             : info.absoluteFilePath();
    m_paths[0] = base + ".vert";
    m_paths[1] = base + ".frag";
    m_origin = QFileInfo(base).fileName();
    m_originEdited = false;
    return save();
}

void EditorPanel::fileChangedOnDisk(const QString &path)
{
    for (ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment}) {
        if (m_paths[index(stage)] != path)
            continue;
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly)) {
            m_status->setText(tr("%1 is gone from the disk; your text is kept").arg(path));
        } else if (isModified(stage)) {
            m_status->setText(tr("%1 changed on disk; your unsaved edits are kept (Open it "
                                 "again to take the disk's version)")
                                  .arg(QFileInfo(path).fileName()));
        } else {
            const QString text = QString::fromUtf8(f.readAll());
            if (text != source(stage)) {
                m_loading = true;
                editor(stage)->setText(text);
                editor(stage)->setModified(false);
                m_loading = false;
                compileNow();
            }
        }
    }
    watch(); // editors that save by renaming replace the watched file
}

void EditorPanel::saveState(QSettings &settings) const
{
    settings.beginGroup("editor");
    settings.setValue("vertex", source(ShaderStage::Vertex));
    settings.setValue("fragment", source(ShaderStage::Fragment));
    settings.setValue("vertexPath", m_paths[0]);
    settings.setValue("fragmentPath", m_paths[1]);
    settings.setValue("vertexModified", isModified(ShaderStage::Vertex));
    settings.setValue("fragmentModified", isModified(ShaderStage::Fragment));
    settings.setValue("origin", m_origin); // restoreState() reads it back
    settings.setValue("originEdited", m_originEdited);
    const bool builtIn = !m_builtInVertex.isEmpty() &&
                         source(ShaderStage::Vertex) == m_builtInVertex &&
                         source(ShaderStage::Fragment) == m_builtInFragment;
    settings.setValue("builtIn", builtIn ? (m_builtInIsGouraud ? "gouraud" : "phong") : "");
    settings.setValue("live", m_live->isChecked());
    settings.setValue("pauseMs", m_delay->value());
    settings.endGroup();
}

bool EditorPanel::restoreState(QSettings &settings)
{
    settings.beginGroup("editor");
    m_live->setChecked(settings.value("live", true).toBool());
    m_delay->setValue(settings.value("pauseMs", kDefaultPauseMs).toInt());
    const bool saved = settings.contains("vertex");
    const QString builtIn = settings.value("builtIn").toString();
    if (saved && !builtIn.isEmpty()) {
        loadPreset(builtInPreset(builtIn == "gouraud"));
    } else if (saved) {
        setSources(settings.value("vertex").toString(), settings.value("fragment").toString());
        m_paths[0] = settings.value("vertexPath").toString();
        m_paths[1] = settings.value("fragmentPath").toString();
        m_restoredUnsaved[0] = settings.value("vertexModified").toBool();
        m_restoredUnsaved[1] = settings.value("fragmentModified").toBool();
        m_origin = settings.value("origin", m_origin).toString();
        m_originEdited = settings.value("originEdited", false).toBool();
        watch();
        updateTitles();
        if (isModified())
            m_status->setText(tr("Your unsaved shader edits from the last session are back"));
    }
    settings.endGroup();
    return saved;
}

void EditorPanel::compileNow()
{
    m_pause.stop();
    emit compileRequested(source(ShaderStage::Vertex), source(ShaderStage::Fragment));
}

void EditorPanel::showBuild(const ProgramBuild &build)
{
    m_shown = build.diagnostics;
    std::vector<Diagnostic> perStage[2];
    m_list->clear();
    int errors = 0, warnings = 0;
    for (const Diagnostic &d : m_shown) {
        const bool error = d.severity == Diagnostic::Severity::Error;
        (error ? errors : warnings)++;
        if (d.stage != ShaderStage::Link)
            perStage[d.stage == ShaderStage::Fragment].push_back(d);
        const QString where =
            d.line > 0 ? QString("%1 %2:%3").arg(stageName(d.stage)).arg(d.line).arg(d.column)
                       : stageName(d.stage);
        auto *item = new QListWidgetItem(
            QString("%1  %2: %3").arg(where, error ? tr("error") : tr("warning"), d.message),
            m_list);
        item->setForeground(error ? QColor("#c62828") : QColor("#8a5a00"));
    }
    m_vertex->showDiagnostics(perStage[0]);
    m_fragment->showDiagnostics(perStage[1]);
    updateTitles();
    if (build.ok())
        m_status->setText(
            warnings ? tr("<span style='color:#8a5a00'>linked, %n warning(s)</span>", "", warnings)
                     : tr("<span style='color:#2e7d32'>linked</span>"));
    else
        m_status->setText(
            tr("<span style='color:#c62828'>%n error(s): last good program drawing</span>", "",
               errors));
}

void EditorPanel::jumpTo(int row)
{
    if (row < 0 || row >= int(m_shown.size()))
        return;
    const Diagnostic &d = m_shown[std::size_t(row)];
    if (d.stage == ShaderStage::Link)
        return;
    m_tabs->setCurrentWidget(editor(d.stage));
    editor(d.stage)->goTo(d.line, d.column);
}

} // namespace lb
