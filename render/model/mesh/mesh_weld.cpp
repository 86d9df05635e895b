#include "mesh_weld.h"

#include "parallel_for.h"

#include <algorithm>
#include <cstring>
#include <thread>

namespace lb {

namespace {

std::uint64_t positionHash(const glm::vec3 &p)
{
    auto bits = [](float f) {
        std::uint32_t u;
        f = f == 0.0f ? 0.0f : f; // -0 welds with 0
        std::memcpy(&u, &f, sizeof u);
        return u;
    };
    std::uint64_t h = bits(p.x) * 0x9E3779B97F4A7C15ull;
    h ^= (h >> 29) + bits(p.y) * 0xBF58476D1CE4E5B9ull;
    h ^= (h >> 31) + bits(p.z) * 0x94D049BB133111EBull;
    return h ^ (h >> 32);
}

// The weld of the vertices `take` accepts (in index order, so that the first at a position is
// the lowest index), by open addressing in a table of at least twice as many slots as they are.
template <typename Take, typename Hash>
void weldSome(const std::vector<glm::vec3> &positions, std::size_t taken, Take &&take, Hash &&hash,
              std::vector<std::uint32_t> &first)
{
    std::size_t capacity = 16;
    while (capacity < 2 * taken)
        capacity *= 2;
    constexpr std::uint32_t kEmpty = 0xffffffffu;
    std::vector<std::uint32_t> table(capacity, kEmpty);
    for (std::size_t v = 0; v < positions.size(); ++v) {
        if (!take(v))
            continue;
        const glm::vec3 &p = positions[v];
        for (std::size_t slot = hash(v) & (capacity - 1);; slot = (slot + 1) & (capacity - 1)) {
            if (table[slot] == kEmpty) {
                table[slot] = std::uint32_t(v);
                first[v] = std::uint32_t(v);
                break;
            }
            if (positions[table[slot]] == p) {
                first[v] = table[slot];
                break;
            }
        }
    }
}

} // namespace

std::vector<std::uint32_t> weldPositions(const std::vector<glm::vec3> &positions)
{
    const std::size_t n = positions.size();
    std::vector<std::uint32_t> first(n);
    // Big meshes: the positions split by their hash's top bits into one table a core, each
    // welded on its own thread (the same position always lands in the same table). Each thread
    // reads every hash but probes only its own table: the probes, random in memory, are the cost.
    const std::size_t parts =
        n < 500'000 ? 1 : std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 8);
    if (parts == 1) {
        weldSome(
            positions, n, [](std::size_t) { return true; },
            [&](std::size_t v) { return positionHash(positions[v]); }, first);
        return first;
    }
    std::vector<std::uint64_t> hashes(n);
    std::vector<std::vector<std::size_t>> counts(parts, std::vector<std::size_t>(parts, 0));
    auto partOf = [parts](std::uint64_t h) { return std::size_t((h >> 40) % parts); };
    parallelFor(n, parts, [&](std::size_t begin, std::size_t end, std::size_t slice) {
        for (std::size_t v = begin; v < end; ++v) {
            hashes[v] = positionHash(positions[v]);
            ++counts[slice][partOf(hashes[v])];
        }
    });
    parallelFor(parts, parts, [&](std::size_t part, std::size_t, std::size_t) {
        std::size_t taken = 0;
        for (const std::vector<std::size_t> &c : counts)
            taken += c[part];
        weldSome(
            positions, taken, [&](std::size_t v) { return partOf(hashes[v]) == part; },
            [&](std::size_t v) { return hashes[v]; }, first);
    });
    return first;
}

const std::vector<std::uint32_t> &givenOrOwnWeld(const std::vector<glm::vec3> &positions,
                                                 const std::vector<std::uint32_t> *given,
                                                 std::vector<std::uint32_t> &own)
{
    if (given && given->size() == positions.size())
        return *given;
    own = weldPositions(positions);
    return own;
}

} // namespace lb
