#pragma once
// Free spin of the mantle about its own axis (docs/theory-crusher.md, "Free spin").
//
// A cone crusher's mantle sits on its eccentric through a bearing: the eccentric forces the
// gyration, but the mantle is free to turn about its own axis, driven by the rocks' friction
// and held back by the bearing. (A real bearing also drags an idle mantle slowly round with
// the eccentric; that drag is not modelled: an idle mantle stays at rest.) For an axisymmetric
// body Euler's equation about the symmetry axis a is exact whatever the gyration does:
//
//     I psi'' = tau_a - c psi'
//
// with I the mantle's moment of inertia about its axis, tau_a = a . (torque of the rocks on
// the mantle about the pivot), and c the viscous drag of the bearing [N m s]. The drive
// delivers the gyration's power only: P_drive = P_wall + psi' tau_a, where P_wall is what the
// wall gives to the rocks; psi' tau_a = d(I psi'^2 / 2)/dt + c psi'^2 (spin energy and bearing
// loss).
namespace rockfrac {

struct MantleSpinSpec {
    bool free = false;             // false: spin fixed (psi = 0 always)
    double inertia = 0.0;          // I about the mantle axis [kg m^2]
    double bearing_damping = 0.0;  // c [N m s]
};

class MantleSpin {
public:
    explicit MantleSpin(const MantleSpinSpec& spec) : spec_(spec) {}

    // One step of length dt under the axial torque tau_a of the last force evaluation:
    // the rate with the bearing drag taken implicitly (stable for any c dt / I), then the
    // angle with the new rate (symplectic Euler). Books the torque's work and the bearing's
    // loss with the mean rate of the step, so that
    //   torqueWork = kineticEnergy() + bearingDissipated   (exactly, up to round-off).
    // That is the spin's own ledger. The wall moves during a step with the rate set before
    // it (the rocks' work is booked with that rate), the angle then advances with the new
    // one: against the rocks' books the spin's differ by O(dt). A step in which the rate
    // changes sign may book a slightly negative bearing loss (the price of the exact identity).
    void advance(double axial_torque, double dt);

    bool free() const { return spec_.free; }
    double angle() const { return angle_; }
    double rate() const { return rate_; }
    double kineticEnergy() const { return 0.5 * spec_.inertia * rate_ * rate_; }
    double torqueWork() const { return torque_work_; }
    double bearingDissipated() const { return bearing_dissipated_; }
    // A restart (crusherState.hpp): the state as written.
    void restore(double angle, double rate, double torque_work, double bearing_dissipated)
    {
        angle_ = angle;
        rate_ = rate;
        torque_work_ = torque_work;
        bearing_dissipated_ = bearing_dissipated;
    }

private:
    MantleSpinSpec spec_;
    double angle_ = 0.0, rate_ = 0.0;
    double torque_work_ = 0.0, bearing_dissipated_ = 0.0;
};

}  // namespace rockfrac
