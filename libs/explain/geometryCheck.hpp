#pragma once
// The set-up check before any fit (docs/explainGap.md, "Geometry check"): the specimens'
// dimensions, where the measurements give them (diameter, thickness, volume,
// equivalentDiameter, per specimen or in the file's 'geometry' defaults), against the
// model case's (constant/geometryProperties, written by meshRock in the prepared template).
// A mismatch is an error of the set-up, not a physical effect: a disc 8 % smaller than the
// model's would otherwise be absorbed by a small strength shift.
#include <filesystem>
#include <string>
#include <vector>

#include "stats/measurements.hpp"

namespace rockfrac::explain {

// A relative difference of the median measured dimension from the model's beyond this is
// a mismatch.
constexpr double geometryTolerance = 0.03;

struct GeometryComparison {
    std::string quantity;   // "diameter", "thickness", "volume", "equivalentDiameter"
    std::string unit;       // "m" or "m^3"
    double measured = 0.0;  // median over the specimens that give it
    int specimens = 0;
    double model = 0.0;
    double relative = 0.0;  // measured / model - 1
    bool mismatch = false;  // |relative| > geometryTolerance
};

// Every dimension both the measurements and the model case's geometryProperties file give;
// empty when the measurements give none or the file does not exist.
std::vector<GeometryComparison> compareGeometry(const stats::MeasurementSet& measurements,
                                                const std::filesystem::path& geometryProperties);

// "diameter 41.2 mm (median of 8 specimens) against the model's 44.8 mm: -8 %".
std::string describeComparison(const GeometryComparison& c);

}  // namespace rockfrac::explain
