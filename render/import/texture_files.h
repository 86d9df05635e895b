#pragma once
// Image files decoded for textures, off the GUI thread, one at a time, and kept by path while
// an object names them (each file decoded once, however many objects show it).

#include "file_failures.h"
#include "texture_file.h"

#include <QObject>
#include <QStringList>
#include <QThreadPool>

#include <map>
#include <memory>

namespace lb {

class TextureFiles : public QObject
{
    Q_OBJECT
public:
    explicit TextureFiles(QObject *parent = nullptr);
    ~TextureFiles() override; // waits for a decode in flight

    // The decoded image of `path`, or nullptr (not asked for, being decoded, or failed).
    std::shared_ptr<const Texture> find(const QString &path) const;
    // Decodes `path` on the worker unless it is in already, queued, or failed before and
    // unchanged since (a file put back, or saved again, is tried again); decoded() follows.
    void request(const QString &path);
    // Why `path` could not be read, when it was tried and failed (empty otherwise).
    QString failure(const QString &path) const;
    // Decodes `path` again (the file may have changed since): the image in stays until the
    // new one replaces it; one that fails leaves it as it was. decoded() follows.
    void reread(const QString &path);
    bool isDecoding() const { return !m_decoding.isEmpty(); }
    // Lets go of the images of paths not in `keep` (requests still queued for them too).
    void keepOnly(const QStringList &keep);

signals:
    void decoded(const QString &path, const lb::TextureFileRead &read);

private:
    void startNext();

    QThreadPool m_pool;
    QString m_decoding; // the path on the worker; empty when idle
    QStringList m_queue;
    std::map<QString, TextureFileRead> m_images; // decoded ones only
    FileFailures m_failed;                       // until read again
};

} // namespace lb
