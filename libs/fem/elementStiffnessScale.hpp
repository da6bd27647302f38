#pragma once
// The stiffness scale of each element: the largest eigenvalue of its stiffness
// matrix K_e = V B^T D B (isotropic elasticity). With the lumped mass rho V / 4 per
// node the element's highest eigenfrequency is omega_e^2 = 4 lambda_max(K_e) / (rho V),
// and omega_max of the assembled mesh never exceeds max_e omega_e (element eigenvalue
// inequality), so 2 / max_e omega_e is a rigorous bound on the stable explicit step.
#include <vector>

#include "fem/elementGeometry.hpp"
#include "fem/symTensor.hpp"

namespace rockfrac::fem {

std::vector<double> largestElementEigenstiffness(const ElementGeometry& geometry,
                                                 const IsotropicElasticity& elastic);

}  // namespace rockfrac::fem
