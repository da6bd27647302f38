// Free spin of the mantle: the pose with a spin angle (libs/geometry/crusherGeometry) and the
// spin's equation of motion I psi'' = tau_a - c psi' (libs/crusher/mantleSpin).
#include <catch2/catch.hpp>
#include <cmath>

#include "../dem/boxMeshes.hpp"
#include "crusher/mantleSpin.hpp"
#include "dem/demModel.hpp"
#include "geometry/crusherGeometry.hpp"

using namespace rockfrac;

namespace {

const double spinPi = 3.14159265358979323846;

CrusherKinematics ch660Like()
{
    CrusherKinematics k;
    k.pivot = {0, 0, 1.5};
    k.eccentric_angle = 0.0085;
    k.eccentric_speed = 2 * spinPi * 290 / 60;
    k.phase = 0.3;
    return k;
}

Vec3 place(const MantlePose& p, const Vec3& x)
{
    return p.translation + p.rotation * x;
}

}  // namespace

TEST_CASE("spinning mantle pose: rigid, pivot fixed, velocities the derivative of the positions",
          "[crusher][spin]")
{
    const CrusherKinematics k = ch660Like();
    const Vec3 z{0, 0, 1};
    for (double rate : {0.0, 3.0, -1.7}) {
        for (double t : {0.0, 0.021, 0.13}) {
            const double angle0 = 0.4;  // psi(t) = angle0 + rate t
            auto at = [&](double s) { return mantlePose(k, s, angle0 + rate * s, rate); };
            const MantlePose a = at(t), g = mantlePose(k, t);
            // Spin 0 is the gyration alone; the spin keeps the pivot and the tilted axis.
            if (rate == 0.0)
                CHECK(norm(mantlePose(k, t, 0.0, 0.0).angular_velocity - g.angular_velocity) == 0.0);
            CHECK(norm(place(a, k.pivot) - k.pivot) < 1e-14);
            CHECK(norm(a.rotation * z - g.rotation * z) < 1e-14);
            // A point off the axis is turned by psi about the tilted axis relative to the gyration.
            const Vec3 x{0.5, 0.0, 0.2};
            const Vec3 r0 = place(g, x) - k.pivot, r1 = place(a, x) - k.pivot;
            CHECK(std::abs(norm(r0) - norm(r1)) < 1e-14);
            CHECK(dot(r0, g.rotation * z) == Approx(dot(r1, g.rotation * z)).epsilon(1e-13));
            // Velocities: central differences of positions with psi advancing at `rate`.
            const double h = 1e-7;
            const Vec3 fd = (place(at(t + h), x) - place(at(t - h), x)) / (2 * h);
            const Vec3 v = a.velocity + cross(a.angular_velocity, place(a, x) - a.translation);
            CHECK(norm(fd - v) < 1e-7 * norm(v) + 1e-12);
        }
    }
}

