#pragma once
// Triangulated surfaces: STL input/output, watertightness checks, and the mass
// properties (volume, centroid, inertia, extents) of the solid they bound.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "core/vec3.hpp"

namespace rockfrac {

struct TriSurface {
    std::vector<Vec3> points;
    std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from outside
};

// ASCII or binary STL (detected from the content). Coincident vertices are
// welded. UserError naming the file for unreadable, truncated, empty or
// non-finite input.
TriSurface readStl(const std::filesystem::path& file);
// The same from the file's bytes already in memory; `file` only names it in
// messages (the STL fuzz target, tests/fuzz/stl, calls this).
TriSurface parseStl(const std::string& bytes, const std::filesystem::path& file);
// ASCII STL, written atomically.
void writeStl(const std::filesystem::path& file, const TriSurface& surface, const std::string& solidName);

struct SurfaceCheck {
    int boundaryEdges = 0;     // edges used by one triangle: holes
    int nonManifoldEdges = 0;  // edges used by more than two triangles
    int misorientedEdges = 0;  // edges traversed twice in the same direction
    int degenerateTriangles = 0;
    bool watertight() const { return boundaryEdges == 0 && nonManifoldEdges == 0 && misorientedEdges == 0; }
    std::string reason() const;  // empty when watertight
};
SurfaceCheck checkSurface(const TriSurface& surface);

struct MassProperties {
    double volume = 0.0;        // [m^3]
    Vec3 centroid;              // [m]
    Mat3 inertia;               // second moment of volume about the centroid [m^5]
    Vec3 principalMoments;      // eigenvalues of inertia, ascending [m^5]
    Mat3 principalAxes;         // columns: unit axes matching principalMoments
    Vec3 boundsMin, boundsMax;  // axis-aligned bounding box [m]
    Vec3 principalExtents;      // extents along the principal axes, sorted descending [m]
};
// By the divergence theorem over the triangles; the surface must be closed.
MassProperties massProperties(const TriSurface& surface);

// x -> R (scale x) + t applied to every point.
void transformSurface(TriSurface& surface, double scale, const Mat3& rotation, const Vec3& translation);
// Rotation from angles in degrees about x, then y, then z (extrinsic).
Mat3 rotationFromDegrees(const Vec3& anglesDeg);

// Closed triangulated cylinder with its axis along y, centred at `centre`.
TriSurface discSurface(double diameter, double thickness, const Vec3& centre, int nSegments);

// Symmetric 3x3 eigen-decomposition (Jacobi), ascending eigenvalues, vectors as columns.
void symmetricEigen(const Mat3& A, Vec3& values, Mat3& vectors);

}  // namespace rockfrac
