#pragma once
// Isotropic linear elasticity (small strain): the reference material for
// verification (patch test, Hertz contact, wave propagation). No coefficients of its
// own (rock { E; poissonRatio; density; } is every material's); `linearElastic { }`
// may be left out of constant/rockProperties.
#include <string>

#include "fem/femMaterial.hpp"

namespace rockfrac {
class Dictionary;
}

namespace rockfrac::fem {

class LinearElasticMaterial : public FemMaterial {
public:
    struct Coefficients {};
    static constexpr const char* keyword = "linearElastic";
    // The sub-dictionary must be empty when given.
    static Coefficients read(const Dictionary& coefficients);
    static void check(const Coefficients&) {}
    static std::string describe(const Coefficients&) { return ""; }

    LinearElasticMaterial(const ElasticParameters& elastic, const Coefficients&) : FemMaterial(elastic) {}

    std::string typeName() const override { return keyword; }
    void initialise(const ElementGeometry&) override {}
    long long computeElementForces(const ElementGeometry& geometry, const double* displacements,
                                   double* stresses, double* elementForces) override;
};

}  // namespace rockfrac::fem
