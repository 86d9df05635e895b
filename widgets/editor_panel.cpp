#include "editor_panel.h"

#include "number_box.h"
#include "presets.h"
#include "shader_editor.h"

#include <QCheckBox>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QSettings>
#include <QShortcut>
#include <QSpinBox>
#include <QSplitter>
#include <QTabWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include <Qsci/qscilexer.h>

#include <algorithm>
#include <cmath>

namespace lb {

namespace {
constexpr int kDefaultPauseMs = 150;
constexpr ShaderStage kStages[] = {ShaderStage::Vertex, ShaderStage::Fragment};

// Where a message is, as the list says it ("fragment 5:3"): the stage in the user's language
// (stageName() gives the command line's English word).
QString stageLabel(ShaderStage stage)
{
    switch (stage) {
    case ShaderStage::Vertex:
        //: the shader stage a message is about, before its line:column
        return EditorPanel::tr("vertex");
    case ShaderStage::Fragment:
        //: the shader stage a message is about, before its line:column
        return EditorPanel::tr("fragment");
    case ShaderStage::Link:
        //: a message of the linker, about no single stage
        return EditorPanel::tr("link");
    }
    return stageName(stage);
}
} // namespace

QString programDisplayName(const ShaderOrigin &origin)
{
    QString name = origin.names.isEmpty() ? origin.name : localized(origin.names, lessonLanguage());
    // A preset's name is its key (scene files and settings keep it in English): shown, it is
    // the preset's title.
    if (origin.kind == ShaderOrigin::Kind::Preset)
        for (const Preset &p : presets())
            if (p.name == name)
                name = p.title();
    if (name.isEmpty())
        name = origin.kind == ShaderOrigin::Kind::Scene ? EditorPanel::tr("the scene's shaders")
                                                        : EditorPanel::tr("your shaders");
    return origin.edited ? EditorPanel::tr("%1 (edited)").arg(name) : name;
}

EditorPanel::EditorPanel(ShaderDocument *document, QWidget *parent)
    : QWidget(parent), m_document(document)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);

    auto *bar = new QHBoxLayout;
    auto *presetButton = m_presetButton = new QToolButton(this);
    presetButton->setText(tr("Presets"));
    presetButton->setAccessibleName(presetButton->text()); // also when it shows its symbol
    presetButton->setPopupMode(QToolButton::InstantPopup);
    m_presets = new QMenu(presetButton);
    for (const Preset &p : presets())
        m_presets->addAction(p.title(), this, [this, &p] { m_document->loadPreset(p); });
    presetButton->setMenu(m_presets);
    presetButton->setToolTip(
        tr("Presets: the built-in programs, the slides' shaders as printed, toon"));

    auto *compile = new QToolButton(this);
    compile->setText(tr("Compile"));
    compile->setToolTip(tr("Compile and link now (Ctrl+Enter)"));
    connect(compile, &QToolButton::clicked, this, &EditorPanel::compileNow);
    bar->addWidget(compile);

    //: recompile while typing (a switch)
    m_live = new QCheckBox(tr("Live"), this);
    m_live->setChecked(true);
    m_live->setToolTip(tr("Recompile after a pause in typing; off: only on Ctrl+Enter"));
    bar->addWidget(m_live);
    m_delay = new IntegerBox(this);
    m_delay->setRange(0, 5000);
    m_delay->setSingleStep(50);
    //: milliseconds, after the number
    m_delay->setSuffix(tr(" ms"));
    m_delay->setValue(kDefaultPauseMs);
    m_delay->setToolTip(tr("The pause after the last key before a live recompile (wheel or "
                           "arrow keys change it)"));
    m_delay->setButtonSymbols(QAbstractSpinBox::NoButtons); // narrow: the editor fits 1024 px
    connect(m_live, &QCheckBox::toggled, m_delay, &QSpinBox::setEnabled);
    bar->addWidget(m_delay);

    m_find = new QLineEdit(this);
    m_find->setPlaceholderText(tr("Find (Ctrl+F)"));
    m_find->setMinimumWidth(m_find->fontMetrics().averageCharWidth() * 5); // narrow docks
    // Found while typing, from the top; Return goes on to the next one.
    connect(m_find, &QLineEdit::textEdited, this, [this](const QString &text) {
        auto *e = static_cast<ShaderEditor *>(m_tabs->currentWidget());
        if (!text.isEmpty())
            e->findFirst(text, false, false, false, true, true, 0, 0);
    });
    connect(m_find, &QLineEdit::returnPressed, this, [this] {
        auto *e = static_cast<ShaderEditor *>(m_tabs->currentWidget());
        e->findFirst(m_find->text(), false, false, false, true);
    });
    bar->addWidget(m_find, 1);
    m_find->installEventFilter(this); // Esc goes back to the code, not to the window
    layout->addLayout(bar);

    m_tabs = new QTabWidget(this);
    m_vertex = new ShaderEditor(this);
    m_fragment = new ShaderEditor(this);
    m_tabs->addTab(m_vertex, tr("Vertex"));     // updateTitles() names the tabs
    m_tabs->addTab(m_fragment, tr("Fragment")); // (and their files) from here on
    // Presets sit before the stage tabs, where they cost no row and leave the bar narrow
    // (the editor fits beside a 1024-pixel screen's view with both tabs shown).
    m_tabs->setCornerWidget(presetButton, Qt::TopLeftCorner);
    m_tabs->installEventFilter(this); // resized: the preset button's word may not fit
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
    for (ShaderStage stage : kStages) {
        connect(editor(stage), &ShaderEditor::textChanged, this, [this, stage] { typed(stage); });
        connect(editor(stage), &ShaderEditor::zoomRequested, this,
                [this](int steps) { setZoom(m_zoom + steps); });
        showSource(stage);
    }
    connect(m_document, &ShaderDocument::sourceChanged, this, &EditorPanel::showSource);
    connect(m_document, &ShaderDocument::filesChanged, this, &EditorPanel::updateTitles);
    connect(m_document, &ShaderDocument::diskChanged, this, &EditorPanel::showDiskChange);
    connect(m_document, &ShaderDocument::compileRequested, this,
            [this](const QString &vertex, const QString &fragment) {
                m_pause.stop();
                emit compileRequested(vertex, fragment);
            });
    connect(m_list, &QListWidget::itemActivated, this,
            [this](QListWidgetItem *item) { jumpTo(m_list->row(item)); });
    connect(m_list, &QListWidget::itemClicked, this,
            [this](QListWidgetItem *item) { jumpTo(m_list->row(item)); });

    // Keys, not words: the same in every language (QKeySequence shows them translated).
    for (const QKeySequence &key :
         {QKeySequence(Qt::CTRL | Qt::Key_Return), QKeySequence(Qt::CTRL | Qt::Key_Enter)}) {
        auto *s = new QShortcut(key, this, this, &EditorPanel::compileNow);
        s->setContext(Qt::WidgetWithChildrenShortcut);
    }
    updateTitles();
}

