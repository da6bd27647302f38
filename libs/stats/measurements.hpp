#pragma once
// Measured data of a laboratory series: the `measurements` dictionary of
// docs/file-formats.md, "Measured data", with its optional force–displacement
// curves (.dat files). Every physical quantity carries a dimension set, so a
// value in kN or mm cannot slip in unnoticed.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "stats/descriptive.hpp"

namespace rockfrac {
class Dictionary;
}

namespace rockfrac::stats {

struct SpecimenGeometry {
    std::optional<double> diameter;            // [m] disc
    std::optional<double> thickness;           // [m] disc
    std::optional<double> volume;              // [m^3] rock
    std::optional<double> equivalentDiameter;  // [m] rock, (6V/π)^(1/3)
};

struct ForceDisplacementCurve {
    std::filesystem::path file;
    std::vector<double> displacement;  // [m]
    std::vector<double> force;         // [N], compression positive
};

struct Specimen {
    std::string id;
    double failureLoad = 0.0;               // [N]
    std::optional<double> tensileStrength;  // [Pa]
    std::optional<int> cells;               // DEM cell count (Table 7), for reference
    SpecimenGeometry geometry;
    std::optional<ForceDisplacementCurve> curve;
};

struct MeasurementSet {
    std::filesystem::path file;
    std::string test;       // e.g. "BDT", "" when not given
    std::string material;   // e.g. "granite"
    std::string reference;  // where the data come from
    std::vector<Specimen> specimens;

    Sample failureLoads() const;
    std::string label() const;  // "measured granite BDT"
};

// Read and check a measurements dictionary: UserError (file:line:column and
// what to do) on a missing or negative failure load, a missing or wrong
// dimension set, no specimens, or a curve file that is empty, lacks a column,
// has a wrong unit or a negative force.
MeasurementSet readMeasurements(const std::filesystem::path& path);
// The same for a dictionary already parsed from `path` (curve files are read
// relative to its directory); the measurements fuzz target calls this.
MeasurementSet readMeasurements(const Dictionary& dict, const std::filesystem::path& path);

// Read a force–displacement curve: columns `displacement [m]` and `force [N]`.
ForceDisplacementCurve readForceDisplacementCurve(const std::filesystem::path& path);

}  // namespace rockfrac::stats
