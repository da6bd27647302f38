#include "dem/bondKernelAvx2.hpp"

#include <cstdlib>
#include <cstring>
#include <vector>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace rockfrac {

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__CUDACC__)
#define RF_BOND_LANES 1
#endif

bool bondLanesEnabled()
{
#ifdef RF_BOND_LANES
    static const bool enabled = [] {
        const char* kernel = std::getenv("ROCKFRAC_BOND_KERNEL");
        if (kernel && std::strcmp(kernel, "scalar") == 0) return false;
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") != 0;
    }();
    return enabled;
#else
    return false;
#endif
}

#ifdef RF_BOND_LANES

#pragma GCC push_options
#pragma GCC target("avx2")

namespace {

constexpr int kLanes = 4;

// What a lane without an interface or a live bond reads: finite, and summed as zero.
const Mat3 no_rotation{};
const Vec3 no_vector{};

// Four doubles and a four-lane mask (all bits set = true). Only AVX2, never FMA: every
// product and sum is rounded as the scalar kernel rounds it.
typedef double V4 __attribute__((vector_size(32), aligned(32)));
typedef long long M4 __attribute__((vector_size(32), aligned(32)));

struct V3 {
    V4 x, y, z;
};

inline __attribute__((always_inline)) V4 keep(V4 v, M4 mask)
{
    return reinterpret_cast<V4>(reinterpret_cast<M4>(v) & mask);
}

// Mat3 * Vec3, dot and cross as in core/vec3.hpp, in the same order of operations.
inline __attribute__((always_inline)) V3 rotate(const V4* r, const V3& v)
{
    return {r[0] * v.x + r[1] * v.y + r[2] * v.z, r[3] * v.x + r[4] * v.y + r[5] * v.z,
            r[6] * v.x + r[7] * v.y + r[8] * v.z};
}

inline __attribute__((always_inline)) V3 cross3(const V3& a, const V3& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

inline __attribute__((always_inline)) V4 dot3(const V3& a, const V3& b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

// What the lanes need of their interfaces: the per-interface half of bondInterfaceKernel,
// computed with the same operations in the same order (so the same values).
struct LaneBatch {
    V4 rotation_i[9], rotation_j[9];
    V3 x_i, x_j, v_i, v_j, w_i, w_j, normal;
    V4 length, inverse_length, shear_stiffness;  // k_t / l (the D = 0 bond)
    V4 area, beta_kn, beta_kt, half_area, damping_scale, tensile_strength, cohesion;
    const Vec3* nodes_i[kLanes];
    const Vec3* nodes_j[kLanes];
    int first[kLanes], count[kLanes];
    bool fallback[kLanes];  // handed to the scalar kernel
};

inline __attribute__((always_inline)) __m256i addresses(const void* const* p)
{
    return _mm256_set_epi64x(reinterpret_cast<long long>(p[3]), reinterpret_cast<long long>(p[2]),
                             reinterpret_cast<long long>(p[1]), reinterpret_cast<long long>(p[0]));
}

// The d-th double at each of the four addresses.
inline __attribute__((always_inline)) V4 gather(__m256i at, int d)
{
    const double* origin = nullptr;
    return _mm256_i64gather_pd(origin + d, at, 1);
}

inline __attribute__((always_inline)) V3 gather3(__m256i at)
{
    return {gather(at, 0), gather(at, 1), gather(at, 2)};
}

// The per-interface doubles of the four lanes' interfaces.
inline __attribute__((always_inline)) V4 gatherInterfaces(const double* p, __m128i k)
{
    const __m256d all = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
    return _mm256_mask_i32gather_pd(_mm256_setzero_pd(), p, k, all, 8);
}

// Lane l < n takes interface ks[l] (every one of another rank's is left out before).
void setUpBatch(const BondKernelArgs& a, const VoronoiQnscLaw::Coefficients& m, const int* ks, int n,
                LaneBatch& batch)
{
    const void* rotation_i[kLanes];
    const void* rotation_j[kLanes];
    const void* state_i[3][kLanes];
    const void* state_j[3][kLanes];
    const void* body_normal_i[kLanes];
    const void* body_normal_j[kLanes];
    alignas(16) int interface[kLanes];
    for (int l = 0; l < kLanes; ++l) {
        const int k = l < n ? ks[l] : ks[0];
        interface[l] = k;
        batch.fallback[l] = false;
        batch.count[l] = 0;
        rotation_i[l] = rotation_j[l] = &no_rotation;
        body_normal_i[l] = body_normal_j[l] = &no_vector;
        for (int s = 0; s < 3; ++s) state_i[s][l] = state_j[s][l] = &no_vector;
        if (l >= n) continue;  // count 0: no bond step takes it
        const int ci = a.cell_i[k], cj = a.cell_j[k];
        rotation_i[l] = a.rotation + ci;
        rotation_j[l] = a.rotation + cj;
        state_i[0][l] = a.position + ci;
        state_j[0][l] = a.position + cj;
        state_i[1][l] = a.velocity + ci;
        state_j[1][l] = a.velocity + cj;
        state_i[2][l] = a.angular_velocity_world + ci;
        state_j[2][l] = a.angular_velocity_world + cj;
        body_normal_i[l] = a.normal_i_body + k;
        body_normal_j[l] = a.normal_j_body + k;
        batch.nodes_i[l] = a.anchor_nodes + a.anchor_node_offset[ci];
        batch.nodes_j[l] = a.anchor_nodes + a.anchor_node_offset[cj];
        batch.first[l] = a.bond_offset[k];
        batch.count[l] = a.bond_offset[k + 1] - a.bond_offset[k];
    }
    const __m256i at_ri = addresses(rotation_i), at_rj = addresses(rotation_j);
    for (int e = 0; e < 9; ++e) {
        batch.rotation_i[e] = gather(at_ri, e);
        batch.rotation_j[e] = gather(at_rj, e);
    }
    batch.x_i = gather3(addresses(state_i[0]));
    batch.x_j = gather3(addresses(state_j[0]));
    batch.v_i = gather3(addresses(state_i[1]));
    batch.v_j = gather3(addresses(state_j[1]));
    batch.w_i = gather3(addresses(state_i[2]));
    batch.w_j = gather3(addresses(state_j[2]));
    // normalised(Ri n_i - Rj n_j): the zero vector stays zero.
    const V3 ni = rotate(batch.rotation_i, gather3(addresses(body_normal_i)));
    const V3 nj = rotate(batch.rotation_j, gather3(addresses(body_normal_j)));
    const V3 d{ni.x - nj.x, ni.y - nj.y, ni.z - nj.z};
    const V4 size = _mm256_sqrt_pd(dot3(d, d)), zero{};
    const M4 nonzero = size > zero;
    batch.normal = {nonzero ? d.x / size : zero, nonzero ? d.y / size : zero, nonzero ? d.z / size : zero};
    const __m128i k = _mm_load_si128(reinterpret_cast<const __m128i*>(interface));
    const V4 length = gatherInterfaces(a.length_i, k) + gatherInterfaces(a.length_j, k);
    const V4 area = gatherInterfaces(a.bond_area, k), beta = gatherInterfaces(a.damping_beta, k);
    batch.length = length;
    batch.inverse_length = 1.0 / length;
    // elasticBondResponse at D = 0: (1 - 0) k_t / l, beta k_n, beta k_t, A / 2, A beta l.
    batch.shear_stiffness = (1.0 - 0.0) * m.shear_modulus * batch.inverse_length;
    batch.area = area;
    batch.beta_kn = beta * m.normal_modulus;
    batch.beta_kt = beta * m.shear_modulus;
    batch.half_area = 0.5 * area;
    batch.damping_scale = area * beta * length;
    // VoronoiQnscLaw::scaleStrength: sigma-bar and C times the interface's factor.
    const V4 strength{m.tensile_strength, m.tensile_strength, m.tensile_strength, m.tensile_strength};
    const V4 cohesion{m.cohesion, m.cohesion, m.cohesion, m.cohesion};
    if (a.strength_scale) {
        const V4 factor = gatherInterfaces(a.strength_scale, k);
        batch.tensile_strength = strength * factor;
        batch.cohesion = cohesion * factor;
    } else {
        batch.tensile_strength = strength;
        batch.cohesion = cohesion;
    }
}

struct LaneSums {
    V3 force{}, torque_i{}, torque_j{};
    V4 strain_energy{}, damping_power{};
    M4 intact{};
};

// The anchor nodes of bond step t of every lane, fetched by AVX2 gathers from each lane's
// node (a zero node for a lane without a live bond); false when no lane has one. A softening
// bond hands its lane to the scalar kernel; a broken one is skipped (mask 0).
bool gatherNodes(const BondKernelArgs& a, LaneBatch& batch, int t, V3& node_i, V3& node_j, M4& live)
{
    const void* at_i[kLanes];
    const void* at_j[kLanes];
    alignas(32) long long lanes[kLanes];
    bool any = false;
    for (int l = 0; l < kLanes; ++l) {
        const Vec3* p = &no_vector;
        const Vec3* q = &no_vector;
        lanes[l] = 0;
        if (t < batch.count[l] && !batch.fallback[l]) {
            const int b = batch.first[l] + t;
            const unsigned char stage = a.stage[b];
            if (stage == bondElastic) {
                p = batch.nodes_i[l] + a.node_i[b];
                q = batch.nodes_j[l] + a.node_j[b];
                lanes[l] = -1;
                any = true;
            } else if (stage != bondBroken) {
                batch.fallback[l] = true;
            }
        }
        at_i[l] = p;
        at_j[l] = q;
    }
    if (!any) return false;
    node_i = gather3(addresses(at_i));
    node_j = gather3(addresses(at_j));
    std::memcpy(&live, lanes, sizeof live);
    return true;
}

// Bond step t of the four lanes: kinematics, the QNSC onset test, the elastic response of
// Eqs. 5-8 and 18-20 (D = 0), and the sums. A lane whose bond reaches its onset falls back.
void bondStep(const BondKernelArgs& a, const VoronoiQnscLaw::Coefficients& m, LaneBatch& batch, int t,
              LaneSums& sums)
{
    V3 node_i, node_j;
    M4 live;
    if (!gatherNodes(a, batch, t, node_i, node_j, live)) return;

    const V3 arm_i = rotate(batch.rotation_i, node_i);
    const V3 arm_j = rotate(batch.rotation_j, node_j);
    const V3 xi = batch.x_i, xj = batch.x_j;
    const V3 opening{(xj.x + arm_j.x) - (xi.x + arm_i.x), (xj.y + arm_j.y) - (xi.y + arm_i.y),
                     (xj.z + arm_j.z) - (xi.z + arm_i.z)};
    const V3 turn_i = cross3(batch.w_i, arm_i), turn_j = cross3(batch.w_j, arm_j);
    const V3 vi = batch.v_i, vj = batch.v_j;
    const V3 velocity{(vj.x + turn_j.x) - (vi.x + turn_i.x), (vj.y + turn_j.y) - (vi.y + turn_i.y),
                      (vj.z + turn_j.z) - (vi.z + turn_i.z)};
    const V3 n = batch.normal;
    const V4 l = batch.length, inverse_l = batch.inverse_length;

    // VoronoiQnscLaw::evaluate: trial stresses and the onset test (onsetReached).
    const V4 normal_opening = dot3(opening, n);
    const V3 shear_opening{opening.x - normal_opening * n.x, opening.y - normal_opening * n.y,
                           opening.z - normal_opening * n.z};
    const V4 shear_opening2 = dot3(shear_opening, shear_opening);
    const V4 sigma = m.normal_modulus * normal_opening * inverse_l;
    const V4 tau2 = m.shear_modulus * m.shear_modulus * shear_opening2 * inverse_l * inverse_l;
    const V4 zero{0.0, 0.0, 0.0, 0.0};
    const V4 shear_strength = batch.cohesion - m.friction * sigma;
    const V4 tensile = sigma > zero ? sigma / batch.tensile_strength : zero;
    const M4 onset =
        (shear_strength <= zero) | (tau2 >= (1.0 - tensile * tensile) * shear_strength * shear_strength);
    const M4 onset_live = onset & live;
    if (_mm256_movemask_pd(reinterpret_cast<__m256d>(onset_live)))
        for (int lane = 0; lane < kLanes; ++lane)
            if (onset_live[lane]) batch.fallback[lane] = true;
    const M4 elastic = live & ~onset;

    // elasticBondResponse with D = 0 (sigma is the trial stress in tension and compression).
    const V4 stiffness_t = batch.shear_stiffness;
    const V3 shear_stress{shear_opening.x * stiffness_t, shear_opening.y * stiffness_t,
                          shear_opening.z * stiffness_t};
    const V4 normal_rate = dot3(velocity, n) * inverse_l;
    const V4 along = normal_rate * l;
    const V3 shear_rate{(velocity.x - along * n.x) * inverse_l, (velocity.y - along * n.y) * inverse_l,
                        (velocity.z - along * n.z) * inverse_l};
    const V4 normal_traction = sigma + batch.beta_kn * normal_rate;
    const V4 beta_kt = batch.beta_kt, area = batch.area;
    const V3 force{((n.x * normal_traction + shear_stress.x) + shear_rate.x * beta_kt) * area,
                   ((n.y * normal_traction + shear_stress.y) + shear_rate.y * beta_kt) * area,
                   ((n.z * normal_traction + shear_stress.z) + shear_rate.z * beta_kt) * area};
    const V4 strain_energy = batch.half_area * (sigma * normal_opening + dot3(shear_stress, shear_opening));
    const V4 damping_power = batch.damping_scale * (m.normal_modulus * normal_rate * normal_rate +
                                                    m.shear_modulus * dot3(shear_rate, shear_rate));

    // The sums, bond by bond in each lane (a skipped bond adds +0, which changes no sum: none is -0).
    const V3 f{keep(force.x, elastic), keep(force.y, elastic), keep(force.z, elastic)};
    const V3 ti = cross3(arm_i, f), tj = cross3(arm_j, f);
    sums.strain_energy += keep(strain_energy, elastic);
    sums.damping_power += keep(damping_power, elastic);
    sums.force.x += f.x;
    sums.force.y += f.y;
    sums.force.z += f.z;
    sums.torque_i.x += keep(ti.x, elastic);
    sums.torque_i.y += keep(ti.y, elastic);
    sums.torque_i.z += keep(ti.z, elastic);
    sums.torque_j.x -= keep(tj.x, elastic);
    sums.torque_j.y -= keep(tj.y, elastic);
    sums.torque_j.z -= keep(tj.z, elastic);
    sums.intact -= elastic;  // a true lane is -1
}

// What the lanes leave of an interface for the block's sums, added in interface order after.
struct InterfaceSums {
    double strain_energy, damping_power;
    bool fallback;
};

// Interfaces ks[0 .. n-1] (n <= 4): the outputs of those that stay in the lanes, and what
// the block's sums need of each (results[k - begin], begin the block's first interface).
void runBatch(const BondKernelArgs& a, const VoronoiQnscLaw::Coefficients& m, const int* ks, int n,
              InterfaceSums* results, int begin)
{
    LaneBatch batch;
    setUpBatch(a, m, ks, n, batch);
    int steps = 0;
    for (int l = 0; l < kLanes; ++l) steps = batch.count[l] > steps ? batch.count[l] : steps;
    LaneSums sums;
    for (int t = 0; t < steps; ++t) bondStep(a, m, batch, t, sums);
    for (int l = 0; l < n; ++l) {
        const int k = ks[l];
        InterfaceSums& r = results[k - begin];
        r.fallback = batch.fallback[l];
        if (r.fallback) continue;
        r.strain_energy = sums.strain_energy[l];
        r.damping_power = sums.damping_power[l];
        a.intact_bonds[k] = static_cast<int>(sums.intact[l]);
        a.force_on_i[k] = {sums.force.x[l], sums.force.y[l], sums.force.z[l]};
        a.torque_on_i[k] = {sums.torque_i.x[l], sums.torque_i.y[l], sums.torque_i.z[l]};
        a.torque_on_j[k] = {sums.torque_j.x[l], sums.torque_j.y[l], sums.torque_j.z[l]};
    }
}

// The block's interfaces in batches of equal bond counts (a lane idles while another lane's
// interface has bonds left): a stable counting sort by count, another rank's left out.
constexpr int kCountClasses = 32;

void orderByBondCount(const BondKernelArgs& a, int begin, int end, std::vector<int>& order)
{
    int start[kCountClasses + 1] = {};
    auto countClass = [&](int k) {
        const int n = a.bond_offset[k + 1] - a.bond_offset[k];
        return n < kCountClasses - 1 ? n : kCountClasses - 1;
    };
    for (int k = begin; k < end; ++k)
        if (!a.counted || a.counted[k]) ++start[countClass(k) + 1];
    for (int c = 0; c < kCountClasses; ++c) start[c + 1] += start[c];
    order.resize(start[kCountClasses]);
    for (int k = begin; k < end; ++k)
        if (!a.counted || a.counted[k]) order[start[countClass(k)]++] = k;
}

void runBlock(const BondKernelArgs& a, const VoronoiQnscLaw::Coefficients& m, int block)
{
    thread_local std::vector<int> order;
    thread_local std::vector<InterfaceSums> results;
    const int begin = block * a.block_size;
    const int end = a.n_interfaces < begin + a.block_size ? a.n_interfaces : begin + a.block_size;
    orderByBondCount(a, begin, end, order);
    const int n = static_cast<int>(order.size());
    results.resize(end - begin);
    for (int p = 0; p < n; p += kLanes) {
        // The next batch's second cells, as the scalar loop does two interfaces ahead.
        for (int ahead = p + kLanes; ahead < p + 2 * kLanes && ahead < n; ++ahead)
            prefetchInterface(a, order[ahead]);
        runBatch(a, m, order.data() + p, n - p < kLanes ? n - p : kLanes, results.data(), begin);
    }
    // The block's sums in interface order, the scalar kernel taking the lanes' fallbacks.
    BondBlockSums sums;
    for (int k = begin; k < end; ++k) {
        if (a.counted && !a.counted[k]) continue;  // another rank's
        const InterfaceSums& r = results[k - begin];
        if (r.fallback) {
            voronoiQnscInterfaceScalar(a, m, k, sums);
            continue;
        }
        BondBlockSums interface;
        interface.strain_energy = r.strain_energy;
        interface.damping_power = r.damping_power;
        sums.add(interface);
    }
    a.block_sums[block] = sums;
}

}  // namespace

void runVoronoiQnscBondLanes(const BondKernelArgs& a, const VoronoiQnscLaw::Coefficients& m)
{
    const int n_blocks = (a.n_interfaces + a.block_size - 1) / a.block_size;
#pragma omp parallel for schedule(static) if (n_blocks > 1)
    for (int block = 0; block < n_blocks; ++block) runBlock(a, m, block);
}

#pragma GCC pop_options

#else  // no AVX2 lanes on this target

void runVoronoiQnscBondLanes(const BondKernelArgs& a, const VoronoiQnscLaw::Coefficients& c)
{
    runBondKernel<VoronoiQnscLaw>(a, c);
}

#endif

}  // namespace rockfrac
