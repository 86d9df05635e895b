// PLY as Assimp 5.2's reader makes it (code/AssetLib/Ply/PlyLoader.cpp) for the files scans
// come in: an element "vertex" of scalars, then an element "face" with one list of corners.
// The mesh stays indexed (the vertex element is the vertex array); x, y, z of any type as
// float; normals when any of nx, ny, nz is there (the others 0); colours when any of red /
// r, green / g, blue / b, alpha is there, normalised by type as Assimp does (uchar / 255,
// ushort and uint / 65535, char (v + 127) / 255, short (v + 32767) / 65535, int v / 255 + 0.5,
// float as is); faces of three corners drawn, of fewer skipped; the default material white
// (Ka = Kd = Ks = 1). Anything else (texture coordinates, a TextureFile comment, faces of more
// than three corners, lists in the vertex element, other elements, a value ASCII cannot be
// read as) is declined, for Assimp to read. A file that ends before its counts is refused.

#include "fast_mesh_readers.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

namespace lb {

namespace {

enum class Type { Char, UChar, Short, UShort, Int, UInt, Float, Double };

bool parseType(const std::string &name, Type &type)
{
    static const std::pair<const char *, Type> names[] = {
        {"char", Type::Char},      {"int8", Type::Char},      {"uchar", Type::UChar},
        {"uint8", Type::UChar},    {"short", Type::Short},    {"int16", Type::Short},
        {"ushort", Type::UShort},  {"uint16", Type::UShort},  {"int", Type::Int},
        {"int32", Type::Int},      {"uint", Type::UInt},      {"uint32", Type::UInt},
        {"float", Type::Float},    {"float32", Type::Float},  {"double", Type::Double},
        {"float64", Type::Double}, {"double64", Type::Double}};
    for (const auto &[n, t] : names)
        if (name == n) {
            type = t;
            return true;
        }
    return false;
}

std::size_t bytes(Type t)
{
    switch (t) {
    case Type::Char:
    case Type::UChar:
        return 1;
    case Type::Short:
    case Type::UShort:
        return 2;
    case Type::Int:
    case Type::UInt:
    case Type::Float:
        return 4;
    case Type::Double:
        return 8;
    }
    return 0;
}

bool integral(Type t)
{
    return t != Type::Float && t != Type::Double;
}

// What a vertex property is for.
enum class Role { Skip, X, Y, Z, NX, NY, NZ, Red, Green, Blue, Alpha };

struct Property
{
    Type type = Type::Float;
    bool list = false;
    Type countType = Type::UChar;
    Role role = Role::Skip;
    bool corners = false; // the face element's list of corners
};

struct Element
{
    std::string name;
    std::uint64_t count = 0;
    std::vector<Property> properties;
};

struct Header
{
    enum { Ascii, Little, Big } format = Ascii;
    std::vector<Element> elements;
};

// Declines with the reason given.
struct Decline
{
    std::string why;
};

Role vertexRole(const std::string &name)
{
    static const std::pair<const char *, Role> roles[] = {
        {"x", Role::X},         {"y", Role::Y},     {"z", Role::Z},       {"nx", Role::NX},
        {"ny", Role::NY},       {"nz", Role::NZ},   {"red", Role::Red},   {"r", Role::Red},
        {"green", Role::Green}, {"g", Role::Green}, {"blue", Role::Blue}, {"b", Role::Blue},
        {"alpha", Role::Alpha}};
    for (const auto &[n, r] : roles)
        if (name == n)
            return r;
    // Texture coordinates under any of Assimp's names: the fast path sends none.
    static const char *uvs[] = {"u", "s", "tx", "texture_u", "v", "t", "ty", "texture_v"};
    for (const char *n : uvs)
        if (name == n)
            throw Decline{"texture coordinates"};
    return Role::Skip;
}

std::vector<std::string> words(const std::string &line)
{
    std::istringstream s(line);
    std::vector<std::string> w;
    for (std::string t; s >> t;)
        w.push_back(t);
    return w;
}

std::uint64_t count(const std::string &text)
{
    std::uint64_t n = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec != std::errc() || end != text.data() + text.size())
        throw Decline{"an element count that is not a number"};
    return n;
}

Header readHeader(Chunks &in)
{
    constexpr std::size_t kMaxLine = 4096, kMaxLines = 1000;
    std::string line;
    if (!in.line(line, kMaxLine) || line != "ply")
        throw Decline{"no \"ply\" line"};
    Header h;
    bool format = false;
    for (std::size_t n = 0; n < kMaxLines; ++n) {
        if (!in.line(line, kMaxLine))
            throw Decline{"the header does not end"};
        const std::vector<std::string> w = words(line);
        if (w.empty())
            continue;
        if (w[0] == "end_header") {
            if (!format)
                throw Decline{"no format line"};
            return h;
        }
        if (w[0] == "comment" || w[0] == "obj_info") {
            if (line.find("TextureFile") != std::string::npos)
                throw Decline{"a texture file"};
        } else if (w[0] == "format" && w.size() == 3 && !format) {
            format = true;
            if (w[1] == "ascii")
                h.format = Header::Ascii;
            else if (w[1] == "binary_little_endian")
                h.format = Header::Little;
            else if (w[1] == "binary_big_endian")
                h.format = Header::Big;
            else
                throw Decline{"format " + w[1]};
        } else if (w[0] == "element" && w.size() == 3) {
            h.elements.push_back({w[1], count(w[2]), {}});
        } else if (w[0] == "property" && !h.elements.empty()) {
            Property p;
            Element &e = h.elements.back();
            std::string name;
            if (w.size() == 3 && parseType(w[1], p.type)) {
                name = w[2];
            } else if (w.size() == 5 && w[1] == "list" && parseType(w[2], p.countType) &&
                       parseType(w[3], p.type) && integral(p.countType)) {
                p.list = true;
                name = w[4];
            } else {
                throw Decline{"a property line: " + line.substr(0, 80)};
            }
            if (e.name == "vertex") {
                if (p.list)
                    throw Decline{"a list in the vertex element"};
                p.role = vertexRole(name);
                for (const Property &q : e.properties)
                    if (p.role != Role::Skip && q.role == p.role)
                        throw Decline{"a vertex property given twice"};
            } else if (e.name == "face" && p.list) {
                if ((name != "vertex_indices" && name != "vertex_index") || !integral(p.type))
                    throw Decline{"a face list other than integer vertex_indices"};
                p.corners = true;
            }
            e.properties.push_back(p);
        } else {
            throw Decline{"a header line: " + line.substr(0, 80)};
        }
    }
    throw Decline{"a header of more than 1000 lines"};
}

// A vertex's properties, decoded: the value as a double (exact for every PLY type), its type.
struct VertexLayout
{
    int position[3] = {-1, -1, -1}, normal[3] = {-1, -1, -1}, colour[4] = {-1, -1, -1, -1};
    bool normals = false, colours = false;
};

VertexLayout layout(const Element &vertex)
{
    VertexLayout l;
    for (std::size_t i = 0; i < vertex.properties.size(); ++i) {
        const Role r = vertex.properties[i].role;
        if (r >= Role::X && r <= Role::Z)
            l.position[int(r) - int(Role::X)] = int(i);
        else if (r >= Role::NX && r <= Role::NZ)
            l.normal[int(r) - int(Role::NX)] = int(i);
        else if (r >= Role::Red && r <= Role::Alpha)
            l.colour[int(r) - int(Role::Red)] = int(i);
    }
    if (l.position[0] < 0 || l.position[1] < 0 || l.position[2] < 0)
        throw Decline{"a vertex without x, y and z"};
    l.normals = l.normal[0] >= 0 || l.normal[1] >= 0 || l.normal[2] >= 0;
    l.colours = l.colour[0] >= 0 || l.colour[1] >= 0 || l.colour[2] >= 0 || l.colour[3] >= 0;
    return l;
}

// A double as float, out-of-range values as infinities (as the processor's conversion gives
// them, and Assimp's cast; the cast itself would be undefined for them).
float toFloat(double v)
{
    if (v > double(std::numeric_limits<float>::max()))
        return std::numeric_limits<float>::infinity();
    if (v < -double(std::numeric_limits<float>::max()))
        return -std::numeric_limits<float>::infinity();
    return float(v); // NaN stays NaN
}

// Assimp's NormalizeColorValue, in float as it computes it.
float colourValue(Type t, double v)
{
    switch (t) {
    case Type::Float:
    case Type::Double:
        return float(v);
    case Type::UChar:
        return float(v) / 255.0f;
    case Type::Char:
        return float(v + 127) / 255.0f;
    case Type::UShort:
    case Type::UInt:
        return float(v) / 65535.0f; // uint as ushort: Assimp's (sic)
    case Type::Short:
        return float(v + 32767) / 65535.0f;
    case Type::Int:
        return float(v) / 255.0f + 0.5f;
    }
    return 0.0f;
}

void storeVertex(const VertexLayout &l, const Element &e, const double *values, std::size_t v,
                 FastMesh &mesh)
{
    for (int c = 0; c < 3; ++c)
        mesh.positions[3 * v + c] = toFloat(values[l.position[c]]);
    if (l.normals)
        for (int c = 0; c < 3; ++c)
            mesh.normals[3 * v + c] = l.normal[c] >= 0 ? toFloat(values[l.normal[c]]) : 0.0f;
    if (l.colours)
        for (int c = 0; c < 3; ++c)
            mesh.colors[3 * v + c] =
                l.colour[c] >= 0 ? colourValue(e.properties[l.colour[c]].type, values[l.colour[c]])
                                 : 0.0f;
}

template <typename T> T load(const unsigned char *p, bool swap)
{
    unsigned char b[sizeof(T)];
    std::memcpy(b, p, sizeof b);
    if (swap)
        std::reverse(b, b + sizeof b);
    T v;
    std::memcpy(&v, b, sizeof v);
    return v;
}

double binaryValue(Type t, const unsigned char *p, bool swap)
{
    switch (t) {
    case Type::Char:
        return load<std::int8_t>(p, swap);
    case Type::UChar:
        return load<std::uint8_t>(p, swap);
    case Type::Short:
        return load<std::int16_t>(p, swap);
    case Type::UShort:
        return load<std::uint16_t>(p, swap);
    case Type::Int:
        return load<std::int32_t>(p, swap);
    case Type::UInt:
        return load<std::uint32_t>(p, swap);
    case Type::Float:
        return load<float>(p, swap);
    case Type::Double:
        return load<double>(p, swap);
    }
    return 0.0;
}

// A corner as Assimp's ConvertTo<unsigned int> makes it: a negative index wraps (and is then
// out of range, so the face is skipped, as Assimp's is).
std::uint32_t cornerIndex(double v)
{
    return std::uint32_t(std::int64_t(v));
}

bool asciiValue(Type t, const char *&p, const char *end, double &v)
{
    while (p < end && (*p == ' ' || *p == '\t'))
        ++p;
    std::from_chars_result r{};
    if (t == Type::Float) {
        float f = 0;
        r = std::from_chars(p, end, f);
        v = f;
    } else if (t == Type::Double) {
        r = std::from_chars(p, end, v);
    } else {
        std::int64_t i = 0;
        r = std::from_chars(p + (p < end && *p == '+'), end, i);
        v = double(i);
    }
    if (r.ec != std::errc() || (r.ptr < end && *r.ptr != ' ' && *r.ptr != '\t'))
        return false;
    p = r.ptr;
    return true;
}

// Reads the vertex and face elements; `ascii`: one instance a line, else binary.
class Body
{
public:
    Body(Chunks &in, const Header &h, FastMesh &mesh)
        : m_in(in), m_ascii(h.format == Header::Ascii), m_swap(h.format == Header::Big),
          m_vertex(h.elements[0]), m_face(h.elements[1]), m_layout(layout(m_vertex)), m_mesh(mesh)
    {
    }