EditorPanel::~EditorPanel()
{
    // The editors are deleted after this, when the document may be gone: nothing they say on
    // the way out may reach it.
    for (ShaderStage stage : kStages)
        disconnect(editor(stage), nullptr, this, nullptr);
}

bool EditorPanel::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_find &&
        (event->type() == QEvent::ShortcutOverride || event->type() == QEvent::KeyPress)) {
        auto *key = static_cast<QKeyEvent *>(event);
        if (key->key() == Qt::Key_Escape) {
            event->accept(); // the window's Esc (clear the probe) is not meant here
            if (event->type() == QEvent::KeyPress)
                m_tabs->currentWidget()->setFocus();
            return true;
        }
    }
    if (watched == m_tabs && event->type() == QEvent::Resize)
        fitPresetButton();
    return QWidget::eventFilter(watched, event);
}

// The Presets button and both stage tabs share one row. In a narrow dock (a 1024-pixel
// screen, Portuguese's "Predefinições" before "Vértices" and "Fragmentos") the button is its
// menu symbol alone, named in full in its tooltip, so that the tabs stay whole.
void EditorPanel::fitPresetButton()
{
    const QString word = tr("Presets");
    const QString symbol = QString::fromUtf8("\u2630");
    QToolButton probe;
    probe.setText(word);
    probe.setPopupMode(m_presetButton->popupMode());
    probe.setMenu(m_presets);
    probe.setFont(m_presetButton->font());
    const int needed = m_tabs->tabBar()->sizeHint().width() + probe.sizeHint().width();
    const QString text = needed <= m_tabs->width() ? word : symbol;
    if (m_presetButton->text() != text)
        m_presetButton->setText(text);
}

ShaderEditor *EditorPanel::editor(ShaderStage stage) const
{
    return stage == ShaderStage::Fragment ? m_fragment : m_vertex;
}

void EditorPanel::typed(ShaderStage stage)
{
    if (m_showing)
        return;
    m_typing = true;
    m_document->setSource(stage, editor(stage)->text());
    m_typing = false;
    // Ctrl+Z took this stage back from a preset, an example or a reset: the other stage
    // follows, so the program (and its origin) come back whole.
    const ShaderStage other =
        stage == ShaderStage::Vertex ? ShaderStage::Fragment : ShaderStage::Vertex;
    if (m_document->otherStageAwaitsUndo(stage) && editor(other)->isUndoAvailable())
        editor(other)->undo();
    if (m_live->isChecked())
        m_pause.start(m_delay->value());
}

void EditorPanel::showSource(ShaderStage stage)
{
    if (m_typing)
        return;
    m_showing = true;
    editor(stage)->replaceText(m_document->source(stage)); // undoable: Ctrl+Z brings it back
    m_showing = false;
}

void EditorPanel::showDiskChange(ShaderStage, ShaderDocument::DiskChange change,
                                 const QString &path)
{
    if (change == ShaderDocument::DiskChange::Gone)
        m_status->setText(tr("%1 is gone from the disk; your text is kept").arg(path));
    else if (change == ShaderDocument::DiskChange::KeptEdits)
        m_status->setText(tr("%1 changed on disk; your unsaved edits are kept (Open it "
                             "again to take the disk's version)")
                              .arg(QFileInfo(path).fileName()));
}

