#include "file_failures.h"

#include <QDateTime>
#include <QFileInfo>

namespace lb {

namespace {

QString fileState(const QString &path)
{
    const QFileInfo info(path);
    return info.exists()
               ? QString("%1 %2").arg(info.size()).arg(info.lastModified().toMSecsSinceEpoch())
               : QString();
}

} // namespace

void FileFailures::add(const QString &path, const QString &error)
{
    m_failures[path] = {error, fileState(path)};
}

bool FileFailures::stillFailing(const QString &path)
{
    const auto failed = m_failures.find(path);
    if (failed == m_failures.end())
        return false;
    if (failed->second.state == fileState(path))
        return true;
    m_failures.erase(failed); // put back or saved again: read it again
    return false;
}

QString FileFailures::error(const QString &path) const
{
    const auto failed = m_failures.find(path);
    return failed == m_failures.end() ? QString() : failed->second.error;
}

void FileFailures::keepOnly(const std::function<bool(const QString &)> &keep)
{
    for (auto it = m_failures.begin(); it != m_failures.end();)
        it = keep(it->first) ? std::next(it) : m_failures.erase(it);
}

} // namespace lb