    void vertices()
    {
        const std::size_t n = m_vertex.count, props = m_vertex.properties.size();
        m_mesh.positions.resize(3 * n);
        if (m_layout.normals)
            m_mesh.normals.resize(3 * n);
        if (m_layout.colours)
            m_mesh.colors.resize(3 * n);
        std::vector<double> values(props);
        std::size_t recordBytes = 0;
        for (const Property &p : m_vertex.properties)
            recordBytes += bytes(p.type);
        for (std::size_t v = 0; v < n; ++v) {
            if (m_ascii) {
                const char *p = line(v, "vertex"), *end = p + m_line.size();
                for (std::size_t i = 0; i < props; ++i)
                    if (!asciiValue(m_vertex.properties[i].type, p, end, values[i]))
                        throw Decline{"vertex " + std::to_string(v) + " cannot be read"};
                trailing(p, end, v, "vertex");
            } else {
                const unsigned char *b = m_in.take(recordBytes);
                if (!b)
                    ended(v, m_vertex.count, "vertices");
                for (std::size_t i = 0; i < props; ++i) {
                    values[i] = binaryValue(m_vertex.properties[i].type, b, m_swap);
                    b += bytes(m_vertex.properties[i].type);
                }
            }
            storeVertex(m_layout, m_vertex, values.data(), v, m_mesh);
        }
    }

