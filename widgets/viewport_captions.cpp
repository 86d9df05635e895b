// The texts over the picture (the compare caption, the colour scale's numbers, the banner and
// the probe's names), which follow the UI scale, and their words: the banner's, the driver line's
// and the compare view's.
#include "viewport.h"

#include "difference_scale_labels.h"

#include <QApplication>
#include <QLabel>

#include <algorithm>
#include <cmath>

namespace lb {

QString Viewport::bannerText(const QString &why, bool builtInDrawing)
{
    // Whole sentences, not a clause glued to another ("Refused: %1; %2").
    if (why.isEmpty())
        return builtInDrawing ? tr("The shader has errors (see the editor): the built-in program "
                                   "is drawing")
                              : tr("The shader has errors (see the editor): the last good "
                                   "program is drawing");
    //: %1 why the program was refused (a loop that never ends, a frame too slow)
    return builtInDrawing ? tr("Refused: %1; the built-in program is drawing").arg(why)
                          //: %1 why the program was refused
                          : tr("Refused: %1; the last good program is drawing").arg(why);
}

QString Viewport::driverText(const QString &version, const QString &renderer, bool webGl1)
{
    //: %1 the OpenGL version (4.5); %2 the driver's renderer (llvmpipe ...)
    return webGl1 ? tr("OpenGL %1, %2; WebGL 1 shaders run as GLSL 3.30").arg(version, renderer)
                  //: %1 the OpenGL version (4.5); %2 the driver's renderer
                  : tr("OpenGL %1, %2").arg(version, renderer);
}

QString Viewport::compareText() const
{
    const Scene &s = m_document->scene();
    const QString b =
        !m_sideBVertex.isEmpty()
            //: side B of the compare view and the program it draws
            ? tr("B: %1").arg(m_sideBName.isEmpty() ? tr("the reference program") : m_sideBName)
            //: side B draws the built-in program: %1 its shading, %2 its specular term
            : tr("B: built-in %1, %2")
                  .arg(s.compare.shading == Shading::Gouraud ? tr("Gouraud")
                       : s.compare.shading == Shading::Flat  ? tr("flat")
                                                             : tr("Phong"),
                       specularModelTitle(s.compare.specular));
    switch (s.compare.mode) {
    case CompareMode::Off:
        return {};
    case CompareMode::SideBySide:
    case CompareMode::Wipe:
        //: side A (left) names its program; %2 says side B's ("B: ..."), on the right
        return tr("A (left): %1  |  %2 (right)")
            .arg(m_programName.isEmpty() ? tr("the program on screen") : m_programName, b);
    case CompareMode::Difference: {
        const DifferenceStats &d = m_renderer.difference();
        if (!d.valid)
            return tr("|A - B|: not drawn yet");
        // The share within the tolerance of the pixels drawn, as Check My Work counts a case.
        const QString figures =
            tr("|A - B|, A: %7, %1: largest %2/255 at (%3, %4); %5% of the drawn pixels "
               "within %8/255; scale 0 (black) to %6/255 (white)")
                .arg(b, QString::number(d.largest), QString::number(d.at.x()),
                     QString::number(d.at.y()),
                     QString::number(std::floor(d.shareWithin * 1000.0) / 10.0, 'f', 1),
                     QString::number(int(std::lround(kDifferenceScale * 255.0f))),
                     m_programName.isEmpty() ? tr("the program on screen") : m_programName,
                     QString::number(d.tolerance));
        if (m_caseNote.isEmpty())
            return figures;
        const QSize frame = size() * devicePixelRatio();
        //: %1 the difference view's figures; %2 x %3 the view's size in pixels; %4 what
        //: Check My Work measured for the case (its own frame size and figures)
        return tr("%1 (this view, %2 x %3 pixels); %4")
            .arg(figures, QString::number(frame.width()), QString::number(frame.height()),
                 m_caseNote);
    }
    }
    return {};
}

void Viewport::setCaseNote(const QString &note)
{
    m_caseNote = note;
    updateCompareLabel();
}

void Viewport::setProgramName(const QString &name)
{
    m_programName = name;
    updateCompareLabel();
}

void Viewport::updateCompareLabel()
{
    const QString text = compareText();
    const bool difference = m_document->scene().compare.mode == CompareMode::Difference;
    m_differenceLabels->setShown(difference);
    m_compareLabel->setText(text);
    m_compareLabel->setVisible(!text.isEmpty());
    if (text.isEmpty())
        return;
    // In the difference view the caption leaves the colour scale's column free.
    const int widest = difference ? m_differenceLabels->leftOfTicks() : width();
    m_compareLabel->setMaximumWidth(widest);
    m_compareLabel->setWordWrap(true);
    // As wide as its one line, up to the room there is: adjustSize() would wrap it at about
    // 400 pixels, seven lines at 200%.
    const QMargins margins = m_compareLabel->contentsMargins();
    const int line = m_compareLabel->fontMetrics().horizontalAdvance(text) + margins.left() +
                     margins.right() + 2 * m_compareLabel->margin() + 16;
    const int w = std::min(widest, line);
    m_compareLabel->resize(w, m_compareLabel->heightForWidth(w));
    m_compareLabel->move(0, height() - m_compareLabel->height());
}

void Viewport::setUiScale(double scale)
{
    // The application's font is already the scaled one (applyUiScale): the texts over the
    // picture take it explicitly, as a style sheet's label does not always follow it.
    const QFont font = QApplication::font();
    for (QWidget *text :
         {static_cast<QWidget *>(m_banner), static_cast<QWidget *>(m_compareLabel),
          static_cast<QWidget *>(m_differenceLabels), static_cast<QWidget *>(m_labels)})
        text->setFont(font);
    m_differenceLabels->setUiScale(scale);
    m_renderer.setUiScale(scale);
    m_banner->setGeometry(0, 0, width(), m_banner->heightForWidth(width()));
    updateCompareLabel();
    update();
}

void Viewport::setProbeArrowsFaded(bool faded)
{
    m_renderer.setProbeArrowsFaded(faded);
    update();
}

} // namespace lb
