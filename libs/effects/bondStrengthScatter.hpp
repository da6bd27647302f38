#pragma once
// Bond strength scatter with a Weibull size effect.
//
// Rock strength is not a constant: flaws are distributed, and a larger interface
// is more likely to hold a weak one. Each interface k gets a strength factor
//     s_k = (A_mean / A_k)^(1/m) W_k / Gamma(1 + 1/m),   W_k = (-ln U_k)^(1/m),
// on sigma-bar and C of its bonds: W_k is a unit Weibull variable of modulus m
// (divided by its mean, so a mean-area interface keeps its strength on average),
// and the first factor is the weakest-link size effect (smaller faces stronger).
// U_k comes from the counter-based stream keyed by `seed` and k, so the draw is
// reproducible and independent of the thread count. The fitted parameter is
// 1/m (0 = no scatter = the baseline exactly).
// Signature: wider spread of failure loads and a lower mean (the weakest bonds
// start the crack); stiffness unchanged.
#include <cmath>
#include <cstdint>
#include <sstream>

#include "core/counterRandom.hpp"
#include "core/dictionary.hpp"
#include "dem/demModel.hpp"
#include "effects/modelEffect.hpp"

namespace rockfrac {

class BondStrengthScatter final : public ModelEffect {
public:
    // Name, physics, signature, fitted entry and its bounds (what explainGap screens).
    static const EffectDescriptor descriptor;
    // The counter-based random stream of the draws (with the case's seed and the interface).
    static constexpr std::uint64_t scatterStream = 0x5ca77e5;

    explicit BondStrengthScatter(const Dictionary& d)
        : inverse_modulus_(d.getScalar("inverseModulus", Bounds::closed(0.0, 1.0))),
          seed_(d.get<std::uint64_t>("seed"))
    {
    }

    void applyToModel(DemModel& model, const EffectContext&) const override
    {
        if (inverse_modulus_ == 0.0) return;
        const InterfaceArrays& interfaces = model.interfaces();
        if (interfaces.size() == 0) return;
        double mean_area = 0.0;
        for (int k = 0; k < interfaces.size(); ++k) mean_area += interfaces.bond_area[k];
        mean_area /= interfaces.size();
        const double mean_weibull = std::tgamma(1.0 + inverse_modulus_);
        for (int k = 0; k < interfaces.size(); ++k) {
            const double u = uniform01(seed_, scatterStream, static_cast<std::uint64_t>(k));
            const double weibull = std::pow(-std::log(u), inverse_modulus_);
            const double size = std::pow(mean_area / interfaces.bond_area[k], inverse_modulus_);
            model.scaleInterfaceStrength(k, size * weibull / mean_weibull);
        }
    }

    std::string describe() const override
    {
        std::ostringstream s;
        s << "bondStrengthScatter: Weibull modulus "
          << (inverse_modulus_ > 0 ? 1.0 / inverse_modulus_ : INFINITY) << " (seed " << seed_ << ")";
        return s.str();
    }

private:
    double inverse_modulus_;
    std::uint64_t seed_;
};

}  // namespace rockfrac
