#pragma once
// The window's mesh and texture controls around ObjectLoader: File > Open Mesh, Open Recent
// Mesh and Open Texture Image, files dropped on the window (an image: the texture), the
// status bar's load progress (with Cancel) and mesh summary, load errors, View > Show Normals, and
// the import limits (Edit > Preferences, kept in QSettings; the command line can override them for
// one session).

#include "object_loader.h"

#include <QMessageBox>
#include <QObject>
#include <QPointer>
#include <QSize>

#include <functional>

class QMainWindow;
class QMenu;
class QSettings;

namespace lb {

class ElidedLabel;
class LoadProgress;
class RecentFiles;
class StatusLine;

class MeshActions : public QObject
{
    Q_OBJECT
public:
    // The progress and the summary go into `status`, the window's status line.
    MeshActions(QMainWindow *window, SceneDocument *document, ObjectLoader *loader,
                QSettings &settings, StatusLine *status);

    void addToMenus(QMenu *file, QMenu *edit, QMenu *view);
    void showOpenDialog();
    void open(const QString &path);
    // File > Open Texture Image (Ctrl+T): an image as the selected object's texture.
    void showImageDialog();
    void openImage(const QString &path);
    void showPreferences();
    // Edit > Preferences' frame budget for user programs (seconds), from the settings.
    double frameBudgetSeconds() const;
    // Limits for this session only (--import-memory-limit): the preferences keep theirs.
    void setSessionLimits(const ImportLimits &limits) { m_loader->setLimits(limits); }

    // Where the status line learns the view's size, to say when a loaded file draws nothing
    // in view (view_coverage.h).
    void setViewSize(std::function<QSize()> size) { m_viewSize = std::move(size); }

    LoadProgress *progress() const { return m_progress; }
    RecentFiles *recent() const { return m_recent; }
    ElidedLabel *summaryLabel() const { return m_summary; }
    // The message box of the last failed load, while it is open.
    QMessageBox *errorBox() const { return m_errorBox; }

signals:
    void shaderFilesDropped(const QStringList &paths);
    void sceneFileDropped(const QString &path);
    // An image dropped at `globalPos`: the window selects the object there, if any, and
    // opens the image for the selected object (openImage()).
    void imageDropped(const QString &path, QPoint globalPos);
    void frameBudgetChanged(double seconds);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override; // drops on the window

private:
    void finished(bool ok, const QString &message);
    void showError(const QString &title, const QString &text, const QString &message);
    void showSummary();
    QString fileFilter() const;

    QMainWindow *m_window;
    SceneDocument *m_document;
    ObjectLoader *m_loader;
    QSettings &m_settings;
    LoadProgress *m_progress;
    ElidedLabel *m_summary;
    RecentFiles *m_recent;
    QPointer<QMessageBox> m_errorBox;
    QString m_pendingPath;   // the file being loaded, for the recent list
    QString m_saidRemarks;   // the summary's remarks last said as a message
    int m_summaryObject = 0; // the object the status bar's summary describes
    std::function<QSize()> m_viewSize;
};

} // namespace lb
