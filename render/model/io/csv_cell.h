#pragma once
// One cell of a CSV file that spreadsheets open as data: RFC 4180 quoting, and text that a
// spreadsheet would run as a formula made plain text.

#include <QString>

namespace lb {

// `text` as a CSV field: led by a quote mark when it starts with = + - @, a tab or a carriage
// return (the characters spreadsheets take as the start of a formula, tab and CR included as
// OWASP's CSV injection advice has it: some strip them and read on), and in double quotes
// (its own doubled) when it holds a comma, a double quote, CR or LF, or was so led.
QString csvCell(const QString &text);

} // namespace lb
