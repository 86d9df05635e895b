#pragma once
// The messages between the workbench and its trial helper (lightbench-trial), which tries a
// user's program on small frames in a process of its own, so that a driver hanging or
// crashing on the program takes the helper down and never the window. Each message is a
// frame on the helper's stdin or stdout: a 32-bit length, then a QDataStream of the message.
// Both ends are one build on one machine.

#include "mesh.h"
#include "program_trial.h"

#include <QByteArray>
#include <QJsonObject>
#include <QSize>
#include <QString>

#include <optional>
#include <vector>

namespace lb::trialwire {

enum class Message : quint32 {
    Mesh = 1,   // the mesh every later trial draws (the window's object)
    Try = 2,    // TryRequest
    Result = 3, // TryReply
    Built = 4,  // TryReply with only id, built and diagnostics: compiled and linked, the
                // frames follow (the window may build it too meanwhile: the driver's
                // compiler took it within bounds here)
};

struct TryRequest
{
    quint64 id = 0;
    QJsonObject scene; // Scene::toJson(): the light, material, camera, shading the frame uses
    QString vertex, fragment;
    QSize target; // the frame the program will be drawn at
    double budgetMs = 1000.0;
};

struct TryReply
{
    quint64 id = 0;
    bool built = true; // false: it did not compile or link in the helper
    // The build's diagnostics (errors and warnings, on the user's lines): the window shows
    // these, as it builds a program itself only once the helper accepted it.
    std::vector<Diagnostic> diagnostics;
    TrialResult result;
};

// The helper's exit codes besides 0: it cannot draw at all (3), the driver reset its context
// (4), the program made the driver take more memory than programMemoryKB() (5).
constexpr int kExitCannotDraw = 3, kExitContextReset = 4, kExitOutOfMemory = 5;

QByteArray encodeMesh(const Mesh &mesh);
QByteArray encodeTry(const TryRequest &request);
QByteArray encodeReply(const TryReply &reply);
QByteArray encodeBuilt(const TryReply &reply);

struct Decoded
{
    Message type = Message::Result;
    Mesh mesh;
    TryRequest request;
    TryReply reply;
};
// nullopt for a frame this build did not write.
std::optional<Decoded> decode(const QByteArray &frame);

// The frame around one encoded message.
QByteArray framed(const QByteArray &message);
// Takes the first whole frame's message off the front of `buffer`, if it holds one.
std::optional<QByteArray> takeFrame(QByteArray &buffer);

} // namespace lb::trialwire
