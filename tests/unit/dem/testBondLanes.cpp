// The bond kernel's AVX2 lanes (dem/bondKernelAvx2.hpp) against the scalar kernel: on random
// interfaces with intact, softening, broken and onset-reaching bonds, interfaces of another
// rank, strength scales and partial blocks, every output, history and block sum bit for bit.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "dem/bondKernelAvx2.hpp"
#include "dem/voronoiQnscBond.hpp"

using namespace rockfrac;

namespace {

template <class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

// A random set of interfaces between rigid cells, with everything the kernel reads.
struct RandomInterfaces {
    std::vector<Vec3> position, velocity, omega, normal_i, normal_j, nodes;
    std::vector<Mat3> rotation;
    std::vector<int> cell_i, cell_j, bond_offset, node_offset, slot;
    std::vector<double> length_i, length_j, area, beta, scale;
    std::vector<std::uint16_t> node_i, node_j;
    std::vector<unsigned char> stage, counted;
    std::vector<BondSoftening> softening;

    RandomInterfaces(unsigned seed, int n_cells, int n_interfaces, double onset_share)
    {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u(-1.0, 1.0), unit(0.0, 1.0);
        auto vec = [&](double s) { return Vec3{s * u(rng), s * u(rng), s * u(rng)}; };
        for (int c = 0; c < n_cells; ++c) {
            position.push_back(vec(1e-2));
            velocity.push_back(vec(0.5));
            omega.push_back(vec(200.0));
            Quat q{u(rng), u(rng), u(rng), u(rng)};
            rotation.push_back(rotationMatrix(normalised(q)));
            node_offset.push_back(static_cast<int>(nodes.size()));
            const int n = 6 + static_cast<int>(unit(rng) * 25);
            for (int i = 0; i < n; ++i) nodes.push_back(vec(1e-3));
        }
        node_offset.push_back(static_cast<int>(nodes.size()));
        int pool = 0;
        for (int k = 0; k < n_interfaces; ++k) {
            const int ci = k * n_cells / n_interfaces;  // sorted by the first cell, as the model
            int cj = static_cast<int>(unit(rng) * n_cells) % n_cells;
            if (cj == ci) cj = (ci + 1) % n_cells;
            cell_i.push_back(ci);
            cell_j.push_back(cj);
            normal_i.push_back(normalised(vec(1.0)));
            normal_j.push_back(normalised(vec(1.0)));
            length_i.push_back(4e-4 + 2e-4 * unit(rng));
            length_j.push_back(4e-4 + 2e-4 * unit(rng));
            area.push_back(1e-7 * (0.5 + unit(rng)));
            beta.push_back(1e-7 * unit(rng));
            // Most interfaces far from their onset, some at the law's own strengths.
            scale.push_back(unit(rng) < onset_share ? 1.0 : 1e6 * (0.5 + unit(rng)));
            counted.push_back(unit(rng) < 0.9 ? 1 : 0);
            bond_offset.push_back(static_cast<int>(stage.size()));
            const int n_bonds = 1 + static_cast<int>(unit(rng) * 9);
            const int ni = node_offset[ci + 1] - node_offset[ci], nj = node_offset[cj + 1] - node_offset[cj];
            bool softening_here = false;
            for (int b = 0; b < n_bonds; ++b) {
                node_i.push_back(static_cast<std::uint16_t>(unit(rng) * ni) % ni);
                node_j.push_back(static_cast<std::uint16_t>(unit(rng) * nj) % nj);
                const double r = unit(rng);
                stage.push_back(r < 0.06 ? bondBroken : r < 0.09 ? bondSoftening : bondElastic);
                softening_here = softening_here || stage.back() == bondSoftening;
            }
            // Softening interfaces and a share of the others own a slot; the rest wait for one.
            const bool has_slot = softening_here || unit(rng) < 0.5;
            slot.push_back(has_slot ? pool : -1);
            if (has_slot) pool += n_bonds;
        }
        bond_offset.push_back(static_cast<int>(stage.size()));
        softening.resize(pool);
        for (BondSoftening& s : softening) {
            s.onset_displacement = 1e-6 * (0.5 + unit(rng));
            s.onset_stress = 1e7;
            s.rupture_displacement = 1e-4;
            s.max_displacement = s.onset_displacement;
            s.damage = 0.3 * unit(rng);
        }
        // Softening bonds of an interface without a slot are elastic (the model's invariant).
        for (int k = 0; k < n_interfaces; ++k)
            if (slot[k] < 0)
                for (int b = bond_offset[k]; b < bond_offset[k + 1]; ++b)
                    if (stage[b] == bondSoftening) stage[b] = bondElastic;
    }
};

// What one kernel run writes.
struct Outputs {
    std::vector<Vec3> force, torque_i, torque_j;
    std::vector<int> intact;
    std::vector<unsigned char> stage;
    std::vector<BondSoftening> softening;
    std::vector<BondBlockSums> blocks;
};

Outputs run(const RandomInterfaces& r, const VoronoiQnscLaw::Coefficients& c, bool lanes, bool scaled,
            bool decomposed, int block_size)
{
    const int n = static_cast<int>(r.cell_i.size());
    Outputs o;
    o.force.assign(n, Vec3{-1.0, -1.0, -1.0});
    o.torque_i = o.torque_j = o.force;
    o.intact.assign(n, -7);
    o.stage = r.stage;
    o.softening = r.softening;
    o.blocks.assign((n + block_size - 1) / block_size, BondBlockSums{});
    BondKernelArgs a;
    a.n_interfaces = n;
    a.block_size = block_size;
    a.position = r.position.data();
    a.velocity = r.velocity.data();
    a.angular_velocity_world = r.omega.data();
    a.rotation = r.rotation.data();
    a.cell_i = r.cell_i.data();
    a.cell_j = r.cell_j.data();
    a.bond_offset = r.bond_offset.data();
    a.normal_i_body = r.normal_i.data();
    a.normal_j_body = r.normal_j.data();
    a.length_i = r.length_i.data();
    a.length_j = r.length_j.data();
    a.bond_area = r.area.data();
    a.damping_beta = r.beta.data();
    a.strength_scale = scaled ? r.scale.data() : nullptr;
    a.softening_slot = r.slot.data();
    a.intact_bonds = o.intact.data();
    a.force_on_i = o.force.data();
    a.torque_on_i = o.torque_i.data();
    a.torque_on_j = o.torque_j.data();
    a.anchor_node_offset = r.node_offset.data();
    a.anchor_nodes = r.nodes.data();
    a.node_i = r.node_i.data();
    a.node_j = r.node_j.data();
    a.stage = o.stage.data();
    a.softening = o.softening.data();
    a.block_sums = o.blocks.data();
    a.counted = decomposed ? r.counted.data() : nullptr;
    if (lanes)
        runVoronoiQnscBondLanes(a, c);
    else
        runBondKernel<VoronoiQnscLaw>(a, c);
    return o;
}

// Every output of the two kernels' runs, bit for bit.
void checkSameOutputs(const Outputs& s, const Outputs& v)
{
    CHECK(sameBits(s.force, v.force));
    CHECK(sameBits(s.torque_i, v.torque_i));
    CHECK(sameBits(s.torque_j, v.torque_j));
    CHECK(sameBits(s.intact, v.intact));
    CHECK(sameBits(s.stage, v.stage));
    CHECK(std::memcmp(s.softening.data(), v.softening.data(), s.softening.size() * sizeof(BondSoftening)) ==
          0);
    CHECK(std::memcmp(s.blocks.data(), v.blocks.data(), s.blocks.size() * sizeof(BondBlockSums)) == 0);
}

VoronoiQnscLaw::Coefficients granite()
{
    VoronoiQnscLaw::Coefficients c;
    c.normal_modulus = 6.0e10;
    c.shear_modulus = 2.3e10;
    c.tensile_strength = 1.2e7;
    c.cohesion = 3.0e7;
    c.friction = 0.6;
    c.fracture_energy_I = 10.0;
    c.fracture_energy_II = 40.0;
    c.bk_exponent = 2.0;
    c.rupture_tolerance = 1e-6;
    return c;
}

}  // namespace

