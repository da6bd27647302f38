#pragma once
// The element loop shared by every material: strain from nodal displacements,
// stress from the material, element internal forces into per-element storage.
//
// Each element writes only its own slots (stress, 12 force components), so the
// loop has no races; the nodes sum their elements' forces afterwards in a fixed
// order (FemModel), which makes results bitwise independent of the thread count.
// The material is a template argument (a lambda) so its stress update inlines.
#include <climits>

#include "fem/elementGeometry.hpp"
#include "fem/symTensor.hpp"

namespace rockfrac::fem {

// Displacement gradient H_ij = sum_a u_a,i dN_a/dx_j of element e.
RF_HD inline Mat3 displacementGradient(const int* nodeIds, const double* gradients,
                                       const double* displacements)
{
    Mat3 h;
    for (int a = 0; a < 4; ++a) {
        const double* u = displacements + 3 * nodeIds[a];
        const double* g = gradients + 3 * a;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) h.m[i][j] += u[i] * g[j];
    }
    return h;
}

RF_HD inline double determinant(const Mat3& a)
{
    return a.m[0][0] * (a.m[1][1] * a.m[2][2] - a.m[1][2] * a.m[2][1]) -
           a.m[0][1] * (a.m[1][0] * a.m[2][2] - a.m[1][2] * a.m[2][0]) +
           a.m[0][2] * (a.m[1][0] * a.m[2][1] - a.m[1][1] * a.m[2][0]);
}

// Internal nodal forces f_a = V sigma . grad N_a of one element.
RF_HD inline void elementInternalForces(const SymTensor& s, double volume, const double* gradients,
                                        double* forces)
{
    for (int a = 0; a < 4; ++a) {
        const double gx = gradients[3 * a], gy = gradients[3 * a + 1], gz = gradients[3 * a + 2];
        forces[3 * a] = volume * (s.xx * gx + s.xy * gy + s.zx * gz);
        forces[3 * a + 1] = volume * (s.xy * gx + s.yy * gy + s.yz * gz);
        forces[3 * a + 2] = volume * (s.zx * gx + s.yz * gy + s.zz * gz);
    }
}

struct NoElementEroded {
    bool operator()(std::size_t) const { return false; }
};

// Runs stressUpdate(e, strain) -> SymTensor over all elements (OpenMP), stores the
// stress (6 per element) and internal forces (12 per element). Returns the lowest
// index of an element that is inverted (det(I + H) <= 0) or not finite, or -1.
// An element for which eroded(e) is true has left the model: zero stress and forces,
// no stress update and no inversion check (its nodes may pass through each other).
template <class StressUpdate, class Eroded = NoElementEroded>
long long elementLoop(const ElementGeometry& geometry, const double* displacements, double* stresses,
                      double* elementForces, StressUpdate&& stressUpdate, Eroded eroded = {})
{
    const long long numElements = static_cast<long long>(geometry.numElements());
    const int* nodeIds = geometry.nodeIds.data();
    const double* gradients = geometry.gradients.data();
    const double* volumes = geometry.volumes.data();
    long long firstBad = LLONG_MAX;
#pragma omp parallel for schedule(static) reduction(min : firstBad)
    for (long long e = 0; e < numElements; ++e) {
        if (eroded(static_cast<std::size_t>(e))) {
            for (int k = 0; k < 6; ++k) stresses[6 * e + k] = 0.0;
            for (int k = 0; k < 12; ++k) elementForces[12 * e + k] = 0.0;
            continue;
        }
        Mat3 h = displacementGradient(nodeIds + 4 * e, gradients + 12 * e, displacements);
        const SymTensor strain = symmetricPart(h);
        for (int i = 0; i < 3; ++i) h.m[i][i] += 1.0;  // deformation gradient F = I + H
        if (!(determinant(h) > 0.0)) firstBad = e < firstBad ? e : firstBad;
        const SymTensor stress = stressUpdate(static_cast<std::size_t>(e), strain);
        stress.toArray(stresses + 6 * e);
        elementInternalForces(stress, volumes[e], gradients + 12 * e, elementForces + 12 * e);
    }
    return firstBad == LLONG_MAX ? -1 : firstBad;
}

}  // namespace rockfrac::fem
