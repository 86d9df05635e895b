#include "object_loader.h"

#include <QFileInfo>

#include <algorithm>
#include <tuple>
#include <utility>

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
        if (m_busy)
            return;
        if (!(parts & ScenePart::Object)) {
            if (parts & ScenePart::Material) // so that a removal is told apart from this
                m_objectsBefore = m_document->scene().objects;
            return;
        }
        const std::vector<ObjectSettings> &now = m_document->scene().objects;
        if (now.size() < m_objectsBefore.size())
            followRemoval(now);
        sync();
    });
    connect(&m_import, &ImportProcess::progress, this,
            [this](double fraction, const QString &stage) {
                emit loadProgress(0.9 * fraction, stage); // the build takes the last tenth
            });
    connect(&m_import, &ImportProcess::finished, this, &ObjectLoader::imported);
    connect(&m_textures, &TextureFiles::decoded, this, &ObjectLoader::textureDecoded);
    sync();
}

ObjectLoader::~ObjectLoader()
{
    if (m_job)
        m_job->cancel = true;
    m_pool.waitForDone();
}

QString ObjectLoader::facesRemark(int index) const
{
    index = resolve(index);
    return index < int(m_slots.size()) ? m_slots[std::size_t(index)].remark : QString();
}

int ObjectLoader::resolve(int index) const
{
    return index < 0 ? m_document->scene().selected : index;
}

const MeshFile *ObjectLoader::file(int index) const
{
    index = resolve(index);
    return index < int(m_slots.size()) ? m_slots[std::size_t(index)].file.get() : nullptr;
}

std::shared_ptr<const Mesh> ObjectLoader::mesh(int index) const
{
    index = resolve(index);
    return index < int(m_slots.size()) ? m_slots[std::size_t(index)].mesh : nullptr;
}

QString ObjectLoader::meshProblem(int index) const
{
    index = resolve(index);
    const std::vector<ObjectSettings> &objects = m_document->scene().objects;
    if (index >= int(objects.size()))
        return {};
    return m_failures.error(objects[std::size_t(index)].meshPath);
}

void ObjectLoader::setLimits(const ImportLimits &limits)
{
    m_limits = limits;
    // A file that failed may fit the new limits: its objects ask for it again.
    if (!m_failures.isEmpty()) {
        m_failures.clear();
        sync();
    }
}

void ObjectLoader::emitChanged()
{
    const std::size_t n = m_slots.size();
    m_sent.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        std::pair drawn{m_slots[i].mesh, drawnTexture(int(i))};
        if (m_sent[i] == drawn)
            continue;
        m_sent[i] = drawn;
        emit meshReady(int(i), drawn.first, drawn.second);
    }
}

std::shared_ptr<const MeshFile> ObjectLoader::loadedFile(const QString &path) const
{
    const auto found = m_files.find(path);
    return found == m_files.end() ? nullptr : found->second;
}

QString ObjectLoader::summary(const std::function<QString(qulonglong)> &count) const
{
    const std::shared_ptr<const Mesh> drawn = mesh();
    if (!drawn)
        return {};
    const MeshFile *loaded = file();
    const QString name = loaded ? QFileInfo(loaded->path).fileName()
                                : shapeLabel(m_document->scene().selectedObject().shape);
    // A two-sided mesh draws each triangle twice; the summary counts the object's own.
    const std::size_t copies =
        m_document->scene().selectedObject().faces == Faces::TwoSided ? 2 : 1;
    return meshSummary(name, drawn->vertexCount() / copies, drawn->triangleCount() / copies, loaded,
                       facesRemark(), count);
}

void ObjectLoader::open(const QString &path)
{
    m_failures.forget(path); // asked for again: read again, whatever failed before
    if (m_job && m_job->commit) {
        m_job->cancel = true; // a file still being built gives way to the newer one
        m_job.reset();
    }
    startImport(path, m_document->scene().selected);
}

void ObjectLoader::followRemoval(const std::vector<ObjectSettings> &now)
{
    const bool opening = m_loading || (m_job && m_job->commit);
    if (!opening && !m_job && m_textureOpens.empty())
        return;
    // Which one went: the first place where the lists differ.
    int removed = -1;
    if (now.size() + 1 == m_objectsBefore.size()) {
        removed = int(now.size());
        for (std::size_t i = 0; i < now.size(); ++i)
            if (!(now[i] == m_objectsBefore[i])) {
                removed = int(i);
                break;
            }
    }
    const auto follow = [&](int &index) { // false: its object is gone
        if (removed < 0 || index == removed)
            return false;
        if (index > removed)
            --index;
        return true;
    };
    if (m_job && !follow(m_job->index))
        m_job->cancel = true; // dropped by finishBuild()
    if (m_loading && !follow(m_loadingObject)) {
        m_removedWhileLoading = true;
        m_import.cancel();
    }
    for (auto it = m_textureOpens.begin(); it != m_textureOpens.end();) {
        if (follow(it->index)) {
            ++it;
            continue;
        }
        emit textureFinished(
            false, tr("%1: not used: its object was removed").arg(QFileInfo(it->path).fileName()));
        it = m_textureOpens.erase(it);
    }
}

