#pragma once
// Keeps the drawn objects in step with the scene, without ever blocking the GUI thread on a
// big mesh: mesh files are read by the import helper (ImportProcess), one at a time, and
// meshes with many triangles are built (shape, generated normals) on a worker thread while
// the previous mesh keeps drawing. A file opened becomes the selected object's mesh only once
// it is loaded and built; a file that fails leaves the scene, and the mesh on screen, as
// they were. A file the scene names (a restart, a scene file) that cannot be read stays
// named, so that a save keeps it: its objects draw their shapes, meshProblem() says why, and
// it is read again at the next change to the scene once the file has changed (nothing watches
// it), when it is opened again, or under new limits. Each loaded file is read once, however
// many objects draw it.

#include "file_failures.h"
#include "import_process.h"
#include "object_mesh.h"
#include "scene_document.h"
#include "texture_files.h"

#include <QObject>
#include <QThreadPool>

#include <atomic>
#include <map>
#include <memory>
#include <optional>

namespace lb {

class ObjectLoader : public QObject
{
    Q_OBJECT
public:
    explicit ObjectLoader(SceneDocument *document, QObject *parent = nullptr);
    ~ObjectLoader() override; // stops the helper and waits for a running build

    // Loads a mesh file; on success the object selected now becomes it. loadFinished()
    // follows.
    void open(const QString &path);
    // "Use the mesh file's material": switches it for the selected object and, with its
    // file on screen, takes the file's Ka, Kd, Ks and shininess in the same edit.
    void setAdoptFileMaterial(bool on);
    // Decodes an image file (off the GUI thread; again, if it was in: it may have changed); on
    // success it becomes the texture of the object selected now, with its texture switch on.
    // textureFinished() follows; a file that fails changes nothing.
    void openTexture(const QString &path);
    bool isDecodingTexture() const { return m_textures.isDecoding(); }
    // Stops a running open(): the helper is killed, a build in progress dropped.
    void cancel();
    bool isLoading() const { return m_loading; }
    qint64 helperPid() const { return m_import.helperPid(); } // 0 when no helper runs
    // New limits; files the scene names that failed are read again under them.
    void setLimits(const ImportLimits &limits);
    const ImportLimits &limits() const { return m_limits; }

    // Object `index`'s loaded file (nullptr while it is a shape) and the mesh and texture
    // being drawn for it (its image file, else its mesh file's texture, else nullptr: the
    // checker); -1: the selected object.
    const MeshFile *file(int index = -1) const;
    std::shared_ptr<const Mesh> mesh(int index = -1) const;
    std::shared_ptr<const Texture> texture(int index = -1) const;
    // Why object `index`'s image file is not shown (missing, not an image, ...), or empty.
    QString textureProblem(int index = -1) const;
    // Why object `index`'s mesh file is not drawn ("FILE: no such file", ...; its shape is
    // drawn instead), or empty.
    QString meshProblem(int index = -1) const;
    // What the Faces choice turned in object `index`'s mesh ("faces turned: the file winds
    // them clockwise"), or empty.
    QString facesRemark(int index = -1) const;
    int objectCount() const { return int(m_slots.size()); }
    // "teapot.obj: 6,320 vertices, 12,288 triangles, loaded in 0.21 s", or the shape's, for
    // the selected object.
    // `count` writes the counts (meshSummary()).
    QString summary(const std::function<QString(qulonglong)> &count = {}) const;
    // True while a build runs on the worker thread (tests wait for it).
    bool isBuilding() const { return m_job != nullptr; }
    // Blocks until the build thread is idle, processing no events (its answer is delivered
    // by the event loop afterwards): for a test that tightens the whole process's memory
    // limit while a build runs, and must not paint meanwhile.
    void waitForBuildThread() { m_pool.waitForDone(); }

signals:
    // Object `index` draws this now (and the list may have grown or shrunk: objectCount()).
    void meshReady(int index, std::shared_ptr<const lb::Mesh> mesh,
                   std::shared_ptr<const lb::Texture> texture);
    void objectCountChanged(int count);
    void loadStarted(const QString &path);
    void loadProgress(double fraction, const QString &stage);
    // `message`: the summary on success, "FILE: what went wrong" otherwise.
    void loadFinished(bool ok, const QString &message);
    // An image file opened, or one a scene names that could not be read: "brick.png: 512 x
    // 512 texels", or "FILE: what went wrong" (the scene's objects keep naming it and show
    // what they would without it; textureProblem() says why).
    void textureFinished(bool ok, const QString &message);
    // Object `index`'s mesh could not be built ("out of memory building the torus at
    // tessellation 2000"): it keeps drawing what it drew (nothing, if it had nothing) and is
    // not built again until it asks for another mesh.
    void buildFailed(int index, const QString &message);

private:
    struct Job
    {
        int index = 0; // the object built
        ObjectSettings object;
        std::shared_ptr<const MeshFile> file;
        ObjectMeshKey key;
        bool commit = false; // the last step of open(): the file becomes the object's mesh
        std::atomic_bool cancel{false};
        std::shared_ptr<const Mesh> mesh;
        QString error;  // why there is no mesh: tryBuildObjectMesh's
        QString remark; // what the Faces choice turned
    };
    // What one object draws, and what it was built from.
    struct Slot
    {
        std::shared_ptr<const MeshFile> file;
        std::shared_ptr<const Mesh> mesh;
        std::shared_ptr<const Texture> texture;
        ObjectMeshKey key;
        QString remark; // what the Faces choice turned ("faces turned: ...")
    };

