#include "probe_panel.h"

#include "choice_labels.h"
#include "model_colours.h"
#include "probe_equation.h"
#include "probe_equation_words.h"
#include "viewport.h"

#include <QClipboard>
#include <QFontInfo>
#include <QGuiApplication>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>

namespace lb {

namespace {

constexpr float kArrowLength = 0.6f; // about a seventh of the view height at the target

QString vec(const glm::vec3 &v)
{
    return QString("(%1, %2, %3)")
        .arg(double(v.x), 0, 'f', 3)
        .arg(double(v.y), 0, 'f', 3)
        .arg(double(v.z), 0, 'f', 3);
}

glm::ivec3 bytes255(const glm::vec3 &v)
{
    return glm::ivec3(std::lround(v.x * 255.0f), std::lround(v.y * 255.0f),
                      std::lround(v.z * 255.0f));
}

QString rgb(const glm::ivec3 &c)
{
    return QString("(%1, %2, %3)").arg(c.r).arg(c.g).arg(c.b);
}

// A name and its value side by side, or (stacked: a narrow panel at 200%) the value under its
// name, whole on its line, rather than wrapped over three beside a column of names.
QString tableRow(const QString &name, const QString &value, bool stacked)
{
    return stacked ? QString("<tr><td><b>%1</b></td></tr><tr><td style='padding-left: "
                             "1em'>%2</td></tr>")
                         .arg(name, value)
                   : QString("<tr><td><b>%1</b></td><td>%2</td></tr>").arg(name, value);
}

} // namespace

ProbePanel::ProbePanel(SceneDocument *document, Viewport *viewport, QWidget *parent)
    : QWidget(parent), m_document(document), m_viewport(viewport)
{
    auto *layout = new QVBoxLayout(this);
    m_text = new QLabel(this);
    m_text->setTextFormat(Qt::RichText);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_text->setWordWrap(true);
    m_text->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    layout->addWidget(m_text);
    m_copyEquation = new QPushButton(tr("Copy the Equation"), this);
    m_copyEquation->setToolTip(tr("The lighting equation with this point's numbers, as text"));
    connect(m_copyEquation, &QPushButton::clicked, this,
            [this] { QGuiApplication::clipboard()->setText(m_equation); });
    layout->addWidget(m_copyEquation, 0, Qt::AlignLeft);
    layout->addStretch();
    clear();
    connect(document, &SceneDocument::changed, this, &ProbePanel::update);
    connect(viewport, &Viewport::objectChanged, this, &ProbePanel::clear);
    connect(viewport, &Viewport::textureChanged, this, &ProbePanel::update);
    // A new view size moves the point's pixel: read the GPU where the point now is.
    connect(viewport, &Viewport::resized, this, &ProbePanel::followResize);
    connect(viewport, &QOpenGLWidget::frameSwapped, this, &ProbePanel::showText);
}

void ProbePanel::clear()
{
    m_point.reset();
    m_result = ProbeResult{};
    m_gpu.reset();
    m_reference.reset();
    m_referenceName.clear();
    m_equation.clear();
    m_copyEquation->setEnabled(false);
    m_viewport->setProbe({}, QPoint(-1, -1), {});
    m_text->setText(tr("Ctrl+click (or Shift+click) the surface to probe a point: the "
                       "vectors, N\u00b7L, the specular angle and the three terms, beside the "
                       "pixel the GPU drew. Esc clears it."));
    emit resultChanged();
}

void ProbePanel::setSideBReference(const QString &name)
{
    if (name == m_sideBReference)
        return;
    m_sideBReference = name;
    update();
}

void ProbePanel::setReferenceNote(const QString &note)
{
    if (note == m_referenceNote)
        return;
    m_referenceNote = note;
    showText();
}

void ProbePanel::probeAt(QPoint framePixel)
{
    const QSize frame = m_viewport->size() * m_viewport->devicePixelRatio();
    PixelView view;
    const ProbeResult r = probeFramePixel(
        m_document->scene(), m_viewport->renderer().probedObjects(), frame, framePixel, &view);
    if (!r.hit) {
        clear();
        m_text->setText(tr("No surface at (%1, %2).").arg(framePixel.x()).arg(framePixel.y()));
        return;
    }
    m_point = Point{r.object, r.triangle, r.barycentric, view.sideB};
    update();
}

// The point kept over a new view size (presentation mode, a dock moved) lies somewhere in its
// new pixel, while the GPU's colour there is the pixel centre's: on a highlight the two differ
// by several 255ths (7 after leaving presentation mode). The probe moves to the surface point
// at that pixel's centre, as a click there would have put it.
void ProbePanel::followResize()
{
    update();
    if (!m_point || !m_result.hit)
        return;
    const QSize frame = m_viewport->size() * m_viewport->devicePixelRatio();
    const QRect view = viewRect(m_document->scene(), frame, m_point->sideB);
    const QPoint pixel = view.topLeft() + QPoint(int(std::floor(m_result.pixel.x())),
                                                 int(std::floor(m_result.pixel.y())));
    PixelView at;
    const ProbeResult r = probeFramePixel(
        m_document->scene(), m_viewport->renderer().probedObjects(), frame, pixel, &at);
    if (!r.hit || r.object != m_point->object || at.sideB != m_point->sideB)
        return; // another object in front there now: the point stays where it was
    m_point = Point{r.object, r.triangle, r.barycentric, at.sideB};
    update();
}

void ProbePanel::update()
{
    if (!m_point)
        return;
    const Scene &scene = m_document->scene();
    const Mesh *mesh = m_viewport->renderer().objectMesh(m_point->object);
    if (!mesh || m_point->triangle >= mesh->triangleCount() ||
        m_point->object >= int(scene.objects.size())) {
        clear();
        return;
    }
    const QSize frame = m_viewport->size() * m_viewport->devicePixelRatio();
    const QRect view = viewRect(scene, frame, m_point->sideB);
    m_result = probeSurface(sceneOfSide(scene, m_point->sideB), m_point->object, *mesh,
                            m_viewport->renderer().texture(m_point->object), view.size(),
                            m_point->triangle, m_point->barycentric);

    // Arrows from the point: N yellow, V cyan, and for each light L in its diffuse colour
    // with H (Blinn-Phong) or R (Phong) in magenta.
    std::vector<Renderer::Arrow> arrows;
    std::vector<ProbeLabel> labels;
    auto add = [&](const glm::vec3 &dir, const glm::vec3 &colour, const QString &name) {
        const glm::vec3 d = kArrowLength * glm::normalize(dir);
        arrows.push_back({m_result.position, d, colour});
        labels.push_back({m_result.position, m_result.position + d, m_point->sideB, name,
                          QColor::fromRgbF(colour.r, colour.g, colour.b)});
    };
    add(m_result.normal, colours::kNormal, "N");
    add(viewVector(m_result.position, scene.shading.projection), colours::kView, "V");
    const bool several = m_result.lights.size() > 1;
    for (const ProbeLight &l : m_result.lights) {
        const QString n = several ? QString::number(l.index + 1) : QString();
        add(l.terms.L, colours::lightArrow(scene.lights[std::size_t(l.index)].colors.id), "L" + n);
        const SpecularModelRow &model = specularModel(scene.shading.specular);
        add(l.terms.*model.vectorOf, colours::kMirror, QString::fromLatin1(model.vector) + n);
    }
    const QPoint pixel = view.topLeft() + QPoint(int(std::floor(m_result.pixel.x())),
                                                 int(std::floor(m_result.pixel.y())));
    const bool againstProgram =
        !m_point->sideB && !m_sideBReference.isEmpty() && m_viewport->hasSideBProgram();
    m_viewport->setProbe(std::move(arrows), pixel, std::move(labels), againstProgram);
    emit resultChanged();
}

bool ProbePanel::stacksRows() const
{
    // A vector's numbers and a name beside them; narrower, each value goes under its name.
    const int vector = fontMetrics().horizontalAdvance(QStringLiteral("(-0.000, -0.000, -0.000)"));
    return m_text->width() < vector * 17 / 10;
}

void ProbePanel::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    if (stacksRows() != m_stacked)
        showText();
}

