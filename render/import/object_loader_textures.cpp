// The object loader's image files: each object's texture, decoded off the GUI thread
// (texture_files.h), and what is wrong with one that cannot be read.
#include "object_loader.h"

namespace lb {

std::shared_ptr<const Texture> ObjectLoader::texture(int index) const
{
    return drawnTexture(resolve(index));
}

QString ObjectLoader::textureProblem(int index) const
{
    index = resolve(index);
    const std::vector<ObjectSettings> &objects = m_document->scene().objects;
    return index < int(objects.size()) ? m_textures.failure(objects[std::size_t(index)].textureFile)
                                       : QString();
}

std::shared_ptr<const Texture> ObjectLoader::drawnTexture(int index) const
{
    const std::vector<ObjectSettings> &objects = m_document->scene().objects;
    if (index < int(objects.size()) && !objects[std::size_t(index)].textureFile.isEmpty())
        if (std::shared_ptr<const Texture> image =
                m_textures.find(objects[std::size_t(index)].textureFile))
            return image;
    return index < int(m_slots.size()) ? m_slots[std::size_t(index)].texture : nullptr;
}

void ObjectLoader::openTexture(const QString &path)
{
    m_textureOpens.push_back({path, m_document->scene().selected});
    m_textures.reread(path); // textureDecoded() follows
}

void ObjectLoader::textureDecoded(const QString &path, const TextureFileRead &read)
{
    // Every object this file was opened for (one open may follow another before either is in).
    std::vector<int> openedFor;
    for (auto it = m_textureOpens.begin(); it != m_textureOpens.end();)
        if (it->path == path) {
            openedFor.push_back(it->index);
            it = m_textureOpens.erase(it);
        } else {
            ++it;
        }

    const bool opened = !openedFor.empty();
    const bool busy = std::exchange(m_busy, true); // synced below
    if (read.texture && opened) {
        m_document->edit([&](Scene &s) {
            for (const int index : openedFor)
                if (index < int(s.objects.size())) {
                    s.objects[std::size_t(index)].textureFile = path;
                    s.objects[std::size_t(index)].texture = true;
                }
        });
    }

    // Named by a scene file or a restart and not readable: those objects keep naming it (a
    // scene saved now loses nothing) and show what they would without it.
    m_busy = busy;
    if (opened || !read.texture)
        emit textureFinished(bool(read.texture),
                             read.texture ? read.summary
                             : opened     ? read.error
                                          : tr("%1 (the objects naming it show the mesh file's "
                                                   "texture or the checker, and keep its name for when "
                                                   "the file is back)")
                                            .arg(read.error));
    sync();
}

} // namespace lb
