// Run-time selection of FEM materials: the keyword table.
#include "fem/femMaterial.hpp"

#include "core/error.hpp"
#include "core/selector.hpp"
#include "fem/kstDfhMaterial.hpp"
#include "fem/linearElasticMaterial.hpp"

namespace rockfrac::fem {

FemMaterial::FemMaterial(const ElasticParameters& parameters)
    : elasticParameters_(parameters),
      elasticity_(IsotropicElasticity::fromYoungPoisson(parameters.youngsModulus, parameters.poissonRatio))
{
    if (!(parameters.density > 0.0)) throw UserError("material: density must be > 0");
    if (!(parameters.youngsModulus > 0.0)) throw UserError("material: Young's modulus must be > 0");
    if (!(parameters.poissonRatio > -1.0 && parameters.poissonRatio < 0.5))
        throw UserError("material: Poisson's ratio must lie in (-1, 0.5)");
}

namespace {

template <class Material>
std::unique_ptr<FemMaterialModel> make(const Dictionary& coefficients)
{
    return std::make_unique<FemMaterialModelOf<Material>>(Material::read(coefficients));
}

}  // namespace

// One line per model.
const Selector<FemMaterialModel>& femMaterials()
{
    static const Selector<FemMaterialModel> table("FEM material",
                                                  {
                                                      {"linearElastic", &make<LinearElasticMaterial>, true},
                                                      {"kstDfh", &make<KstDfhMaterial>},
                                                  });
    return table;
}

std::vector<std::string> femMaterialNames()
{
    return femMaterials().names();
}

std::shared_ptr<const FemMaterialModel> defaultFemMaterial()
{
    return std::make_shared<FemMaterialModelOf<KstDfhMaterial>>();
}

}  // namespace rockfrac::fem
