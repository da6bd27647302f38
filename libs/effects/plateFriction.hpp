#pragma once
// Plate friction — the rock–steel Coulomb coefficient at the platens.
//
// Friction at the platens restrains the lateral spreading of the rock under the
// contact (the end-constraint of compression tests); lubricated plates (the
// paper's BDT) remove it. The fitted parameter multiplies the rock–steel friction
// of constant/rockProperties; 1 is the baseline exactly.
// Signature: a confined, stronger contact zone with friction, more contact
// sliding and splitting without it; the size of the change depends on the specimen
// shape (small for a disc between flat plates, larger for irregular rocks).
#include <sstream>

#include "core/dictionary.hpp"
#include "effects/modelEffect.hpp"

namespace rockfrac {

class PlateFriction final : public ModelEffect {
public:
    // Name, physics, signature, fitted entry and its bounds (what explainGap screens).
    static const EffectDescriptor descriptor;

    explicit PlateFriction(const Dictionary& d)
        : factor_(d.getScalar("frictionFactor", Bounds::closed(0.0, 2.0)))
    {
    }

    void applyToParameters(DemParameters& p) const override { p.rock_steel_friction *= factor_; }

    std::string describe() const override
    {
        std::ostringstream s;
        s << "plateFriction: rock-steel friction x " << factor_;
        return s.str();
    }

private:
    double factor_;
};

}  // namespace rockfrac
