#pragma once
// Isotropic linear elasticity (small strain): the reference material for
// verification (patch test, Hertz contact, wave propagation).
#include "fem/femMaterial.hpp"

namespace rockfrac::fem {

class LinearElasticMaterial : public FemMaterial {
public:
    explicit LinearElasticMaterial(const MaterialParameters& parameters) : FemMaterial(parameters) {}

    std::string typeName() const override { return "linearElastic"; }
    void initialise(const ElementGeometry&) override {}
    long long computeElementForces(const ElementGeometry& geometry, const double* displacements,
                                   double* stresses, double* elementForces) override;
};

}  // namespace rockfrac::fem
