#pragma once
// The material interface of the explicit FEM solver and its run-time selection.
//
// A material owns its per-element history (structure of arrays) and runs the
// element loop itself (elementLoop.hpp) so that its stress update is inlined into
// the loop: one virtual call per step, not per element. A model is chosen by a
// keyword (`linearElastic`, `kstDfh`) through the table in femMaterial.cpp; a new
// model is a new file pair plus one line in that table.
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "fem/elementGeometry.hpp"
#include "fem/symTensor.hpp"

namespace rockfrac::fem {

// Every parameter of the shipped models. Defaults are the documented ones of
// docs/physics.md section 2 (granite); the case dictionary overrides them.
struct MaterialParameters {
    // Elasticity and density (physics.md: Table 2 rock values).
    double density = 2540.0;        // kg/m^3
    double youngsModulus = 77.0e9;  // Pa
    double poissonRatio = 0.21;

    // KST shear yield, written for the von Mises equivalent stress:
    //   sigma_eq = sqrt(a0 + a1 P + a2 P^2), P = -tr(sigma)/3 (compression positive),
    // so a0 is in Pa^2 (the paper's a0^2), a1 in Pa, a2 dimensionless.
    double kstA0 = 1.0e16;  // Pa^2
    double kstA1 = 3.1e8;   // Pa
    double kstA2 = 2.0;
    // Most tensile pressure the material can hold (P_cut <= 0, Pa). NaN means
    // "automatic": the upper root of a0 + a1 P + a2 P^2 = 0 where the surface closes
    // (about -46 MPa with the defaults), or 0 if that polynomial has no real root.
    double tensilePressureCutoff = std::numeric_limits<double>::quiet_NaN();
    // Optional KST compaction curve: (compressive volumetric strain, pressure) points,
    // piecewise linear, starting at (0, 0) implicitly; empty = off (the paper's case).
    std::vector<std::pair<double, double>> compactionCurve;

    // DFH tensile damage (Weibull): m, sigma_w = mean strength of volume V_ref.
    bool damageEnabled = true;
    double weibullModulus = 7.0;
    double weibullStress = 21.0e6;  // Pa
    double referenceVolume = 0.0;   // m^3; a case entry, must be set when damage is on
    std::uint64_t seed = 0;         // case seed for the per-element thresholds
    // Fraction of the shear stiffness kept in the planes containing an open crack's normal.
    double crackShearRetention = 0.0;
    // Crack band: fracture energy G_F of a crack [N/m]; 0 = complete failure at the
    // threshold (the paper's DFH). With G_F > 0 a crack's normal stress softens linearly
    // over an opening set by G_F and the element's width across the crack.
    double fractureEnergy = 0.0;
    // Element erosion: an element whose number of failed directions reaches this value
    // stops contributing (zero stress from then on, never checked for inversion), as in
    // the paper's FEM ("an element stops contributing once the damage variable reaches
    // one"). 0 = never (cracked elements carry compression across closed cracks).
    int erodeAfterCracks = 0;
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

    const MaterialParameters& parameters() const { return parameters_; }
    const IsotropicElasticity& elasticity() const { return elasticity_; }

protected:
    explicit FemMaterial(const MaterialParameters& parameters);

    MaterialParameters parameters_;
    IsotropicElasticity elasticity_;
};

// The material registered under `name`; UserError listing the known names otherwise.
std::unique_ptr<FemMaterial> makeFemMaterial(const std::string& name, const MaterialParameters& parameters);
std::vector<std::string> femMaterialNames();

}  // namespace rockfrac::fem
