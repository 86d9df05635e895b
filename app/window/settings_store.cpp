#include "settings_store.h"

#include "bounded_read.h"
#include "safe_write.h"

#include <QDir>
#include <QFileInfo>

namespace lb {

namespace {

// Far more than a session holds (the editor's text is at most two sources of 1 MiB).
constexpr qint64 kMaxSettingsBytes = 256ll << 20;

QString scratchOf(const QTemporaryDir &dir, const QString &path)
{
    return dir.isValid() ? dir.filePath(QFileInfo(path).fileName()) : path;
}

} // namespace

SettingsStore::SettingsStore(const QString &path)
    : m_path(path), m_scratch(QDir::temp().filePath("lightbench-settings-XXXXXX"))
{
    const QString scratch = scratchOf(m_scratch, path);
    if (!m_scratch.isValid())
        m_error = tr("no temporary folder for the settings (%1): they are written directly")
                      .arg(m_scratch.errorString());
    else if (QFileInfo::exists(path)) {
        const BoundedRead read = readBounded(
            path, {QT_TRANSLATE_NOOP("lb::FileLimit", "a settings file"), kMaxSettingsBytes});
        if (read.error.isEmpty())
            m_error = writeFileSafely(scratch, read.bytes);
        else
            m_error = read.error;
    }
    m_settings = std::make_unique<QSettings>(scratch, QSettings::IniFormat);
}

QString SettingsStore::save()
{
    m_settings->sync();
    if (!m_scratch.isValid()) // QSettings wrote the file itself
        return m_settings->status() == QSettings::NoError ? QString()
                                                          : tr("%1: cannot be written").arg(m_path);
    if (m_settings->status() != QSettings::NoError)
        return tr("%1: its scratch copy %2 cannot be written (a full temporary folder?)")
            .arg(m_path, m_settings->fileName());
    const BoundedRead scratch =
        readBounded(m_settings->fileName(),
                    {QT_TRANSLATE_NOOP("lb::FileLimit", "a settings file"), kMaxSettingsBytes});
    if (!scratch.error.isEmpty())
        return scratch.error;
    QDir().mkpath(QFileInfo(m_path).absolutePath()); // ~/.config/lightbench at the first start
    return writeFileSafely(m_path, scratch.bytes);
}

} // namespace lb
