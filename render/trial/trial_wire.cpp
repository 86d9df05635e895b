#include "trial_wire.h"

#include <QDataStream>
#include <QIODevice>
#include <QJsonDocument>

#include <cstring>

namespace lb::trialwire {

namespace {

constexpr quint32 kMaxFrameBytes = 0x7fffffffu;

// Encodes one message: its type, then what `write` puts in the stream.
template <typename F> QByteArray message(Message type, F &&write)
{
    QByteArray bytes;
    QDataStream out(&bytes, QIODevice::WriteOnly);
    out.setVersion(QDataStream::Qt_6_0);
    out << quint32(type);
    write(out);
    return bytes;
}

template <typename T> QByteArray raw(const std::vector<T> &v)
{
    return QByteArray(reinterpret_cast<const char *>(v.data()), qsizetype(v.size() * sizeof(T)));
}

template <typename T> bool fromRaw(const QByteArray &bytes, std::vector<T> &v)
{
    if (bytes.size() % qsizetype(sizeof(T)) != 0)
        return false;
    v.resize(std::size_t(bytes.size()) / sizeof(T));
    if (!v.empty())
        std::memcpy(v.data(), bytes.constData(), std::size_t(bytes.size()));
    return true;
}

QDataStream &operator<<(QDataStream &out, const Diagnostic &d)
{
    return out << qint32(d.severity) << qint32(d.stage) << qint32(d.line) << qint32(d.column)
               << d.message;
}

QDataStream &operator>>(QDataStream &in, Diagnostic &d)
{
    qint32 severity = 0, stage = 0, line = 0, column = 0;
    in >> severity >> stage >> line >> column >> d.message;
    d.severity = Diagnostic::Severity(severity);
    d.stage = ShaderStage(stage);
    d.line = line;
    d.column = column;
    return in;
}

} // namespace

QByteArray encodeMesh(const Mesh &mesh)
{
    return message(Message::Mesh, [&](QDataStream &out) {
        out << raw(mesh.positions) << raw(mesh.normals) << raw(mesh.colors) << raw(mesh.uvs)
            << raw(mesh.indices);
    });
}

QByteArray encodeTry(const TryRequest &r)
{
    return message(Message::Try, [&](QDataStream &out) {
        out << r.id << QJsonDocument(r.scene).toJson(QJsonDocument::Compact) << r.vertex
            << r.fragment << r.target << r.budgetMs;
    });
}

QByteArray encodeReply(const TryReply &r)
{
    return message(Message::Result, [&](QDataStream &out) {
        out << r.id << r.built << r.result.fixedMs << r.result.perPixelMs << r.result.estimatedMs
            << r.result.referenceMs << r.result.extraPerPixelMs << r.result.light
            << r.result.nearReference << bool(r.result.refusal);
        if (r.result.refusal)
            out << *r.result.refusal;
        out << quint32(r.diagnostics.size());
        for (const Diagnostic &d : r.diagnostics)
            out << d;
    });
}

QByteArray encodeBuilt(const TryReply &r)
{
    return message(Message::Built, [&](QDataStream &out) {
        out << r.id << r.built << quint32(r.diagnostics.size());
        for (const Diagnostic &d : r.diagnostics)
            out << d;
    });
}

namespace {
// (Each diagnostic takes at least 20 bytes: a count past the frame is a broken one.)
bool readDiagnostics(QDataStream &in, qsizetype frameSize, std::vector<Diagnostic> &diagnostics)
{
    quint32 count = 0;
    in >> count;
    if (qint64(count) * 20 > frameSize)
        return false;
    diagnostics.resize(count);
    for (Diagnostic &diagnostic : diagnostics)
        in >> diagnostic;
    return true;
}
} // namespace

std::optional<Decoded> decode(const QByteArray &frame)
{
    QDataStream in(frame);
    in.setVersion(QDataStream::Qt_6_0);
    quint32 type = 0;
    in >> type;
    Decoded d;
    d.type = Message(type);
    switch (d.type) {
    case Message::Mesh: {
        QByteArray positions, normals, colors, uvs, indices;
        in >> positions >> normals >> colors >> uvs >> indices;
        Mesh &m = d.mesh;
        if (!fromRaw(positions, m.positions) || !fromRaw(normals, m.normals) ||
            !fromRaw(colors, m.colors) || !fromRaw(uvs, m.uvs) || !fromRaw(indices, m.indices))
            return std::nullopt;
        break;
    }
    case Message::Try: {
        QByteArray scene;
        TryRequest &r = d.request;
        in >> r.id >> scene >> r.vertex >> r.fragment >> r.target >> r.budgetMs;
        r.scene = QJsonDocument::fromJson(scene).object();
        break;
    }
    case Message::Result: {
        TryReply &r = d.reply;
        bool refused = false;
        in >> r.id >> r.built >> r.result.fixedMs >> r.result.perPixelMs >> r.result.estimatedMs >>
            r.result.referenceMs >> r.result.extraPerPixelMs >> r.result.light >>
            r.result.nearReference >> refused;
        if (refused) {
            Diagnostic diagnostic;
            in >> diagnostic;
            r.result.refusal = diagnostic;
        }
        if (!readDiagnostics(in, frame.size(), r.diagnostics))
            return std::nullopt;
        break;
    }
    case Message::Built: {
        TryReply &r = d.reply;
        in >> r.id >> r.built;
        if (!readDiagnostics(in, frame.size(), r.diagnostics))
            return std::nullopt;
        break;
    }
    default:
        return std::nullopt;
    }
    if (in.status() != QDataStream::Ok)
        return std::nullopt;
    return d;
}

QByteArray framed(const QByteArray &message)
{
    const quint32 size = quint32(message.size());
    QByteArray frame(reinterpret_cast<const char *>(&size), sizeof size);
    return frame + message;
}

std::optional<QByteArray> takeFrame(QByteArray &buffer)
{
    quint32 size = 0;
    if (buffer.size() < qsizetype(sizeof size))
        return std::nullopt;
    std::memcpy(&size, buffer.constData(), sizeof size);
    if (size > kMaxFrameBytes || buffer.size() < qsizetype(sizeof size + size))
        return std::nullopt;
    QByteArray message = buffer.mid(sizeof size, size);
    buffer.remove(0, qsizetype(sizeof size + size));
    return message;
}

} // namespace lb::trialwire
