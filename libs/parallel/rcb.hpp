#pragma once
// Weighted recursive coordinate bisection (RCB; Berger and Bokhari 1987, the method of Zoltan's
// RCB and of exaDEM's load balancer): the items (cells, by their centroids) are cut by planes
// normal to a coordinate axis, recursively, until there are as many parts as subdomains; each
// cut splits the weight of its items in the ratio of the parts on either side, so a part count
// need not be a power of two.
//
// Deterministic: the items are ordered by (coordinate, index), the cut axis is the longest
// extent of the items' bounding box (the lowest axis on a tie), and a cut is placed half-way
// between two distinct coordinates, so the tree also answers "which part owns this point" for
// a point that was not one of the items (a cell that has moved: migration).
#include <vector>

#include "core/vec3.hpp"

namespace rockfrac {

struct RcbNode {
    int axis = -1;          // 0, 1, 2: x, y, z; -1 for a leaf
    double position = 0.0;  // the cut: coordinate < position goes to `below`, else `above`
    int below = -1;         // child node indices; -1 for a leaf
    int above = -1;
    int part = -1;  // a leaf's part (subdomain) number; -1 for a cut
};

struct RcbDecomposition {
    std::vector<int> part_of;    // per item: its part, 0 .. n_parts - 1
    std::vector<RcbNode> nodes;  // the cut tree, root first
    int n_parts = 0;

    // The part that owns point p (the tree's leaf p falls in). For an item, part_of.
    int partOf(const Vec3& p) const;
};

// Splits `points` (weights[i] > 0 and finite, one per point) into `n_parts` parts.
// Throws UserError when n_parts < 1 or exceeds the number of points, when a weight is not
// positive and finite, or when the points cannot be cut (fewer distinct points than parts).
RcbDecomposition rcbDecompose(const std::vector<Vec3>& points, const std::vector<double>& weights,
                              int n_parts);

// The weight of each part and the imbalance max / mean - 1 (0 when perfectly balanced).
struct PartBalance {
    std::vector<double> weight;
    std::vector<int> items;
    double imbalance = 0.0;
};
PartBalance partBalance(const std::vector<int>& part_of, const std::vector<double>& weights, int n_parts);

}  // namespace rockfrac
