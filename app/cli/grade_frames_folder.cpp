#include "grade_frames_folder.h"

#include <QDir>
#include <QFileInfo>

namespace lb {

namespace {

constexpr char kPrefix[] = "lightbench-frames-";
constexpr char kLockName[] = "batch.lock";

} // namespace

FramesFolder::FramesFolder() : m_dir(QDir::temp().filePath(QString(kPrefix) + "XXXXXX"))
{
    if (!m_dir.isValid())
        return;
    m_lock = std::make_unique<QLockFile>(QDir(m_dir.path()).filePath(kLockName));
    // Never stale by age: a batch may run for hours; only a lock whose process is gone is.
    m_lock->setStaleLockTime(0);
    if (!m_lock->tryLock(0))
        remove();
}

FramesFolder::~FramesFolder()
{
    remove();
}

bool FramesFolder::isValid() const
{
    return m_dir.isValid() && m_lock && m_lock->isLocked();
}

QString FramesFolder::path() const
{
    return m_dir.path();
}

void FramesFolder::remove()
{
    m_lock.reset(); // unlocked: its file goes
    m_dir.remove();
}

int removeAbandonedFramesFolders()
{
    int removed = 0;
    const QDir temporary = QDir::temp();
    for (const QString &name : temporary.entryList(
             {QString(kPrefix) + "*"}, QDir::Dirs | QDir::NoSymLinks | QDir::NoDotAndDotDot)) {
        const QString folder = temporary.filePath(name);
        const QString lockPath = QDir(folder).filePath(kLockName);
        // No lock (yet): a batch making its folder this moment, or not ours.
        if (!QFileInfo(lockPath).isFile())
            continue;
        QLockFile lock(lockPath);
        lock.setStaleLockTime(0); // taken only from a process that is gone
        if (!lock.tryLock(0))
            continue; // its batch is running
        lock.unlock();
        // Links in it are removed, not followed; what cannot be removed (another user's) stays.
        if (QDir(folder).removeRecursively())
            ++removed;
    }
    return removed;
}

} // namespace lb
