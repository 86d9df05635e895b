#include "grading_report.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QList>

#include <algorithm>

namespace lb {

int GradingReport::passedCount() const
{
    return int(
        std::count_if(cases.begin(), cases.end(), [](const CaseResult &c) { return c.passed; }));
}

int GradingReport::largest() const
{
    int worst = 0;
    for (const CaseResult &c : cases)
        worst = std::max(worst, c.largest);
    return worst;
}

double GradingReport::meanShare() const
{
    double sum = 0.0;
    for (const CaseResult &c : cases)
        sum += c.shareWithin;
    return cases.empty() ? 0.0 : sum / double(cases.size());
}

QJsonObject gradingReportJson(const GradingReport &report)
{
    QJsonObject out{{"submission", report.submission}, {"status", report.status}};
    if (!report.diagnostic.isEmpty())
        out["diagnostic"] = report.diagnostic;
    if (report.graded()) {
        QJsonArray cases;
        for (std::size_t k = 0; k < report.cases.size(); ++k) {
            const CaseResult &r = report.cases[k];
            cases.append(QJsonObject{{"case", int(k)},
                                     {"largest", r.largest},
                                     {"at", QJsonArray{r.at.x(), r.at.y()}},
                                     {"shareWithin", r.shareWithin},
                                     {"compared", r.compared},
                                     {"passed", r.passed}});
        }
        out["cases"] = cases;
        out["worstCase"] = report.worstCase;
    }
    if (report.mistake)
        out["mistake"] = QJsonObject{{"index", report.mistake->index},
                                     {"name", report.mistake->name},
                                     {"hint", report.mistake->hint},
                                     {"shareWithin", report.mistake->shareWithin}};
    if (!report.sheet.isEmpty())
        out["sheet"] = report.sheet;
    if (!report.sheetError.isEmpty())
        out["sheetError"] = report.sheetError;
    return out;
}

std::optional<GradingReport> readGradingReport(const QByteArray &output)
{
    const QList<QByteArray> lines = output.split('\n');
    for (auto it = lines.rbegin(); it != lines.rend(); ++it) {
        const QJsonObject o = QJsonDocument::fromJson(it->trimmed()).object();
        if (!o["status"].isString())
            continue;
        GradingReport r;
        r.submission = o["submission"].toString();
        r.status = o["status"].toString();
        r.diagnostic = o["diagnostic"].toString();
        r.sheet = o["sheet"].toString();
        r.sheetError = o["sheetError"].toString();
        r.worstCase = o["worstCase"].toInt(-1);
        if (const QJsonObject m = o["mistake"].toObject(); !m.isEmpty())
            r.mistake = MistakeMatch{m["index"].toInt(-1), m["name"].toString(),
                                     m["hint"].toString(), m["shareWithin"].toDouble()};
        for (const QJsonValue &v : o["cases"].toArray()) {
            const QJsonObject c = v.toObject();
            CaseResult cr;
            cr.largest = c["largest"].toInt();
            const QJsonArray at = c["at"].toArray();
            cr.at = QPoint(at.at(0).toInt(-1), at.at(1).toInt(-1));
            cr.shareWithin = c["shareWithin"].toDouble();
            cr.compared = c["compared"].toInt();
            cr.passed = c["passed"].toBool();
            r.cases.push_back(cr);
        }
        return r;
    }
    return std::nullopt;
}

} // namespace lb
