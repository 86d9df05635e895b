#pragma once
// Keeps the drawn object in step with the scene, without ever blocking the GUI thread on a big
// mesh: mesh files are read by the import helper (ImportProcess), and meshes with many
// triangles are built (shape, generated normals) on a worker thread while the previous mesh
// keeps drawing. A file becomes the scene's object only once it is loaded and built; a file
// that fails leaves the scene, and the mesh on screen, as they were.

#include "import_process.h"
#include "object_mesh.h"
#include "scene_document.h"

#include <QObject>
#include <QThreadPool>

#include <atomic>
#include <memory>

namespace lb {

class ObjectLoader : public QObject
{
    Q_OBJECT
public:
    explicit ObjectLoader(SceneDocument *document, QObject *parent = nullptr);
    ~ObjectLoader() override; // stops the helper and waits for a running build

    // Loads a mesh file; on success the scene's object becomes it. loadFinished() follows.
    void open(const QString &path);
    // "Use the mesh file's material": switches it in the scene and, with a file on screen,
    // takes the file's Ka, Kd, Ks and shininess in the same edit.
    void setAdoptFileMaterial(bool on);
    // Stops a running open(): the helper is killed, a build in progress dropped.
    void cancel();
    bool isLoading() const { return m_loading; }
    qint64 helperPid() const { return m_import.helperPid(); } // 0 when no helper runs
    void setLimits(const ImportLimits &limits) { m_limits = limits; }
    const ImportLimits &limits() const { return m_limits; }

    // The loaded file (nullptr while the object is a shape) and the mesh being drawn.
    const MeshFile *file() const { return m_file.get(); }
    std::shared_ptr<const Mesh> mesh() const { return m_mesh; }
    std::shared_ptr<const Texture> texture() const { return m_texture; }
    // "teapot.obj: 6,320 vertices, 12,288 triangles, loaded in 0.21 s", or the shape's.
    QString summary() const;
    // True while a build runs on the worker thread (tests wait for it).
    bool isBuilding() const { return m_job != nullptr; }

signals:
    void meshReady(std::shared_ptr<const lb::Mesh> mesh,
                   std::shared_ptr<const lb::Texture> texture);
    void loadStarted(const QString &path);
    void loadProgress(double fraction, const QString &stage);
    // `message`: the summary on success, "FILE: what went wrong" otherwise.
    void loadFinished(bool ok, const QString &message);

private:
    struct Job
    {
        ObjectSettings object;
        std::shared_ptr<const MeshFile> file;
        ObjectMeshKey key;
        bool commit = false; // the last step of open(): the file becomes the scene's object
        std::atomic_bool cancel{false};
        std::shared_ptr<const Mesh> mesh;
    };

    void sync();
    void startBuild(const ObjectSettings &object, std::shared_ptr<const MeshFile> file,
                    bool commit);
    void finishBuild(const std::shared_ptr<Job> &job);
    void imported(const ImportResult &result);

    SceneDocument *m_document;
    ImportProcess m_import;
    ImportLimits m_limits;
    QThreadPool m_pool;
    std::shared_ptr<Job> m_job; // the build in flight; one at a time
    bool m_loading = false;
    QString m_loadingPath;
    std::shared_ptr<const MeshFile> m_file;
    std::shared_ptr<const Mesh> m_mesh;
    std::shared_ptr<const Texture> m_texture;
    ObjectMeshKey m_key;
};

} // namespace lb
