#include "parallel/rcb.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "core/error.hpp"

namespace rockfrac {

namespace {

struct Builder {
    const std::vector<Vec3>& points;
    const std::vector<double>& weights;
    RcbDecomposition& result;

    // Sorts `items` by (coordinate on `axis`, index) and returns the cut index k (items[0..k)
    // below, items[k..) above) whose weight below is nearest `target`, with items[k - 1] and
    // items[k] at distinct coordinates and at least `min_below` / `min_above` items on each
    // side; -1 when no such cut exists on this axis.
    int bestCut(std::vector<int>& items, int axis, double target, int min_below, int min_above) const
    {
        std::sort(items.begin(), items.end(), [&](int a, int b) {
            const double ca = points[a][axis], cb = points[b][axis];
            return ca < cb || (ca == cb && a < b);
        });
        const int n = static_cast<int>(items.size());
        int best = -1;
        double best_miss = 0.0;
        double below = 0.0;
        for (int k = 1; k < n; ++k) {
            below += weights[items[k - 1]];
            if (k < min_below || n - k < min_above) continue;
            if (!(points[items[k - 1]][axis] < points[items[k]][axis])) continue;
            const double miss = std::fabs(below - target);
            if (best < 0 || miss < best_miss) {
                best = k;
                best_miss = miss;
            }
        }
        return best;
    }

    int build(std::vector<int> items, int first_part, int n_parts)
    {
        const int node = static_cast<int>(result.nodes.size());
        result.nodes.emplace_back();
        if (n_parts == 1) {
            result.nodes[node].part = first_part;
            for (int i : items) result.part_of[i] = first_part;
            return node;
        }
        Vec3 lo = points[items[0]], hi = lo;
        double total = 0.0;
        for (int i : items) {
            for (int d = 0; d < 3; ++d) {
                lo[d] = std::min(lo[d], points[i][d]);
                hi[d] = std::max(hi[d], points[i][d]);
            }
            total += weights[i];
        }
        const int parts_below = n_parts / 2;
        const double target = total * parts_below / n_parts;
        // Axes by decreasing extent (stable: the lower axis first on a tie).
        int axes[3] = {0, 1, 2};
        std::stable_sort(axes, axes + 3, [&](int a, int b) { return hi[a] - lo[a] > hi[b] - lo[b]; });
        int axis = -1, k = -1;
        for (int a : axes) {
            k = bestCut(items, a, target, parts_below, n_parts - parts_below);
            if (k > 0) {
                axis = a;
                break;
            }
        }
        if (axis < 0)
            throw UserError("recursive coordinate bisection: " + std::to_string(items.size()) +
                            " items cannot be cut into " + std::to_string(n_parts) +
                            " parts (too few distinct positions); use fewer subdomains");
        const double position = 0.5 * (points[items[k - 1]][axis] + points[items[k]][axis]);
        std::vector<int> below(items.begin(), items.begin() + k), above(items.begin() + k, items.end());
        items.clear();
        items.shrink_to_fit();
        const int child_below = build(std::move(below), first_part, parts_below);
        const int child_above = build(std::move(above), first_part + parts_below, n_parts - parts_below);
        RcbNode& n = result.nodes[node];
        n.axis = axis;
        n.position = position;
        n.below = child_below;
        n.above = child_above;
        return node;
    }
};

}  // namespace

int RcbDecomposition::partOf(const Vec3& p) const
{
    int node = 0;
    while (nodes[node].part < 0)
        node = p[nodes[node].axis] < nodes[node].position ? nodes[node].below : nodes[node].above;
    return nodes[node].part;
}

RcbDecomposition rcbDecompose(const std::vector<Vec3>& points, const std::vector<double>& weights,
                              int n_parts)
{
    const std::size_t n = points.size();
    if (weights.size() != n)
        throw UserError("recursive coordinate bisection: " + std::to_string(weights.size()) +
                        " weights for " + std::to_string(n) + " items");
    if (n_parts < 1 || static_cast<std::size_t>(n_parts) > n)
        throw UserError("recursive coordinate bisection: cannot cut " + std::to_string(n) + " items into " +
                        std::to_string(n_parts) + " parts; numberOfSubdomains must be in [1, " +
                        std::to_string(n) + "]");
    for (std::size_t i = 0; i < n; ++i) {
        if (!(weights[i] > 0.0) || !std::isfinite(weights[i]))
            throw UserError("recursive coordinate bisection: item " + std::to_string(i) + " has weight " +
                            std::to_string(weights[i]) + "; every weight must be positive and finite");
        for (int d = 0; d < 3; ++d)
            if (!std::isfinite(points[i][d]))
                throw UserError("recursive coordinate bisection: item " + std::to_string(i) +
                                " has a non-finite position");
    }
    RcbDecomposition result;
    result.n_parts = n_parts;
    result.part_of.assign(n, -1);
    std::vector<int> items(n);
    std::iota(items.begin(), items.end(), 0);
    Builder{points, weights, result}.build(std::move(items), 0, n_parts);
    return result;
}

PartBalance partBalance(const std::vector<int>& part_of, const std::vector<double>& weights, int n_parts)
{
    PartBalance b;
    b.weight.assign(n_parts, 0.0);
    b.items.assign(n_parts, 0);
    double total = 0.0;
    for (std::size_t i = 0; i < part_of.size(); ++i) {
        b.weight[part_of[i]] += weights[i];
        b.items[part_of[i]] += 1;
        total += weights[i];
    }
    const double mean = total / n_parts;
    b.imbalance = mean > 0.0 ? *std::max_element(b.weight.begin(), b.weight.end()) / mean - 1.0 : 0.0;
    return b;
}

}  // namespace rockfrac
