#pragma once
// Geometry of one convex polyhedron given as vertices and faces, shared by the
// domain (volume of a hull) and the tessellation (volume, centroid and inertia
// of every cell), so both are computed by the same arithmetic.
#include <vector>

#include "core/vec3.hpp"

namespace rockfrac {

// A read-only view of one polyhedron in compressed (CSR) form: face f lists
// indices into `vertices` in faceVertices[faceVertexOffset[f] .. [f+1]),
// counter-clockwise seen from outside. faceVertexOffset has nFaces + 1 entries
// and may point into the middle of a larger array (a cell of a mesh).
struct PolyhedronView {
    const Vec3* vertices = nullptr;
    const int* faceVertexOffset = nullptr;
    const int* faceVertices = nullptr;
    int nFaces = 0;

    int faceSize(int f) const { return faceVertexOffset[f + 1] - faceVertexOffset[f]; }
    const Vec3& faceVertex(int f, int k) const { return vertices[faceVertices[faceVertexOffset[f] + k]]; }
};

// Area vector of face f: the outward unit normal times the area (half the sum
// of the cross products of a triangle fan, exact for a planar polygon).
Vec3 faceAreaVector(const PolyhedronView& poly, int f);

// Mean of the vertices of face f: a point on the face plane.
Vec3 faceCentre(const PolyhedronView& poly, int f);

struct CellMassProperties {
    double volume = 0.0;  // [m^3]
    Vec3 centroid;        // centre of volume [m]
    // Inertia tensor per unit density about the centroid,
    // J = integral of (|r|^2 I - r r^T) dV with r = x - centroid [m^5].
    Mat3 inertia;
};

// Volume, centroid and inertia of a closed polyhedron with outward faces,
// exact up to round-off: the solid is split into tetrahedra (a reference
// point, then the centroid, and a triangle fan of each face) whose moments
// have closed forms.
CellMassProperties massProperties(const PolyhedronView& poly);

}  // namespace rockfrac