    void sync();
    // Sends meshReady() for each object whose mesh or texture differs from what it last sent.
    void emitChanged();
    std::shared_ptr<const Texture> drawnTexture(int index) const;
    void textureDecoded(const QString &path, const TextureFileRead &read);
    // Slots follow the objects when the list changes: a slot whose key an object still
    // wants is kept for it, wherever it moved to.
    void matchSlots();
    void startBuild(int index, const ObjectSettings &object, std::shared_ptr<const MeshFile> file,
                    bool commit);
    void finishBuild(const std::shared_ptr<Job> &job);
    void imported(const ImportResult &result);
    std::shared_ptr<const MeshFile> loadedFile(const QString &path) const;
    int resolve(int index) const;

    SceneDocument *m_document;
    ImportProcess m_import;
    ImportLimits m_limits;
    QThreadPool m_pool;
    std::shared_ptr<Job> m_job; // the build in flight; one at a time
    bool m_loading = false;
    QString m_loadingPath;
    int m_loadingObject = 0; // the object the file being read is for
    std::map<QString, std::shared_ptr<const MeshFile>> m_files; // loaded, by path
    FileFailures m_failures;   // files the scene names that could not be read
    std::vector<Slot> m_slots; // by object
    // What meshReady() last said of each object.
    using Drawn = std::pair<std::shared_ptr<const Mesh>, std::shared_ptr<const Texture>>;
    std::vector<std::optional<Drawn>> m_sent;
    TextureFiles m_textures;
    struct TextureOpen
    {
        QString path;
        int index = 0; // the object it is for
    };
    std::vector<TextureOpen> m_textureOpens; // opened, not decoded yet; oldest first
    // The loader's own edits and imports: while one runs, the document's changed() and a
    // replaced import's cancellation are not acted on (each site syncs itself afterwards).
    bool m_busy = false;
    std::vector<ObjectSettings> m_objectsBefore; // the list at the last change (removals)
    // One object removed: the file being opened and the build in flight follow their objects
    // to their new indices (or stop, if it was theirs); several at once: they stop.
    void followRemoval(const std::vector<ObjectSettings> &now);
    bool m_removedWhileLoading = false;
    // Starts reading `path` for object `index` (a replaced import is not reported).
    void startImport(const QString &path, int index);
};

} // namespace lb
