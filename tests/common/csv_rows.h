#pragma once
// A report's CSV read back as the spreadsheet reads it, for the grading tests.

#include <QFile>
#include <QList>
#include <QString>
#include <QStringList>

// RFC 4180: fields with commas or quotes are quoted, quotes doubled.
inline QList<QStringList> csvRows(const QString &path)
{
    QFile f(path);
    QList<QStringList> rows;
    if (!f.open(QIODevice::ReadOnly))
        return rows;
    for (const QByteArray &bytes : f.readAll().split('\n')) {
        const QString line = QString::fromUtf8(bytes);
        if (line.isEmpty())
            continue;
        QStringList fields{QString()};
        bool quoted = false;
        for (int i = 0; i < line.size(); ++i) {
            const QChar c = line[i];
            if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
                fields.last() += line[++i];
            else if (c == '"')
                quoted = !quoted;
            else if (c == ',' && !quoted)
                fields << QString();
            else
                fields.last() += c;
        }
        rows << fields;
    }
    return rows;
}
