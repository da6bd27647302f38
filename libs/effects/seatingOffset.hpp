#pragma once
// Seating — the toe region of a laboratory curve.
//
// Before a specimen carries load the platens must seat: surface roughness, a not
// quite parallel specimen, packing or lubricant between disc and plate. That
// closes a gap of `depth` against a small force, so the recorded curve starts with
// a soft toe and then runs parallel to the seated curve. Modelled as a saturating
// element in series with the specimen: recorded displacement = plate approach +
// depth (1 - exp(-F / closureForce)). depth = 0 is the baseline exactly.
// Signature: toe index up (soft start), displacement at peak up by about `depth`,
// stiffness after seating and peak force unchanged.
#include <cmath>
#include <sstream>

#include "core/dictionary.hpp"
#include "effects/modelEffect.hpp"

namespace rockfrac {

class SeatingOffset final : public ModelEffect {
public:
    // Name, physics, signature, fitted entry and its bounds (what explainGap screens).
    static const EffectDescriptor descriptor;

    explicit SeatingOffset(const Dictionary& d)
        : depth_(d.getScalar("depth", Bounds::closed(0.0, 1e-3))),
          closure_force_(d.getScalar("closureForce", Bounds::positive()))
    {
    }

    double recordedDisplacement(double plateApproach, double force) const override
    {
        if (depth_ == 0.0 || force <= 0.0) return plateApproach;
        return plateApproach + depth_ * (1.0 - std::exp(-force / closure_force_));
    }

    std::string describe() const override
    {
        std::ostringstream s;
        s << "seatingOffset: " << 1e3 * depth_ << " mm closing under about " << 1e-3 * closure_force_
          << " kN";
        return s.str();
    }

private:
    double depth_, closure_force_;
};

}  // namespace rockfrac