void ProbePanel::showText()
{
    if (!m_point || !m_result.hit)
        return;
    m_stacked = stacksRows();
    const auto row = [stacked = m_stacked](const QString &name, const QString &value) {
        return tableRow(name, value, stacked);
    };
    m_gpu = m_viewport->renderer().probedColour();
    const Scene &scene = m_document->scene();
    const Scene side = sceneOfSide(scene, m_point->sideB);
    const ProbeResult &r = m_result;
    const SpecularModelRow &specular = specularModel(side.shading.specular);
    const QSize frame = m_viewport->size() * m_viewport->devicePixelRatio();
    const QRect view = viewRect(scene, frame, m_point->sideB);
    const Frames frames = computeFrames(side, float(view.width()) / float(view.height()), r.object);

    QString html = "<table cellspacing='2'>";
    //: %1, %2 the pixel; %3 the object's name; %4 the triangle's number
    const QString point = scene.compare.mode == CompareMode::Off
                              ? tr("pixel (%1, %2), %3, triangle %4")
                          //: the point is on side B of a compare view
                          : m_point->sideB ? tr("pixel (%1, %2), %3, triangle %4, side B")
                                           //: the point is on side A of a compare view
                                           : tr("pixel (%1, %2), %3, triangle %4, side A");
    html += row(tr("Point"),
                // One arg() for all four: a "%4" in the object's name stays as typed.
                point.arg(QString::number(std::lround(r.pixel.x() + view.x())),
                          QString::number(std::lround(r.pixel.y() + view.y())),
                          displayName(scene.objects[std::size_t(r.object)]).toHtmlEscaped(),
                          QString::number(r.triangle)));
    //: P, the probed point, in eye coordinates
    html += row(tr("P (eye)"), vec(r.position));
    // The vectors' names are the course's symbols, as the equation writes them: not words.
    html += row(QStringLiteral("N"), vec(r.normal));
    html += row(QStringLiteral("V"), vec(viewVector(r.position, side.shading.projection)));
    const ObjectSettings &object = side.objects[std::size_t(r.object)];
    if (object.texture) {
        // Where the texture is read, and which mipmap levels the level of detail picks.
        const Texture &texture = m_viewport->renderer().texture(r.object);
        const Texture::Levels levels = texture.levelsAt(r.lod, object.sampling);
        const QString read = levels.weight > 0.0f ? tr("levels %1 and %2 (%3% of %2)")
                                                        .arg(levels.first)
                                                        .arg(levels.second)
                                                        .arg(std::lround(100.0f * levels.weight))
                                                  : tr("level %1").arg(levels.first);
        //: %1, %2 the texture coordinates; %3 the level of detail; %4 the mipmap levels read
        const QString where = object.sampling.mipmaps
                                  ? tr("uv (%1, %2), level of detail %3: %4, mipmaps")
                                  : tr("uv (%1, %2), level of detail %3: %4, no mipmaps");
        html += row(tr("texture"), where.arg(double(r.uv.x), 0, 'f', 3)
                                       .arg(double(r.uv.y), 0, 'f', 3)
                                       .arg(double(r.lod), 0, 'f', 2)
                                       .arg(read));
        html += row(tr("base colour"), vec(r.base));
    }
    for (const ProbeLight &l : r.lights) {
        const Light &light = scene.lights[std::size_t(l.index)];
        const LightingTerms &t = l.terms;
        html += QString("<tr><td colspan='2'><hr>%1</td></tr>")
                    //: %1 the light's name in bold (Light 2); %2 its frame (camera, world, object)
                    .arg(tr("%1 (%2 frame)")
                             .arg("<b>" + tr("Light %1").arg(l.index + 1) + "</b>",
                                  frameLabel(light.frame)));
        html += row("L", vec(t.L));
        html += row(QString::fromLatin1(specular.vector), vec(t.*specular.vectorOf));
        // The light's own frame: the way lightInEye() came, undone.
        if (light.frame != LightFrame::Camera) {
            const glm::vec4 p =
                eyeToFrame(frames, l.index, glm::vec4(r.position, 1.0f), light.frame);
            const glm::vec4 towards =
                eyeToFrame(frames, l.index, glm::vec4(t.L, 0.0f), light.frame);
            //: P and L in the light's own frame: %1 the frame (world, object)
            html += row(tr("P, L (%1)").arg(frameLabel(light.frame)),
                        vec(glm::vec3(p)) + ", " + vec(glm::normalize(glm::vec3(towards))));
        }
        html += row(QString("N\u00b7L"), QString::number(double(t.nDotL), 'f', 4));
        html += row(QString::fromUtf8(specular.angle),
                    QString::number(double(t.specularAngle), 'f', 4));
        if (light.position.w != 0.0f)
            html += row(tr("distance, attenuation"), QString("%1, %2")
                                                         .arg(double(t.distance), 0, 'f', 4)
                                                         .arg(double(t.attenuation), 0, 'f', 4));
        if (light.spot.cutoffDegrees < limits::kMaxSpotCutoff)
            html += row(tr("spot"), t.spot > 0.0f ? QString::number(double(t.spot), 'f', 4)
                                                  : tr("0 (outside the cone)"));
        const TermSwitches &on = side.shading.terms;
        const auto term = [&](const QString &name, bool enabled, const glm::vec3 &value) {
            html += row(enabled ? name : tr("%1 (off)").arg(name), vec(value));
        };
        term(tr("ambient"), on.ambient, t.ambient);
        term(tr("diffuse"), on.diffuse, t.diffuse);
        term(tr("specular"), on.specular, t.specular);
    }
    html += QString("<tr><td colspan='2'><hr><b>%1</b></td></tr>").arg(tr("Sum"));
    html += row(tr("ambient"), vec(r.total.ambient));
    html += row(tr("diffuse"), vec(r.total.diffuse));
    html += row(tr("specular"), vec(r.total.specular));
    // What the pixel is compared with: the model with the probed side's choices, or where
    // side B is side A's reference, what side B draws at this point (its program's pixel, or
    // the model with its choices); a point drawn by side B's program is the reference itself.
    const bool sideBProgram = m_viewport->hasSideBProgram();
    const bool againstSideB = !m_point->sideB && !m_sideBReference.isEmpty();
    m_reference.reset();
    m_referenceName.clear();
    if (againstSideB) {
        m_referenceName = m_sideBReference;
        if (sideBProgram) {
            m_reference = m_viewport->renderer().probedSideBColour();
        } else if (const Mesh *mesh = m_viewport->renderer().objectMesh(r.object)) {
            const ProbeResult b = probeSurface(
                sceneOfSide(scene, true), r.object, *mesh, m_viewport->renderer().texture(r.object),
                view.size(), m_point->triangle, m_point->barycentric);
            m_reference = bytes255(b.reference);
        }
    } else if (!(m_point->sideB && sideBProgram)) {
        m_referenceName = tr("the model (%1 shading)").arg(shadingLabel(side.shading.shading));
        m_reference = bytes255(r.reference);
    }
    // On side B's program the side's shading choice is greyed: it is not the program's.
    //: %1 the colour (r, g, b) of 255; %2 the shading (gouraud, phong, flat)
    const QString model = m_point->sideB && sideBProgram
                              ? tr("%1 of 255 (the built-in model, %2 shading)")
                              : tr("%1 of 255 (%2 shading)");
    html += row(againstSideB || (m_point->sideB && sideBProgram) ? tr("model") : tr("reference"),
                model.arg(rgb(bytes255(r.reference)), shadingLabel(side.shading.shading)));
    if (againstSideB)
        html += row(tr("reference"),
                    m_reference
                        //: %1 the reference's name; %2 its colour (r, g, b) at the point
                        ? tr("%1 draws %2").arg(m_referenceName.toHtmlEscaped(), rgb(*m_reference))
                        : tr("%1 draws nothing here").arg(m_referenceName.toHtmlEscaped()));
    if (m_gpu && scene.compare.mode != CompareMode::Difference) {
        html += row(tr("GPU drew"), rgb(*m_gpu));
        if (m_reference) {
            const glm::ivec3 d = glm::abs(*m_gpu - *m_reference);
            html += row(tr("difference"), againstSideB
                                              ? tr("%1 of 255 from %2")
                                                    .arg(std::max({d.r, d.g, d.b}))
                                                    .arg(m_referenceName.toHtmlEscaped())
                                              : tr("%1 of 255").arg(std::max({d.r, d.g, d.b})));
        }
    }
    html += "</table>";
    // The equation with the numbers, as the course writes it (also copied by the button).
    m_equation = equationForDisplay(lightingEquationLines(side, r));
    m_copyEquation->setEnabled(!m_equation.isEmpty());
    // The monospace at the panel's size, which follows the UI scale: in presentation mode too,
    // where the back row reads it (issue 49, item 15).
    const int equationPixels = std::max(8, QFontInfo(font()).pixelSize());
    html += QString("<hr><b>%1</b><pre style='white-space: pre-wrap; font-size: %3px'>%2</pre>")
                // A product of symbols may break after each dot (a zero-width space): at
                // 200% in a narrow column "att·spot·Id·Kd·max(N·L," is wider than the panel.
                .arg(tr("The equation at this point"),
                     m_equation.toHtmlEscaped().replace(QChar(0x00b7),
                                                        QString::fromUtf8("\u00b7\u200b")))
                .arg(equationPixels);
    if (!m_referenceNote.isEmpty())
        html += QString("<p><i>%1</i></p>").arg(m_referenceNote.toHtmlEscaped());
    if (m_point->sideB && sideBProgram)
        html += QString("<p><i>%1</i></p>")
                    .arg(tr("This point is drawn by %1 (side B), which is itself the "
                            "reference: it is compared with nothing. The numbers above are the "
                            "built-in model's, which that program need not follow.")
                             .arg(m_viewport->sideBName().toHtmlEscaped()));
    else if (againstSideB)
        html += QString("<p><i>%1</i></p>")
                    .arg(tr("The pixel is compared with what %1 draws at this point; the numbers "
                            "above are the built-in model's.")
                             .arg(m_referenceName.toHtmlEscaped()));
    m_text->setText(html);
}

} // namespace lb