TEST_CASE("mantle spin: constant torque against the bearing drag, energies booked exactly", "[crusher][spin]")
{
    // I psi'' = tau - c psi', psi'(0) = 0: psi'(t) = tau/c (1 - exp(-c t / I)).
    const MantleSpinSpec spec{true, 800.0, 4000.0};  // I [kg m^2], c [N m s]; time constant 0.2 s
    const double tau = 2.0e4, T = 0.5;
    auto rateError = [&](double dt) {
        MantleSpin s(spec);
        const long n = std::lround(T / dt);
        for (long i = 0; i < n; ++i) s.advance(tau, dt);
        // Exact booking: the torque's work is the spin energy plus the bearing's loss.
        CHECK(s.torqueWork() == Approx(s.kineticEnergy() + s.bearingDissipated()).epsilon(1e-12));
        const double exact =
            tau / spec.bearing_damping * (1 - std::exp(-spec.bearing_damping * T / spec.inertia));
        // psi(T) = tau/c (T - I/c (1 - exp(-c T / I)))
        const double angle = tau / spec.bearing_damping *
                             (T - spec.inertia / spec.bearing_damping *
                                      (1 - std::exp(-spec.bearing_damping * T / spec.inertia)));
        CHECK(s.angle() == Approx(angle).epsilon(20 * dt / 0.2));
        return std::abs(s.rate() - exact) / exact;
    };
    const double e1 = rateError(1e-4), e2 = rateError(5e-5);
    CHECK(e1 < 1e-3);
    CHECK(e2 / e1 == Approx(0.5).margin(0.05));  // first order in the step

    SECTION("no drag: the torque's work is all spin energy; no torque: the spin keeps its rate")
    {
        MantleSpin s(MantleSpinSpec{true, 800.0, 0.0});
        for (int i = 0; i < 1000; ++i) s.advance(tau, 1e-4);
        CHECK(s.rate() == Approx(tau * 0.1 / 800.0).epsilon(1e-12));
        const double rate = s.rate();
        for (int i = 0; i < 1000; ++i) s.advance(0.0, 1e-4);
        CHECK(s.rate() == rate);
        CHECK(s.bearingDissipated() == 0.0);
        CHECK(s.torqueWork() == Approx(s.kineticEnergy()).epsilon(1e-12));
    }
    SECTION("spin fixed: nothing moves whatever the torque")
    {
        MantleSpin s(MantleSpinSpec{});
        for (int i = 0; i < 10; ++i) s.advance(tau, 1e-4);
        CHECK(s.rate() == 0.0);
        CHECK(s.angle() == 0.0);
        CHECK(s.torqueWork() == 0.0);
    }
}

TEST_CASE(
    "a spinning wall drags a resting cell: the rocks' axial torque opposes the spin and "
    "the wall's power is the spin's alone",
    "[crusher][spin]")
{
    // A flat triangulated floor (normal +z) turning about the z axis at omega, one box cell
    // pressed on it off the axis. The wall slides under the cell, friction drags the cell
    // along and holds the wall back: the cells' torque on the wall about the axis (what
    // crusherRun feeds to I psi'' = tau_a - c psi') must be against omega, and the wall's
    // power on the cells must be -omega tau_a, so that the drive's share
    // P_wall + psi' tau_a of a spin-only motion is zero.
    DemParameters p;
    p.gravity = {0.0, 0.0, 0.0};
    const double cell = 0.01, rd = 5e-4, overlap = 2e-5, omega = 2.0;
    const std::vector<Vec3> floor{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    const Vec3 pivot{0.0, 0.0, 1.5};  // any point on the axis
    for (double sign : {1.0, -1.0}) {
        DemModel model(test::boxBlockMesh(1, 1, 1, {cell, cell, cell}, rd, false), p);
        const int w = model.addTriSurface(floor, {{{0, 1, 2}}, {{0, 2, 3}}});
        model.setCellPose(0, {0.3, 0.1, 0.5 * cell - overlap}, Quat{});
        model.setCellVelocity(0, {}, {});
        model.setWallMotion(w, WallMotion{{}, Quat{}, {}, {0.0, 0.0, sign * omega}});
        for (int i = 0; i < 5; ++i) model.evaluateForces(1e-5);  // the tangential spring loads
        const Vec3 force = model.wallReaction(w);
        const Vec3 torque = model.wallReactionTorque(w) + cross(model.wall(w).origin - pivot, force);
        const double axial = dot(Vec3{0, 0, 1}, torque);
        const Vec3 friction =
            model.cells().force[0] - dot(model.cells().force[0], Vec3{0, 0, 1}) * Vec3{0, 0, 1};
        INFO("spin " << sign * omega << " rad/s: cell force " << model.cells().force[0].x << " "
                     << model.cells().force[0].y << " " << model.cells().force[0].z << ", axial torque "
                     << axial << " N m, wall power " << model.wallPower(w) << " W");
        REQUIRE(norm(friction) > 1e-3 * std::abs(model.cells().force[0].z));
        CHECK(sign * axial < 0.0);
        CHECK(model.wallPower(w) + sign * omega * axial ==
              Approx(0.0).margin(1e-9 * std::abs(model.wallPower(w))));
        CHECK(model.wallPower(w) > 0.0);  // the sliding floor drags the cell along
    }
}