void ObjectLoader::startImport(const QString &path, int index)
{
    m_loading = true;
    m_loadingPath = path;
    m_loadingObject = index;
    emit loadStarted(path);
    // start() ends an import still running at once, and reports that one's cancellation
    // from inside: imported() leaves it unreported while m_busy is set.
    const bool busy = std::exchange(m_busy, true);
    m_import.start(path, m_limits);
    m_busy = busy;
}

void ObjectLoader::setAdoptFileMaterial(bool on)
{
    const ObjectSettings &object = m_document->scene().selectedObject();
    const MeshFile *drawn = file();
    const std::shared_ptr<const MeshFile> loaded =
        drawn && drawn->path == object.meshPath ? loadedFile(drawn->path) : nullptr;
    m_document->edit([&](Scene &s) {
        ObjectSettings &o = s.selectedObject();
        o.adoptFileMaterial = on;
        if (on && loaded)
            o.material = adoptMaterial(o.material, loaded->material);
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
        if (result.cancelled && (m_busy || m_import.isRunning()))
            return;
        m_loading = false;
        const bool removed = std::exchange(m_removedWhileLoading, false);
        // Objects that name this file (a restart, a scene file) keep naming it and draw their
        // shapes until it changes or is opened again (a cancelled one too, or sync() would
        // start it again at once). Known before loadFinished(), whose listeners show it.
        if (!removed && !loadedFile(m_loadingPath)) // a loaded one stays as it is
            m_failures.add(m_loadingPath, result.cancelled
                                              ? tr("%1: not loaded: cancelled").arg(m_loadingPath)
                                              : result.error);
        emit loadFinished(false, removed ? tr("%1: not loaded: its object was removed")
                                               .arg(QFileInfo(m_loadingPath).fileName())
                                 : result.cancelled ? tr("Loading cancelled")
                                                    : result.error);
        sync(); // their shapes, and another file a scene names, maybe
        return;
    }
    m_files[result.file->path] = result.file;
    const Scene &scene = m_document->scene();
    const int index =
        m_loadingObject < int(scene.objects.size()) ? m_loadingObject : scene.selected;
    ObjectSettings object = scene.objects[std::size_t(index)];
    object.meshPath = result.file->path;
    if (m_job) // a shape build in flight is superseded; its result is dropped
        m_job->cancel = true;
    m_job.reset();
    startBuild(index, object, result.file, true);
}

void ObjectLoader::matchSlots()
{
    const std::vector<ObjectSettings> &objects = m_document->scene().objects;
    const std::size_t n = objects.size();
    std::vector<ObjectMeshKey> wanted(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::shared_ptr<const MeshFile> f =
            objects[i].meshPath.isEmpty() ? nullptr : loadedFile(objects[i].meshPath);
        wanted[i] = objectMeshKey(objects[i], f.get());
    }
    std::vector<Slot> old = std::move(m_slots);
    std::vector<bool> taken(old.size(), false);
    m_slots.assign(n, Slot{});
    std::vector<bool> matched(n, false);
    // What an object still wants it keeps, wherever it was; then the rest keep what they
    // drew (shown until their new mesh is built).
    const auto take = [&](std::size_t i, std::size_t j) {
        m_slots[i] = old[j];
        taken[j] = matched[i] = true;
    };
    for (std::size_t i = 0; i < n; ++i)
        if (i < old.size() && old[i].mesh && old[i].key == wanted[i])
            take(i, i);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < old.size() && !matched[i]; ++j)
            if (!taken[j] && old[j].mesh && old[j].key == wanted[i])
                take(i, j);
    for (std::size_t i = 0; i < n; ++i)
        if (!matched[i] && i < old.size() && !taken[i])
            take(i, i);
    if (old.size() != n)
        emit objectCountChanged(int(n));
    emitChanged();
}

