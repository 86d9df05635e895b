// Binary STL as Assimp 5.2's reader makes it (code/AssetLib/STL/STLLoader.cpp): three vertices a
// facet, the facet's normal on each; a facet with bit 15 of its attribute set gives the mesh
// colours (5 bits each, blue in the low bits, or red there when the header holds "COLOR=",
// whose four bytes are then the default colour; else 0.6 grey); the material white (Kd = Ks =
// 1), or the COLOR= colour when no facet has one, with Ka 0.05.

#include "fast_mesh_readers.h"

#include <cstring>

namespace lb {

namespace {

constexpr std::size_t kHeaderBytes = 84, kFacetBytes = 50;

// Assimp's search for "COLOR=" in the 80-byte header, as it is written: each letter that
// matches moves on, so that a near miss skips the letters it matched (the default colour's
// four bytes may come from past the header).
bool materialiseColour(const unsigned char *file, float (&colour)[4])
{
    const unsigned char *p = file, *const end = file + 80;
    while (p < end) {
        if ('C' == *p++ && 'O' == *p++ && 'L' == *p++ && 'O' == *p++ && 'R' == *p++ &&
            '=' == *p++) {
            for (float &c : colour)
                c = float(*p++) * (1.0f / 255.0f);
            return true;
        }
    }
    return false;
}

} // namespace

FastRead readBinaryStl(Assimp::IOStream &file, FastMesh &mesh, std::string &why,
                       const ReadProgress &progress)
{
    Chunks in(file, progress);
    // The header, the count and enough of the first facet for Assimp's COLOR= search (which
    // can read up to 10 bytes past the header's 80).
    unsigned char head[kHeaderBytes + 6] = {};
    const std::size_t headBytes = in.size() >= sizeof head ? sizeof head : kHeaderBytes;
    if (in.size() < kHeaderBytes || !in.read(head, kHeaderBytes)) {
        why = "shorter than a binary STL header";
        return FastRead::Declined;
    }
    std::uint32_t facets = 0;
    std::memcpy(&facets, head + 80, 4);
    if (in.size() != kHeaderBytes + std::uint64_t(facets) * kFacetBytes || facets == 0) {
        why = "not a binary STL (its size is not 84 + 50 a facet), or no facets";
        return FastRead::Declined;
    }
    float defaultColour[4] = {0.6f, 0.6f, 0.6f, 0.6f};
    const unsigned char *first = in.take(headBytes - kHeaderBytes);
    if (!first) {
        why = "stopped";
        return FastRead::Failed;
    }
    std::memcpy(head + kHeaderBytes, first, headBytes - kHeaderBytes);
    const bool materialise = materialiseColour(head, defaultColour);

    const std::size_t vertices = std::size_t(facets) * 3;
    mesh.positions.resize(vertices * 3);
    mesh.normals.resize(vertices * 3);
    mesh.triangles.resize(vertices);
    bool coloured = false;
    float *position = mesh.positions.data(), *normal = mesh.normals.data();
    for (std::uint32_t f = 0; f < facets; ++f) {
        // The first facet's first bytes went to the COLOR= search: they are taken again here.
        unsigned char facet[kFacetBytes];
        const std::size_t early = f == 0 ? headBytes - kHeaderBytes : 0;
        std::memcpy(facet, head + kHeaderBytes, early);
        if (!in.read(facet + early, kFacetBytes - early)) {
            why = in.stopped() ? "stopped" : "the file ended inside its facets";
            return FastRead::Failed;
        }
        float values[12];
        std::memcpy(values, facet, sizeof values);
        for (int corner = 0; corner < 3; ++corner) {
            std::memcpy(normal, values, 3 * sizeof(float));
            std::memcpy(position, values + 3 + 3 * corner, 3 * sizeof(float));
            normal += 3;
            position += 3;
        }
        std::uint16_t attribute = 0;
        std::memcpy(&attribute, facet + 48, 2);
        if (attribute & (1u << 15)) {
            if (!coloured) {
                coloured = true;
                mesh.colors.resize(vertices * 3);
                for (std::size_t v = 0; v < vertices; ++v)
                    std::memcpy(&mesh.colors[3 * v], defaultColour, 3 * sizeof(float));
            }
            const float low = float(attribute & 0x1fu) / 31.0f,
                        mid = float((attribute >> 5) & 0x1fu) / 31.0f,
                        high = float((attribute >> 10) & 0x1fu) / 31.0f;
            const float rgb[3] = {materialise ? low : high, mid, materialise ? high : low};
            for (int corner = 0; corner < 3; ++corner)
                std::memcpy(&mesh.colors[9 * std::size_t(f) + 3 * corner], rgb, sizeof rgb);
        }
    }
    for (std::size_t v = 0; v < vertices; ++v)
        mesh.triangles[v] = std::uint32_t(v);

    wire::MaterialRecord &m = mesh.material;
    const bool materialColour = materialise && !coloured;
    for (int c = 0; c < 3; ++c) {
        m.kd[c] = m.ks[c] = materialColour ? defaultColour[c] : 1.0f;
        m.ka[c] = 0.05f;
    }
    m.present = wire::kHasAmbient | wire::kHasDiffuse | wire::kHasSpecular;
    return FastRead::Read;
}

} // namespace lb
