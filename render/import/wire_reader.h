#pragma once
// Reads the import helper's stream (wire.h) as it arrives, straight into the mesh's arrays.
// Everything in it is checked before it is used: record sizes, counts, indices. A helper
// that dies half-way or writes nonsense gives an error, never a bad mesh.

#include "mesh.h"
#include "wire.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QMap>
#include <QString>
#include <QStringList>

#include <functional>
#include <optional>

namespace lb {

struct FileMaterial;

class WireReader
{
    Q_DECLARE_TR_FUNCTIONS(lb::WireReader)

public:
    // Called for each Progress record and as the mesh arrives: fraction in [0, 1], stage.
    std::function<void(double, const QString &)> onProgress;

    // The most bytes a mesh record may announce (the helper's own memory limit): a bigger
    // announcement fails before anything is allocated. The arrays grow as their bytes
    // arrive, so a stream that announces more than it sends costs only what it sent.
    void setMaxMeshBytes(std::uint64_t bytes) { m_maxMeshBytes = bytes; }

    // Consumes the next bytes. False once the stream is malformed; error() says why.
    bool feed(const char *data, qint64 size);
    bool complete() const { return m_state == State::Done; }
    bool failed() const { return m_state == State::Failed; }
    // Failed because the stream itself was wrong (not because the helper reported an error).
    bool malformed() const { return m_malformed; }
    // The helper's Error record, or what was wrong with the stream.
    const QString &error() const { return m_error; }

    // After complete():
    Mesh takeMesh() { return std::move(m_mesh); }
    const QMap<QString, QString> &info() const { return m_info; }
    const std::optional<wire::MaterialRecord> &material() const { return m_material; }
    const QString &texturePath() const { return m_texturePath; }
    const std::optional<wire::TextureHeader> &textureHeader() const { return m_textureHeader; }
    const QByteArray &textureBytes() const { return m_textureBytes; }
    // The helper's Warning records: files the mesh names that were not used, and why.
    const QStringList &warnings() const { return m_warnings; }

private:
    enum class State { Magic, Header, Payload, MeshHeader, MeshArrays, Done, Failed };
    bool fail(const QString &why);
    bool finishRecord();
    bool startMesh();

    State m_state = State::Magic;
    bool m_malformed = false;
    QString m_error;
    QByteArray m_pending; // bytes of the magic, a header or a small payload
    wire::RecordHeader m_header;
    std::uint64_t m_payloadLeft = 0;

    Mesh m_mesh;
    bool m_haveMesh = false;
    // One of the mesh's arrays: how many bytes it is announced to hold, and how to make room
    // for `bytes` of them (grown as they arrive) and where they start.
    struct Target
    {
        std::uint64_t size;
        std::function<char *(std::uint64_t bytes)> grow;
    };
    std::vector<Target> m_targets; // the mesh's arrays, filled in order
    std::size_t m_target = 0;
    std::uint64_t m_targetOffset = 0;
    std::uint64_t m_meshBytes = 0, m_meshReceived = 0;
    std::uint64_t m_maxMeshBytes = wire::kMaxRecordBytes;

    QMap<QString, QString> m_info;
    std::optional<wire::MaterialRecord> m_material;
    QString m_texturePath;
    std::optional<wire::TextureHeader> m_textureHeader;
    QByteArray m_textureBytes;
    QStringList m_warnings;
};

} // namespace lb
