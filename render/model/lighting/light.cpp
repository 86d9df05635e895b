#include "light.h"

namespace lb {

Lights defaultLights()
{
    Lights lights;
    const LightColors none{glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
    for (std::size_t i = 1; i < lights.size(); ++i) {
        lights[i].enabled = false;
        lights[i].colors = none;
    }
    lights[1].position = {-2.5f, 0.5f, 1.0f, 1.0f};
    lights[1].colors.id = {0.25f, 0.35f, 0.7f};
    lights[1].colors.is = {0.4f, 0.5f, 0.9f};
    lights[2].position = {2.0f, -1.2f, 1.5f, 1.0f};
    lights[2].colors.id = {0.6f, 0.45f, 0.2f};
    lights[2].colors.is = {0.6f, 0.5f, 0.3f};
    lights[3].position = {0.0f, 0.0f, 1.0f, 0.0f}; // a headlight: along the view direction
    // Made a spotlight, a point light aims at the object's centre from where it starts.
    for (Light &l : lights)
        if (l.position.w != 0.0f)
            l.spot.direction = -glm::vec3(l.position);
    lights[3].frame = LightFrame::Camera;
    lights[3].colors.id = glm::vec3(0.3f);
    lights[3].colors.is = glm::vec3(0.3f);
    return lights;
}

} // namespace lb
