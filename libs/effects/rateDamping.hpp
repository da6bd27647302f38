#pragma once
// Rate effect through the bond damping beta (Eqs. 18-19).
//
// The dashpots of the bonds resist the opening rate: a larger beta carries more
// load in the dynamic part of the response and spreads the softening, so the
// post-peak drop becomes more gradual and, at high rates, the peak rises. The
// fitted parameter multiplies the case's beta (whatever its reading, seconds or
// critical fraction); 1 is the baseline exactly.
// Signature: softening length (displacement from the peak to half of it) up;
// little change before the peak at quasi-static rates.
#include <sstream>

#include "core/dictionary.hpp"
#include "effects/modelEffect.hpp"

namespace rockfrac {

class RateDamping final : public ModelEffect {
public:
    // Name, physics, signature, fitted entry and its bounds (what explainGap screens).
    static const EffectDescriptor descriptor;

    explicit RateDamping(const Dictionary& d) : factor_(d.getScalar("betaFactor", Bounds::closed(0.05, 10.0)))
    {
    }

    void applyToParameters(DemParameters& p) const override { p.bond_damping *= factor_; }

    std::string describe() const override
    {
        std::ostringstream s;
        s << "rateDamping: bond damping beta x " << factor_;
        return s.str();
    }

private:
    double factor_;
};

}  // namespace rockfrac
