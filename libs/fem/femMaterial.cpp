// Run-time selection of FEM materials: the keyword table.
#include "fem/femMaterial.hpp"

#include "core/error.hpp"
#include "fem/kstDfhMaterial.hpp"
#include "fem/linearElasticMaterial.hpp"

namespace rockfrac::fem {

FemMaterial::FemMaterial(const MaterialParameters& parameters)
    : parameters_(parameters),
      elasticity_(IsotropicElasticity::fromYoungPoisson(parameters.youngsModulus, parameters.poissonRatio))
{
    if (!(parameters.density > 0.0)) throw UserError("material: density must be > 0");
    if (!(parameters.youngsModulus > 0.0)) throw UserError("material: Young's modulus must be > 0");
    if (!(parameters.poissonRatio > -1.0 && parameters.poissonRatio < 0.5))
        throw UserError("material: Poisson's ratio must lie in (-1, 0.5)");
}

namespace {

using Factory = std::unique_ptr<FemMaterial> (*)(const MaterialParameters&);

template <class Material>
std::unique_ptr<FemMaterial> make(const MaterialParameters& parameters)
{
    return std::make_unique<Material>(parameters);
}

// One line per model.
const std::pair<const char*, Factory> materialTable[] = {
    {"linearElastic", &make<LinearElasticMaterial>},
    {"kstDfh", &make<KstDfhMaterial>},
};

}  // namespace

std::vector<std::string> femMaterialNames()
{
    std::vector<std::string> names;
    for (const auto& entry : materialTable) names.emplace_back(entry.first);
    return names;
}

std::unique_ptr<FemMaterial> makeFemMaterial(const std::string& name, const MaterialParameters& parameters)
{
    for (const auto& entry : materialTable)
        if (name == entry.first) return entry.second(parameters);
    std::string known;
    for (const auto& n : femMaterialNames()) known += (known.empty() ? "" : ", ") + n;
    throw UserError("unknown FEM material '" + name + "'; known materials: " + known);
}

}  // namespace rockfrac::fem
