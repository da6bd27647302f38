#include "crusher/mantleSpin.hpp"

namespace rockfrac {

void MantleSpin::advance(double axial_torque, double dt)
{
    if (!spec_.free) return;
    const double old_rate = rate_;
    // I (w1 - w0) / dt = tau - c w1
    rate_ = (spec_.inertia * old_rate + dt * axial_torque) / (spec_.inertia + dt * spec_.bearing_damping);
    angle_ += dt * rate_;
    // With the mean rate m = (w0 + w1)/2: tau m dt - c w1 m dt = I (w1 - w0) m = I (w1^2 - w0^2)/2.
    const double mean_rate = 0.5 * (old_rate + rate_);
    torque_work_ += axial_torque * mean_rate * dt;
    bearing_dissipated_ += spec_.bearing_damping * rate_ * mean_rate * dt;
}

}  // namespace rockfrac
