#include "object_loader.h"

#include <QFileInfo>
#include <QLocale>

namespace lb {

namespace {

// Builds of up to this much work (objectMeshWork: triangles whose normals are generated) run
// on the GUI thread: 10-50 ms at most, whatever the mesh, and the new mesh is on screen in the
// same frame. More goes to the worker, where Cancel stops it.
constexpr std::size_t kBuildInlineWork = 100'000;

} // namespace

ObjectLoader::ObjectLoader(SceneDocument *document, QObject *parent)
    : QObject(parent), m_document(document)
{
    m_pool.setMaxThreadCount(1);
    connect(document, &SceneDocument::changed, this, [this](SceneParts parts) {
        if (parts & ScenePart::Object)
            sync();
    });
    connect(&m_import, &ImportProcess::progress, this,
            [this](double fraction, const QString &stage) {
                emit loadProgress(0.9 * fraction, stage); // the build takes the last tenth
            });
    connect(&m_import, &ImportProcess::finished, this, &ObjectLoader::imported);
    sync();
}

ObjectLoader::~ObjectLoader()
{
    if (m_job)
        m_job->cancel = true;
    m_pool.waitForDone();
}

QString ObjectLoader::summary() const
{
    if (!m_mesh)
        return {};
    const QLocale locale;
    const QString name =
        m_file ? QFileInfo(m_file->path).fileName() : toName(m_document->scene().object.shape);
    QString s = tr("%1: %2 vertices, %3 triangles")
                    .arg(name, locale.toString(qulonglong(m_mesh->vertexCount())),
                         locale.toString(qulonglong(m_mesh->triangleCount())));
    if (m_file) {
        s += tr(", loaded in %1 s").arg(m_file->seconds, 0, 'f', 2);
        if (!m_file->hasNormals())
            s += tr(", normals generated (the file has none)");
        const QStringList remarks = m_file->remarks();
        if (!remarks.isEmpty())
            s += " (" + remarks.join("; ") + ")";
    }
    return s;
}

void ObjectLoader::open(const QString &path)
{
    if (m_job && m_job->commit) {
        m_job->cancel = true; // a file still being built gives way to the newer one
        m_job.reset();
    }
    m_loading = true;
    m_loadingPath = path;
    emit loadStarted(path);
    m_import.start(path, m_limits);
}

void ObjectLoader::setAdoptFileMaterial(bool on)
{
    const bool onScreen = m_file && m_file->path == m_document->scene().object.meshPath;
    const std::shared_ptr<const MeshFile> file = onScreen ? m_file : nullptr;
    m_document->edit([&](Scene &s) {
        s.object.adoptFileMaterial = on;
        if (on && file)
            s.material = adoptMaterial(s.material, file->material);
    });
}

void ObjectLoader::cancel()
{
    if (m_import.isRunning())
        m_import.cancel(); // imported() reports it
    else if (m_job && m_job->commit)
        m_job->cancel = true; // finishBuild() reports it
}

void ObjectLoader::imported(const ImportResult &result)
{
    if (!result.ok()) {
        // A newer open() replaced this one: that one reports for itself.
        if (result.cancelled && m_import.isRunning())
            return;
        m_loading = false;
        emit loadFinished(false, result.cancelled ? tr("Loading cancelled") : result.error);
        // A scene that names this file (a restart, a scene file) falls back to its shape.
        if (m_document->scene().object.meshPath == m_loadingPath && !result.cancelled)
            m_document->edit([](Scene &s) { s.object.meshPath.clear(); });
        return;
    }
    ObjectSettings object = m_document->scene().object;
    object.meshPath = result.file->path;
    if (m_job) // a shape build in flight is superseded; its result is dropped
        m_job->cancel = true;
    m_job.reset();
    startBuild(object, result.file, true);
}

void ObjectLoader::sync()
{
    if (m_job)
        return; // one build at a time; finishBuild() syncs again with the newest scene
    const ObjectSettings &object = m_document->scene().object;
    std::shared_ptr<const MeshFile> file;
    if (!object.meshPath.isEmpty()) {
        if (m_file && m_file->path == object.meshPath) {
            file = m_file;
        } else {
            if (!m_loading || m_loadingPath != object.meshPath)
                open(object.meshPath); // named by a restored or opened scene
            if (m_mesh)
                return; // what is on screen stays until the file is in
        }
    } else if (m_file) {
        m_file.reset(); // back to the shapes
    }
    const ObjectMeshKey key = objectMeshKey(object, file.get());
    if (m_mesh && key == m_key)
        return;
    ObjectSettings shape = object;
    if (!file)
        shape.meshPath.clear();
    startBuild(shape, file, false);
}

void ObjectLoader::startBuild(const ObjectSettings &object, std::shared_ptr<const MeshFile> file,
                              bool commit)
{
    auto job = std::make_shared<Job>();
    job->object = object;
    job->file = std::move(file);
    job->key = objectMeshKey(object, job->file.get());
    job->commit = commit;
    m_job = job;
    if (objectMeshWork(job->object, job->file.get()) <= kBuildInlineWork) {
        job->mesh = buildObjectMesh(job->object, job->file.get());
        finishBuild(job);
        return;
    }
    if (commit)
        emit loadProgress(0.9, tr("building"));
    m_pool.start([this, job] {
        job->mesh = buildObjectMesh(job->object, job->file.get(), &job->cancel);
        // The destructor waits for this task, so `this` is alive when the call is queued;
        // Qt drops it if the loader is gone before it is delivered.
        QMetaObject::invokeMethod(
            this, [this, job] { finishBuild(job); }, Qt::QueuedConnection);
    });
}

void ObjectLoader::finishBuild(const std::shared_ptr<Job> &job)
{
    if (job != m_job)
        return; // superseded by a newer build or file
    m_job.reset();
    const bool built = job->mesh && !job->cancel;
    if (built) {
        m_mesh = job->mesh;
        m_key = job->key;
        m_texture = job->file ? job->file->texture : nullptr;
        if (job->commit)
            m_file = job->file;
    }
    if (job->commit) {
        m_loading = false;
        if (built) {
            const QString path = job->file->path;
            const bool adopt = job->object.adoptFileMaterial;
            const FileMaterial material = job->file->material;
            m_document->edit([&](Scene &s) {
                s.object.meshPath = path;
                if (adopt)
                    s.material = adoptMaterial(s.material, material);
            });
        }
    }
    if (built)
        emit meshReady(m_mesh, m_texture);
    if (job->commit)
        emit loadFinished(built, built ? summary() : tr("Loading cancelled"));
    sync(); // whatever the scene asked for meanwhile
}

} // namespace lb
