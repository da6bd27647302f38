#pragma once
// Small fixed-size vector and matrix types usable on host and device.
//
// The DEM and FEM kernels are written once as plain functions over indices so
// that the OpenMP and CUDA backends share them; these types therefore avoid
// anything that is not available in device code (no exceptions, no heap).
#include <cmath>

#if defined(__CUDACC__)
#define RF_HD __host__ __device__
#else
#define RF_HD
#endif

// Inline a small hot function into its kernel loop whatever the compiler's size heuristics
// say (the bond law into the interface kernel: docs/benchmarks.md, profile-driven changes).
#if defined(__CUDACC__)
#define RF_FORCE_INLINE __forceinline__
#elif defined(__GNUC__)
#define RF_FORCE_INLINE inline __attribute__((always_inline))
#else
#define RF_FORCE_INLINE inline
#endif

namespace rockfrac {

struct Vec3 {
    double x = 0.0, y = 0.0, z = 0.0;

    constexpr Vec3() = default;  // defaulted: host and device alike
    RF_HD constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}

    RF_HD double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    RF_HD double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }

    RF_HD Vec3& operator+=(const Vec3& b)
    {
        x += b.x;
        y += b.y;
        z += b.z;
        return *this;
    }
    RF_HD Vec3& operator-=(const Vec3& b)
    {
        x -= b.x;
        y -= b.y;
        z -= b.z;
        return *this;
    }
    RF_HD Vec3& operator*=(double s)
    {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    RF_HD Vec3& operator/=(double s)
    {
        x /= s;
        y /= s;
        z /= s;
        return *this;
    }
};

RF_HD inline Vec3 operator+(Vec3 a, const Vec3& b)
{
    return a += b;
}
RF_HD inline Vec3 operator-(Vec3 a, const Vec3& b)
{
    return a -= b;
}
RF_HD inline Vec3 operator-(const Vec3& a)
{
    return {-a.x, -a.y, -a.z};
}
RF_HD inline Vec3 operator*(Vec3 a, double s)
{
    return a *= s;
}
RF_HD inline Vec3 operator*(double s, Vec3 a)
{
    return a *= s;
}
RF_HD inline Vec3 operator/(Vec3 a, double s)
{
    return a /= s;
}
RF_HD inline bool operator==(const Vec3& a, const Vec3& b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}
RF_HD inline bool operator!=(const Vec3& a, const Vec3& b)
{
    return !(a == b);
}

RF_HD inline double dot(const Vec3& a, const Vec3& b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
RF_HD inline Vec3 cross(const Vec3& a, const Vec3& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
RF_HD inline double norm2(const Vec3& a)
{
    return dot(a, a);
}
RF_HD inline double norm(const Vec3& a)
{
    return std::sqrt(dot(a, a));
}
// Unit vector along a; the zero vector stays zero (no NaN from 0/0).
RF_HD inline Vec3 normalised(const Vec3& a)
{
    const double n = norm(a);
    return n > 0.0 ? a / n : Vec3{};
}

// Row-major 3x3 matrix.
struct Mat3 {
    double m[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};

    RF_HD static Mat3 identity()
    {
        Mat3 I;
        I.m[0][0] = I.m[1][1] = I.m[2][2] = 1.0;
        return I;
    }
    RF_HD double& operator()(int i, int j) { return m[i][j]; }
    RF_HD double operator()(int i, int j) const { return m[i][j]; }
};

RF_HD inline Vec3 operator*(const Mat3& A, const Vec3& v)
{
    return {A.m[0][0] * v.x + A.m[0][1] * v.y + A.m[0][2] * v.z,
            A.m[1][0] * v.x + A.m[1][1] * v.y + A.m[1][2] * v.z,
            A.m[2][0] * v.x + A.m[2][1] * v.y + A.m[2][2] * v.z};
}
RF_HD inline Mat3 operator*(const Mat3& A, const Mat3& B)
{
    Mat3 C;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            C.m[i][j] = A.m[i][0] * B.m[0][j] + A.m[i][1] * B.m[1][j] + A.m[i][2] * B.m[2][j];
    return C;
}
RF_HD inline Mat3 transpose(const Mat3& A)
{
    Mat3 T;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) T.m[i][j] = A.m[j][i];
    return T;
}

}  // namespace rockfrac
