#include "submission.h"

#include "bounded_read.h"
#include "scene_file.h"
#include "shader_document.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>

namespace lb {

namespace {

Submission pair(const QString &name, const QString &vertexPath, const QString &fragmentPath)
{
    Submission s;
    s.name = name;
    s.vertexPath = vertexPath;
    s.fragmentPath = fragmentPath;
    for (const auto &[path, text] :
         {std::pair{vertexPath, &s.vertex}, {fragmentPath, &s.fragment}}) {
        const ShaderFileRead read = readShaderFile(path);
        if (!read.ok()) {
            s.error = read.error;
            return s;
        }
        *text = read.text;
    }
    return s;
}

bool isShaderSuffix(const QString &suffix)
{
    return suffix == "vert" || suffix == "frag";
}

} // namespace

QStringList distinctSubmissions(const QStringList &paths)
{
    QStringList distinct, seen;
    for (const QString &given : paths) {
        const QFileInfo info(QDir::cleanPath(given));
        // A folder alice/ beside alice.vert is another submission.
        const QString key = info.isDir() ? info.absoluteFilePath() + '/'
                            : isShaderSuffix(info.suffix().toLower())
                                ? QDir(info.absolutePath()).filePath(info.completeBaseName())
                                : info.absoluteFilePath();
        if (!seen.contains(key)) {
            seen << key;
            distinct << given;
        }
    }
    return distinct;
}

Submission readSubmission(const QString &given)
{
    const QString path = QDir::cleanPath(given); // "alice/" is the folder alice
    const QFileInfo info(path);
    Submission s;
    s.name = info.completeBaseName();
    if (info.isDir()) {
        s.name = info.fileName();
        const QDir dir(path);
        // System too: a FIFO or a device named lighting.frag is counted, and refused when it
        // is read, by name ("not a regular file"), not left out of the count ("it has 1 and 0").
        const QStringList verts = dir.entryList({"*.vert"}, QDir::Files | QDir::System);
        const QStringList frags = dir.entryList({"*.frag"}, QDir::Files | QDir::System);
        if (verts.size() != 1 || frags.size() != 1) {
            s.error = Submission::tr("%1: a folder needs one NAME.vert and one NAME.frag (it has "
                                     "%2 and %3)")
                          .arg(path, QString::number(verts.size()), QString::number(frags.size()));
            return s;
        }
        return pair(s.name, dir.filePath(verts[0]), dir.filePath(frags[0]));
    }
    const QString suffix = info.suffix().toLower();
    if (suffix == "json" || suffix == "lbscene") { // a scene file, the course's or the desktop's
        const SceneFileRead read = readSceneFile(path);
        if (!read.file) {
            s.error = read.error;
        } else if (!read.file->program) {
            // A program the reader refused is named with its reason, not as none at all.
            const QStringList refused = read.ignored.filter(QRegularExpression("^program \\("));
            s.error = refused.isEmpty()
                          ? Submission::tr("%1: the scene file has no program").arg(path)
                          //: %2 why the scene's program was not used ("program (the vertex
                          //: shader has ... characters, ...)")
                          : Submission::tr("%1: the scene file's program cannot be used: %2")
                                .arg(path, refused.first());
        } else {
            s.vertexPath = s.fragmentPath = path;
            s.vertex = read.file->program->vertex;
            s.fragment = read.file->program->fragment;
        }
        return s;
    }
    // NAME.vert, NAME.frag or NAME: the pair beside each other.
    const bool shader = isShaderSuffix(suffix);
    const QString stem = shader ? info.dir().filePath(info.completeBaseName()) : path;
    if (!shader)
        s.name = info.fileName();
    const QString vertex = stem + ".vert", fragment = stem + ".frag";
    if (shader && !info.exists()) {
        s.error = QString("%1: %2").arg(path, missingFileReason(path));
        return s;
    }
    for (const QString &p : {vertex, fragment})
        if (!QFileInfo::exists(p)) {
            s.error =
                Submission::tr("%1: no %2 beside it (a submission is NAME.vert and NAME.frag)")
                    .arg(path, QFileInfo(p).fileName());
            return s;
        }
    return pair(s.name, vertex, fragment);
}

} // namespace lb
