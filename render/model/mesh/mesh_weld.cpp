#include "mesh_weld.h"

#include <cstring>

namespace lb {

std::vector<std::uint32_t> weldPositions(const std::vector<glm::vec3> &positions)
{
    const std::size_t n = positions.size();
    std::size_t capacity = 16;
    while (capacity < 2 * n)
        capacity *= 2;
    constexpr std::uint32_t kEmpty = 0xffffffffu;
    std::vector<std::uint32_t> table(capacity, kEmpty);
    std::vector<std::uint32_t> first(n);
    auto bits = [](float f) {
        std::uint32_t u;
        f = f == 0.0f ? 0.0f : f;
        std::memcpy(&u, &f, sizeof u);
        return u;
    };
    for (std::size_t v = 0; v < n; ++v) {
        const glm::vec3 &p = positions[v];
        std::uint64_t h = bits(p.x) * 0x9E3779B97F4A7C15ull;
        h ^= (h >> 29) + bits(p.y) * 0xBF58476D1CE4E5B9ull;
        h ^= (h >> 31) + bits(p.z) * 0x94D049BB133111EBull;
        h ^= h >> 32;
        for (std::size_t slot = h & (capacity - 1);; slot = (slot + 1) & (capacity - 1)) {
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