    void faces()
    {
        m_mesh.triangles.reserve(3 * std::size_t(m_face.count));
        for (std::uint64_t f = 0; f < m_face.count; ++f) {
            const char *p = nullptr, *end = nullptr;
            if (m_ascii) {
                p = line(f, "face");
                end = p + m_line.size();
            }
            for (const Property &prop : m_face.properties) {
                double n = 1;
                if (prop.list && !value(prop.countType, p, end, n, f))
                    throw Decline{"face " + std::to_string(f) + " cannot be read"};
                if (n < 0 || (prop.corners && n > 3))
                    throw Decline{"a face of more than three corners (Assimp triangulates it)"};
                if (prop.list && !prop.corners && n > 0)
                    throw Decline{"a face list other than its corners"};
                double c[3] = {};
                for (int k = 0; k < int(n); ++k)
                    if (!value(prop.type, p, end, c[k], f))
                        throw Decline{"face " + std::to_string(f) + " cannot be read"};
                if (!prop.corners)
                    continue;
                if (n < 3) {
                    ++m_mesh.skippedFaces;
                    continue;
                }
                m_mesh.triangles.insert(m_mesh.triangles.end(),
                                        {cornerIndex(c[0]), cornerIndex(c[1]), cornerIndex(c[2])});
            }
            if (m_ascii)
                trailing(p, end, f, "face");
        }
    }

