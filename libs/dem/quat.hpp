#pragma once
// Unit quaternions for the orientation of rigid cells (host and device).
//
// A cell's orientation q maps body-frame vectors (principal axes, origin at the
// centroid) to the world frame: x_world = x_cell + R(q) x_body. Angular
// velocities are kept in the body frame, so the orientation advances by a
// right multiplication q <- q * exp(omega_body dt / 2).
#include <cmath>

#include "core/vec3.hpp"

namespace rockfrac {

struct Quat {
    double w = 1.0, x = 0.0, y = 0.0, z = 0.0;

    constexpr Quat() = default;  // defaulted: host and device alike
    RF_HD constexpr Quat(double w_, double x_, double y_, double z_) : w(w_), x(x_), y(y_), z(z_) {}
};

RF_HD inline Quat operator*(const Quat& a, const Quat& b)
{
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

// Component-wise equality (not rotation equality: q and -q compare unequal).
RF_HD inline bool operator==(const Quat& a, const Quat& b)
{
    return a.w == b.w && a.x == b.x && a.y == b.y && a.z == b.z;
}

RF_HD inline Quat conjugate(const Quat& q)
{
    return {q.w, -q.x, -q.y, -q.z};
}

RF_HD inline Quat normalised(const Quat& q)
{
    const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return {q.w / n, q.x / n, q.y / n, q.z / n};
}

// The rotation by the angle |theta| about theta/|theta| (the exponential map),
// exactly unit for any angle, with a Taylor branch near zero.
RF_HD inline Quat quatFromRotationVector(const Vec3& theta)
{
    const double angle = norm(theta);
    const double half = 0.5 * angle;
    const double s = angle > 1e-8 ? std::sin(half) / angle : 0.5 - angle * angle / 48.0;
    return {std::cos(half), s * theta.x, s * theta.y, s * theta.z};
}

// Rotation matrix R(q) (body to world).
RF_HD inline Mat3 rotationMatrix(const Quat& q)
{
    const double xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
    const double xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
    const double wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
    Mat3 R;
    R.m[0][0] = 1.0 - 2.0 * (yy + zz);
    R.m[0][1] = 2.0 * (xy - wz);
    R.m[0][2] = 2.0 * (xz + wy);
    R.m[1][0] = 2.0 * (xy + wz);
    R.m[1][1] = 1.0 - 2.0 * (xx + zz);
    R.m[1][2] = 2.0 * (yz - wx);
    R.m[2][0] = 2.0 * (xz - wy);
    R.m[2][1] = 2.0 * (yz + wx);
    R.m[2][2] = 1.0 - 2.0 * (xx + yy);
    return R;
}

// R^T v without forming the transpose.
RF_HD inline Vec3 transposeTimes(const Mat3& R, const Vec3& v)
{
    return {R.m[0][0] * v.x + R.m[1][0] * v.y + R.m[2][0] * v.z,
            R.m[0][1] * v.x + R.m[1][1] * v.y + R.m[2][1] * v.z,
            R.m[0][2] * v.x + R.m[1][2] * v.y + R.m[2][2] * v.z};
}

// Quaternion of a proper rotation matrix (Shepperd's method, stable for all angles).
RF_HD inline Quat quatFromRotationMatrix(const Mat3& R)
{
    const double trace = R.m[0][0] + R.m[1][1] + R.m[2][2];
    Quat q;
    if (trace > 0.0) {
        const double s = 2.0 * std::sqrt(trace + 1.0);
        q = {0.25 * s, (R.m[2][1] - R.m[1][2]) / s, (R.m[0][2] - R.m[2][0]) / s, (R.m[1][0] - R.m[0][1]) / s};
    } else if (R.m[0][0] > R.m[1][1] && R.m[0][0] > R.m[2][2]) {
        const double s = 2.0 * std::sqrt(1.0 + R.m[0][0] - R.m[1][1] - R.m[2][2]);
        q = {(R.m[2][1] - R.m[1][2]) / s, 0.25 * s, (R.m[0][1] + R.m[1][0]) / s, (R.m[0][2] + R.m[2][0]) / s};
    } else if (R.m[1][1] > R.m[2][2]) {
        const double s = 2.0 * std::sqrt(1.0 + R.m[1][1] - R.m[0][0] - R.m[2][2]);
        q = {(R.m[0][2] - R.m[2][0]) / s, (R.m[0][1] + R.m[1][0]) / s, 0.25 * s, (R.m[1][2] + R.m[2][1]) / s};
    } else {
        const double s = 2.0 * std::sqrt(1.0 + R.m[2][2] - R.m[0][0] - R.m[1][1]);
        q = {(R.m[1][0] - R.m[0][1]) / s, (R.m[0][2] + R.m[2][0]) / s, (R.m[1][2] + R.m[2][1]) / s, 0.25 * s};
    }
    return normalised(q);
}

}  // namespace rockfrac
