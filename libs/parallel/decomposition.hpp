#pragma once
// Domain decomposition of a DEM case (docs/models/decomposition/): system/decomposeParDict,
// the decomposition methods (a run-time selection table, core/selector.hpp), and the halo a
// decomposition implies: which cells a subdomain must see as ghosts and which interfaces
// cross between subdomains. The figures the MPI run's communication and the performance
// model start from (docs/benchmarks.md "Decomposition").
//
//     numberOfSubdomains  4;
//     method              rcb;     // weighted recursive coordinate bisection
//     weights             cost;    // cost: 1 + the items of the cell; uniform: 1 per cell
//     imbalanceTolerance  0.2;     // optional: re-balance when the imbalance grows by this
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/dictionary.hpp"
#include "core/selector.hpp"
#include "core/vec3.hpp"

namespace rockfrac {

// A way of splitting cells (centroids with weights) into subdomains.
class DecompositionMethod {
public:
    virtual ~DecompositionMethod() = default;
    virtual const char* type() const = 0;
    // part_of[i] in [0, n_parts) for every point; deterministic in its inputs.
    virtual std::vector<int> decompose(const std::vector<Vec3>& points, const std::vector<double>& weights,
                                       int n_parts) const = 0;
};

const Selector<DecompositionMethod>& decompositionMethods();

struct DecomposeParameters {
    int n_subdomains = 1;
    std::shared_ptr<const DecompositionMethod> method;
    bool cost_weights = true;  // weights cost (true) or uniform (false)
    // A decomposed run cuts its cells anew when the ranks' cost imbalance (largest / mean - 1)
    // grows past the one after the last cut by more than this (imbalanceTolerance, default 0.2).
    double imbalance_tolerance = 0.2;
};

// Reads and checks <case>/system/decomposeParDict; a UserError naming the file and line of
// any missing, out-of-range or unknown entry.
DecomposeParameters readDecomposeParDict(const std::filesystem::path& caseDir);
DecomposeParameters readDecomposeParameters(const Dictionary& dict);
// The entries of system/decomposeParDict (an unknown one is an error, also without -strict).
const std::vector<std::string>& decomposeParDictEntries();

// The halo of a decomposition. A cell j of another subdomain is a ghost of subdomain p when
// some cell i of p lies within reach_i + reach_j + margin of it (centroid distance): the
// cells p must know to compute every bond and contact of its own cells. An interface whose
// two cells lie in different subdomains is cut: its force crosses between them.
struct SubdomainHalo {
    int cells = 0;
    double weight = 0.0;
    int ghost_cells = 0;     // cells of other subdomains this one must see
    int cut_interfaces = 0;  // interfaces with one cell here and one elsewhere
    int neighbours = 0;      // subdomains it exchanges ghosts with
};
struct HaloReport {
    std::vector<SubdomainHalo> subdomains;
    double imbalance = 0.0;   // max weight / mean weight - 1
    long ghost_cells = 0;     // summed over subdomains
    long cut_interfaces = 0;  // counted once
};
HaloReport haloReport(const std::vector<Vec3>& centroids, const std::vector<double>& reach,
                      const std::vector<double>& weights, const std::vector<std::pair<int, int>>& interfaces,
                      const std::vector<int>& part_of, int n_parts, double margin);

}  // namespace rockfrac
