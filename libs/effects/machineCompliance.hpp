#pragma once
// Machine compliance — a linear spring in series with the specimen.
//
// A testing machine measures the crosshead (or actuator) travel; the frame, load
// cell and platens deflect under the load, so the recorded displacement is the
// specimen's plate approach plus F x compliance. The force is the same through the
// series chain; with the loading quasi-static (the rate study of docs/validation.md:
// peak force independent of plate speed within 0.6 % from 50 to 250 mm/s) the plate
// keeps its prescribed speed and the spring enters the recorded displacement only.
// Signature: a uniformly softer curve and a larger displacement at peak, same peak
// force and same shape. On a single specimen size it is indistinguishable from a
// lower bond modulus; an extensometer on the specimen separates them.
#include <sstream>

#include "core/dictionary.hpp"
#include "effects/modelEffect.hpp"

namespace rockfrac {

class MachineCompliance final : public ModelEffect {
public:
    // Name, physics, signature, fitted entry and its bounds (what explainGap screens).
    static const EffectDescriptor descriptor;

    explicit MachineCompliance(const Dictionary& d)
        : compliance_(d.getScalar("compliance", Bounds::closed(0.0, 1e-6)))
    {
    }

    double recordedDisplacement(double plateApproach, double force) const override
    {
        return plateApproach + compliance_ * force;
    }

    std::string describe() const override
    {
        std::ostringstream s;
        s << "machineCompliance: " << compliance_ << " m/N in series (stiffness "
          << (compliance_ > 0 ? 1e-6 / compliance_ : 0.0) << " N/um)";
        return s.str();
    }

private:
    double compliance_;
};

}  // namespace rockfrac
