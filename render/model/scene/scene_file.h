#pragma once
// Scene files: one versioned JSON document that reproduces the view, to hand out. It holds
// the scene (lights, material, shading, object, camera, the shader's own uniform values,
// compare settings), the program's sources inline, and the mesh's path relative to the file.
//
// {"format": "lightbench-scene", "version": 2, "program": {...}, "lights": [...], ...}

#include "exercise.h"
#include "scene.h"

#include <QByteArray>
#include <QDir>
#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <optional>

namespace lb {

constexpr int kSceneFileVersion = 3; // 1: the settings' single-light scene, no program;
                                     // 2: one object; 3: a list of objects
constexpr qint64 kMaxSceneFileBytes = 64 * 1024 * 1024;

// The program drawn with: where it came from (a preset's or a file's name, as data: never
// translated text; a shipped example's by language), whether it was edited since, and both
// sources. Written as
// "program": {"name": ..., "edited": true/false, "vertex": ..., "fragment": ...}; files from
// before the "edited" field carry it as the name's English suffix " (edited)", read as edited.
struct ProgramText
{
    LocalizedText name;
    QString vertex, fragment;
    bool edited = false;
    bool operator==(const ProgramText &o) const
    {
        return name == o.name && vertex == o.vertex && fragment == o.fragment && edited == o.edited;
    }
};

struct SceneFile
{
    Scene scene; // the mesh path is absolute here
    // Absent: the built-in program of the scene's shading (it follows Gouraud / Phong).
    // In an exercise, the student's starting point.
    std::optional<ProgramText> program;
    std::optional<Exercise> exercise; // exercise.h
};

struct SceneFileRead
{
    std::optional<SceneFile> file; // empty when the file cannot be used at all
    QString error;                 // why, as "PATH: message"
    QStringList ignored;           // what was read but not used, for one message
    QString exerciseError;         // an "exercise" that cannot be graded against: why
};

// The document; a mesh inside `dir` (or below, or beside) is written relative to it.
QByteArray sceneFileBytes(const SceneFile &file, const QDir &dir);
// Parses a document; relative mesh paths are taken relative to `dir`. `name` prefixes errors.
SceneFileRead parseSceneFile(const QByteArray &bytes, const QDir &dir, const QString &name);
SceneFileRead readSceneFile(const QString &path);
// The same as a JSON object (a lesson holds scenes inline: lesson.h).
QJsonObject sceneFileJson(const SceneFile &file, const QDir &dir);
SceneFileRead parseSceneObject(QJsonObject root, const QDir &dir);
// Writes atomically (QSaveFile); returns an empty string or "PATH: message".
QString writeSceneFile(const QString &path, const SceneFile &file);

} // namespace lb
