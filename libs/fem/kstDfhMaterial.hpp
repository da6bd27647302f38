#pragma once
// KST-DFH rock model (paper section 3; docs/physics.md section 2): KST pressure-
// dependent shear plasticity plus DFH probabilistic anisotropic tensile damage with
// three Weibull thresholds per element. The point update is in kstDfhModel.hpp;
// this class owns the per-element history as arrays over elements.
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "fem/femMaterial.hpp"
#include "fem/kstDfhModel.hpp"

namespace rockfrac {
class Dictionary;
}

namespace rockfrac::fem {

// The coefficients of kstDfh { kst { ... } dfh { ... } } (docs/models/fem/kstDfh.md).
// Defaults are the documented ones of docs/physics.md section 2 (granite).
struct KstDfhParameters {
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

class KstDfhMaterial : public FemMaterial {
public:
    using Coefficients = KstDfhParameters;
    static constexpr const char* keyword = "kstDfh";
    // kstDfh { kst { a0; a1; a2; ... } dfh { weibullModulus; ... } }: units, bounds, no unknown entries.
    static Coefficients read(const Dictionary& coefficients);
    // UserError naming the first impossible value.
    static void check(const Coefficients& coefficients);
    static std::string describe(const Coefficients& coefficients);

    KstDfhMaterial(const ElasticParameters& elastic, const Coefficients& coefficients);

    std::string typeName() const override { return keyword; }
    const Coefficients& coefficients() const { return coefficients_; }
    // Samples the thresholds: element e uses the stream (seed, e) and its own volume.
    void initialise(const ElementGeometry& geometry) override;
    long long computeElementForces(const ElementGeometry& geometry, const double* displacements,
                                   double* stresses, double* elementForces) override;
    std::vector<StateField> stateFields() override;

    // 1 for a failed direction; with a crack band, the fraction of its softening opened.
    double damage(std::size_t element, int direction) const override;
    double equivalentPlasticStrain(std::size_t element) const override
    {
        return equivalentPlasticStrain_[element];
    }
    const KstDfhConstants& constants() const { return constants_; }
    // Crack normal of element e in direction 0..2 (meaningful once that crack exists).
    Vec3 crackNormal(std::size_t element, int direction) const;

    // History of one element gathered from / scattered to the arrays.
    KstDfhPointState pointState(std::size_t element) const;
    void setPointState(std::size_t element, const KstDfhPointState& state);

private:
    void storePlasticHistory(std::size_t element, const KstDfhPointState& state);
    void storeCracks(std::size_t element, const KstDfhPointState& state);
    void storeCrackOpenings(std::size_t element, const KstDfhPointState& state);

    Coefficients coefficients_;
    KstDfhConstants constants_;
    std::vector<double> compactionStrains_, compactionPressures_;
    std::vector<double> plasticStrain_;            // 6 per element
    std::vector<double> equivalentPlasticStrain_;  // 1
    std::vector<double> compactionStrain_;         // 1
    std::vector<double> crackCount_;               // 1 (0..3, stored as double for restart files)
    std::vector<double> crackFrame_;               // 9 (rows n1, n2, n3)
    std::vector<double> failureStress_;            // 3 (ascending)
    std::vector<double> crackOpening_;             // 3, crack band only: largest opening strain
    std::vector<double> softeningStrain_;          // 3, crack band only: opening strain at t = 0
};

}  // namespace rockfrac::fem
