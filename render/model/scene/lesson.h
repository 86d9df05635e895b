#pragma once
// Lesson files: a lecture as an ordered list of steps, each a scene (inline, or a scene file
// named relative to the lesson) with a title and a short caption, optionally the panel to bring
// forward and a control to point at. Titles and captions are given per language ("en", "pt",
// "de"), chosen by the UI language and falling back to English.
//
// {"format": "lightbench-lesson", "version": 1, "title": {"en": ..., "pt": ...},
//  "steps": [{"title": ..., "caption": ..., "scene": {...} or "scene": "terms.json",
//             "panel": "light", "highlight": "light.frame"}, ...]}
//
// Read with the care of scene files: the lesson and every scene file it names are read within
// one size limit together, and a step whose scene cannot be used keeps its place with the
// reason (the window shows it there; the command line refuses that step).

#include "localized_text.h"

#include "scene_file.h"

#include <QDir>
#include <QMap>
#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace lb {

constexpr int kLessonFileVersion = 1;
// The lesson with the scene files it names, together: a lecture is a few dozen small scenes.
constexpr qint64 kMaxLessonBytes = 64 * 1024 * 1024;
constexpr int kMaxLessonSteps = 500;
constexpr int kMaxLessonTextCharacters = 4000; // a title or a caption, in one language

// The panels a step may bring forward, and the controls it may point at (as written in files).
const QStringList &lessonPanels();
const QStringList &lessonHighlights();

struct LessonStep
{
    LocalizedText title, caption;
    SceneFile scene;
    // The scene file this step's scene came from (absolute, or ":/..." built in); empty for a
    // scene held inline. Saving names the file again (relative to the lesson) instead of
    // writing the scene: whoever gives the step another scene clears it.
    QString scenePath;
    QString panel;     // one of lessonPanels(), or empty
    QString highlight; // one of lessonHighlights(), or empty
    QString error;     // why this step's scene cannot be used ("step 3: ..."); empty when it can
};

struct Lesson
{
    LocalizedText title;
    std::vector<LessonStep> steps;
};

struct LessonRead
{
    std::optional<Lesson> lesson; // empty when the file cannot be used at all
    QString error;                // why, as "PATH: message"
    QStringList ignored;          // what was read but not used ("step 2: panel (...)")
    QStringList stepErrors;       // the steps kept with an error, for one message
};

LessonRead readLessonFile(const QString &path);
// `dir`: where relative scene references and mesh paths start; `name` prefixes errors;
// `budget`: the bytes scene files may still take (the lesson's own bytes already counted).
LessonRead parseLesson(const QByteArray &bytes, const QDir &dir, const QString &name,
                       qint64 budget = kMaxLessonBytes);
// References are written relative to `dir` again; every other scene inline.
QByteArray lessonFileBytes(const Lesson &lesson, const QDir &dir);
// Writes through the safe writer; returns an empty string or "PATH: message".
QString writeLessonFile(const QString &path, const Lesson &lesson);

} // namespace lb
