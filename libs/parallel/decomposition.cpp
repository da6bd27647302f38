#include "parallel/decomposition.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>

#include "core/error.hpp"
#include "parallel/rcb.hpp"

namespace rockfrac {

namespace {

class RcbMethod final : public DecompositionMethod {
public:
    explicit RcbMethod(const Dictionary& coefficients) { requireKnownEntries(coefficients, {}); }
    const char* type() const override { return "rcb"; }
    std::vector<int> decompose(const std::vector<Vec3>& points, const std::vector<double>& weights,
                               int n_parts) const override
    {
        return rcbDecompose(points, weights, n_parts).part_of;
    }
};

std::unique_ptr<DecompositionMethod> makeRcb(const Dictionary& coefficients)
{
    return std::make_unique<RcbMethod>(coefficients);
}

}  // namespace

const Selector<DecompositionMethod>& decompositionMethods()
{
    static const Selector<DecompositionMethod> table("decomposition method", {
                                                                                 {"rcb", &makeRcb, true},
                                                                             });
    return table;
}

const std::vector<std::string>& decomposeParDictEntries()
{
    static const std::vector<std::string> entries = {"numberOfSubdomains", "method", "weights", "rcb",
                                                     "imbalanceTolerance"};
    return entries;
}

DecomposeParameters readDecomposeParameters(const Dictionary& dict)
{
    requireKnownEntries(dict, decomposeParDictEntries());
    DecomposeParameters p;
    const double n = dict.getScalar("numberOfSubdomains", Bounds::closed(1, 1 << 20));
    if (n != std::floor(n))
        throw UserError(dict.location("numberOfSubdomains").str() +
                        ": numberOfSubdomains must be a whole number (got " + formatNumber(n) + ")");
    p.n_subdomains = static_cast<int>(n);
    p.method = decompositionMethods().select(dict, "method");
    p.cost_weights = dict.getWord("weights", {"cost", "uniform"}) == "cost";
    p.imbalance_tolerance =
        dict.getScalarOrDefault("imbalanceTolerance", p.imbalance_tolerance, Bounds::closed(0.0, 100.0));
    return p;
}

DecomposeParameters readDecomposeParDict(const std::filesystem::path& caseDir)
{
    const std::filesystem::path file = caseDir / "system" / "decomposeParDict";
    if (!std::filesystem::exists(file))
        throw UserError(file.string() +
                        ": not found; a parallel run reads numberOfSubdomains, method and "
                        "weights from it (docs/models/decomposition/rcb.md shows one)");
    return readDecomposeParameters(Dictionary::readFile(file));
}

HaloReport haloReport(const std::vector<Vec3>& centroids, const std::vector<double>& reach,
                      const std::vector<double>& weights, const std::vector<std::pair<int, int>>& interfaces,
                      const std::vector<int>& part_of, int n_parts, double margin)
{
    const int n = static_cast<int>(centroids.size());
    HaloReport r;
    r.subdomains.assign(n_parts, {});
    const PartBalance balance = partBalance(part_of, weights, n_parts);
    for (int p = 0; p < n_parts; ++p) {
        r.subdomains[p].cells = balance.items[p];
        r.subdomains[p].weight = balance.weight[p];
    }
    r.imbalance = balance.imbalance;

    for (const auto& [a, b] : interfaces)
        if (part_of[a] != part_of[b]) {
            r.subdomains[part_of[a]].cut_interfaces += 1;
            r.subdomains[part_of[b]].cut_interfaces += 1;
            r.cut_interfaces += 1;
        }
    if (n == 0) return r;

    // Bin the centroids in a grid of spacing 2 max(reach) + margin: every pair within reach
    // lies in the same or a neighbouring bin.
    const double max_reach = *std::max_element(reach.begin(), reach.end());
    const double h = 2.0 * max_reach + margin;
    Vec3 lo = centroids[0];
    for (const Vec3& c : centroids)
        for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], c[d]);
    auto binOf = [&](const Vec3& c) {
        return std::array<long, 3>{static_cast<long>(std::floor((c.x - lo.x) / h)),
                                   static_cast<long>(std::floor((c.y - lo.y) / h)),
                                   static_cast<long>(std::floor((c.z - lo.z) / h))};
    };
    std::map<std::array<long, 3>, std::vector<int>> bins;
    for (int i = 0; i < n; ++i) bins[binOf(centroids[i])].push_back(i);

    std::vector<std::uint64_t> ghosts;  // (part << 32) | cell, the cell a ghost of the part
    for (const auto& [key, members] : bins)
        for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy)
                for (long dz = -1; dz <= 1; ++dz) {
                    const auto other = bins.find({key[0] + dx, key[1] + dy, key[2] + dz});
                    if (other == bins.end()) continue;
                    for (int i : members)
                        for (int j : other->second) {
                            if (part_of[i] == part_of[j]) continue;
                            const Vec3 d = centroids[j] - centroids[i];
                            const double range = reach[i] + reach[j] + margin;
                            if (dot(d, d) <= range * range)
                                ghosts.push_back((static_cast<std::uint64_t>(part_of[i]) << 32) |
                                                 static_cast<std::uint32_t>(j));
                        }
                }
    std::sort(ghosts.begin(), ghosts.end());
    ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());
    std::vector<std::set<int>> neighbours(n_parts);
    for (std::uint64_t g : ghosts) {
        const int p = static_cast<int>(g >> 32);
        const int cell = static_cast<int>(g & 0xffffffffu);
        r.subdomains[p].ghost_cells += 1;
        neighbours[p].insert(part_of[cell]);
    }
    r.ghost_cells = static_cast<long>(ghosts.size());
    for (int p = 0; p < n_parts; ++p) r.subdomains[p].neighbours = static_cast<int>(neighbours[p].size());
    return r;
}

}  // namespace rockfrac
