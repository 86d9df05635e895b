// The options lightbench knows, as --help, the man page and the shell's completion show them
// (command_line.h: visibleOptions()): one table, so the three cannot drift apart.
#include "command_line.h"

#include "grading_formats.h"
#include "plots.h"
#include "scene.h"

namespace lb {

namespace {

// The endings of the files opened by --scene and --lesson: lightbench's own (the desktop's
// MIME types) and JSON (the course's files).
const QStringList kSceneSuffixes{"lbscene", "json"};
const QStringList kLessonSuffixes{"lblesson", "json"};

OptionInfo value(const char *name, const char *valueName, const QString &help)
{
    OptionInfo o;
    o.names = QStringList{QString::fromLatin1(name)};
    o.valueName = QString::fromLatin1(valueName);
    o.description = help;
    return o;
}

// "Specular exponent (1 to 1000)."
QString parameterHelp(const LightingParameter &p)
{
    return QString(p.count == 1 ? "%1 (%2 to %3)." : "%1 (each %2 to %3).")
        .arg(QString::fromUtf8(p.description))
        .arg(double(p.lo))
        .arg(double(p.hi));
}

// "Specular term: phong, Phong's (R.V)^n; or blinn, Blinn-Phong's (N.H)^n.", from the models'
// table (lighting_models.h).
QString specularHelp()
{
    QStringList models;
    for (const SpecularModelRow &row : specularModels())
        models << QString("%1, %2's %3")
                      .arg(QString::fromLatin1(row.word), QString::fromUtf8(row.name),
                           QString::fromUtf8(row.factor).replace(QChar(0x00b7), '.'));
    return "Specular term: " + models.join("; or ") + ".";
}

OptionInfo flag(const char *name, const QString &help)
{
    return value(name, "", help);
}

// A value from a fixed list: the list the parser checks against, shown as "a|b|c".
OptionInfo words(const char *name, const QStringList &words, const QString &help)
{
    OptionInfo o = value(name, "", help);
    o.valueName = words.join('|');
    o.words = words;
    return o;
}

// A file's name: `suffixes` are the endings the shell offers (none: any file).
OptionInfo file(const char *name, const char *valueName, const QStringList &suffixes,
                const QString &help)
{
    OptionInfo o = value(name, valueName, help);
    o.files = true;
    o.suffixes = suffixes;
    return o;
}

OptionInfo folder(const char *name, const char *valueName, const QString &help)
{
    OptionInfo o = value(name, valueName, help);
    o.directory = true;
    return o;
}

// --object: a shape's name or a mesh file (any format Assimp reads: any file).
OptionInfo object(const QString &help)
{
    OptionInfo o = file("object", "SHAPE|FILE", {}, help);
    o.words = shapeNames();
    return o;
}

} // namespace

QStringList commandLineLanguages()
{
    return {"system", "en", "pt", "de"};
}

QStringList onOffNames()
{
    return {"on", "off"};
}

QStringList sceneFileSuffixes()
{
    return kSceneSuffixes;
}

QStringList lessonFileSuffixes()
{
    return kLessonSuffixes;
}

QString fileArgumentsHelp()
{
    return "Scene files (.lbscene, .json) or lesson files (.lblesson, .json) to open "
           "in the window: the first opens, the others are named in a message. With "
           "--grade, the submissions.";
}

std::vector<OptionInfo> visibleOptions()
{
    OptionInfo help = flag("help", "Print this help and exit.");
    help.names.prepend("h");
    OptionInfo version = flag("version", "Print the version and exit.");
    version.names.prepend("v");
    std::vector<OptionInfo> options{
        help,
        version,
        file("scene", "FILE.json", kSceneSuffixes,
             "Start from a scene file (lights, material, shading, object, camera, "
             "program, compare); the other options override it."),
        file("save-scene", "FILE.json", kSceneSuffixes,
             "Write the scene (with --scene and every option applied) to FILE.json; "
             "exit unless --render, --probe or --bench-frames is given too."),
        file("lesson", "FILE.json", kLessonSuffixes,
             "Open a lesson (steps of scenes with captions) at --step, in the window; "
             "with --render, --screenshot or --probe, that step's scene. Not with "
             "--scene."),
        value("step", "N", "With --lesson: the step, from 1 (default 1)."),
        file("render", "FILE.png", {"png", "svg"},
             "Draw one frame offscreen into FILE.png and exit (with --plot: the plot, as "
             "PNG, or SVG where FILE ends in .svg)."),
        value("probe", "X,Y", "Print the probe's JSON for pixel X,Y (origin top-left) and exit."),
        value("size", "WxH", "Frame size for --render and --probe (default 800x600)."),
        words("plot", plotKindNames(),
              "Draw one of the model's curves for the scene instead of a frame: the specular "
              "factor (Phong's n, Blinn-Phong's n and 4n) against the angle from R, the "
              "diffuse factor against the angle of incidence, each point light's attenuation "
              "against the distance, each spotlight's factor against the angle from its axis, "
              "or the lobe of the three terms in the plane of incidence; into --render and/or "
              "--plot-data; with --probe, that pixel's point is marked on the curves."),
        file("plot-data", "FILE.csv", {"csv"},
             "With --plot: the curves' samples as CSV (angle_degrees or distance, then one "
             "column per curve; numbers with a point)."),
        object("Add an object: " + shapeNames().join(", ") +
               " or a mesh file (repeatable; placed side by side and the camera framing "
               "them). The object options (shape, mesh, model, material, texture) apply "
               "to the last object named; without --object, to the scene's selected "
               "object. Without --scene the objects named replace the saved session's."),
        words("shape", shapeNames(), "Object shape."),
        value("tessellation", "N", "Subdivisions of the sphere, torus and plane (3 to 2000)."),
        file("mesh", "FILE", {},
             "Draw a mesh file (any format Assimp reads) instead of the shape."),
        words("normals", normalModeNames(),
              "Normals: the mesh's own (generated smooth when it has none), smooth or flat."),
        words("faces", facesNames(),
              "Which way a mesh file's faces look: outward (closed parts wound inwards are "
              "turned; the default), as in the file, flipped, or two-sided (each face lit from "
              "both sides)."),
        value("crease-angle", "DEGREES",
              "Generated smooth normals stop at sharper edges (0 to 180)."),
        words("show-normals", onOffNames(), "Draw each vertex normal as a short line."),
        words("cull-back-faces", onOffNames(),
              "Leave out triangles facing away (closed meshes: the same picture, drawn faster)."),
        words("file-material", onOffNames(), "Take Ka, Kd, Ks and shininess from the mesh file."),
        value("import-memory-limit", "MB",
              "Memory limit of the import helper (default: half of physical memory)."),
        value("import-time-limit", "SECONDS", "Time limit of the import helper (default 300)."),
        words("shading", shadingNames(),
              "Lighting per vertex (Gouraud), per fragment (Phong) or per triangle at "
              "its last vertex (flat)."),
        words("specular", specularModelNames(), specularHelp()),
        words("show", showChoiceNames(),
              "What the surface shows: the lit colour, or N, L, V, H, R (as 0.5v + 0.5), "
              "N.L, the specular factor or the attenuation (as grey); L, H, R and the "
              "numbers are light 1's."),
        value("terms", "ambient,diffuse,specular",
              "The terms of the model that are on: any of the three, or none (default "
              "all); the others add nothing."),
        words("frame", lightFrameNames(), "Frame the light position is given in."),
        value("light-object", "INDEX",
              "The object (0 for the first) whose frame an object-frame light 1 is given in."),
    };
    // Light 1's and the selected object's numbers, as the lighting model's table declares
    // them (lighting_parameters.h), with their ranges.
    for (const LightingParameter &p : lightingParameters())
        if (p.option)
            options.push_back(value(p.option, p.metavar, parameterHelp(p)));
    options.insert(
        options.end(),
        {
            value("spot", "DX,DY,DZ,CUTOFF,EXPONENT",
                  "Make light 1 a spotlight: the cone's axis in the light's frame, its "
                  "half-angle in degrees (0 to 180; 180: no spot) and its exponent (0 to "
                  "128)."),
            words("projection", projectionNames(), "Projection; V = -posC or (0,0,1) to match."),
            value("camera-orbit", "YAW,PITCH", "Camera orbit in degrees (pitch -89 to 89)."),
            value("model-rotate", "X,Y,Z", "Model rotation in degrees about X, then Y, then Z."),
            value("model-scale", "X,Y,Z", "Model scale per axis (0.01 to 100)."),
            value("model-translate", "X,Y,Z",
                  "Where the object's centre lies in the world (-1000 to 1000)."),
            words("lighting", onOffNames(), "Lighting model on, or the diffuse colour unlit."),
            words("vertex-colors", onOffNames(),
                  "Modulate ambient and diffuse by the vertex colours."),
            words("texture", onOffNames(),
                  "Modulate ambient and diffuse by the texture: the image file, else the "
                  "mesh file's own, else the checker."),
            file("texture-file", "FILE", {},
                 "An image (PNG, JPEG, any format Qt reads; at most 16384 x 16384, drawn at "
                 "most 4096 on a side) as the texture; switches the texture on."),
            words("texture-wrap", textureWrapNames(),
                  "Texture coordinates outside 0 to 1 repeat or clamp."),
            words("texture-filter", textureFilterNames(),
                  "The nearest texel or the four around, weighted."),
            words("texture-mipmaps", onOffNames(),
                  "Read smaller copies of the texture where it is minified (trilinear with "
                  "the linear filter)."),
            words("show-light", onOffNames(), "Draw the light's marker."),
            file("screenshot", "FILE.png", {"png"},
                 "Open the window, save a screenshot once it has drawn, exit."),
            flag("presentation", "Open the window in presentation mode: full screen, the "
                                 "presentation UI scale (F11)."),
            value("ui-scale", "PERCENT",
                  "UI scale of the window (or of presentation mode with --presentation), 100 "
                  "to 250; kept."),
            words("language", commandLineLanguages(),
                  "The window's language for this run, and --plot's picture's (View > Language "
                  "keeps one; the command line's own output is English)."),
            value("bench-frames", "N", "Draw N frames offscreen and print the frame rate as JSON."),
            value("bench-edits", "N",
                  "Open the window, time N shader edits to the screen, print JSON, exit."),
            file("vertex", "FILE", {},
                 "Vertex shader to draw with instead of the built-in one (with --fragment)."),
            file("fragment", "FILE", {}, "Fragment shader to draw with (with --vertex)."),
            value("frame-budget", "SECONDS",
                  "Refuse your program when one frame at --size would take longer (default "
                  "1; 0.01 to 60)."),
            value("bind", "NAME=KEY",
                  "Feed the uniform NAME with KEY, one of what the scene gives (model-view, "
                  "projection, light-position-world, material-diffuse...; a KEY it does not know "
                  "lists them all), or none: its own value; repeatable; saved with --save-scene."),
            flag("translate-webgl1",
                 "Run WebGL 1 shaders (no #version) translated to GLSL 3.30 core instead of "
                 "under \"#version 100\" (automatic where the driver refuses #version 100)."),
            flag("grade", "Grade submissions (the arguments after the options: NAME.vert + "
                          "NAME.frag, a folder with one such pair, or a scene file with a program) "
                          "against --exercise; one line per submission, and a progress line on a "
                          "terminal; exit 0, 2 when one could not be read (the others are graded), "
                          "1 when the report or a sheet could not be written, 3 with "
                          "--report-format github when the submission did not pass every case."),
            file("exercise", "FILE.json", kSceneSuffixes,
                 "The exercise to grade against: a scene file with an \"exercise\" section "
                 "(reference program, cases, tolerance)."),
            file("report", "FILE", {"csv", "xml", "json"},
                 "With --grade: the report, written again whole after each submission (one CSV "
                 "row per submission unless --report-format says otherwise); - writes it to "
                 "standard output once the batch ends, and the summary lines to standard error."),
            words("report-format", reportFormatNames(),
                  "With --report: csv (default; points, seed and version in columns), junit (XML, "
                  "one testsuite per submission, as GitLab and Jenkins read it), or one "
                  "submission's file for a platform: gradescope (results.json), github (GitHub "
                  "Classroom's runner result: base64 it into the step's result output; exit 3 "
                  "unless every case passed) or coderunner (CodeRunner's combinator grader JSON; "
                  "nothing on standard error, a batch error goes into the JSON)."),
            folder("sheets", "DIR",
                   "With --grade: one PNG per submission (its worst case: student, reference, "
                   "difference); the sheets of the previous run there (listed in "
                   "DIR/.lightbench-sheets) are removed first."),
            value("seed", "N",
                  "With --grade: the cases' random parameters (default 1; the same seed "
                  "gives the same cases)."),
            flag("check",
                 "Compile and link --vertex and --fragment and try them on small frames, "
                 "print each diagnostic as FILE:LINE:COLUMN: error|warning: message; exit 0 "
                 "if the program links and passes the trial (see --frame-budget), 1 if not."),
        });
    return options;
}

} // namespace lb
