#include "csv_cell.h"

namespace lb {

QString csvCell(const QString &text)
{
    QString s = text;
    const bool formula = !s.isEmpty() && QStringLiteral("=+-@\t\r").contains(s[0]);
    if (formula)
        s.prepend('\'');
    if (formula || s.contains(',') || s.contains('"') || s.contains('\r') || s.contains('\n')) {
        s.replace('"', QLatin1String("\"\""));
        s = '"' + s + '"';
    }
    return s;
}

} // namespace lb
