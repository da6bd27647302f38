// DemModel: the stable time step (bonds and contacts) and the step check that splits steps.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>

#include "dem/demModel.hpp"

namespace rockfrac {

namespace {

// Linearised bond system: generalised displacement per cell (translation u, world;
// rotation theta, world), bond stiffness K_b = (A/n)/l (k_n n n^T + k_t (1 - n n^T))
// acting on the relative displacement of the anchor points.
struct BondSystem {
    const CellArrays& cells;
    const InterfaceArrays& faces;
    const BondStorage& bonds;
    double normal_modulus, shear_modulus;  // k_n, k_t [Pa]
    std::vector<Mat3> rotation;

    // (fu, ftheta) = K x (the gradient of the bond energy); x^T K_k x per interface in energy.
    void apply(const std::vector<Vec3>& u, const std::vector<Vec3>& theta, std::vector<Vec3>& fu,
               std::vector<Vec3>& ftheta, std::vector<double>* energy) const
    {
        const int n = cells.size();
        fu.assign(n, Vec3{});
        ftheta.assign(n, Vec3{});
        if (energy) energy->assign(faces.size(), 0.0);
        for (int k = 0; k < faces.size(); ++k) {
            const int i = faces.cell_i[k], j = faces.cell_j[k];
            const Vec3 normal = normalised(rotation[i] * faces.normal_i[k] - rotation[j] * faces.normal_j[k]);
            const double scale = faces.bond_area[k] / (faces.length_i[k] + faces.length_j[k]);
            for (int b = faces.bond_offset[k]; b < faces.bond_offset[k + 1]; ++b) {
                if (bonds.stage[b] == bondBroken) continue;
                const Vec3 ri =
                    rotation[i] * cells.anchor_nodes[cells.anchor_node_offset[i] + bonds.node_i[b]];
                const Vec3 rj =
                    rotation[j] * cells.anchor_nodes[cells.anchor_node_offset[j] + bonds.node_j[b]];
                const Vec3 d = (u[j] + cross(theta[j], rj)) - (u[i] + cross(theta[i], ri));
                const double dn = dot(d, normal);
                const Vec3 f =
                    scale * (normal_modulus * dn * normal + shear_modulus * (d - dn * normal));  // K_b d
                fu[j] += f;
                ftheta[j] += cross(rj, f);
                fu[i] -= f;
                ftheta[i] -= cross(ri, f);
                if (energy) (*energy)[k] += dot(d, f);
            }
        }
    }
};

}  // namespace

CriticalTimeStep DemModel::criticalTimeStep() const
{
    CriticalTimeStep result;
    const int n = cells_.size();
    const BondLawModel& law = *parameters_.bond_law;
    BondSystem system{cells_, interfaces_, bonds_, law.normalModulus(), law.shearModulus(), {}};
    system.rotation.resize(n);
    for (int c = 0; c < n; ++c) system.rotation[c] = rotationMatrix(cells_.orientation[c]);
    // World inverse inertia R I^-1 R^T applied to a vector.
    auto inverseInertia = [&](int c, const Vec3& v) {
        const Vec3 body = transposeTimes(system.rotation[c], v);
        const Vec3 I = cells_.principal_inertia[c];
        return system.rotation[c] * Vec3{body.x / I.x, body.y / I.y, body.z / I.z};
    };
    auto inertiaTimes = [&](int c, const Vec3& v) {
        const Vec3 body = transposeTimes(system.rotation[c], v);
        const Vec3 I = cells_.principal_inertia[c];
        return system.rotation[c] * Vec3{body.x * I.x, body.y * I.y, body.z * I.z};
    };

    // Gershgorin bounds of the translation and rotation blocks, per cell (undamped).
    std::vector<double> row_u(n, 0.0), row_theta(n, 0.0);
    for (int k = 0; k < interfaces_.size(); ++k) {
        const int i = interfaces_.cell_i[k], j = interfaces_.cell_j[k];
        const double stiffness = law.normalModulus() * interfaces_.bond_area[k] /
                                 (interfaces_.length_i[k] + interfaces_.length_j[k]);
        const double mi = cells_.mass[i], mj = cells_.mass[j];
        const Vec3 Ii = cells_.principal_inertia[i], Ij = cells_.principal_inertia[j];
        const double ii = std::min({Ii.x, Ii.y, Ii.z}), ij = std::min({Ij.x, Ij.y, Ij.z});
        for (int b = interfaces_.bond_offset[k]; b < interfaces_.bond_offset[k + 1]; ++b) {
            if (bonds_.stage[b] == bondBroken) continue;
            const double ri = norm(cells_.anchor_nodes[cells_.anchor_node_offset[i] + bonds_.node_i[b]]);
            const double rj = norm(cells_.anchor_nodes[cells_.anchor_node_offset[j] + bonds_.node_j[b]]);
            row_u[i] += stiffness * (1.0 / mi + 1.0 / std::sqrt(mi * mj));
            row_u[j] += stiffness * (1.0 / mj + 1.0 / std::sqrt(mi * mj));
            row_theta[i] += stiffness * (ri * ri / ii + ri * rj / std::sqrt(ii * ij));
            row_theta[j] += stiffness * (rj * rj / ij + ri * rj / std::sqrt(ii * ij));
        }
    }
    const double largest_u = n > 0 ? *std::max_element(row_u.begin(), row_u.end()) : 0.0;
    const double largest_theta = n > 0 ? *std::max_element(row_theta.begin(), row_theta.end()) : 0.0;
    result.bond_translation_bound = largest_u > 0.0 ? 2.0 / std::sqrt(largest_u) : 1e300;
    result.bond_rotation_bound = largest_theta > 0.0 ? 2.0 / std::sqrt(largest_theta) : 1e300;

    // Power iteration on M^-1 K (M-normalised), deterministic start vector.
    std::vector<Vec3> u(n), theta(n), fu, ftheta;
    std::uint64_t state = 88172645463325252ULL;
    auto random = [&]() {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        return double(state >> 11) / double(1ULL << 53) - 0.5;
    };
    for (int c = 0; c < n; ++c) {
        u[c] = {random(), random(), random()};
        theta[c] = Vec3{random(), random(), random()} * (1.0 / std::max(cells_.bounding_radius[c], 1e-300));
    }
    auto massNorm2 = [&]() {
        double sum = 0.0;
        for (int c = 0; c < n; ++c)
            sum += cells_.mass[c] * norm2(u[c]) + dot(theta[c], inertiaTimes(c, theta[c]));
        return sum;
    };
    double lambda = 0.0;
    std::vector<double> energy;
    const int iterations = 400;
    for (int it = 0; it < iterations && largest_u + largest_theta > 0.0; ++it) {
        const double scale = 1.0 / std::sqrt(massNorm2());
        for (int c = 0; c < n; ++c) {
            u[c] *= scale;
            theta[c] *= scale;
        }
        system.apply(u, theta, fu, ftheta, it + 1 == iterations ? &energy : nullptr);
        // Rayleigh quotient x^T K x / x^T M x (x is M-normalised).
        double quotient = 0.0;
        for (int c = 0; c < n; ++c) quotient += dot(u[c], fu[c]) + dot(theta[c], ftheta[c]);
        lambda = quotient;
        for (int c = 0; c < n; ++c) {
            u[c] = (1.0 / cells_.mass[c]) * fu[c];
            theta[c] = inverseInertia(c, ftheta[c]);
        }
    }
    if (lambda > 0.0) {
        result.bond_frequency = std::sqrt(lambda);
        // Damping ratio of that mode: C = sum_k beta_k K_k, zeta = omega/2 sum beta_k e_k / sum e_k.
        double weighted = 0.0, total = 0.0;
        for (int k = 0; k < interfaces_.size(); ++k) {
            weighted += interfaces_.damping_beta[k] * energy[k];
            total += energy[k];
        }
        const double beta = total > 0.0 ? weighted / total : 0.0;
        const double zeta = 0.5 * beta * result.bond_frequency;
        result.bond_damping_ratio = zeta;
        result.bond = 2.0 * (std::sqrt(1.0 + zeta * zeta) - zeta) / result.bond_frequency;
    } else {
        result.bond = 1e300;
    }

    // Contacts: a rock–steel Hertz contact at an overlap of 0.1 r_d on the lightest cell,
    // acting at its bounding radius (translation and rotation), with its restitution damping.
    double contact_omega2 = 0.0;
    for (int c = 0; c < n; ++c) {
        const double r = cells_.dilation_radius[c];
        const double stiffness = 2.0 * std::max(rock_steel_.effective_modulus, rock_rock_.effective_modulus) *
                                 std::sqrt(r * 0.1 * r);
        contact_omega2 = std::max(
            contact_omega2, contactFrequency2(stiffness, 0.0, cells_.mass[c], cells_.principal_inertia[c],
                                              cells_.bounding_radius[c]));
    }
    const double contact_zeta = contactDampingRatio();
    result.contact =
        contact_omega2 > 0.0
            ? 2.0 * (std::sqrt(1.0 + contact_zeta * contact_zeta) - contact_zeta) / std::sqrt(contact_omega2)
            : 1e300;
    result.value = std::min(result.bond, result.contact);
    return result;
}

std::string stepCheckSummary(const DemCounters& counters)
{
    std::ostringstream line;
    line << "Step check: " << counters.split_steps << " step(s) split into substeps";
    if (counters.split_steps > 0)
        line << " (" << counters.substeps << " substeps, at most " << counters.most_substeps
             << " in one step): contacts stiffened a cell beyond the step";
    return line.str();
}

void DemModel::setStepLimit(double fraction, double bond_frequency, double bond_damping_ratio)
{
    if (!(fraction >= 0.0) || !(bond_frequency >= 0.0) || !(bond_damping_ratio >= 0.0))
        throw std::invalid_argument("DemModel::setStepLimit: negative or NaN argument");
    step_limit_.fraction = fraction;
    step_limit_.bond_frequency2 = bond_frequency * bond_frequency;
    step_limit_.bond_damping_ratio = bond_damping_ratio;
    step_limit_.contact_damping_ratio = contactDampingRatio();
}

// Damping ratio of the stiffer-damped contact pairing, sqrt(5/6) |beta_e| (restitution).
double DemModel::contactDampingRatio() const
{
    return std::sqrt(5.0 / 6.0) *
           std::fabs(std::min(rock_steel_.restitution_beta, rock_rock_.restitution_beta));
}

double DemModel::currentCriticalStep() const
{
    // The larger of the bonds' frequency and the stiffest cell's contact bound: the bound
    // (a trace, gatherCellForces) exceeds the cell's highest contact mode (5.5x in omega^2
    // for a box cell's face pressed flat on a plate), which stands in for the bonds' share
    // that the sum would add; the sum split nearly every step of the Brazilian disc test,
    // whose runs are stable (docs/theory-dem.md §2).
    const double omega2 = std::max(step_limit_.bond_frequency2, max_contact_frequency2_);
    if (step_limit_.fraction <= 0.0 || !(omega2 > 0.0)) return 1e300;
    const double zeta = max_contact_frequency2_ > step_limit_.bond_frequency2
                            ? step_limit_.contact_damping_ratio
                            : step_limit_.bond_damping_ratio;
    return 2.0 * (std::sqrt(1.0 + zeta * zeta) - zeta) / std::sqrt(omega2);
}

int DemModel::substepsNeeded(double dt) const
{
    if (step_limit_.fraction <= 0.0) return 1;
    const double parts = std::ceil(dt / (step_limit_.fraction * currentCriticalStep()));
    return parts <= 1.0 ? 1 : static_cast<int>(std::min<double>(parts, max_substeps));
}

}  // namespace rockfrac
