#include "exclusive_file.h"
#include "qt_paths.h"

#include <QFileInfo>

#include <csignal>
#include <system_error>

// What Qt and standard C++ cannot do here:
// - Flush to the disk: Qt has no public fsync, and the standard none at all. A file system
//   that reports a full disk or a quota only then (NFS) is heard at the close, or not at all,
//   and the old file may be replaced by one the disk does not hold yet.
// - Keep the set-user-ID, set-group-ID and sticky bits of the old file: Qt's permissions have
//   no place for them (QFileDevice::setPermissions sets the rest on the open file).
// A rename that replaces the target on every system is std::filesystem::rename's (QFile's
// refuses an existing target).

namespace lb::platform {

namespace {

FileError failure(const QString &why, FileError::Code code = FileError::Other)
{
    FileError e;
    e.code = code;
    e.reason = why.toLocal8Bit().toStdString();
    return e;
}

QFileDevice::Permissions qtPermissions(unsigned bits)
{
    QFileDevice::Permissions p;
    const auto set = [&](unsigned bit, QFileDevice::Permissions flags) {
        if (bits & bit)
            p |= flags;
    };
    set(0400, QFileDevice::ReadOwner | QFileDevice::ReadUser);
    set(0200, QFileDevice::WriteOwner | QFileDevice::WriteUser);
    set(0100, QFileDevice::ExeOwner | QFileDevice::ExeUser);
    set(0040, QFileDevice::ReadGroup);
    set(0020, QFileDevice::WriteGroup);
    set(0010, QFileDevice::ExeGroup);
    set(0004, QFileDevice::ReadOther);
    set(0002, QFileDevice::WriteOther);
    set(0001, QFileDevice::ExeOther);
    return p;
}

} // namespace

struct ExclusiveFile::Handle
{
    QFile file;
    bool ours = false; // created here and not yet committed: discard() removes it
};

ExclusiveFile::ExclusiveFile() : m_handle(new Handle) {}

ExclusiveFile::~ExclusiveFile()
{
    discard();
}

FileError ExclusiveFile::create(const QString &path)
{
    discard();
    m_handle->file.setFileName(path);
    // NewOnly: O_EXCL where the system has it; Unbuffered: every write reaches the system
    // at once, so its failure is this call's.
    if (!m_handle->file.open(QIODevice::WriteOnly | QIODevice::NewOnly | QIODevice::Unbuffered)) {
        const QFileInfo there(path);
        return failure(m_handle->file.errorString(),
                       there.exists() || there.isSymLink() ? FileError::Exists : FileError::Other);
    }
    m_handle->ours = true;
    return {};
}

void ExclusiveFile::keepPermissions(unsigned permissions)
{
    if (m_handle->file.isOpen())
        m_handle->file.setPermissions(qtPermissions(permissions));
}

FileError ExclusiveFile::writeAll(const char *data, std::size_t size)
{
    // QFile returns what it wrote before a failure and says why only at the next call.
    for (std::size_t done = 0; done < size;) {
        const qint64 n = m_handle->file.write(data + done, qint64(size - done));
        if (n <= 0)
            return failure(
                n < 0 ? m_handle->file.errorString()
                      : QString::fromStdString(
                            std::make_error_code(std::errc::no_space_on_device).message()));
        done += std::size_t(n);
    }
    return {};
}

FileError ExclusiveFile::finish()
{
    m_handle->file.close();
    if (m_handle->file.error() != QFileDevice::NoError)
        return failure(m_handle->file.errorString());
    return {};
}

FileError ExclusiveFile::commitOver(const QString &target)
{
    std::error_code ec;
    std::filesystem::rename(nativePath(m_handle->file.fileName()), nativePath(target), ec);
    if (ec)
        return failure(QString::fromLocal8Bit(ec.message().c_str()));
    m_handle->ours = false;
    return {};
}

void ExclusiveFile::discard()
{
    m_handle->file.close();
    if (m_handle->ours)
        m_handle->file.remove();
    m_handle->ours = false;
}

void reportFileSizeLimitAsError()
{
    // SIGXFSZ is POSIX's, not the standard's: where it exists (macOS, this Linux build) it
    // is ignored all the same; Windows has no such signal.
#ifdef SIGXFSZ
    std::signal(SIGXFSZ, SIG_IGN);
#endif
}

} // namespace lb::platform
