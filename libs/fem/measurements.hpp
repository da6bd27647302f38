#pragma once
// Measurements taken from a running FemModel: the virtual extensometer of the
// paper's BDT calibration and the failure-load detector.
#include <array>

#include "fem/femModel.hpp"

namespace rockfrac::fem {

// A material point located in the reference mesh: its tet and barycentric weights.
struct MaterialPoint {
    int tet = -1;
    std::array<double, 4> weights{};
};

// Locates a point in the reference configuration (UserError if outside the mesh).
MaterialPoint locateMaterialPoint(const TetMesh& mesh, const Vec3& point);
// Displacement of a located point interpolated with the linear shape functions.
Vec3 interpolateDisplacement(const TetMesh& mesh, const std::vector<double>& displacements,
                             const MaterialPoint& point);

// Two material points at centre -/+ (length/2) axis; the reading is the change of
// their distance along the axis (positive = elongation), as the paper's l = 20 mm
// extensometer along the loading diameter of the Brazilian disc.
class VirtualExtensometer {
public:
    VirtualExtensometer(const TetMesh& mesh, const Vec3& centre, const Vec3& axis, double length);
    double elongation(const FemModel& model) const;
    double length() const { return length_; }

private:
    Vec3 axis_;
    double length_;
    MaterialPoint first_, second_;
};

// Proposed failure-load criterion (docs/theory.md): the failure load is the running
// maximum force at the first drop of more than dropFraction of it (e.g. 0.2), the
// "first notable force drop" of the SPB experiments.
class FailureLoadDetector {
public:
    explicit FailureLoadDetector(double dropFraction) : dropFraction_(dropFraction) {}
    // Feed forces in time order; returns true once failure has been detected.
    bool update(double force);
    bool failed() const { return failed_; }
    double failureLoad() const { return failed_ ? maximum_ : 0.0; }
    double maximum() const { return maximum_; }

private:
    double dropFraction_;
    double maximum_ = 0.0;
    bool failed_ = false;
};

}  // namespace rockfrac::fem
