#pragma once
// A "recent files" submenu kept in QSettings: newest first, at most ten, files that went
// missing are dropped when chosen.

#include <QMenu>

class QSettings;

namespace lb {

class RecentFiles : public QMenu
{
    Q_OBJECT
public:
    static constexpr int kMaxFiles = 10;
    RecentFiles(const QString &title, QSettings &settings, const QString &key,
                QWidget *parent = nullptr);

    void add(const QString &path);
    void remove(const QString &path);
    QStringList files() const;

signals:
    void fileChosen(const QString &path);

private:
    void rebuild();

    QSettings &m_settings;
    QString m_key;
};

} // namespace lb
