#include "import_process.h"

#include "bounded_read.h"
#include "helper_program.h"
#include "message_text.h"
#include "scene_budget.h"
#include "signal_names.h"

#include <QBuffer>
#include <QDir>
#include <QEventLoop>
#include <QFileInfo>
#include <QImageReader>

#include <algorithm>
#include <csignal>

namespace lb {

namespace {

constexpr qsizetype kStderrKept = 4096;

// What the helper's death by `signal` says: a whole sentence for each signal named.
QString crashMessage(int signal)
{
    switch (signal) {
    case SIGSEGV:
        return ImportProcess::tr("the importer crashed with a segmentation fault while reading "
                                 "this file; the workbench is fine");
    case SIGABRT:
        return ImportProcess::tr("the importer crashed with an abort while reading this file; the "
                                 "workbench is fine");
#ifdef SIGBUS // POSIX's, not standard C's
    case SIGBUS:
        return ImportProcess::tr("the importer crashed with a bus error while reading this file; "
                                 "the workbench is fine");
#endif
    case SIGFPE:
        return ImportProcess::tr("the importer crashed with an arithmetic error while reading "
                                 "this file; the workbench is fine");
    case SIGILL:
        return ImportProcess::tr("the importer crashed with an illegal instruction while reading "
                                 "this file; the workbench is fine");
    default:
        //: %1 a signal's number, %2 the system's name for it
        return ImportProcess::tr("the importer crashed with signal %1 (%2) while reading this "
                                 "file; the workbench is fine")
            .arg(QString::number(signal), platform::signalName(signal));
    }
}

// An image file bigger than this is no texture (QImageReader's own limit on the decoded
// image, 256 MB by default, catches the rest).
const FileLimit kTextureFileLimit{QT_TRANSLATE_NOOP("lb::FileLimit", "a texture file"),
                                  256ll << 20};

// The diffuse texture a file names, beside the model as written or by its name alone (files
// made on Windows carry their author's absolute paths). Like every file a mesh names, it must
// be inside the model's folder tree, links resolved: a mesh from a stranger must not show
// the user's own pictures from elsewhere (the helper does the same for the files Assimp
// reads). Returns the path, or empty with `problem` set.
QString findTexture(const QString &modelPath, QString name, QString &problem)
{
    name.replace('\\', '/');
    const QDir dir = QFileInfo(modelPath).absoluteDir();
    const QString root = dir.canonicalPath() + '/';
    bool outside = false;
    for (const QString &candidate :
         {dir.filePath(name), dir.filePath(QFileInfo(name).fileName())}) {
        if (name.isEmpty() || !QFileInfo::exists(candidate)) // a folder: a message later
            continue;
        const QString real = QFileInfo(candidate).canonicalFilePath();
        if (root != "/" && !real.startsWith(root)) {
            outside = true;
            continue;
        }
        return candidate;
    }
    problem =
        outside
            ? ImportProcess::tr("texture '%1': outside the mesh's folder").arg(echoedValue(name))
            : ImportProcess::tr("texture '%1' not found").arg(echoedValue(name));
    return {};
}

} // namespace

qint64 ImportLimits::machineMemoryMB()
{
    return qint64(machineMemoryBytes() >> 20); // one reading of it, the scene budget's
}

qint64 ImportLimits::defaultMemoryMB()
{
    return machineMemoryMB() / 2;
}

std::uint64_t ImportLimits::meshByteCap() const
{
    qint64 mb = machineMemoryMB();
    if (memoryMB > 0)
        mb = std::min(mb, memoryMB);
    return std::uint64_t(mb) << 20;
}

ImportProcess::ImportProcess(QObject *parent) : QObject(parent)
{
    qRegisterMetaType<lb::ImportResult>();
    m_deadline.setSingleShot(true);
    connect(&m_deadline, &QTimer::timeout, this, [this] {
        m_timedOut = true;
        m_process.kill();
    });
    connect(&m_process, &QProcess::readyReadStandardOutput, this, &ImportProcess::readOutput);
    connect(&m_process, &QProcess::readyReadStandardError, this, [this] {
        m_stderr += m_process.readAllStandardError();
        if (m_stderr.size() > kStderrKept)
            m_stderr = m_stderr.right(kStderrKept);
    });
    connect(&m_process, &QProcess::finished, this, &ImportProcess::processFinished);
    connect(&m_process, &QProcess::errorOccurred, this, [this](QProcess::ProcessError error) {
        if (error == QProcess::FailedToStart && m_running)
            finish({nullptr,
                    tr("%1: cannot start the import helper '%2': %3")
                        .arg(m_path, m_process.program(), m_process.errorString()),
                    false});
    });
}

ImportProcess::~ImportProcess()
{
    if (m_process.state() != QProcess::NotRunning) {
        m_process.disconnect(this);
        m_process.kill();
        m_process.waitForFinished(2000);
    }
}

QString ImportProcess::helperPath()
{
    return helperProgramPath(QStringLiteral("lightbench-import"), "LIGHTBENCH_IMPORT_HELPER");
}

QStringList ImportProcess::filePatterns()
{
    static QStringList patterns = [] {
        QProcess helper;
        helper.start(helperPath(), {"--formats"});
        if (!helper.waitForFinished(10000) || helper.exitCode() != 0)
            return QStringList();
        return QString::fromUtf8(helper.readAllStandardOutput())
            .trimmed()
            .split(';', Qt::SkipEmptyParts);
    }();
    return patterns;
}

void ImportProcess::start(const QString &path, const ImportLimits &limits)
{
    if (m_running)
        cancel();
    if (m_process.state() != QProcess::NotRunning) { // a helper still exiting after its End
        m_process.kill();
        m_process.waitForFinished(2000);
    }
    m_path = path;
    m_limits = limits;
    m_running = true;
    m_cancelled = m_timedOut = false;
    m_stderr.clear();
    m_clock.start();
    m_reader = std::make_unique<WireReader>();
    // What the helper may allocate bounds what it may send; the machine bounds both.
    m_reader->setMaxMeshBytes(limits.meshByteCap());
    m_reader->onProgress = [this](double fraction, const QString &stage) {
        emit progress(fraction, stage);
    };

    // Assimp reads most formats whole into memory: a file over the helper's memory limit
    // could only end in "out of memory", after reading gigabytes.
    const QFileInfo info(path);
    QString problem = unreadableFile(
        path, {QT_TRANSLATE_NOOP("lb::FileLimit", "a mesh file"), qint64(limits.meshByteCap()),
               QT_TRANSLATE_NOOP("lb::FileLimit", "the import memory limit")});
    if (problem.isEmpty() && !info.isReadable())
        problem = tr("%1: not readable (permissions)").arg(m_path);
    else if (problem.isEmpty() && info.size() == 0)
        problem = tr("%1: the file is empty").arg(m_path);
    if (!problem.isEmpty()) {
        // Queued, so that callers always hear of the result after start() returned.
        QMetaObject::invokeMethod(
            this,
            [this, problem] {
                finish({nullptr, problem, false});
            },
            Qt::QueuedConnection);
        return;
    }
    QStringList arguments;
    if (limits.memoryMB > 0)
        arguments << "--memory-limit" << QString::number(limits.memoryMB);
    if (limits.seconds > 0) {
        arguments << "--time-limit" << QString::number(limits.seconds);
        m_deadline.start(limits.seconds * 1000);
    }
    arguments << info.absoluteFilePath();
    m_process.start(helperPath(), arguments, QIODevice::ReadOnly);
}

void ImportProcess::cancel()
{
    if (!m_running)
        return;
    m_cancelled = true;
    if (m_process.state() != QProcess::NotRunning) {
        m_process.kill();
        m_process.waitForFinished(2000); // finished() arrives from here
    }
}

void ImportProcess::readOutput()
{
    if (!m_reader) { // output after the result was given: nobody listens any more
        m_process.readAllStandardOutput();
        return;
    }
    char buffer[1 << 16];
    for (;;) {
        const qint64 n = m_process.read(buffer, sizeof buffer);
        if (n <= 0)
            break;
        if (!m_reader->feed(buffer, n) && m_reader->malformed()) {
            m_process.kill(); // a helper writing nonsense has nothing more to say
            break;
        }
    }
    // The whole mesh is in: no need to wait for the helper to exit.
    if (m_reader->complete() && m_running && !m_cancelled)
        finish({meshFile(), {}, false}); // processFinished() ignores the exit that follows
}

void ImportProcess::processFinished(int exitCode, QProcess::ExitStatus status)
{
    if (!m_running)
        return;
    readOutput();
    m_deadline.stop();
    const QString name = m_path;
    if (m_cancelled) {
        finish({nullptr, tr("%1: cancelled").arg(name), true});
    } else if (m_timedOut) {
        finish({nullptr,
                tr("%1: gave up after %2 s (the import time limit)")
                    .arg(name, QString::number(m_limits.seconds)),
                false});
    } else if (status == QProcess::NormalExit && exitCode == 0 && m_reader->complete()) {
        finish({meshFile(), {}, false});
    } else {
        finish({nullptr, name + ": " + describeFailure(exitCode, status), false});
    }
}

QString ImportProcess::describeFailure(int exitCode, QProcess::ExitStatus status) const
{
    if (m_reader->failed())
        return m_reader->error();
    if (status == QProcess::CrashExit) {
#if defined(SIGXCPU) && defined(SIGKILL) // POSIX's (setrlimit's signals); not standard C's
        if (exitCode == SIGXCPU)
            return tr("gave up after %1 s of CPU time (the import time limit)")
                .arg(m_limits.seconds);
        if (exitCode == SIGKILL)
            return tr("the import helper was killed (by the system, for memory?)");
#endif
        return crashMessage(exitCode);
    }
    if (exitCode == wire::kExitOutOfMemory)
        return tr("out of memory: reading this file needs more than the import memory limit "
                  "(%1 MB)")
            .arg(m_limits.memoryMB);
    const QString detail = QString::fromLocal8Bit(m_stderr).trimmed();
    if (detail.isEmpty())
        return tr("the import helper stopped (exit code %1) before sending the whole mesh")
            .arg(exitCode);
    //: %2 the last line the helper wrote on its error output (its own words, in English)
    return tr("the import helper stopped (exit code %1) before sending the whole mesh: %2")
        .arg(QString::number(exitCode), detail.split('\n').last());
}

std::shared_ptr<MeshFile> ImportProcess::meshFile()
{
    auto file = std::make_shared<MeshFile>();
    file->path = m_path;
    file->mesh = std::make_shared<const Mesh>(m_reader->takeMesh());
    const QMap<QString, QString> &info = m_reader->info();
    file->meshes = info.value("meshes").toInt();
    file->skippedFaces = info.value("skippedFaces").toLongLong();
    file->nonFiniteVertices = info.value("nonFinite").toLongLong();
    file->droppedTriangles = info.value("droppedTriangles").toLongLong();
    file->nonFiniteNormals = info.value("nonFiniteNormals").toLongLong();
    for (const QString &warning : m_reader->warnings()) // names from a stranger's file
        file->sideFileProblems << echoedValue(warning, 400);
    file->readSeconds = info.value("seconds").toDouble();
    file->reader = echoedValue(info.value("reader"), 40);
    file->helperPeakKB = info.value("peakKB").toLongLong();

    if (const auto &m = m_reader->material()) {
        if (m->present & wire::kHasAmbient)
            file->material.ka = glm::vec3(m->ka[0], m->ka[1], m->ka[2]);
        if (m->present & wire::kHasDiffuse)
            file->material.kd = glm::vec3(m->kd[0], m->kd[1], m->kd[2]);
        if (m->present & wire::kHasSpecular)
            file->material.ks = glm::vec3(m->ks[0], m->ks[1], m->ks[2]);
        if (m->present & wire::kHasShininess)
            file->material.shininess = m->shininess;
    }

    QImage image;
    if (const auto &h = m_reader->textureHeader()) {
        const QByteArray &bytes = m_reader->textureBytes();
        if (h->width == 0) {
            QBuffer buffer(const_cast<QByteArray *>(&bytes));
            QImageReader reader(&buffer);
            image = reader.read();
            if (image.isNull())
                file->textureProblem =
                    tr("embedded texture unreadable: %1").arg(reader.errorString());
        } else {
            // Assimp's texels are B, G, R, A in memory: QImage's ARGB32 on this machine.
            image = QImage(reinterpret_cast<const uchar *>(bytes.constData()), int(h->width),
                           int(h->height), QImage::Format_ARGB32)
                        .copy();
        }
    } else if (!m_reader->texturePath().isEmpty()) {
        QString problem;
        const QString found = findTexture(m_path, m_reader->texturePath(), problem);
        if (found.isEmpty()) {
            file->textureProblem = problem;
        } else if (const QString why = unreadableFile(found, kTextureFileLimit); !why.isEmpty()) {
            //: %1 why a texture file cannot be used, "PATH: reason"
            file->textureProblem = tr("texture %1").arg(why);
        } else {
            QImageReader reader(found);
            image = reader.read();
            if (image.isNull())
                file->textureProblem =
                    tr("texture '%1': %2").arg(echoedValue(found), reader.errorString());
        }
    }
    if (!image.isNull()) {
        if (file->mesh->uvs.empty())
            file->textureProblem = tr("the file has a texture but no texture coordinates");
        else
            file->texture = std::make_shared<const Texture>(Texture::fromImage(image));
    }
    file->seconds = double(m_clock.nsecsElapsed()) * 1e-9;
    return file;
}

void ImportProcess::finish(ImportResult result)
{
    if (!m_running)
        return;
    m_running = false;
    m_deadline.stop();
    m_reader.reset();
    // A path of megabytes (a broken scene file) is no message: its ends are.
    result.error = elidedForMessage(result.error, 1000);
    emit finished(result);
}

ImportResult ImportProcess::import(const QString &path, const ImportLimits &limits)
{
    ImportProcess process;
    ImportResult result;
    QEventLoop loop;
    connect(&process, &ImportProcess::finished, &loop, [&](const ImportResult &r) {
        result = r;
        loop.quit();
    });
    process.start(path, limits);
    loop.exec();
    return result;
}

} // namespace lb
