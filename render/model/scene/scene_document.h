#pragma once
// The scene every panel edits and the viewport draws. Panels change it through set(); the
// changed() signal says which parts changed: the viewport repaints, the panels showing those
// parts show the new values.

#include "scene.h"

#include <QObject>

#include <functional>

namespace lb {

class SceneDocument : public QObject
{
    Q_OBJECT
public:
    explicit SceneDocument(QObject *parent = nullptr) : QObject(parent) {}
    const Scene &scene() const { return m_scene; }
    // What the scene may ask of the machine: `limit` sees every scene before it is stored (and
    // before any listener builds from it), may change it (the scene budget lowers tessellations)
    // and says what it changed, or nothing.
    void setLimit(std::function<QString(Scene &)> limit) { m_limit = std::move(limit); }
    // Stores `scene` as the limit leaves it; returns what the limit changed (also said by
    // limited()), or an empty string.
    QString set(const Scene &scene)
    {
        Scene limited = scene;
        const QString why = m_limit ? m_limit(limited) : QString();
        const SceneParts parts = differingParts(m_scene, limited);
        if (parts) {
            m_scene = std::move(limited);
            emit changed(parts);
        }
        if (!why.isEmpty())
            emit this->limited(why);
        return why;
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
    // The limit changed a scene on its way in: "32 objects at tessellation 2000 would ...".
    void limited(const QString &message);

private:
    Scene m_scene;
    std::function<QString(Scene &)> m_limit;
};

} // namespace lb
