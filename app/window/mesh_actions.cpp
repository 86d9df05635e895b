#include "mesh_actions.h"

#include "language.h"

#include "load_progress.h"
#include "main_window_settings.h"
#include "message_box.h"
#include "preferences_dialog.h"
#include "recent_files.h"
#include "status_line.h"
#include "view_coverage.h"

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QImageReader>
#include <QLocale>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QSettings>
#include <QStatusBar>

#include <algorithm>
#include <cmath>

namespace lb {

namespace {

const char *kMemoryKey = "import/memoryLimitMB";
const char *kTimeKey = "import/timeLimitSeconds";
const char *kBudgetKey = "editor/frameBudgetSeconds";
const char *kRecentMeshesKey = "recentMeshes";
const char *kDialogDirKey = "import/lastDirectory";
const char *kImageDirKey = "texture/lastDirectory";

bool isShaderFile(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    return suffix == "vert" || suffix == "frag";
}

bool isImageFile(const QString &path)
{
    return QImageReader::supportedImageFormats().contains(
        QFileInfo(path).suffix().toLower().toLatin1());
}

} // namespace

MeshActions::MeshActions(QMainWindow *window, SceneDocument *document, ObjectLoader *loader,
                         QSettings &settings, StatusLine *status)
    : QObject(window), m_window(window), m_document(document), m_loader(loader),
      m_settings(settings)
{
    ImportLimits limits;
    limits.memoryMB =
        std::max<qint64>(64, m_settings.value(kMemoryKey, limits.memoryMB).toLongLong());
    limits.seconds = std::clamp(m_settings.value(kTimeKey, limits.seconds).toInt(), 1, 3600);
    m_loader->setLimits(limits);

    m_progress = new LoadProgress(window);
    m_summary = status->meshLabel();
    status->setProgressWidget(m_progress);
    m_recent = new RecentFiles(tr("Open &Recent Mesh"), settings, kRecentMeshesKey, window);
    connect(m_recent, &RecentFiles::fileChosen, this, &MeshActions::open);

    connect(m_progress, &LoadProgress::cancelRequested, loader, &ObjectLoader::cancel);
    connect(loader, &ObjectLoader::loadStarted, this, [this](const QString &path) {
        m_pendingPath = path;
        m_progress->start(QFileInfo(path).fileName());
    });
    connect(loader, &ObjectLoader::loadProgress, m_progress, &LoadProgress::setProgress);
    connect(loader, &ObjectLoader::loadFinished, this, &MeshActions::finished);
    connect(loader, &ObjectLoader::meshReady, this, &MeshActions::showSummary);
    connect(loader, &ObjectLoader::textureFinished, this, [this](bool ok, const QString &message) {
        if (ok)
            showStatusMessage(m_window, message, 5000);
        else
            showError(tr("Texture not used"), tr("An image could not be used as a texture."),
                      message);
    });
    connect(loader, &ObjectLoader::buildFailed, this, [this](int, const QString &message) {
        showError(tr("Mesh not built"),
                  tr("An object's mesh could not be built; it keeps what it drew before."),
                  message);
    });
    // Another object selected: the status bar describes that one.
    connect(m_document, &SceneDocument::changed, this, [this](SceneParts parts) {
        const int selected = m_document->scene().selected;
        if ((parts & ScenePart::Object) && selected != m_summaryObject) {
            m_summaryObject = selected;
            showSummary();
        }
    });
    showSummary();

    window->setAcceptDrops(true);
    window->installEventFilter(this);
}

void MeshActions::addToMenus(QMenu *file, QMenu *edit, QMenu *view)
{
    QAction *open = file->addAction(tr("Open &Mesh..."), this, &MeshActions::showOpenDialog);
    open->setShortcut(QKeySequence(tr("Ctrl+M")));
    file->addMenu(m_recent);
    QAction *image =
        file->addAction(tr("Open &Texture Image..."), this, &MeshActions::showImageDialog);
    image->setShortcut(QKeySequence(tr("Ctrl+T")));

    QAction *preferences =
        edit->addAction(tr("&Preferences..."), this, &MeshActions::showPreferences);
    preferences->setShortcut(QKeySequence::Preferences);
    if (preferences->shortcut().isEmpty())
        preferences->setShortcut(QKeySequence(tr("Ctrl+,")));

    QAction *normals = view->addAction(tr("Show &Normals"), this, [this] {
        m_document->edit([](Scene &s) {
            bool &shown = s.selectedObject().showNormals;
            shown = !shown;
        });
    });
    normals->setShortcut(QKeySequence(tr("N", "shortcut")));
}

void MeshActions::showSummary()
{
    // The status bar gets the short form, so the program's line beside it stays readable;
    // the whole summary (vertices, what was skipped) is the tooltip.
    const std::shared_ptr<const Mesh> mesh = m_loader->mesh();
    if (!mesh)
        return;
    const MeshFile *file = m_loader->file();
    const ObjectSettings &object = m_document->scene().selectedObject();
    if (const QString problem = m_loader->meshProblem(); !problem.isEmpty()) {
        //: %1: the mesh file; %2: the built-in shape drawn instead (cube, sphere, ...)
        m_summary->setText(
            tr("%1 not loaded (%2 drawn)")
                .arg(QFileInfo(object.meshPath).fileName(), shapeLabel(object.shape)));
        m_summary->setFullText(problem);
        return;
    }
    // A two-sided mesh draws each triangle twice: the object's own are counted.
    const std::size_t copies = object.faces == Faces::TwoSided ? 2 : 1;
    const QString triangles = writtenCount(qulonglong(mesh->triangleCount() / copies));
    // A file says how long it took to read, in the same sentence, and what was turned.
    QString text = file ? tr("%1: %2 triangles, %3 s")
                              .arg(QFileInfo(file->path).fileName(), triangles,
                                   QString::number(file->seconds, 'f', 2))
                        : tr("%1: %2 triangles").arg(displayName(object), triangles);
    QString remarks = m_loader->facesRemark();
    // A file that draws nothing in view, or only its back, says so (as the view is now).
    if (file && m_viewSize)
        if (const QString problem =
                viewProblem(m_document->scene(), m_document->scene().selected, *mesh, m_viewSize());
            !problem.isEmpty())
            remarks = remarks.isEmpty() ? problem : tr("%1; %2").arg(remarks, problem);
    if (!remarks.isEmpty())
        //: a mesh's short summary (%1) and what was turned in it or why it draws nothing
        //: (%2: "faces turned: ...", "draws nothing in view: ...")
        text = tr("%1; %2").arg(text, remarks);
    // A new remark is also said where messages go, which has room for it when the mesh's
    // place is narrow (a 1024-pixel window elides it after the load time); once, not at
    // every redraw of the summary.
    if (!remarks.isEmpty() && remarks != m_saidRemarks && file)
        showStatusMessage(m_window, tr("%1: %2").arg(QFileInfo(file->path).fileName(), remarks),
                          15000);
    m_saidRemarks = remarks;
    m_summary->setText(text);
    const QString full = m_loader->summary(writtenCount);
    m_summary->setFullText(
        remarks.isEmpty() || full.contains(remarks) ? full : tr("%1; %2").arg(full, remarks));
}

QString MeshActions::fileFilter() const
{
    const QStringList patterns = ImportProcess::filePatterns();
    QString filter;
    if (!patterns.isEmpty())
        filter = tr("Meshes Assimp reads (%1);;").arg(patterns.join(' '));
    return filter + tr("All files (*)");
}

void MeshActions::showOpenDialog()
{
    const QString path = QFileDialog::getOpenFileName(
        m_window, tr("Open a mesh"), m_settings.value(kDialogDirKey).toString(), fileFilter());
    if (path.isEmpty())
        return;
    m_settings.setValue(kDialogDirKey, QFileInfo(path).absolutePath());
    open(path);
}

void MeshActions::open(const QString &path)
{
    m_loader->open(QFileInfo(path).absoluteFilePath());
}

void MeshActions::showImageDialog()
{
    QStringList patterns;
    for (const QByteArray &format : QImageReader::supportedImageFormats())
        patterns << "*." + QString::fromLatin1(format);
    const QString path =
        QFileDialog::getOpenFileName(m_window, tr("Open an image as the selected object's texture"),
                                     m_settings.value(kImageDirKey).toString(),
                                     tr("Images (%1);;All files (*)").arg(patterns.join(' ')));
    if (path.isEmpty())
        return;
    m_settings.setValue(kImageDirKey, QFileInfo(path).absolutePath());
    openImage(path);
}

void MeshActions::openImage(const QString &path)
{
    m_loader->openTexture(QFileInfo(path).absoluteFilePath());
}

double MeshActions::frameBudgetSeconds() const
{
    const double s =
        m_settings.value(kBudgetKey, PreferencesDialog::kDefaultFrameBudgetSeconds).toDouble();
    return std::isfinite(s) ? std::clamp(s, 0.05, 60.0)
                            : PreferencesDialog::kDefaultFrameBudgetSeconds;
}

void MeshActions::showPreferences()
{
    PreferencesDialog dialog(m_loader->limits(), frameBudgetSeconds(), m_window);
    dialog.setAnimateLessons(m_settings.value(window_settings::kAnimateLessonsKey, true).toBool());
    if (dialog.exec() != QDialog::Accepted)
        return;
    m_settings.setValue(window_settings::kAnimateLessonsKey, dialog.animateLessons());
    const ImportLimits limits = dialog.limits();
    m_settings.setValue(kMemoryKey, limits.memoryMB);
    m_settings.setValue(kTimeKey, limits.seconds);
    m_loader->setLimits(limits);
    m_settings.setValue(kBudgetKey, dialog.frameBudgetSeconds());
    emit frameBudgetChanged(dialog.frameBudgetSeconds());
}

void MeshActions::finished(bool ok, const QString &message)
{
    m_progress->stop();
    if (ok) {
        m_recent->add(m_pendingPath);
        showSummary();
        return;
    }
    showSummary(); // a file the scene names and could not be read: the status bar says so
    // The loader's own words (its context), so that a translated "Loading cancelled" is
    // still told from an error.
    if (message == lb::ObjectLoader::tr("Loading cancelled")) {
        showStatusMessage(m_window, message, 5000);
        return;
    }
    // A file the scene names and that is not loaded (not a loaded one read again).
    const std::vector<ObjectSettings> &objects = m_document->scene().objects;
    bool named = false;
    for (int i = 0; i < int(objects.size()) && !named; ++i)
        named = objects[std::size_t(i)].meshPath == m_pendingPath &&
                !m_loader->meshProblem(i).isEmpty();
    showError(tr("Mesh not loaded"),
              named ? tr("A mesh file the scene names could not be loaded. Its objects draw their "
                         "shapes and keep its name, so saving keeps it; it is read again after "
                         "the file changes (at your next change to the scene) or when you open "
                         "it.")
                    : tr("The mesh could not be loaded; the previous one stays."),
              message);
}

void MeshActions::showError(const QString &title, const QString &text, const QString &message)
{
    // Several at once (a scene whose folder lost its files): one box lists them all.
    if (m_errorBox && m_errorBox->isVisible()) {
        if (m_errorBox->windowTitle() != title) {
            m_errorBox->setWindowTitle(tr("Files not used"));
            m_errorBox->setText(tr("Some files could not be used."));
        }
        m_errorBox->setInformativeText(m_errorBox->informativeText() + "\n" + message);
        showStatusMessage(m_window, message, 10000);
        return;
    }
    showFileMessage(m_errorBox, m_window, QMessageBox::Warning, title, text, message);
    showStatusMessage(m_window, message, 10000);
}

bool MeshActions::eventFilter(QObject *watched, QEvent *event)
{
    if (watched != m_window)
        return false;
    if (event->type() == QEvent::DragEnter) {
        auto *drag = static_cast<QDragEnterEvent *>(event);
        if (drag->mimeData()->hasUrls()) {
            drag->acceptProposedAction();
            return true;
        }
    } else if (event->type() == QEvent::Drop) {
        auto *drop = static_cast<QDropEvent *>(event);
        QStringList shaders, meshes, scenes, images;
        for (const QUrl &url : drop->mimeData()->urls()) {
            const QString path = url.toLocalFile();
            if (!url.isLocalFile())
                continue;
            // Scenes and lessons (main_window.cpp tells them apart, file_arguments.h).
            if (QStringList{"json", "lbscene", "lblesson"}.contains(
                    QFileInfo(path).suffix().toLower()))
                scenes << path;
            else if (isImageFile(path))
                images << path;
            else
                (isShaderFile(path) ? shaders : meshes) << path;
        }
        if (!scenes.isEmpty()) { // a scene brings its own mesh and shaders
            emit sceneFileDropped(scenes.first());
            drop->acceptProposedAction();
            return true;
        }
        if (!shaders.isEmpty())
            emit shaderFilesDropped(shaders);
        if (!meshes.isEmpty())
            open(meshes.first()); // one object at a time
        if (!images.isEmpty())    // the texture of the object it lands on, or the selected one
            emit imageDropped(images.first(), m_window->mapToGlobal(drop->position().toPoint()));
        drop->acceptProposedAction();
        return true;
    }
    return false;
}

} // namespace lb
