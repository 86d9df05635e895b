#pragma once
// The window's settings file (scene, layout, editor text), written whole or not at all.
// QSettings writes its file through QSaveFile, which in Qt 6.4 renames its temporary over the
// file even when the last write failed: on a full disk the settings became an empty file and
// the next start lost the session. So QSettings works on a scratch copy in a private temporary
// folder, and save() takes what it holds to the settings file through the one writer
// (safe_write.h), which leaves the old file as it was when a write fails and says why.

#include <QCoreApplication>
#include <QSettings>
#include <QString>
#include <QTemporaryDir>

#include <memory>

namespace lb {

class SettingsStore
{
    Q_DECLARE_TR_FUNCTIONS(lb::SettingsStore) // its messages reach the window's status line
public:
    // `path`: the settings file (QSettings().fileName() for the application's own). Its
    // values are read now; `error()` says why they could not be (the store starts empty).
    explicit SettingsStore(const QString &path);

    QSettings &settings() { return *m_settings; }
    const QString &fileName() const { return m_path; }
    const QString &error() const { return m_error; }
    // What settings() holds, to the settings file: empty, or "PATH: why" (the file as it was).
    QString save();

private:
    QString m_path;
    QTemporaryDir m_scratch;
    std::unique_ptr<QSettings> m_settings;
    QString m_error;
};

} // namespace lb
