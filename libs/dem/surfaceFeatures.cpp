#include "dem/surfaceFeatures.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace rockfrac {

std::vector<std::uint16_t> surfaceFeatureFlags(const std::vector<Vec3>& vertices,
                                               const std::vector<std::array<int, 3>>& triangles,
                                               double flat_tolerance)
{
    const int n = static_cast<int>(triangles.size());
    std::vector<std::uint16_t> flags(n, 0);
    // Edges by their vertex pair: the (triangle, local edge) that use each, in triangle order.
    std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> edges;
    for (int t = 0; t < n; ++t)
        for (int k = 0; k < 3; ++k) {
            const int a = triangles[t][k], b = triangles[t][(k + 1) % 3];
            edges[{std::min(a, b), std::max(a, b)}].push_back({t, k});
        }
    // Per vertex: ridge sides seen so far (bit 0: winding side, bit 1: other side).
    std::map<int, unsigned> vertex_sides;
    for (const auto& [key, users] : edges) {
        unsigned sides = 0;
        if (users.size() != 2) {
            sides = 3;  // an open rim, or a non-manifold edge: it sticks out from both sides
        } else {
            const auto& tri1 = triangles[users[0].first];
            const auto& tri2 = triangles[users[1].first];
            const Vec3 a = vertices[tri1[0]];
            const Vec3 normal1 = cross(vertices[tri1[1]] - a, vertices[tri1[2]] - a);
            // The corner of the second triangle off the shared edge.
            const int far = tri2[(users[1].second + 2) % 3];
            const Vec3 e0 = vertices[key.first], e1 = vertices[key.second];
            const Vec3 along = e1 - e0;
            const Vec3 off = vertices[far] - e0;
            const Vec3 off_edge = off - (norm2(along) > 0.0 ? dot(off, along) / norm2(along) : 0.0) * along;
            const double normal_length = norm(normal1), reach = norm(off_edge);
            if (normal_length > 0.0 && reach > 0.0) {
                const double height = dot(off, normal1) / normal_length;  // of the far corner over plane 1
                if (height < -flat_tolerance * reach) sides = 1;          // bends away from the winding side
                if (height > flat_tolerance * reach) sides = 2;
            }
        }
        if (sides == 0) continue;
        const auto [t, k] = users.front();  // the lowest-numbered triangle owns the edge
        if (sides & 1) flags[t] |= static_cast<std::uint16_t>(1u << k);
        if (sides & 2) flags[t] |= static_cast<std::uint16_t>(1u << (3 + k));
        vertex_sides[key.first] |= sides;
        vertex_sides[key.second] |= sides;
    }
    // Convex vertices on their lowest-numbered triangle.
    std::map<int, std::pair<int, int>> owner;
    for (int t = n - 1; t >= 0; --t)
        for (int k = 2; k >= 0; --k) owner[triangles[t][k]] = {t, k};
    for (const auto& [vertex, sides] : vertex_sides) {
        const auto [t, k] = owner.at(vertex);
        if (sides & 1) flags[t] |= static_cast<std::uint16_t>(1u << (6 + k));
        if (sides & 2) flags[t] |= static_cast<std::uint16_t>(1u << (9 + k));
    }
    return flags;
}

}  // namespace rockfrac
