#include "settings_autosave.h"

#include "message_text.h"
#include "status_line.h"

#include <QFile>
#include <QSettings>

namespace lb {

namespace {

// Counts the saves, so that reading the file back tells this save from an older one.
constexpr const char *kSerialKey = "autosave/serial";
constexpr const char *kSerialName = "serial"; // its line in the INI file: serial=N

// "PATH cannot be written": a whole sentence for each reason, the path in it.
QString notWritten(const QString &path, QSettings::Status status)
{
    return (status == QSettings::FormatError ? SettingsAutosave::tr("%1 is not a settings file")
                                             : SettingsAutosave::tr("%1 cannot be written"))
        .arg(path);
}

} // namespace

SettingsAutosave::SettingsAutosave(QSettings &settings, StatusLine *status,
                                   std::function<void()> write, QObject *parent)
    : QObject(parent), m_settings(settings), m_status(status), m_write(std::move(write))
{
    m_serial = m_settings.value(kSerialKey, 0).toLongLong();
    for (QTimer *t : {&m_delay, &m_retry})
        t->setSingleShot(true);
    m_delay.setInterval(kDelayMs);
    m_retry.setInterval(kRetryMs);
    connect(&m_delay, &QTimer::timeout, this, &SettingsAutosave::saveNow);
    connect(&m_retry, &QTimer::timeout, this, &SettingsAutosave::sync);
}

void SettingsAutosave::schedule()
{
    if (!m_delay.isActive())
        m_delay.start();
}

void SettingsAutosave::saveNow()
{
    m_delay.stop();
    m_write();
    sync();
}

void SettingsAutosave::setWriteThrough(const QString &path, std::function<QString()> writeThrough)
{
    m_path = path;
    m_writeThrough = std::move(writeThrough);
}

QString SettingsAutosave::fileName() const
{
    return m_writeThrough ? m_path : m_settings.fileName();
}

void SettingsAutosave::sync()
{
    m_settings.setValue(kSerialKey, ++m_serial);
    QString error;
    if (m_writeThrough) {
        error = m_writeThrough();
    } else {
        m_settings.sync();
        if (!reachedTheDisk())
            error = notWritten(m_settings.fileName(), m_settings.status());
    }
    if (error.isEmpty()) {
        if (m_failing)
            m_status->showMessage(
                tr("Your work is saved again in %1").arg(elidedForMessage(fileName(), 120)));
        m_failing = false;
        m_retry.stop();
        return;
    }
    if (!m_failing)
        // What matters first: a narrow status line shows the start (the rest is its tooltip).
        m_status->showMessage(tr("Your work is not saved, trying again every %1 s: %2")
                                  .arg(kRetryMs / 1000)
                                  .arg(elidedForMessage(error, 240)),
                              0);
    m_failing = true;
    m_retry.start();
}

bool SettingsAutosave::reachedTheDisk()
{
    if (m_settings.status() == QSettings::NoError)
        return true;
    // Read as bytes: a second QSettings on the same file would answer from the first one's
    // cache in this process, not from the disk.
    QFile file(m_settings.fileName());
    if (!file.open(QIODevice::ReadOnly))
        return false;
    const QByteArray line = QByteArray(kSerialName) + '=' + QByteArray::number(m_serial);
    while (!file.atEnd())
        if (file.readLine().trimmed() == line)
            return true;
    return false;
}

} // namespace lb
