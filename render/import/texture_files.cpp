#include "texture_files.h"

#include "file_failures.h"

#include <algorithm>

namespace lb {

TextureFiles::TextureFiles(QObject *parent) : QObject(parent)
{
    m_pool.setMaxThreadCount(1);
}

TextureFiles::~TextureFiles()
{
    m_pool.waitForDone();
}

std::shared_ptr<const Texture> TextureFiles::find(const QString &path) const
{
    const auto found = m_images.find(path);
    return found == m_images.end() ? nullptr : found->second.texture;
}

void TextureFiles::request(const QString &path)
{
    if (m_images.count(path) || m_failed.stillFailing(path) || path == m_decoding ||
        m_queue.contains(path))
        return;
    m_queue << path;
    startNext();
}

QString TextureFiles::failure(const QString &path) const
{
    return m_failed.error(path);
}

void TextureFiles::reread(const QString &path)
{
    m_failed.forget(path);
    if (m_queue.contains(path))
        return;
    m_queue << path;
    startNext();
}

void TextureFiles::keepOnly(const QStringList &keep)
{
    for (auto it = m_images.begin(); it != m_images.end();)
        it = keep.contains(it->first) ? std::next(it) : m_images.erase(it);
    m_failed.keepOnly([&keep](const QString &path) { return keep.contains(path); });
    m_queue.erase(std::remove_if(m_queue.begin(), m_queue.end(),
                                 [&](const QString &p) { return !keep.contains(p); }),
                  m_queue.end());
}

void TextureFiles::startNext()
{
    if (!m_decoding.isEmpty() || m_queue.isEmpty())
        return;
    m_decoding = m_queue.takeFirst();
    m_pool.start([this, path = m_decoding] {
        auto read = std::make_shared<TextureFileRead>(readTextureFile(path));
        // The destructor waits for this task, so `this` is alive when the call is queued;
        // Qt drops it if the object is gone before it is delivered.
        QMetaObject::invokeMethod(
            this,
            [this, path, read] {
                m_decoding.clear();
                if (read->texture)
                    m_images[path] = *read;
                else if (!m_images.count(path)) // a reread that fails keeps the image in
                    m_failed.add(path, read->error);
                emit decoded(path, *read);
                startNext();
            },
            Qt::QueuedConnection);
    });
}

} // namespace lb
