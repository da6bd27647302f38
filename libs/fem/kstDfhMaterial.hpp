#pragma once
// KST-DFH rock model (paper section 3; docs/physics.md section 2): KST pressure-
// dependent shear plasticity plus DFH probabilistic anisotropic tensile damage with
// three Weibull thresholds per element. The point update is in kstDfhModel.hpp;
// this class owns the per-element history as arrays over elements.
#include "fem/femMaterial.hpp"
#include "fem/kstDfhModel.hpp"

namespace rockfrac::fem {

class KstDfhMaterial : public FemMaterial {
public:
    explicit KstDfhMaterial(const MaterialParameters& parameters);

    std::string typeName() const override { return "kstDfh"; }
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
