#pragma once
// The window's autosave (scene, layout, editor text) that says when it fails. A change asks for
// a save within half a second; a save that does not reach the disk (a read-only or full
// disk, a settings path that cannot be made) is said once in the status line and retried every
// few seconds until it does, then the status line says the work is saved again.
// QSettings keeps the first error it met for good, so once a save failed, each later one is
// verified by reading the settings file back.

#include <QObject>
#include <QTimer>

#include <functional>

class QSettings;

namespace lb {

class StatusLine;

class SettingsAutosave : public QObject
{
    Q_OBJECT
public:
    static constexpr int kDelayMs = 500;
    static constexpr int kRetryMs = 5000;

    // `write` puts the values into `settings`; saveNow() writes them and takes them to the disk.
    SettingsAutosave(QSettings &settings, StatusLine *status, std::function<void()> write,
                     QObject *parent = nullptr);

    // A change: saved within kDelayMs. Not restarted by later changes (auto-rotation edits
    // the scene 60 times a second, and a timer restarted that often would never fire).
    void schedule();
    // Writes the values and takes them to the disk now, checking that they got there.
    void saveNow();
    bool isFailing() const { return m_failing; }
    // Where the settings reach the disk through `writeThrough` (settings_store.h: QSettings
    // works on a scratch copy, and this writes the settings file `path` from it, returning
    // empty or "PATH: why"); without, QSettings' own file, checked by reading it back.
    void setWriteThrough(const QString &path, std::function<QString()> writeThrough);
    QString fileName() const; // the settings file, for messages

private:
    void sync(); // takes what the settings hold to the disk, and checks
    bool reachedTheDisk();

    QSettings &m_settings;
    StatusLine *m_status;
    std::function<void()> m_write;
    std::function<QString()> m_writeThrough;
    QString m_path;
    QTimer m_delay, m_retry;
    qint64 m_serial = 0;
    bool m_failing = false;
};

} // namespace lb
