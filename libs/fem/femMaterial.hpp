#pragma once
// The material interface of the explicit FEM solver and its run-time selection.
//
// A material owns its per-element history (structure of arrays) and runs the
// element loop itself (elementLoop.hpp) so that its stress update is inlined into
// the loop: one virtual call per step, not per element. A model is chosen by a
// keyword (`material linearElastic;`, `material kstDfh;`) through the table in
// femMaterial.cpp and reads its own coefficients from the sub-dictionary named after
// it (`kstDfh { kst {...} dfh {...} }`); a new model is a new file pair plus one line
// in that table. The selected FemMaterialModel holds the coefficients; each FemModel
// makes its own FemMaterial (with the per-element history) from it.
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "fem/elementGeometry.hpp"
#include "fem/symTensor.hpp"

namespace rockfrac::fem {

// Elasticity and density, common to every material (rock { } of constant/rockProperties;
// physics.md: Table 2 rock values).
struct ElasticParameters {
    double density = 2540.0;        // kg/m^3
    double youngsModulus = 77.0e9;  // Pa
    double poissonRatio = 0.21;
};

// A per-element state array the caller can write and read back for restarts.
struct StateField {
    std::string name;
    int components = 1;
    std::vector<double>* values = nullptr;  // components per element, element-major
};

class FemMaterial {
public:
    virtual ~FemMaterial() = default;

    virtual std::string typeName() const = 0;
    // Sizes the per-element history for the mesh (element volumes for size effects).
    virtual void initialise(const ElementGeometry& geometry) = 0;
    // Stresses and element internal forces for the current displacements; updates
    // the history. Returns the lowest index of an inverted/non-finite element or -1.
    virtual long long computeElementForces(const ElementGeometry& geometry, const double* displacements,
                                           double* stresses, double* elementForces) = 0;
    // History arrays, for restart files.
    virtual std::vector<StateField> stateFields() { return {}; }

    // Output: damage of element e in crack direction 0..2 (0 intact, 1 failed).
    virtual double damage(std::size_t /*element*/, int /*direction*/) const { return 0.0; }
    virtual double equivalentPlasticStrain(std::size_t /*element*/) const { return 0.0; }

    const ElasticParameters& elasticParameters() const { return elasticParameters_; }
    const IsotropicElasticity& elasticity() const { return elasticity_; }

protected:
    explicit FemMaterial(const ElasticParameters& parameters);

    ElasticParameters elasticParameters_;
    IsotropicElasticity elasticity_;
};

// A selected material with its coefficients (immutable, shared by copies of the
// parameters): what a case chose; make() gives a FemModel its own material.
class FemMaterialModel {
public:
    virtual ~FemMaterialModel() = default;
    virtual std::string type() const = 0;
    virtual std::unique_ptr<FemMaterial> make(const ElasticParameters& elastic) const = 0;
    // The coefficients for the log, after "Material <type>: E ..., nu ..., density ...":
    // "; KST a0 ... DFH ..." (empty for a material without coefficients).
    virtual std::string describe() const = 0;
};

// A model of Material with its Coefficients (Material::Coefficients, ::keyword, ::read,
// ::check, ::describe).
template <class Material>
class FemMaterialModelOf final : public FemMaterialModel {
public:
    using Coefficients = typename Material::Coefficients;
    explicit FemMaterialModelOf(const Coefficients& coefficients = Coefficients{})
        : coefficients_(coefficients)
    {
        Material::check(coefficients_);
    }
    std::string type() const override { return Material::keyword; }
    std::unique_ptr<FemMaterial> make(const ElasticParameters& elastic) const override
    {
        return std::make_unique<Material>(elastic, coefficients_);
    }
    std::string describe() const override { return Material::describe(coefficients_); }
    const Coefficients& coefficients() const { return coefficients_; }

private:
    Coefficients coefficients_;
};

}  // namespace rockfrac::fem

namespace rockfrac {
class Dictionary;
template <class Base, class... Args>
class Selector;
}  // namespace rockfrac

namespace rockfrac::fem {

// The table of materials (femMaterial.cpp): keyword -> model read from its sub-dictionary.
const Selector<FemMaterialModel>& femMaterials();
std::vector<std::string> femMaterialNames();
// kstDfh with the documented defaults (KstDfhParameters).
std::shared_ptr<const FemMaterialModel> defaultFemMaterial();

}  // namespace rockfrac::fem
