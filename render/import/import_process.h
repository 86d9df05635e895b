#pragma once
// Loads a mesh file through the import helper (lightbench-import): starts it with a memory
// and time limit, reads its stream as it arrives, and turns whatever happens to it (an
// Assimp error, a crash, a hang, a runaway allocation) into a message naming the file. The
// window uses it asynchronously; the command line and tests through import().

#include "mesh_file.h"
#include "wire_reader.h"

#include <QElapsedTimer>
#include <QObject>
#include <QProcess>
#include <QTimer>

#include <cstdint>
#include <memory>

namespace lb {

struct ImportLimits
{
    qint64 memoryMB = defaultMemoryMB();
    int seconds = 300;
    static qint64 defaultMemoryMB(); // half of the machine's physical memory
    static qint64 machineMemoryMB(); // the machine's physical memory
    // The most the window takes for one mesh the helper announces: what the helper may have
    // made (its memory limit), and never more than the machine has, whatever the limit says.
    std::uint64_t meshByteCap() const;
};

struct ImportResult
{
    std::shared_ptr<const MeshFile> file; // set on success
    QString error;                        // "FILE: what went wrong" otherwise
    bool cancelled = false;
    bool ok() const { return file != nullptr; }
};

class ImportProcess : public QObject
{
    Q_OBJECT
public:
    explicit ImportProcess(QObject *parent = nullptr);
    ~ImportProcess() override; // a running helper is killed

    // Starts loading; finished() follows, also for a helper that cannot start. A load
    // already running is cancelled first.
    void start(const QString &path, const ImportLimits &limits = {});
    // Kills the helper; finished() follows with `cancelled` set.
    void cancel();
    bool isRunning() const { return m_running; }
    qint64 helperPid() const { return m_process.processId(); }

    // Loads and waits (runs an event loop meanwhile); needs a QCoreApplication.
    static ImportResult import(const QString &path, const ImportLimits &limits = {});

    // The helper: $LIGHTBENCH_IMPORT_HELPER, else lightbench-import beside the executable, in
    // the installed libexec folder or on the PATH (helper_program.h).
    static QString helperPath();
    // The patterns of every format Assimp reads ("*.obj", ...), asked of the helper once.
    static QStringList filePatterns();

signals:
    void progress(double fraction, const QString &stage);
    void finished(const lb::ImportResult &result);

private:
    void readOutput();
    void processFinished(int exitCode, QProcess::ExitStatus status);
    void finish(ImportResult result);
    std::shared_ptr<MeshFile> meshFile();
    QString describeFailure(int exitCode, QProcess::ExitStatus status) const;

    QProcess m_process;
    QTimer m_deadline;
    QElapsedTimer m_clock;
    std::unique_ptr<WireReader> m_reader;
    QString m_path;
    ImportLimits m_limits;
    QByteArray m_stderr; // the last few KB, for a crash message
    bool m_running = false;
    bool m_cancelled = false;
    bool m_timedOut = false;
};

} // namespace lb

Q_DECLARE_METATYPE(lb::ImportResult)
