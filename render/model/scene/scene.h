#pragma once
// The scene model: everything the panels, the command line and the renderer agree on.
// Plain data; SceneDocument (scene_document.h) wraps it with a "changed" signal.

#include "bindings.h"
#include "camera.h"
#include "light.h"
#include "lighting.h"
#include "lighting_models.h"
#include "lighting_parameters.h"
#include "localized_text.h"
#include "texture_sampling.h"

#include <QFlags>
#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <map>
#include <optional>
#include <vector>

namespace lb {

// Gouraud: the model at the vertices, interpolated; Phong: at every fragment; flat: at each
// triangle's provoking (last) vertex, one colour per triangle, as GL's flat shading gives.
enum class Shading { Gouraud, Phong, Flat };
// Whether the model runs at the vertices (the Gouraud program's text, flat or not).
inline bool perVertex(Shading s)
{
    return s != Shading::Phong;
}
enum class Shape { Cube, Sphere, Torus, Plane };
// Where the object's normals come from: the mesh's own (generated smooth when it has none),
// or generated smooth (within the crease angle) or flat, whatever the mesh has.
enum class NormalMode { File, Smooth, Flat };
// Which way a mesh file's faces look. Outward: each closed part wound inwards (negative
// signed volume) is turned, winding and normals, and normals that point against an outward
// winding are turned too; parts that enclose no volume (open sheets) stay as the file has
// them. File: as the file has them. Flipped: every face turned. TwoSided: as the file has
// them, and each face also seen from behind, lit with its normal reversed (a reversed copy
// of every triangle, with back faces culled: any program lights both sides). Shapes are
// outward already: only TwoSided and Flipped change them.
enum class Faces { Outward, File, Flipped, TwoSided };
// Two programs on one camera: A (the editor's program) and B (a built-in one).
enum class CompareMode { Off, SideBySide, Wipe, Difference };

struct ShadingSettings
{
    Shading shading = Shading::Phong;
    SpecularModel specular = SpecularModel::Blinn; // the slides' complete shaders use H
    Projection projection = Projection::Perspective;
    bool lighting = true;
    TermSwitches terms;                   // ambient, diffuse and specular, each on or off
    ShowChoice show = ShowChoice::Colour; // the lit colour, or a vector or number of the model
    bool vertexColors = false;
    // Wrong on purpose, to show why: normals transformed by the model-view itself instead of
    // its inverse transpose (they tilt under a non-uniform scale).
    bool normalsByModelView = false;
};

struct ObjectSettings
{
    // As the Object panel lists it, by language (a shipped example names its objects in each
    // language; a name typed in the panel is plainText); empty: named after its shape or file.
    LocalizedText name;
    bool visible = true; // a hidden object is neither drawn nor probed
    Shape shape = Shape::Sphere;
    int tessellation = 16; // coarse on purpose: Gouraud and Phong visibly differ
    QString meshPath;      // a mesh file drawn instead of the shape; empty: the shape
    NormalMode normals = NormalMode::File;
    float creaseDegrees = 30.0f; // generated smooth normals don't blend across sharper edges
    Faces faces = Faces::Outward;
    bool showNormals = false; // draw each vertex normal as a short line
    // Triangles facing away from the camera are not drawn (nor probed): right for closed
    // meshes and about twice as fast to draw; an open mesh loses its inside faces.
    bool cullBackFaces = false;
    // Culled in fact: asked for, or lighting both sides (the reversed copy is the back face).
    bool culls() const { return cullBackFaces || faces == Faces::TwoSided; }
    bool adoptFileMaterial = false; // a mesh file's material replaces Ka, Kd, Ks, shininess
    glm::vec3 rotationDegrees{0.0f};
    glm::vec3 scale{1.0f};
    glm::vec3 translation{0.0f}; // where the object's origin lies in the world
    bool autoRotate = false;
    Material material;
    // The texture switch: the image file when one is named, else the mesh file's texture,
    // else the checker.
    bool texture = false;
    QString textureFile; // an image (absolute path); empty: none
    TextureSampling sampling;
};

// A scene holds from one to this many objects.
constexpr int kMaxObjects = 32;

struct CompareSettings
{
    CompareMode mode = CompareMode::Off;
    float wipe = 0.5f; // the wipe's position across the viewport, 0 to 1
    // Side B is the built-in program with its own shading and specular choices; the rest of
    // the scene is shared. Gouraud by default, so that A = Phong shows the difference at once.
    Shading shading = Shading::Gouraud;
    SpecularModel specular = SpecularModel::Blinn;
};

struct Scene
{
    Lights lights = defaultLights();
    ShadingSettings shading;
    // Never empty; each object has its own mesh, transform and material.
    std::vector<ObjectSettings> objects = std::vector<ObjectSettings>(1);
    int selected = 0; // the object the Object and Material panels edit
    OrbitCamera camera;
    bool showLight = true; // draw the lights' markers (unlit sphere or arrow)
    CompareSettings compare;
    // Values of the user shader's own uniforms (those no panel feeds), by name; they outlive
    // recompiles and restarts. 1 to 4 numbers each.
    std::map<QString, std::vector<float>> shaderValues;
    // What the user chose to feed the program's uniforms, by name (the Bindings view,
    // --bind): they override what the names give (bindings.h).
    UniformBindings bindings;

    ObjectSettings &selectedObject() { return objects[std::size_t(selected)]; }
    const ObjectSettings &selectedObject() const { return objects[std::size_t(selected)]; }