TEST_CASE("bond lanes give the scalar kernel's results bit for bit", "[bond][lanes]")
{
    if (!bondLanesEnabled()) {
        WARN("this CPU has no AVX2 (or ROCKFRAC_BOND_KERNEL=scalar): the lanes are not used");
        return;
    }
    const VoronoiQnscLaw::Coefficients c = granite();
    for (const unsigned seed : {1u, 2u, 3u}) {
        const RandomInterfaces r(seed, 61, 603, 0.08);
        for (const bool scaled : {true, false})
            for (const bool decomposed : {false, true})
                for (const int block_size : {16, 256}) {
                    INFO("seed " << seed << ", scaled " << scaled << ", decomposed " << decomposed
                                 << ", block " << block_size);
                    const Outputs s = run(r, c, false, scaled, decomposed, block_size);
                    const Outputs v = run(r, c, true, scaled, decomposed, block_size);
                    checkSameOutputs(s, v);
                    // Both paths were taken: intact interfaces summed with forces, and interfaces
                    // the lanes handed back (onsets, softening bonds, pending slots).
                    int summed = 0, pending = 0, broken_now = 0;
                    for (std::size_t k = 0; k < s.intact.size(); ++k)
                        summed += s.intact[k] > 0 && norm2(s.force[k]) > 0.0;
                    for (const BondBlockSums& b : s.blocks) {
                        pending += b.pending_onsets;
                        broken_now += b.bonds_broken_now;
                    }
                    CHECK(summed > 100);
                    if (scaled) {
                        CHECK(pending > 5);
                        CHECK(broken_now + pending > 10);
                    }
                }
    }
}

TEST_CASE("bond lanes: far from any onset, the scalar kernel's forces, torques and energies", "[bond][lanes]")
{
    if (!bondLanesEnabled()) return;
    VoronoiQnscLaw::Coefficients c = granite();
    c.tensile_strength = 1e20;
    c.cohesion = 1e20;
    const RandomInterfaces r(9, 40, 257, 0.0);
    const Outputs s = run(r, c, false, false, false, 64);
    const Outputs v = run(r, c, true, false, false, 64);
    CHECK(sameBits(s.force, v.force));
    CHECK(sameBits(s.torque_i, v.torque_i));
    CHECK(sameBits(s.torque_j, v.torque_j));
    CHECK(sameBits(s.intact, v.intact));
    CHECK(std::memcmp(s.blocks.data(), v.blocks.data(), s.blocks.size() * sizeof(BondBlockSums)) == 0);
    double energy = 0.0;
    for (const BondBlockSums& b : v.blocks) energy += b.strain_energy;
    CHECK(energy > 0.0);
}