void ObjectLoader::sync()
{
    const Scene &scene = m_document->scene();
    m_objectsBefore = scene.objects;
    // Images: those named and not in yet are decoded; the rest let go.
    QStringList images;
    for (const ObjectSettings &object : scene.objects)
        if (!object.textureFile.isEmpty()) {
            images << object.textureFile;
            if (!m_textures.find(object.textureFile))
                m_textures.request(object.textureFile);
        }
    for (const TextureOpen &open : m_textureOpens)
        images << open.path;
    m_textures.keepOnly(images);

    matchSlots(); // also while a build runs: the view draws each object's own mesh meanwhile
    if (m_job)
        return; // one build at a time; finishBuild() syncs again with the newest scene
    for (int i = 0; i < int(scene.objects.size()); ++i) {
        const ObjectSettings &object = scene.objects[std::size_t(i)];
        std::shared_ptr<const MeshFile> file;
        if (!object.meshPath.isEmpty()) {
            file = loadedFile(object.meshPath);
            if (!file && !m_failures.stillFailing(object.meshPath)) {
                if (!m_loading) // named by a restored or opened scene
                    startImport(object.meshPath, i);
                if (m_slots[std::size_t(i)].mesh)
                    continue; // what is on screen stays until the file is in
            }
        }
        const Slot &slot = m_slots[std::size_t(i)];
        if (slot.mesh && objectMeshKey(object, file.get()) == slot.key)
            continue;
        ObjectSettings shape = object;
        if (!file)
            shape.meshPath.clear();
        startBuild(i, shape, file, false);
        return; // finishBuild() syncs again for the next one
    }
    // Files no object names any more are let go, and so are their failures.
    auto named = [&scene](const QString &path) {
        return std::any_of(scene.objects.begin(), scene.objects.end(),
                           [&](const ObjectSettings &o) { return o.meshPath == path; });
    };
    for (auto it = m_files.begin(); it != m_files.end();)
        it = named(it->first) ? std::next(it) : m_files.erase(it);
    m_failures.keepOnly(named);
}

void ObjectLoader::startBuild(int index, const ObjectSettings &object,
                              std::shared_ptr<const MeshFile> file, bool commit)
{
    auto job = std::make_shared<Job>();
    job->index = index;
    job->object = object;
    job->file = std::move(file);
    job->key = objectMeshKey(object, job->file.get());
    job->commit = commit;
    m_job = job;
    const auto build = [job] { // nothing escapes: an exception would end the process
        ObjectMeshBuild b = tryBuildObjectMesh(job->object, job->file.get(), &job->cancel);
        job->mesh = std::move(b.mesh);
        job->error = std::move(b.error);
        job->remark = std::move(b.remark);
    };
    if (objectMeshWork(job->object, job->file.get()) <= kBuildInlineWork) {
        build();
        finishBuild(job);
        return;
    }
    if (commit)
        emit loadProgress(0.9, tr("building"));
    m_pool.start([this, job, build] {
        build();
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
    const int index = job->index;
    // The list may have changed while the build ran: the object must still be there and, for
    // a shape or a file already in, still want this mesh (a file being opened is checked
    // when the list shrinks: see the constructor).
    const std::vector<ObjectSettings> &objects = m_document->scene().objects;
    const bool there = index < int(objects.size());
    const bool wanted =
        there && (job->commit || objectMeshKey(objects[std::size_t(index)],
                                               objects[std::size_t(index)].meshPath.isEmpty()
                                                   ? nullptr
                                                   : job->file.get()) == job->key);
    const bool built = job->mesh && !job->cancel && wanted;
    if (!job->error.isEmpty() && !job->commit && wanted) { // what it drew stays, not rebuilt
        m_slots.resize(std::max(m_slots.size(), std::size_t(index) + 1));
        Slot &slot = m_slots[std::size_t(index)];
        slot.mesh = slot.mesh ? slot.mesh : std::make_shared<const Mesh>();
        slot.key = job->key;
        emitChanged();
    }
    if (!job->error.isEmpty() && !job->commit) // an open says it in loadFinished()
        emit buildFailed(index, job->error);
    if (built) {
        if (int(m_slots.size()) <= index)
            m_slots.resize(std::size_t(index) + 1);
        m_slots[std::size_t(index)] = {
            job->file, job->mesh, job->file ? job->file->texture : nullptr, job->key, job->remark};
    }
    if (job->commit) {
        m_loading = false;
        if (built) {
            const QString path = job->file->path;
            const bool adopt = job->object.adoptFileMaterial;
            const FileMaterial material = job->file->material;
            const bool busy = std::exchange(m_busy, true); // synced below, after the signals
            m_document->edit([&](Scene &s) {
                ObjectSettings &o = s.objects[std::size_t(index)];
                o.meshPath = path;
                if (adopt)
                    o.material = adoptMaterial(o.material, material);
            });
            m_busy = busy;
        }
    }
    if (built)
        emitChanged();
    if (job->commit)
        emit loadFinished(built, built                  ? summary()
                                 : job->error.isEmpty() ? tr("Loading cancelled")
                                                        : job->error);
    sync(); // whatever the scene asked for meanwhile
}

} // namespace lb
