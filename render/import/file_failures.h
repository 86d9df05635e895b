#pragma once
// Files that could not be loaded, each with why and what the file looked like then (its
// existence, size and modification time), so that it is tried again once it changes (put
// back, saved again) and not before. The image files and the object loader keep one each.

#include <QString>

#include <functional>
#include <map>

namespace lb {

class FileFailures
{
public:
    // `path` failed now, for this reason ("FILE: what went wrong").
    void add(const QString &path, const QString &error);
    // True while `path` failed and has not changed since; a changed one is forgotten.
    bool stillFailing(const QString &path);
    // Why `path` failed, or empty.
    QString error(const QString &path) const;
    void forget(const QString &path) { m_failures.erase(path); }
    void clear() { m_failures.clear(); }
    bool isEmpty() const { return m_failures.empty(); }
    // Forgets the paths `keep` says no to.
    void keepOnly(const std::function<bool(const QString &)> &keep);

private:
    struct Failure
    {
        QString error;
        QString state;
    };
    std::map<QString, Failure> m_failures;
};

} // namespace lb
