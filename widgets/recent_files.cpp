#include "recent_files.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace lb {

RecentFiles::RecentFiles(const QString &title, QSettings &settings, const QString &key,
                         QWidget *parent)
    : QMenu(title, parent), m_settings(settings), m_key(key)
{
    rebuild();
}

QStringList RecentFiles::files() const
{
    return m_settings.value(m_key).toStringList();
}

void RecentFiles::add(const QString &path)
{
    QStringList list = files();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    list.removeAll(absolute);
    list.prepend(absolute);
    while (list.size() > kMaxFiles)
        list.removeLast();
    m_settings.setValue(m_key, list);
    rebuild();
}

void RecentFiles::remove(const QString &path)
{
    QStringList list = files();
    list.removeAll(path);
    m_settings.setValue(m_key, list);
    rebuild();
}

void RecentFiles::rebuild()
{
    clear();
    const QStringList list = files();
    for (int i = 0; i < list.size(); ++i) {
        const QString &path = list[i];
        // &1 ... &9, &0: the first ten entries get an accelerator.
        const QString label = QString("&%1 %2").arg((i + 1) % 10).arg(QFileInfo(path).fileName());
        QAction *action = addAction(label);
        action->setToolTip(QDir::toNativeSeparators(path));
        action->setStatusTip(QDir::toNativeSeparators(path));
        connect(action, &QAction::triggered, this, [this, path] { emit fileChosen(path); });
    }
    if (list.isEmpty()) {
        addAction(tr("(none yet)"))->setEnabled(false);
        return;
    }
    addSeparator();
    connect(addAction(tr("Clear the list")), &QAction::triggered, this, [this] {
        m_settings.remove(m_key);
        rebuild();
    });
}

} // namespace lb
