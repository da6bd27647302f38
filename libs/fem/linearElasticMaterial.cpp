#include "fem/linearElasticMaterial.hpp"

#include "core/selector.hpp"
#include "fem/elementLoop.hpp"

namespace rockfrac::fem {

LinearElasticMaterial::Coefficients LinearElasticMaterial::read(const Dictionary& coefficients)
{
    requireKnownEntries(
        coefficients, {},
        "linearElastic has no coefficients of its own: rock { } holds E, poissonRatio, density");
    return {};
}

long long LinearElasticMaterial::computeElementForces(const ElementGeometry& geometry,
                                                      const double* displacements, double* stresses,
                                                      double* elementForces)
{
    const IsotropicElasticity elastic = elasticity_;
    return elementLoop(geometry, displacements, stresses, elementForces,
                       [elastic](std::size_t, const SymTensor& strain) { return elastic.stress(strain); });
}

}  // namespace rockfrac::fem