    struct Ended
    {
        std::string why;
    };

private:
    bool value(Type t, const char *&p, const char *end, double &v, std::uint64_t f)
    {
        if (m_ascii)
            return asciiValue(t, p, end, v);
        const unsigned char *b = m_in.take(bytes(t));
        if (!b)
            ended(f, m_face.count, "faces");
        v = binaryValue(t, b, m_swap);
        return true;
    }

    const char *line(std::uint64_t i, const char *what)
    {
        constexpr std::size_t kMaxLine = 64 * 1024;
        if (!m_in.line(m_line, kMaxLine)) {
            if (m_in.left() > 0 && !m_in.stopped())
                throw Decline{std::string("a ") + what + " line longer than 64 KB"};
            ended(i, what == std::string("vertex") ? m_vertex.count : m_face.count,
                  what == std::string("vertex") ? "vertices" : "faces");
        }
        return m_line.c_str();
    }

    static void trailing(const char *p, const char *end, std::uint64_t i, const char *what)
    {
        while (p < end && (*p == ' ' || *p == '\t'))
            ++p;
        if (p != end)
            throw Decline{std::string("more values than properties on ") + what + " " +
                          std::to_string(i)};
    }

    [[noreturn]] void ended(std::uint64_t i, std::uint64_t total, const char *what)
    {
        if (m_in.stopped())
            throw Ended{"stopped"};
        std::ostringstream s;
        s << "the file ends before its " << total << " " << what << " (" << i << " read)";
        throw Ended{s.str()};
    }

    Chunks &m_in;
    bool m_ascii, m_swap;
    const Element &m_vertex, &m_face;
    VertexLayout m_layout;
    FastMesh &m_mesh;
    std::string m_line;
};

// The least a file of `h`'s counts can hold: a file that claims more vertices or faces than its
// bytes can hold is refused before anything is allocated for them.
std::uint64_t leastBytes(const Header &h)
{
    const Element &v = h.elements[0], &f = h.elements[1];
    std::uint64_t vertex = 0, face = 0;
    for (const Property &p : v.properties)
        vertex += h.format == Header::Ascii ? 2 : bytes(p.type);
    for (const Property &p : f.properties)
        face += h.format == Header::Ascii ? 2 : bytes(p.list ? p.countType : p.type);
    const double total = double(v.count) * double(vertex) + double(f.count) * double(face);
    return total > 1e19 ? ~std::uint64_t(0) : std::uint64_t(total);
}

} // namespace

FastRead readPly(Assimp::IOStream &file, FastMesh &mesh, std::string &why,
                 const ReadProgress &progress)
{
    try {
        Chunks in(file, progress);
        const Header h = readHeader(in);
        if (h.elements.size() != 2 || h.elements[0].name != "vertex" ||
            h.elements[1].name != "face")
            throw Decline{"elements other than a vertex element, then a face element"};
        if (std::count_if(h.elements[1].properties.begin(), h.elements[1].properties.end(),
                          [](const Property &p) { return p.corners; }) != 1)
            throw Decline{"a face element without one list of corners"};
        if (h.elements[0].count > wire::kMaxVertices || h.elements[1].count > 0xffffffffull / 3)
            throw Decline{"more vertices or faces than 32-bit indices reach"};
        if (leastBytes(h) > in.left()) {
            std::ostringstream s;
            s << "the file ends before its " << h.elements[0].count << " vertices and "
              << h.elements[1].count << " faces (" << in.size() << " bytes: too few for them)";
            why = s.str();
            return FastRead::Failed;
        }
        Body body(in, h, mesh);
        body.vertices();
        body.faces();
        wire::MaterialRecord &m = mesh.material;
        for (int c = 0; c < 3; ++c)
            m.ka[c] = m.kd[c] = m.ks[c] = 1.0f;
        m.present = wire::kHasAmbient | wire::kHasDiffuse | wire::kHasSpecular;
        return FastRead::Read;
    } catch (const Decline &d) {
        why = d.why;
        mesh = FastMesh();
        return FastRead::Declined;
    } catch (const Body::Ended &e) {
        why = e.why;
        mesh = FastMesh();
        return FastRead::Failed;
    }
}

} // namespace lb
