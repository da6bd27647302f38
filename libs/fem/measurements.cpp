#include "fem/measurements.hpp"

#include <limits>
#include <sstream>

#include "core/error.hpp"

namespace rockfrac::fem {

namespace {

// Barycentric coordinates of p in tet t (they sum to one).
std::array<double, 4> barycentric(const TetMesh& mesh, const std::array<int, 4>& t, const Vec3& p)
{
    const Vec3 &a = mesh.nodes[t[0]], &b = mesh.nodes[t[1]], &c = mesh.nodes[t[2]], &d = mesh.nodes[t[3]];
    const double volume = tetSignedVolume(a, b, c, d);
    const double w1 = tetSignedVolume(a, p, c, d) / volume;
    const double w2 = tetSignedVolume(a, b, p, d) / volume;
    const double w3 = tetSignedVolume(a, b, c, p) / volume;
    return {1.0 - w1 - w2 - w3, w1, w2, w3};
}

}  // namespace

MaterialPoint locateMaterialPoint(const TetMesh& mesh, const Vec3& point)
{
    // The tet whose most negative barycentric weight is largest: the containing tet,
    // or, for points on faces and edges, one of the tets sharing them.
    MaterialPoint best;
    double bestWorst = -std::numeric_limits<double>::infinity();
    for (std::size_t e = 0; e < mesh.numTets(); ++e) {
        const auto w = barycentric(mesh, mesh.tets[e], point);
        const double worst = std::min(std::min(w[0], w[1]), std::min(w[2], w[3]));
        if (worst > bestWorst) bestWorst = worst, best = {static_cast<int>(e), w};
    }
    constexpr double tolerance = 1e-9;
    if (bestWorst < -tolerance) {
        std::ostringstream s;
        s << "the point (" << point.x << " " << point.y << " " << point.z << ") lies outside the mesh";
        throw UserError(s.str());
    }
    return best;
}

Vec3 interpolateDisplacement(const TetMesh& mesh, const std::vector<double>& displacements,
                             const MaterialPoint& point)
{
    Vec3 u;
    for (int a = 0; a < 4; ++a) {
        const double* ua = &displacements[3 * static_cast<std::size_t>(mesh.tets[point.tet][a])];
        u += point.weights[a] * Vec3{ua[0], ua[1], ua[2]};
    }
    return u;
}

VirtualExtensometer::VirtualExtensometer(const TetMesh& mesh, const Vec3& centre, const Vec3& axis,
                                         double length)
    : axis_(normalised(axis)), length_(length)
{
    if (!(length > 0.0) || !(norm(axis) > 0.0))
        throw UserError("extensometer: the length and the axis must be non-zero");
    first_ = locateMaterialPoint(mesh, centre - 0.5 * length * axis_);
    second_ = locateMaterialPoint(mesh, centre + 0.5 * length * axis_);
}

double VirtualExtensometer::elongation(const FemModel& model) const
{
    const auto& u = model.state().displacements;
    return dot(
        interpolateDisplacement(model.mesh(), u, second_) - interpolateDisplacement(model.mesh(), u, first_),
        axis_);
}

bool FailureLoadDetector::update(double force)
{
    if (failed_) return true;
    if (force > maximum_) maximum_ = force;
    if (maximum_ > 0.0 && force < (1.0 - dropFraction_) * maximum_) failed_ = true;
    return failed_;
}

}  // namespace rockfrac::fem
