#include "wire_reader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>
#include <type_traits>

namespace lb {

namespace {

constexpr std::uint64_t kMaxSmallRecord = 1 << 20;     // progress, error, info, paths
constexpr std::uint64_t kMaxTextureRecord = 512 << 20; // an embedded texture
constexpr qsizetype kMaxWarnings = 20;                 // the helper sends no more either

bool finite(const glm::vec3 &v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

template <typename T> T read(const QByteArray &bytes)
{
    T value;
    std::memcpy(&value, bytes.constData(), sizeof value);
    return value;
}

} // namespace

bool WireReader::fail(const QString &why)
{
    if (m_state != State::Failed) {
        m_error = why;
        m_malformed = true;
    }
    m_state = State::Failed;
    m_targets.clear();
    m_mesh = Mesh{};
    return false;
}

bool WireReader::feed(const char *data, qint64 size)
{
    while (size > 0) {
        switch (m_state) {
        case State::Failed:
            return false;
        case State::Done:
            return fail(tr("the import stream goes on after its end"));
        case State::Magic:
        case State::Header:
        case State::MeshHeader: {
            const qint64 need = m_state == State::Magic    ? qint64(sizeof wire::kMagic)
                                : m_state == State::Header ? qint64(sizeof(wire::RecordHeader))
                                                           : qint64(sizeof(wire::MeshHeader));
            const qint64 take = std::min(size, need - qint64(m_pending.size()));
            m_pending.append(data, take);
            data += take;
            size -= take;
            if (m_pending.size() < need)
                break;
            if (m_state == State::Magic) {
                if (std::memcmp(m_pending.constData(), wire::kMagic, sizeof wire::kMagic) != 0)
                    return fail(tr("the import helper wrote something that is not a mesh stream"));
                m_pending.clear();
                m_state = State::Header;
            } else if (m_state == State::Header) {
                m_header = read<wire::RecordHeader>(m_pending);
                m_pending.clear();
                m_payloadLeft = m_header.size;
                const auto type = wire::Record(m_header.type);
                if (type == wire::Record::Mesh) {
                    if (m_haveMesh)
                        return fail(tr("the import stream holds two meshes"));
                    if (m_header.size < sizeof(wire::MeshHeader) ||
                        m_header.size > wire::kMaxRecordBytes)
                        return fail(tr("the import stream announces a mesh of a bad size"));
                    m_state = State::MeshHeader;
                    break;
                }
                const std::uint64_t limit =
                    type == wire::Record::TextureData ? kMaxTextureRecord : kMaxSmallRecord;
                if (m_header.size > limit)
                    return fail(tr("the import stream holds a record too large to be right"));
                m_state = State::Payload;
                if (m_payloadLeft == 0 && !finishRecord())
                    return false;
            } else {
                if (!startMesh())
                    return false;
            }
            break;
        }
        case State::Payload: {
            const qint64 take = qint64(std::min<std::uint64_t>(std::uint64_t(size), m_payloadLeft));
            m_pending.append(data, take);
            data += take;
            size -= take;
            m_payloadLeft -= std::uint64_t(take);
            if (m_payloadLeft == 0 && !finishRecord())
                return false;
            break;
        }
        case State::MeshArrays: {
            Target &t = m_targets[m_target];
            const std::uint64_t take =
                std::min<std::uint64_t>(std::uint64_t(size), t.size - m_targetOffset);
            try {
                std::memcpy(t.grow(m_targetOffset + take) + m_targetOffset, data, take);
            } catch (const std::bad_alloc &) {
                return fail(tr("not enough memory for the mesh (%1 MB received)")
                                .arg(m_meshReceived >> 20));
            }
            data += take;
            size -= qint64(take);
            m_targetOffset += take;
            m_meshReceived += take;
            if (m_targetOffset == t.size) {
                m_targetOffset = 0;
                ++m_target;
            }
            if (onProgress && (m_target == m_targets.size() || (m_meshReceived & 0xffffff) < take))
                onProgress(0.85 + 0.15 * double(m_meshReceived) / double(m_meshBytes),
                           //: a stage of loading a mesh file, shown beside its progress
                           tr("receiving"));
            if (m_target == m_targets.size()) {
                for (const std::uint32_t i : m_mesh.indices)
                    if (i >= m_mesh.positions.size())
                        return fail(tr("the import stream holds an index past the last vertex"));
                // The helper drops what is not finite; NaN here would reach the bounds, the
                // probe and the driver.
                for (const auto *array : {&m_mesh.positions, &m_mesh.normals})
                    if (!std::all_of(array->begin(), array->end(), finite))
                        return fail(tr("the import stream holds coordinates that are not finite"));
                m_targets.clear();
                m_haveMesh = true;
                m_state = State::Header;
            }
            break;
        }
        }
    }
    return m_state != State::Failed;
}

bool WireReader::startMesh()
{
    const auto h = read<wire::MeshHeader>(m_pending);
    m_pending.clear();
    const std::uint64_t perVertex = 12 + (h.flags & wire::kHasNormals ? 12 : 0) +
                                    (h.flags & wire::kHasColors ? 12 : 0) +
                                    (h.flags & wire::kHasUvs ? 8 : 0);
    if (h.vertexCount == 0 || h.vertexCount > wire::kMaxVertices || h.indexCount == 0 ||
        h.indexCount % 3 != 0 || h.indexCount > wire::kMaxRecordBytes / 4 ||
        h.vertexCount * perVertex + h.indexCount * 4 + sizeof h != m_header.size)
        return fail(tr("the import stream announces a mesh whose sizes don't add up"));
    if (m_header.size > m_maxMeshBytes)
        return fail(tr("the import stream announces a mesh of %1 MB, more than the helper "
                       "may use (%2 MB)")
                        .arg(m_header.size >> 20)
                        .arg(m_maxMeshBytes >> 20));
    // Memory is used as the bytes arrive, never for what is only announced.
    auto target = [](auto &vector, std::uint64_t bytes) {
        using T = typename std::decay_t<decltype(vector)>::value_type;
        return Target{bytes, [&vector, bytes](std::uint64_t filled) {
                          // Address space for all of it at once (no copies as it grows),
                          // but pages only for what arrived: resize() writes only those.
                          if (vector.capacity() * sizeof(T) < bytes)
                              vector.reserve(std::size_t(bytes / sizeof(T)));
                          vector.resize(std::size_t((filled + sizeof(T) - 1) / sizeof(T)));
                          return reinterpret_cast<char *>(vector.data());
                      }};
    };
    const std::uint64_t n = h.vertexCount;
    m_targets = {target(m_mesh.positions, n * 12)};
    if (h.flags & wire::kHasNormals)
        m_targets.push_back(target(m_mesh.normals, n * 12));
    if (h.flags & wire::kHasColors)
        m_targets.push_back(target(m_mesh.colors, n * 12));
    if (h.flags & wire::kHasUvs)
        m_targets.push_back(target(m_mesh.uvs, n * 8));
    m_targets.push_back(target(m_mesh.indices, h.indexCount * 4));
    m_target = 0;
    m_targetOffset = 0;
    m_meshBytes = m_header.size - sizeof h;
    m_meshReceived = 0;
    m_state = State::MeshArrays;
    return true;
}

bool WireReader::finishRecord()
{
    const QByteArray payload = std::exchange(m_pending, {});
    m_state = State::Header;
    switch (wire::Record(m_header.type)) {
    case wire::Record::Progress:
        if (payload.size() < qsizetype(sizeof(float)))
            return fail(tr("the import stream holds a short progress record"));
        if (onProgress)
            onProgress(std::clamp(double(read<float>(payload)), 0.0, 1.0),
                       QString::fromUtf8(payload.mid(sizeof(float))));
        return true;
    case wire::Record::Error:
        m_error = QString::fromUtf8(payload).trimmed();
        if (m_error.isEmpty())
            m_error = tr("the import failed without saying why");
        m_state = State::Failed;
        return false;
    case wire::Record::Info:
        for (const QByteArray &line : payload.split('\n')) {
            const qsizetype eq = line.indexOf('=');
            if (eq > 0)
                m_info[QString::fromUtf8(line.left(eq))] = QString::fromUtf8(line.mid(eq + 1));
        }
        return true;
    case wire::Record::Material:
        if (payload.size() != qsizetype(sizeof(wire::MaterialRecord)))
            return fail(tr("the import stream holds a material of the wrong size"));
        m_material = read<wire::MaterialRecord>(payload);
        return true;
    case wire::Record::TexturePath:
        m_texturePath = QString::fromUtf8(payload);
        return true;
    case wire::Record::Warning:
        if (m_warnings.size() < kMaxWarnings)
            m_warnings << QString::fromUtf8(payload).trimmed();
        return true;
    case wire::Record::TextureData: {
        if (payload.size() < qsizetype(sizeof(wire::TextureHeader)))
            return fail(tr("the import stream holds a short texture"));
        const auto h = read<wire::TextureHeader>(payload);
        const std::uint64_t bytes = std::uint64_t(payload.size()) - sizeof h;
        if ((h.width || h.height) && std::uint64_t(h.width) * h.height * 4 != bytes)
            return fail(tr("the import stream holds a texture whose size doesn't add up"));
        m_textureHeader = h;
        m_textureBytes = payload.mid(sizeof h);
        return true;
    }
    case wire::Record::End:
        if (!m_haveMesh)
            return fail(tr("the import stream ended without a mesh"));
        m_state = State::Done;
        return true;
    case wire::Record::Mesh:
        break;
    }
    return fail(tr("the import stream holds a record of unknown type %1").arg(m_header.type));
}

} // namespace lb
