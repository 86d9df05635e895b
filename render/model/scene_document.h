#pragma once
// The scene every panel edits and the viewport draws. Panels change it through set(); the
// changed() signal tells the viewport to repaint and the panels to show the new values.

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
        if (scene == m_scene)
            return;
        m_scene = scene;
        emit changed();
    }
    // Edits a copy and stores it: document.edit([](Scene &s) { s.material.shininess = 20; });
    template <typename F> void edit(F &&change)
    {
        Scene copy = m_scene;
        change(copy);
        set(copy);
    }

signals:
    void changed();

private:
    Scene m_scene;
};

} // namespace lb
