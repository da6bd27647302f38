#pragma once
// Symmetric second-order tensors (strain, stress) for the element kernels.
//
// Six tensor components in the order xx, yy, zz, xy, yz, zx (tensor shear
// components, not engineering strains). Plain functions over a small struct so
// the same code runs on host and device (RF_HD).
#include <cmath>

#include "core/vec3.hpp"

namespace rockfrac::fem {

struct SymTensor {
    double xx = 0, yy = 0, zz = 0, xy = 0, yz = 0, zx = 0;

    RF_HD static SymTensor fromArray(const double* v) { return {v[0], v[1], v[2], v[3], v[4], v[5]}; }
    RF_HD void toArray(double* v) const { v[0] = xx, v[1] = yy, v[2] = zz, v[3] = xy, v[4] = yz, v[5] = zx; }
    RF_HD static SymTensor isotropic(double s) { return {s, s, s, 0, 0, 0}; }
};

RF_HD inline SymTensor operator+(const SymTensor& a, const SymTensor& b)
{
    return {a.xx + b.xx, a.yy + b.yy, a.zz + b.zz, a.xy + b.xy, a.yz + b.yz, a.zx + b.zx};
}
RF_HD inline SymTensor operator-(const SymTensor& a, const SymTensor& b)
{
    return {a.xx - b.xx, a.yy - b.yy, a.zz - b.zz, a.xy - b.xy, a.yz - b.yz, a.zx - b.zx};
}
RF_HD inline SymTensor operator*(double s, const SymTensor& a)
{
    return {s * a.xx, s * a.yy, s * a.zz, s * a.xy, s * a.yz, s * a.zx};
}

RF_HD inline double trace(const SymTensor& a)
{
    return a.xx + a.yy + a.zz;
}
RF_HD inline SymTensor deviator(const SymTensor& a)
{
    return a - SymTensor::isotropic(trace(a) / 3.0);
}
// a : b, counting each off-diagonal pair twice.
RF_HD inline double doubleContraction(const SymTensor& a, const SymTensor& b)
{
    return a.xx * b.xx + a.yy * b.yy + a.zz * b.zz + 2.0 * (a.xy * b.xy + a.yz * b.yz + a.zx * b.zx);
}
// Von Mises equivalent stress sqrt(3 J2) of a stress tensor.
RF_HD inline double vonMises(const SymTensor& stress)
{
    const SymTensor s = deviator(stress);
    return std::sqrt(1.5 * doubleContraction(s, s));
}

RF_HD inline Mat3 toMat3(const SymTensor& a)
{
    Mat3 m;
    m.m[0][0] = a.xx, m.m[1][1] = a.yy, m.m[2][2] = a.zz;
    m.m[0][1] = m.m[1][0] = a.xy;
    m.m[1][2] = m.m[2][1] = a.yz;
    m.m[2][0] = m.m[0][2] = a.zx;
    return m;
}
// Symmetric part of a general matrix.
RF_HD inline SymTensor symmetricPart(const Mat3& m)
{
    return {m.m[0][0],
            m.m[1][1],
            m.m[2][2],
            0.5 * (m.m[0][1] + m.m[1][0]),
            0.5 * (m.m[1][2] + m.m[2][1]),
            0.5 * (m.m[2][0] + m.m[0][2])};
}

// Components in a rotated frame whose rows are the orthonormal basis vectors:
// a'_ij = r_i . a . r_j.
RF_HD inline SymTensor toFrame(const SymTensor& a, const Mat3& rows)
{
    return symmetricPart(rows * toMat3(a) * transpose(rows));
}
RF_HD inline SymTensor fromFrame(const SymTensor& a, const Mat3& rows)
{
    return symmetricPart(transpose(rows) * toMat3(a) * rows);
}

// Normal component n . a . n along a unit vector.
RF_HD inline double normalComponent(const SymTensor& a, const Vec3& n)
{
    return a.xx * n.x * n.x + a.yy * n.y * n.y + a.zz * n.z * n.z +
           2.0 * (a.xy * n.x * n.y + a.yz * n.y * n.z + a.zx * n.z * n.x);
}

// Upper bound of the largest eigenvalue (Gershgorin discs): a cheap screen that
// skips the eigen-decomposition when no principal value can reach a threshold.
RF_HD inline double largestEigenvalueBound(const SymTensor& a)
{
    const double r0 = a.xx + std::abs(a.xy) + std::abs(a.zx);
    const double r1 = a.yy + std::abs(a.xy) + std::abs(a.yz);
    const double r2 = a.zz + std::abs(a.yz) + std::abs(a.zx);
    return r0 > r1 ? (r0 > r2 ? r0 : r2) : (r1 > r2 ? r1 : r2);
}

// Eigenvalues (descending) and unit eigenvectors of a symmetric tensor by cyclic
// Jacobi rotations: robust for repeated eigenvalues and deterministic.
struct EigenSystem {
    double values[3];
    Vec3 vectors[3];  // vectors[i] belongs to values[i]
};

RF_HD inline EigenSystem eigenSystem(const SymTensor& tensor)
{
    Mat3 a = toMat3(tensor);
    Mat3 v = Mat3::identity();
    for (int sweep = 0; sweep < 50; ++sweep) {
        const double offDiagonal = a.m[0][1] * a.m[0][1] + a.m[1][2] * a.m[1][2] + a.m[0][2] * a.m[0][2];
        const double diagonal = a.m[0][0] * a.m[0][0] + a.m[1][1] * a.m[1][1] + a.m[2][2] * a.m[2][2];
        if (offDiagonal <= 1e-32 * diagonal || offDiagonal == 0.0) break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (a.m[p][q] == 0.0) continue;
                // Rotation in the (p, q) plane that zeroes a_pq (Numerical Recipes form).
                const double theta = (a.m[q][q] - a.m[p][p]) / (2.0 * a.m[p][q]);
                const double t =
                    (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 3; ++k) {  // a <- a G
                    const double akp = a.m[k][p], akq = a.m[k][q];
                    a.m[k][p] = c * akp - s * akq;
                    a.m[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) {  // a <- G^T a
                    const double apk = a.m[p][k], aqk = a.m[q][k];
                    a.m[p][k] = c * apk - s * aqk;
                    a.m[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {  // v <- v G
                    const double vkp = v.m[k][p], vkq = v.m[k][q];
                    v.m[k][p] = c * vkp - s * vkq;
                    v.m[k][q] = s * vkp + c * vkq;
                }
            }
    }
    int order[3] = {0, 1, 2};
    for (int i = 0; i < 2; ++i)
        for (int j = i + 1; j < 3; ++j)
            if (a.m[order[j]][order[j]] > a.m[order[i]][order[i]]) {
                const int swap = order[i];
                order[i] = order[j];
                order[j] = swap;
            }
    EigenSystem result;
    for (int i = 0; i < 3; ++i) {
        result.values[i] = a.m[order[i]][order[i]];
        result.vectors[i] = {v.m[0][order[i]], v.m[1][order[i]], v.m[2][order[i]]};
    }
    return result;
}

// Isotropic linear elasticity in Lamé form.
struct IsotropicElasticity {
    double lambda = 0.0;        // first Lamé parameter
    double shearModulus = 0.0;  // mu

    RF_HD static IsotropicElasticity fromYoungPoisson(double youngsModulus, double poissonRatio)
    {
        return {youngsModulus * poissonRatio / ((1.0 + poissonRatio) * (1.0 - 2.0 * poissonRatio)),
                youngsModulus / (2.0 * (1.0 + poissonRatio))};
    }
    RF_HD double bulkModulus() const { return lambda + 2.0 * shearModulus / 3.0; }
    RF_HD double youngsModulus() const
    {
        return shearModulus * (3.0 * lambda + 2.0 * shearModulus) / (lambda + shearModulus);
    }
    // lambda + 2 mu: the modulus of longitudinal (P) waves.
    RF_HD double pWaveModulus() const { return lambda + 2.0 * shearModulus; }
    RF_HD SymTensor stress(const SymTensor& strain) const
    {
        return SymTensor::isotropic(lambda * trace(strain)) + (2.0 * shearModulus) * strain;
    }
    // Strain that this elasticity maps to the given stress (isotropic compliance).
    RF_HD SymTensor strain(const SymTensor& stress) const
    {
        const SymTensor s = deviator(stress);
        return (0.5 / shearModulus) * s + SymTensor::isotropic(trace(stress) / (9.0 * bulkModulus()));
    }
};

}  // namespace rockfrac::fem
