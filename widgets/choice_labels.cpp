#include "choice_labels.h"

#include <QCoreApplication>

namespace lb {

// The English words are toName()'s, so English reads as it did before they were translated.
// The disambiguation tells "phong" the shading from "phong" the specular term.

QString frameLabel(LightFrame frame)
{
    switch (frame) {
    case LightFrame::Camera:
        return QCoreApplication::translate("lb::ChoiceLabels", "camera", "light frame");
    case LightFrame::World:
        return QCoreApplication::translate("lb::ChoiceLabels", "world", "light frame");
    case LightFrame::Object:
        return QCoreApplication::translate("lb::ChoiceLabels", "object", "light frame");
    }
    return toName(frame);
}

QString shadingLabel(Shading shading)
{
    switch (shading) {
    case Shading::Gouraud:
        //: Gouraud shading (per vertex), as in "gouraud shading"
        return QCoreApplication::translate("lb::ChoiceLabels", "gouraud", "shading");
    case Shading::Phong:
        //: Phong shading (per fragment), as in "phong shading"
        return QCoreApplication::translate("lb::ChoiceLabels", "phong", "shading");
    case Shading::Flat:
        //: flat shading (per triangle), as in "flat shading"
        return QCoreApplication::translate("lb::ChoiceLabels", "flat", "shading");
    }
    return toName(shading);
}

QString specularLabel(SpecularModel specular)
{
    const TranslatableText &label = specularModel(specular).label;
    return QCoreApplication::translate("lb::ChoiceLabels", label.source, label.comment);
}

QString showLabel(ShowChoice show)
{
    // What the Shading panel's Show choice puts on the surface instead of the lit colour.
    switch (show) {
    case ShowChoice::Colour:
        return QCoreApplication::translate("lb::ChoiceLabels", "colour", "show");
    case ShowChoice::Normal:
        //: the normal N, drawn as a colour
        return QCoreApplication::translate("lb::ChoiceLabels", "normal", "show");
    case ShowChoice::Light:
        //: the light vector L, drawn as a colour
        return QCoreApplication::translate("lb::ChoiceLabels", "light", "show");
    case ShowChoice::View:
        //: the view vector V, drawn as a colour
        return QCoreApplication::translate("lb::ChoiceLabels", "view", "show");
    case ShowChoice::Half:
        //: the half vector H, drawn as a colour
        return QCoreApplication::translate("lb::ChoiceLabels", "half", "show");
    case ShowChoice::Reflect:
        //: the reflected light R, drawn as a colour
        return QCoreApplication::translate("lb::ChoiceLabels", "reflect", "show");
    case ShowChoice::NDotL:
        //: N·L drawn as grey
        return QCoreApplication::translate("lb::ChoiceLabels", "ndotl", "show");
    case ShowChoice::Specular:
        //: the specular factor drawn as grey
        return QCoreApplication::translate("lb::ChoiceLabels", "specular", "show");
    case ShowChoice::Attenuation:
        //: the attenuation drawn as grey
        return QCoreApplication::translate("lb::ChoiceLabels", "attenuation", "show");
    }
    return toName(show);
}

} // namespace lb
