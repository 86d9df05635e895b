#include "texture_controls.h"

#include "narrow_forms.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QToolButton>

#include "status_line.h"
#include "texture_file.h"

namespace lb {

TextureControls::TextureControls(SceneDocument *document, QWidget *parent)
    : ScenePanel(document, ScenePart::Object, parent)
{
    auto *form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);

    // Two rows, so that the Object panel fits a 720-pixel-high screen without scrolling:
    // the switch, the image and its buttons; then the sampling.
    auto *imageRow = new WrapRow(WrapRow::Room::Left);
    m_texture = new QCheckBox(tr("Texture"), this);
    m_texture->setToolTip(tr("uEnableTexture: multiply ambient and diffuse by the texture "
                             "(uSampler): the image file, else the mesh file's diffuse "
                             "texture, else the checker"));
    connect(m_texture, &QCheckBox::toggled, this,
            [this](bool on) { edit([&](Scene &s) { s.selectedObject().texture = on; }); });
    feeds(m_texture, {Semantic::EnableTexture});
    imageRow->addWidget(m_texture);
    m_image = new ElidedLabel(this); // a long name ends in "...", the whole path as tooltip
    m_image->setMinimumWidth(30);
    m_image->setSizePolicy(QSizePolicy::Expanding, m_image->sizePolicy().verticalPolicy());
    imageRow->addWidget(m_image);
    m_open = new QToolButton(this);
    m_open->setText(tr("Image..."));
    m_open->setToolTip(tr("Open a PNG, JPEG or any image Qt reads as this object's texture "
                          "(Ctrl+T, or drop it on the window); at most %1 x %1 texels")
                           .arg(kMaxTextureFileSide));
    connect(m_open, &QToolButton::clicked, this, &TextureControls::openImageRequested);
    imageRow->addWidget(m_open);
    m_clear = new QToolButton(this);
    m_clear->setText(QStringLiteral("\u00d7"));
    m_clear->setToolTip(tr("No image: back to the mesh file's texture or the checker"));
    connect(m_clear, &QToolButton::clicked, this,
            [this] { edit([&](Scene &s) { s.selectedObject().textureFile.clear(); }); });
    imageRow->addWidget(m_clear);
    form->addRow(imageRow);

    auto *samplingRow = new WrapRow(WrapRow::Room::Left);
    //: texture wrapping: GL_REPEAT or GL_CLAMP_TO_EDGE
    m_wrap = makeCombo({tr("Repeat"), tr("Clamp")},
                       tr("Texture coordinates outside 0 to 1: the image repeats (GL_REPEAT) or "
                          "its edge stretches (GL_CLAMP_TO_EDGE)"));
    connect(m_wrap, &QComboBox::currentIndexChanged, this, [this](int i) {
        edit([&](Scene &s) { s.selectedObject().sampling.wrap = TextureWrap(i); });
    });
    samplingRow->addWidget(m_wrap);
    //: texture filtering: GL_NEAREST or GL_LINEAR
    m_filter = makeCombo({tr("Nearest"), tr("Linear")},
                         tr("The texel nearest the coordinate (GL_NEAREST: blocky when "
                            "magnified) or the four around it weighted (GL_LINEAR)"));
    connect(m_filter, &QComboBox::currentIndexChanged, this, [this](int i) {
        edit([&](Scene &s) { s.selectedObject().sampling.filter = TextureFilter(i); });
    });
    samplingRow->addWidget(m_filter);
    m_mipmaps = new QCheckBox(tr("Mipmaps"), this);
    m_mipmaps->setToolTip(tr("Where the texture is minified, read a smaller copy of it chosen "
                             "by the level of detail (GL_NEAREST_MIPMAP_NEAREST, or trilinear "
                             "GL_LINEAR_MIPMAP_LINEAR with the linear filter): no shimmer far "
                             "away. The probe shows the level"));
    connect(m_mipmaps, &QCheckBox::toggled, this,
            [this](bool on) { edit([&](Scene &s) { s.selectedObject().sampling.mipmaps = on; }); });
    samplingRow->addWidget(m_mipmaps);
    form->addRow(samplingRow);
    refreshNow();
}

void TextureControls::refresh(const Scene &scene)
{
    const ObjectSettings &o = scene.selectedObject();
    const QSignalBlocker b1(m_texture), b2(m_wrap), b3(m_filter), b4(m_mipmaps);
    m_texture->setChecked(o.texture);
    const bool image = !o.textureFile.isEmpty();
    const QString problem = image && m_problem ? m_problem() : QString();
    m_image->setText(image && !problem.isEmpty()
                         //: %1 an image file's name that could not be shown as the texture
                         ? tr("%1 (not shown)").arg(QFileInfo(o.textureFile).fileName())
                         : image                  ? QFileInfo(o.textureFile).fileName()
                           : o.meshPath.isEmpty() ? tr("the checker")
                                                  : tr("the mesh file's texture, or the checker"));
    m_image->setFullText(!problem.isEmpty() ? problem : image ? o.textureFile : QString());
    m_clear->setEnabled(image);
    m_wrap->setCurrentIndex(int(o.sampling.wrap));
    m_filter->setCurrentIndex(int(o.sampling.filter));
    m_mipmaps->setChecked(o.sampling.mipmaps);
}

} // namespace lb
