#pragma once
// The scene every panel edits and the viewport draws. Panels change it through set(); the
// changed() signal says which parts changed: the viewport repaints, the panels showing those
// parts show the new values.

#include "scene.h"

#include <QObject>

namespace lb {

class SceneDocument : public QObject
{
    Q_OBJECT
public:
    explicit SceneDocument(QObject *parent = nullptr) : QObject(parent) {}
    const Scene &scene() const { return m_scene; }
    void set(const Scene &scene)
    {
        const SceneParts parts = differingParts(m_scene, scene);
        if (!parts)
            return;
        m_scene = scene;
        emit changed(parts);
    }
    // Edits a copy and stores it: document.edit([](Scene &s) { s.material.shininess = 20; });
    template <typename F> void edit(F &&change)
    {
        Scene copy = m_scene;
        change(copy);
        set(copy);
    }

signals:
    // `parts`: what differs from the scene before (never empty).
    void changed(lb::SceneParts parts);

private:
    Scene m_scene;
};

} // namespace lb
