#include "grade_frames_folder.h"

#include "qt_paths.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>

namespace lb {

namespace {

constexpr char kPrefix[] = "lightbench-frames-";
constexpr char kLockName[] = "batch.lock";
// A folder without a whole lock (a batch killed between making the folder and writing the
// lock's owner) is left alone this long: it may be a batch's that is making it now.
constexpr qint64 kLocklessSeconds = 3600;

// Only a folder this user made for itself (QTemporaryDir's 0700) is looked into: in a shared
// temporary folder anyone can make one of that name, and what another user can change while
// it is being removed (a folder swapped for a link) must not decide what is removed.
bool isOwnPrivateFolder(const QString &path)
{
    const platform::FileStatus s =
        platform::fileStatus(platform::nativePath(path), platform::Links::Keep);
    return s.kind == platform::FileKind::Folder && s.ownedByThisUser && (s.permissions & 077u) == 0;
}

// Whether the batch that made `folder` is gone: its lock can be taken (the lock's process is
// not running), or it has no whole lock and is old.
bool abandoned(const QString &folder)
{
    const QString lockPath = QDir(folder).filePath(kLockName);
    const platform::FileStatus s =
        platform::fileStatus(platform::nativePath(lockPath), platform::Links::Keep);
    if (s.kind == platform::FileKind::Regular && s.size > 0) {
        QLockFile lock(lockPath);
        lock.setStaleLockTime(0); // taken only from a process that is gone
        if (!lock.tryLock(0))
            return false; // its batch is running
        lock.unlock();
        return true;
    }
    return QFileInfo(folder).lastModified().secsTo(QDateTime::currentDateTime()) > kLocklessSeconds;
}

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
        if (isOwnPrivateFolder(folder) && abandoned(folder) && QDir(folder).removeRecursively())
            ++removed;
    }
    return removed;
}

} // namespace lb
