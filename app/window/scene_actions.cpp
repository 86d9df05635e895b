#include "scene_actions.h"

#include "export_size_dialog.h"
#include "message_box.h"
#include "message_text.h"
#include "recent_files.h"
#include "safe_write.h"
#include "scene_document.h"
#include "shader_document.h"
#include "status_line.h"
#include "viewport.h"

#include <QApplication>
#include <QClipboard>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenu>
#include <QSettings>
#include <QStatusBar>

namespace lb {

namespace {
const char *kRecentScenesKey = "recentScenes";
const char *kSceneDirKey = "scenes/lastDirectory";
const char *kExportSizeKey = "export/size";
const char *kCurrentSceneKey = "scenes/current"; // the file the session's scene came from
// Translated when a dialog opens (a constant would be made before any translator is in).
// Scene files end in .lbscene (the desktop's type for them) or .json (the course's).
QString sceneOpenFilter()
{
    return SceneActions::tr("Scenes (*.lbscene *.json);;All files (*)");
}
// Saving: .json first, the format the course hands out, so a name typed without an ending
// gets .json unless the .lbscene filter is chosen.
QString jsonSceneFilter()
{
    return SceneActions::tr("Scenes (*.json)");
}
QString lbsceneFilter()
{
    return SceneActions::tr("lightbench scenes (*.lbscene)");
}
// A scene file as the window opens it: an example's mesh (none today) would name a file beside
// the resource, so its objects keep their shapes.
SceneFile asOpened(SceneFile file, bool example)
{
    if (example)
        for (ObjectSettings &o : file.scene.objects)
            o.meshPath.clear();
    return file;
}

} // namespace

SceneActions::SceneActions(QMainWindow *window, SceneDocument *document, ShaderDocument *shaders,
                           Viewport *viewport, QSettings &settings)
    : QObject(window), m_window(window), m_document(document), m_shaders(shaders),
      m_viewport(viewport), m_settings(settings)
{
    m_recent = new RecentFiles(tr("Open Recent S&cene"), settings, kRecentScenesKey, window);
    connect(m_recent, &RecentFiles::fileChosen, this,
            [this](const QString &path) { openAsking(path); });
    // The session's scene came from this file: it is still the document (with the session's
    // changes unsaved, as the title's * says), as long as the file can be read.
    const QString current = m_settings.value(kCurrentSceneKey).toString();
    if (!current.isEmpty()) {
        const SceneFileRead read = readSceneFile(current);
        if (read.file) {
            setDocument(current);
            m_saved = asOpened(*read.file, current.startsWith(":/"));
            m_exercise = read.file->exercise; // saving the session's scene keeps it
            m_exerciseScene = read.file->scene;
        }
    }
}

QList<QPair<QString, QString>> SceneActions::examples()
{
    return {
        {tr("Gouraud vs Phong (the slides)"), ":/examples/gouraud_vs_phong.json"},
        {tr("Phong vs Blinn-Phong specular"), ":/examples/phong_vs_blinn.json"},
        {tr("The three light frames"), ":/examples/light_frames.json"},
        {tr("The normal matrix"), ":/examples/normal_matrix.json"},
        {tr("Toon shading"), ":/examples/toon.json"},
        {tr("The terms one at a time (keys A, D, S)"), ":/examples/terms.json"},
        {tr("Attenuation of a point light"), ":/examples/attenuation.json"},
        {tr("A spotlight"), ":/examples/spotlight.json"},
        {tr("The exercise: a textured cube and a sphere, light in camera coordinates"),
         ":/examples/exercise.json"},
        {tr("A light in one object's frame (it turns with the torus)"),
         ":/examples/attached_light.json"},
        {tr("Texture filtering: nearest, linear and mipmaps"), ":/examples/texture_filtering.json"},
        {tr("Exercise: per-fragment lighting (Check My Work, F9)"),
         ":/examples/exercise_lighting.json"}};
}

void SceneActions::addToMenu(QMenu *file)
{
    // The scene is the document (its shaders inline): the conventional keys are its.
    QAction *open = file->addAction(tr("&Open Scene..."), this, &SceneActions::showOpenDialog);
    open->setShortcut(QKeySequence::Open);
    file->addMenu(m_recent);
    QMenu *examples = file->addMenu(tr("E&xamples"));
    for (const auto &[text, resource] : SceneActions::examples())
        examples->addAction(
            text, this, [this, text = text, resource = resource] { openAsking(resource, text); });
    QAction *save = file->addAction(tr("&Save Scene"), this, &SceneActions::saveScene);
    save->setShortcut(QKeySequence::Save);
    QAction *saveAs = file->addAction(tr("Save Scene &As..."), this, &SceneActions::showSaveDialog);
    saveAs->setShortcut(QKeySequence(tr("Ctrl+Shift+S")));
    file->addSeparator();
    QAction *exportImage =
        file->addAction(tr("E&xport Image..."), this, &SceneActions::showExportDialog);
    exportImage->setShortcut(QKeySequence(tr("Ctrl+E")));
    QAction *copy = file->addAction(tr("Cop&y Image"), this, &SceneActions::copyImage);
    copy->setShortcut(QKeySequence(tr("Ctrl+Shift+C")));
}

bool SceneActions::open(const QString &path)
{
    const bool example = path.startsWith(":/");
    const SceneFileRead read = readSceneFile(path);
    if (!read.file) {
        showMessage(QMessageBox::Warning, tr("The scene could not be opened; nothing changed."),
                    read.error);
        if (!example && !QFileInfo::exists(path))
            m_recent->remove(path);
        return false;
    }
    if (!example)
        m_recent->add(QFileInfo(path).absoluteFilePath());
    apply(asOpened(*read.file, example), read.ignored,
          example ? path : QFileInfo(path).absoluteFilePath());
    return true;
}

void SceneActions::apply(const SceneFile &file, const QStringList &ignoredFields,
                         const QString &origin)
{
    // An exercise's reference and grading ride along, so that saving it keeps them.
    m_exercise = file.exercise;
    m_exerciseScene = file.scene;
    // The program first: the scene's shading is held to a program that fixes its own.
    m_shaders->setProgram(file.program, perVertex(file.scene.shading.shading));
    // Held to the scene budget on its way in (MainWindow::limitScenes): what was lowered.
    const QString lowered = m_document->set(file.scene);
    emit exerciseChanged(); // after the scene: side B's choices may follow the exercise
    setDocument(origin);
    remember();
    if (!lowered.isEmpty()) {
        // The file's own values are what it holds: the lowered scene is a change the user has
        // not saved (the title's * and quitting ask), not one the file had. Saving writes
        // what is drawn, as after any edit; nothing is written without being asked.
        m_saved->scene = file.scene;
        emit documentChanged();
    }
    // A lesson's step (no origin) names itself in the lesson bar, and says what it ignored
    // once for the whole lesson. A whole sentence for a step and for a file, for translators.
    const bool step = origin.isEmpty();
    const QString name = escapedName(m_name);
    const int ignoredCount = int(ignoredFields.size());
    const QString ignored =
        ignoredFields.isEmpty()
            ? QString()
            : tr("%n field(s) could not be used and kept their defaults:", "", ignoredCount) +
                  "\n" + summarisedList(ignoredFields, "\n", 20);
    if (!lowered.isEmpty())
        showMessage(QMessageBox::Information,
                    step ? tr("This step opened with less tessellation than it asks for, to fit "
                              "this machine's memory; the file is unchanged unless you save the "
                              "scene.")
                         : tr("%1 opened with less tessellation than it asks for, to fit this "
                              "machine's memory; the file is unchanged unless you save the scene.")
                               .arg(name),
                    lowered + (ignored.isEmpty() ? QString() : "\n\n" + ignored));
    else if (!ignoredFields.isEmpty())
        showMessage(QMessageBox::Information,
                    step ? tr("This step opened; %n field(s) could not be used and kept their "
                              "defaults.",
                              "", ignoredCount)
                         : tr("%1 opened; %n field(s) could not be used and kept their defaults.",
                              "", ignoredCount)
                               .arg(name),
                    summarisedList(ignoredFields, "\n", 20));
    if (lowered.isEmpty() && !origin.isEmpty()) // else the status line says what was lowered
        showStatusMessage(m_window, tr("Opened the scene %1").arg(name), 5000);
    emit sceneOpened(origin);
}

bool SceneActions::openAsking(const QString &path, const QString &shownName)
{
    // A file that is gone (a recent one) opens nothing: no need to ask, open() says why.
    const bool openable = path.startsWith(":/") || QFileInfo(path).isFile();
    if (openable && m_maySetAside &&
        !m_maySetAside(shownName.isEmpty() ? QFileInfo(path).fileName() : shownName))
        return false;
    return open(path);
}

bool SceneActions::saveScene()
{
    return m_path.isEmpty() ? showSaveDialog() : save(m_path).isEmpty();
}

QString SceneActions::save(const QString &path)
{
    const QString error =
        writeSceneFile(path, SceneFile{sceneToSave(), m_shaders->program(), m_exercise});
    if (!error.isEmpty()) {
        showMessage(QMessageBox::Warning, tr("The scene was not saved."), error);
        return error;
    }
    setDocument(QFileInfo(path).absoluteFilePath());
    remember();
    m_recent->add(m_path);
    showStatusMessage(m_window, tr("Saved the scene to %1").arg(path), 5000);
    return {};
}

QString SceneActions::exportImage(const QString &path, QSize pixels)
{
    // A program too slow for a frame this big is not asked to draw one (its trial says so),
    // and a device or a pipe is not replaced by a file.
    const QString tooSlow = m_viewport->tooSlowAt(pixels);
    QString error = unwritableTarget(path);
    if (error.isEmpty() && !tooSlow.isEmpty())
        error = tr("%1: not drawn: %2").arg(path, tooSlow);
    if (error.isEmpty()) {
        const QImage image = m_viewport->renderImage(pixels);
        if (image.isNull())
            error =
                tr("%1: the view could not be drawn at %2 x %3")
                    .arg(path, QString::number(pixels.width()), QString::number(pixels.height()));
        else
            error = writeImageSafely(path, image); // a temporary file, then a rename
    }
    if (!error.isEmpty())
        showMessage(QMessageBox::Warning, tr("The image was not exported."), error);
    else
        showStatusMessage(m_window, tr("Exported %1").arg(path), 5000);
    return error;
}

void SceneActions::copyImage()
{
    const QImage image =
        m_viewport->renderImage(m_viewport->size() * m_viewport->devicePixelRatio());
    if (image.isNull())
        return;
    QApplication::clipboard()->setImage(image);
    showStatusMessage(
        m_window,
        tr("Copied the view (%1 x %2) to the clipboard").arg(image.width()).arg(image.height()),
        5000);
}

void SceneActions::showOpenDialog()
{
    const QString path = QFileDialog::getOpenFileName(
        m_window, tr("Open a scene"), m_settings.value(kSceneDirKey).toString(), sceneOpenFilter());
    if (path.isEmpty())
        return;
    m_settings.setValue(kSceneDirKey, QFileInfo(path).absolutePath());
    openAsking(path);
}

bool SceneActions::showSaveDialog()
{
    // The filter shown first: the one of the scene's own file's ending.
    QString chosenFilter =
        m_path.endsWith(".lbscene", Qt::CaseInsensitive) ? lbsceneFilter() : jsonSceneFilter();
    QString path = QFileDialog::getSaveFileName(
        m_window, tr("Save the scene"),
        m_path.isEmpty() ? m_settings.value(kSceneDirKey).toString() : m_path,
        jsonSceneFilter() + ";;" + lbsceneFilter() + ";;" + tr("All files (*)"), &chosenFilter);
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += chosenFilter == lbsceneFilter() ? ".lbscene" : ".json";
    m_settings.setValue(kSceneDirKey, QFileInfo(path).absolutePath());
    return save(path).isEmpty();
}

void SceneActions::showExportDialog()
{
    const QSize current = m_viewport->size() * m_viewport->devicePixelRatio();
    ExportSizeDialog sizes(m_settings.value(kExportSizeKey, current).toSize(), m_window);
    if (sizes.exec() != QDialog::Accepted)
        return;
    m_settings.setValue(kExportSizeKey, sizes.size());
    QString path = QFileDialog::getSaveFileName(m_window, tr("Export the view"),
                                                m_settings.value(kSceneDirKey).toString(),
                                                tr("PNG images (*.png);;All files (*)"));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += ".png";
    exportImage(path, sizes.size());
}

void SceneActions::showMessage(QMessageBox::Icon icon, const QString &text, const QString &details)
{
    showFileMessage(m_messageBox, m_window, icon, tr("Scene"), text, details);
}

void SceneActions::setDocument(const QString &origin)
{
    // An example (":/examples/NAME.json") is the document too, also after a restart, with no
    // file to save to.
    const bool example = origin.startsWith(":/");
    m_path = example ? QString() : origin;
    m_name = example ? origin.section('/', -1) : QFileInfo(origin).fileName();
    m_settings.setValue(kCurrentSceneKey, origin);
}

void SceneActions::restoreExercise(const SceneFile &file)
{
    m_exercise = file.exercise;
    m_exerciseScene = file.scene;
    emit exerciseChanged();
}

void SceneActions::forgetFile()
{
    setDocument({});
    m_saved.reset();
    if (m_exercise) {
        m_exercise.reset();
        emit exerciseChanged();
    }
    emit documentChanged();
}

Scene SceneActions::sceneToSave() const
{
    return m_sceneToSave ? m_sceneToSave() : m_document->scene();
}

void SceneActions::remember()
{
    m_saved = SceneFile{sceneToSave(), m_shaders->program(), m_exercise};
    emit documentChanged();
}

SceneFile SceneActions::savedFile() const
{
    return m_saved.value_or(SceneFile{Scene{}, std::nullopt, std::nullopt});
}

bool SceneActions::isModified() const
{
    return differsFromSaved(true);
}

bool SceneActions::isSceneModified() const
{
    return differsFromSaved(false);
}

bool SceneActions::differsFromSaved(bool withProgram) const
{
    SceneFile now{sceneToSave(), m_shaders->program(), m_exercise};
    const SceneFile saved = savedFile();
    // Auto-rotation turns the object 60 times a second: the turn is not an edit.
    for (std::size_t i = 0; i < now.scene.objects.size(); ++i)
        if (now.scene.objects[i].autoRotate && i < saved.scene.objects.size())
            now.scene.objects[i].rotationDegrees.y = saved.scene.objects[i].rotationDegrees.y;
    // The program's text decides, not its name or 'edited' flag (a saved scene's program
    // reads back under the file's name).
    auto text = [](const std::optional<ProgramText> &p) {
        return p ? std::make_pair(p->vertex, p->fragment) : std::make_pair(QString(), QString());
    };
    return !(now.scene == saved.scene) || (withProgram && text(now.program) != text(saved.program));
}

} // namespace lb
