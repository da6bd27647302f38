#include "fem/elementStiffnessScale.hpp"

#include <Eigen/Dense>

namespace rockfrac::fem {

namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using StrainMatrix = Eigen::Matrix<double, 6, 12>;

// Voigt strain-displacement matrix (engineering shear) of a linear tet.
StrainMatrix strainDisplacementMatrix(const double* gradients)
{
    StrainMatrix b = StrainMatrix::Zero();
    for (int a = 0; a < 4; ++a) {
        const double gx = gradients[3 * a], gy = gradients[3 * a + 1], gz = gradients[3 * a + 2];
        const int c = 3 * a;
        b(0, c) = gx, b(1, c + 1) = gy, b(2, c + 2) = gz;
        b(3, c) = gy, b(3, c + 1) = gx;
        b(4, c + 1) = gz, b(4, c + 2) = gy;
        b(5, c) = gz, b(5, c + 2) = gx;
    }
    return b;
}

Matrix6 elasticityMatrix(const IsotropicElasticity& elastic)
{
    Matrix6 d = Matrix6::Zero();
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) d(i, j) = elastic.lambda;
        d(i, i) += 2.0 * elastic.shearModulus;
        d(i + 3, i + 3) = elastic.shearModulus;
    }
    return d;
}

}  // namespace

std::vector<double> largestElementEigenstiffness(const ElementGeometry& geometry,
                                                 const IsotropicElasticity& elastic)
{
    // lambda_max(B^T D B) = lambda_max(L^T B B^T L) with D = L L^T: a 6x6 problem.
    const Matrix6 lower = elasticityMatrix(elastic).llt().matrixL();
    std::vector<double> eigenstiffness(geometry.numElements());
    for (std::size_t e = 0; e < geometry.numElements(); ++e) {
        const StrainMatrix b = strainDisplacementMatrix(&geometry.gradients[12 * e]);
        const Matrix6 reduced = lower.transpose() * (b * b.transpose()) * lower;
        const double largest =
            Eigen::SelfAdjointEigenSolver<Matrix6>(reduced, Eigen::EigenvaluesOnly).eigenvalues()(5);
        eigenstiffness[e] = geometry.volumes[e] * largest;
    }
    return eigenstiffness;
}

}  // namespace rockfrac::fem