void EditorPanel::updateTitles()
{
    for (ShaderStage stage : kStages) {
        const int i = stage == ShaderStage::Fragment ? 1 : 0;
        const QString path = m_document->filePath(stage);
        const QString file = QFileInfo(path).fileName();
        QString title;
        if (i == 0)
            //: the vertex shader's tab; %1 its file's name
            title = !path.isEmpty() ? tr("Vertex - %1").arg(file) : tr("Vertex");
        else
            //: the fragment shader's tab; %1 its file's name
            title = !path.isEmpty() ? tr("Fragment - %1").arg(file) : tr("Fragment");
        if (m_document->isModified(stage) && !path.isEmpty())
            title += " *";
        if (editor(stage)->markedLineCount() > 0)
            title += " \u25cf";
        m_tabs->setTabText(i, title);
        m_tabs->setTabToolTip(i, path);
    }
    fitPresetButton();
}

void EditorPanel::saveState(QSettings &settings) const
{
    settings.beginGroup("editor");
    settings.setValue("live", m_live->isChecked());
    settings.setValue("pauseMs", m_delay->value());
    settings.setValue("zoom", m_zoom);
    settings.endGroup();
    m_document->saveState(settings);
}

bool EditorPanel::restoreState(QSettings &settings)
{
    settings.beginGroup("editor");
    m_live->setChecked(settings.value("live", true).toBool());
    m_delay->setValue(settings.value("pauseMs", kDefaultPauseMs).toInt());
    setZoom(settings.value("zoom", 0).toInt());
    settings.endGroup();
    const bool restored = m_document->restoreState(settings);
    m_restoredUnsaved = restored && m_document->isModified();
    if (m_restoredUnsaved)
        m_status->setText(tr("Your unsaved shader edits from the last session are back"));
    return restored;
}

int EditorPanel::scaleShare() const
{
    // Scintilla's zoom adds points to every style's size: the scale's share is the base size
    // times (scale - 1).
    return int(std::lround(m_vertex->lexer()->defaultFont().pointSizeF() * (m_uiScale - 1.0)));
}

void EditorPanel::setZoom(int steps)
{
    // Scintilla keeps its zoom within -10 to +20 points: the user's steps stay where each one
    // still shows, with the scale's share on top.
    const int share = scaleShare();
    m_zoom = std::clamp(steps, std::max(kMinZoom, -10 - share), std::min(kMaxZoom, 20 - share));
    applyZoom();
}

void EditorPanel::setUiScale(double scale)
{
    m_uiScale = scale;
    fitMessages();   // the status line's height follows the font
    setZoom(m_zoom); // within what Scintilla shows at this scale
}

double EditorPanel::fontPointSize() const
{
    return m_vertex->lexer()->defaultFont().pointSizeF() +
           m_vertex->SendScintilla(QsciScintilla::SCI_GETZOOM);
}

void EditorPanel::applyZoom()
{
    for (ShaderStage stage : kStages)
        editor(stage)->setZoom(m_zoom + scaleShare());
}

void EditorPanel::fitMessages()
{
    // No empty box under the code: without messages their pane shrinks to the status line.
    const bool any = m_list->count() > 0;
    m_list->setVisible(any);
    m_list->parentWidget()->setMaximumHeight(any ? QWIDGETSIZE_MAX
                                                 : m_status->fontMetrics().height() + 8);
}

void EditorPanel::startFind()
{
    m_find->setFocus();
    m_find->selectAll();
}

void EditorPanel::undo()
{
    static_cast<ShaderEditor *>(m_tabs->currentWidget())->undo();
}

void EditorPanel::redo()
{
    static_cast<ShaderEditor *>(m_tabs->currentWidget())->redo();
}

void EditorPanel::compileNow()
{
    m_pause.stop();
    m_document->requestCompile(); // comes back through compileRequested
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
            d.line > 0 ? QString("%1 %2:%3").arg(stageLabel(d.stage)).arg(d.line).arg(d.column)
                       : stageLabel(d.stage);
        //: %1 where (fragment 5:3); %2 the compiler's message
        auto *item = new QListWidgetItem(
            (error ? tr("%1  error: %2") : tr("%1  warning: %2")).arg(where, d.message), m_list);
        item->setForeground(error ? QColor("#c62828") : QColor("#8a5a00"));
    }
    fitMessages();
    m_vertex->showDiagnostics(perStage[0]);
    m_fragment->showDiagnostics(perStage[1]);
    updateTitles();
    // The colour is markup around the words, so translators see the words alone.
    const auto coloured = [](const char *colour, const QString &text) {
        return QString("<span style='color:%1'>%2</span>").arg(colour, text.toHtmlEscaped());
    };
    if (build.ok())
        m_status->setText(warnings ? coloured("#8a5a00", tr("linked, %n warning(s)", "", warnings))
                                   //: the shaders compiled and linked without a message
                                   : coloured("#2e7d32", tr("linked")));
    else
        m_status->setText(
            coloured("#c62828", tr("%n error(s): last good program drawing", "", errors)));
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
