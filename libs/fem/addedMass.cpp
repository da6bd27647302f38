#include "fem/addedMass.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "fem/femModel.hpp"

namespace rockfrac::fem {

namespace {

double median(std::vector<double> values)
{
    if (values.empty()) return 0.0;
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

}  // namespace

AddedMassSummary summariseAddedMass(const FemModel& model, double density)
{
    const ElementGeometry& geometry = model.geometry();
    const std::vector<double>& elementDensity = model.elementDensities();
    AddedMassSummary s;
    s.fraction = model.addedMassFraction();
    s.elements = geometry.numElements();
    std::vector<char> onSurface(model.mesh().numNodes(), 0);
    for (int node : model.contactNodes()) onSurface[node] = 1;
    auto centre = [&](std::size_t e) {
        Vec3 c;
        for (int a = 0; a < 4; ++a) c = c + 0.25 * model.mesh().nodes[geometry.nodeIds[4 * e + a]];
        return c;
    };
    std::vector<double> scaledHeights;
    double added = 0.0, addedOnSurface = 0.0;
    Vec3 moment;
    for (std::size_t e = 0; e < s.elements; ++e) {
        const double extra = (elementDensity[e] - density) * geometry.volumes[e];
        if (!(extra > 0.0)) continue;
        ++s.scaledElements;
        scaledHeights.push_back(geometry.heights[e]);
        moment = moment + extra * centre(e);
        added += extra;
        int surfaceNodes = 0;
        for (int a = 0; a < 4; ++a) surfaceNodes += onSurface[geometry.nodeIds[4 * e + a]];
        if (surfaceNodes >= 3) addedOnSurface += extra;
    }
    if (added > 0.0) {
        s.centroid = (1.0 / added) * moment;
        s.surfaceShare = addedOnSurface / added;
    }
    if (s.elements > 0) {
        const auto smallest = std::min_element(geometry.heights.begin(), geometry.heights.end());
        s.smallestHeight = *smallest;
        s.smallestAt = centre(static_cast<std::size_t>(smallest - geometry.heights.begin()));
    }
    s.medianHeight = median(geometry.heights);
    s.scaledMedianHeight = median(std::move(scaledHeights));
    return s;
}

std::string addedMassWarning(const AddedMassSummary& s, double massScalingTimeStep, double limit)
{
    if (!(s.fraction > limit)) return "";
    char line[1200];
    std::snprintf(
        line, sizeof(line),
        "Warning: mass scaling adds %.3g %% to the rock's mass (more than %.0f %%): %zu of %zu elements are "
        "below the %.3g s step target, %.0f %% of the added mass in elements with a face on the surface, "
        "centred at (%.4g %.4g %.4g) mm; their median smallest altitude %.3g mm against %.3g mm over the "
        "mesh, the smallest %.3g mm at (%.4g %.4g %.4g) mm; the run's inertia is not the rock's: coarsen the "
        "mesh (elementSize in system/feMeshDict), simplify the surface (fewer, larger hull facets: a "
        "decimated or smoothed scan) or lower massScalingTimeStep in system/controlDict",
        100.0 * s.fraction, 100.0 * limit, s.scaledElements, s.elements, massScalingTimeStep,
        100.0 * s.surfaceShare, 1e3 * s.centroid.x, 1e3 * s.centroid.y, 1e3 * s.centroid.z,
        1e3 * s.scaledMedianHeight, 1e3 * s.medianHeight, 1e3 * s.smallestHeight, 1e3 * s.smallestAt.x,
        1e3 * s.smallestAt.y, 1e3 * s.smallestAt.z);
    return line;
}

}  // namespace rockfrac::fem
