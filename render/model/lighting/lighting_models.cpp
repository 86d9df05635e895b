#include "lighting_models.h"

#include <QCoreApplication>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>

namespace lb {

namespace {

std::optional<float> degreesOf(float c)
{
    return degreesFromCosine(c);
}

} // namespace

const std::vector<SpecularModelRow> &specularModels()
{
    static const std::vector<SpecularModelRow> rows{
        {SpecularModel::Phong,
         "phong",
         0,
         "Phong",
         //: Phong's specular term (R.V)^n, as in "phong specular"
         QT_TRANSLATE_NOOP3("lb::ChoiceLabels", "phong", "specular"),
         "R\u00b7V",
         "RdotV",
         "R",
         "(R\u00b7V)^n",
         &LightingTerms::R,
         [](const LightingTerms &t) { return glm::dot(t.R, t.V); },
         degreesOf,
         {{"phong", 1.0f, false}},
         {1.0f, 0.35f, 1.0f}}, // the probe's magenta for R
        // In the plane of N and V with L = N, N·H = cos(angle / 2): Blinn-Phong needs about 4n
        // to look like Phong's n, which the dashed curve shows.
        {SpecularModel::Blinn,
         "blinn",
         1,
         "Blinn-Phong",
         //: Blinn-Phong's specular term (N.H)^n, as in "blinn specular"
         QT_TRANSLATE_NOOP3("lb::ChoiceLabels", "blinn", "specular"),
         "N\u00b7H",
         "NdotH",
         "H",
         "(N\u00b7H)^n",
         &LightingTerms::H,
         [](const LightingTerms &t) { return glm::dot(t.N, t.H); },
         [](float c) -> std::optional<float> {
             if (c < 0.0f) // beyond 180 degrees: the factor is 0 there
                 return std::nullopt;
             return 2.0f * degreesFromCosine(c);
         },
         {{"blinn", 1.0f, false}, {"blinn_4n", 4.0f, true}},
         {0.45f, 0.9f, 0.4f}}, // a green beside Phong's magenta
    };
    return rows;
}

const SpecularModelRow &specularModel(SpecularModel model)
{
    for (const SpecularModelRow &row : specularModels())
        if (row.model == model)
            return row;
    return specularModels().front();
}

const SpecularModelRow *specularModelOfCurve(const QString &key, const SpecularPlotCurve **curve)
{
    for (const SpecularModelRow &row : specularModels())
        for (const SpecularPlotCurve &c : row.curves)
            if (key == QLatin1String(c.key)) {
                if (curve)
                    *curve = &c;
                return &row;
            }
    return nullptr;
}

SpecularModel nextSpecularModel(SpecularModel model)
{
    const std::vector<SpecularModelRow> &rows = specularModels();
    for (std::size_t i = 0; i < rows.size(); ++i)
        if (rows[i].model == model)
            return rows[(i + 1) % rows.size()].model;
    return rows.front().model;
}

QString specularModelTitle(SpecularModel model)
{
    const SpecularModelRow &row = specularModel(model);
    return QString("%1 (%2)").arg(QString::fromUtf8(row.name), QString::fromUtf8(row.angle));
}

QString toName(SpecularModel v)
{
    return QString::fromLatin1(specularModel(v).word);
}

std::optional<SpecularModel> parseSpecularModel(const QString &s)
{
    for (const SpecularModelRow &row : specularModels())
        if (s == QLatin1String(row.word))
            return row.model;
    return std::nullopt;
}

QStringList specularModelNames()
{
    QStringList names;
    for (const SpecularModelRow &row : specularModels())
        names << QString::fromLatin1(row.word);
    return names;
}

} // namespace lb