    QJsonObject toJson() const;
    // Missing or ill-typed fields keep their defaults. Those present but not used (unknown,
    // ill-typed or out of range) are added to `ignored` as paths such as "lights[2].frame".
    static Scene fromJson(const QJsonObject &json, QStringList *ignored = nullptr);
};

// The parts of a scene that change together. SceneDocument::changed() names those that
// changed, so that each listener does only its own work (the object loader rebuilds on Object
// alone, the Light panel refreshes on Lights alone).
enum class ScenePart : unsigned {
    Lights = 1u << 0,   // the lights and whether their markers show
    Material = 1u << 1, // any object's material
    Shading = 1u << 2,
    Object = 1u << 3, // the object list, the selection, and every object's settings
    Camera = 1u << 4,
    Compare = 1u << 5,
    Program = 1u << 6,  // the values of the program's own uniforms (shaderValues)
    Bindings = 1u << 7, // what feeds the program's uniforms: the program is built again
};
Q_DECLARE_FLAGS(SceneParts, ScenePart)
constexpr SceneParts kAllSceneParts = SceneParts(0xff);

// Object list edits that keep the lights' attachments and the selection pointing at the
// same objects. Each returns false and changes nothing where the list would leave 1 to
// kMaxObjects objects or the index is out of range.
bool addObject(Scene &scene, const ObjectSettings &object); // appended and selected
bool removeObject(Scene &scene, int index);                 // its lights go to the object before it
// The first place, on a grid 2.5 apart in the world's XY plane spiralling out from the
// origin, that no object of `scene` occupies (none within 2 of it): where Add and Duplicate
// put a new object.
glm::vec3 freePlace(const Scene &scene);
// Puts the objects side by side along world X, 2.5 apart, centred on the origin.
void placeInRow(std::vector<ObjectSettings> &objects);
// The camera at its default angles, aimed at the middle of the scene's visible objects and
// far enough to see them all (each taken as its unit bounds, scaled).
void frameScene(Scene &scene);
// The name the Object panel shows: the object's own, or its shape's (shapeLabel) or file's.
QString displayName(const ObjectSettings &object);
// A shape as the window names it, translated ("sphere"); toName() gives the files' word.
QString shapeLabel(Shape shape);

// Field by field: the parts in which `a` and `b` differ.
SceneParts differingParts(const Scene &a, const Scene &b);

bool operator==(const Scene &a, const Scene &b);
inline bool operator!=(const Scene &a, const Scene &b)
{
    return !(a == b);
}
bool operator==(const Light &a, const Light &b);
bool operator==(const LightColors &a, const LightColors &b);
bool operator==(const Spot &a, const Spot &b);
bool operator==(const TermSwitches &a, const TermSwitches &b);
bool operator==(const Material &a, const Material &b);
bool operator==(const ShadingSettings &a, const ShadingSettings &b);
bool operator==(const ObjectSettings &a, const ObjectSettings &b);
bool operator==(const OrbitCamera &a, const OrbitCamera &b);
bool operator==(const CompareSettings &a, const CompareSettings &b);

// Limits shared by the panels and the command line (the lighting model's own:
// lighting_parameters.h).
namespace limits {
constexpr int kMinTessellation = 3;
constexpr int kMaxTessellation = 2000;
constexpr float kMinScale = 0.01f;
constexpr float kMaxScale = 100.0f;
constexpr float kMaxCreaseDegrees = 180.0f;
// The program's own uniform values a scene keeps (Scene::shaderValues): far more than a program
// has, few enough that a scene at every limit is smaller than a scene file may be
// (kMaxSceneFileBytes), so what is saved can be opened again.
constexpr int kMaxShaderValues = 16384;
constexpr int kMaxShaderValueName = 1024; // GLSL ES's longest identifier
constexpr int kMaxBindings = 1024;        // far more than a program has uniforms
constexpr int kMaxNameCharacters = 4096;  // an object's or a program's name, in each language
} // namespace limits

// Names used on the command line, in JSON and in the panels' combo boxes (the specular
// models': lighting_models.h).
QString toName(LightFrame v);
QString toName(Shading v);
QString toName(Projection v);
QString toName(Shape v);
QString toName(NormalMode v);
QString toName(Faces v);
QString toName(CompareMode v);
QString toName(ShowChoice v);
QString toName(TextureWrap v);
QString toName(TextureFilter v);
std::optional<LightFrame> parseLightFrame(const QString &s);
std::optional<Shading> parseShading(const QString &s);
std::optional<Projection> parseProjection(const QString &s);
std::optional<Shape> parseShape(const QString &s);
std::optional<NormalMode> parseNormalMode(const QString &s);
std::optional<Faces> parseFaces(const QString &s);
std::optional<CompareMode> parseCompareMode(const QString &s);
std::optional<ShowChoice> parseShowChoice(const QString &s);
std::optional<TextureWrap> parseTextureWrap(const QString &s);
std::optional<TextureFilter> parseTextureFilter(const QString &s);
QStringList lightFrameNames();
QStringList shadingNames();
QStringList projectionNames();
QStringList shapeNames();
QStringList normalModeNames();
QStringList facesNames();
QStringList compareModeNames();
QStringList showChoiceNames();
QStringList textureWrapNames();
QStringList textureFilterNames();

} // namespace lb

Q_DECLARE_OPERATORS_FOR_FLAGS(lb::SceneParts)
