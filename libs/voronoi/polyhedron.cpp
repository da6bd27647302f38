#include "voronoi/polyhedron.hpp"

namespace rockfrac {

namespace {

// Outer product a b^T added into M with weight w.
void addOuterProduct(Mat3& M, const Vec3& a, const Vec3& b, double w)
{
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) M.m[i][j] += w * a[i] * b[j];
}

// Mean of all vertices referenced by the faces: an interior point of a convex
// polyhedron, used as the apex of the tetrahedra so their volumes are small
// numbers with little cancellation.
Vec3 vertexMean(const PolyhedronView& poly)
{
    Vec3 sum;
    int count = 0;
    for (int f = 0; f < poly.nFaces; ++f) {
        for (int k = 0; k < poly.faceSize(f); ++k) sum += poly.faceVertex(f, k);
        count += poly.faceSize(f);
    }
    return count > 0 ? sum / count : sum;
}

// Calls visit(a, b, c) for each triangle of a fan over every face (a = the
// face's first vertex), all counter-clockwise seen from outside.
template <class Visitor>
void forEachFaceTriangle(const PolyhedronView& poly, Visitor&& visit)
{
    for (int f = 0; f < poly.nFaces; ++f) {
        const Vec3& a = poly.faceVertex(f, 0);
        for (int k = 1; k + 1 < poly.faceSize(f); ++k)
            visit(a, poly.faceVertex(f, k), poly.faceVertex(f, k + 1));
    }
}

}  // namespace

Vec3 faceAreaVector(const PolyhedronView& poly, int f)
{
    const Vec3& a = poly.faceVertex(f, 0);
    Vec3 twiceArea;
    for (int k = 1; k + 1 < poly.faceSize(f); ++k)
        twiceArea += cross(poly.faceVertex(f, k) - a, poly.faceVertex(f, k + 1) - a);
    return 0.5 * twiceArea;
}

Vec3 faceCentre(const PolyhedronView& poly, int f)
{
    Vec3 sum;
    for (int k = 0; k < poly.faceSize(f); ++k) sum += poly.faceVertex(f, k);
    return sum / poly.faceSize(f);
}

CellMassProperties massProperties(const PolyhedronView& poly)
{
    CellMassProperties result;

    // Volume and centroid from tetrahedra (apex, a, b, c): the centroid of a
    // tetrahedron is the mean of its four corners.
    const Vec3 apex = vertexMean(poly);
    double sixVolume = 0.0;
    Vec3 weightedCentre;  // sum of 6V_tet * 4 * centroid_tet, relative to apex
    forEachFaceTriangle(poly, [&](const Vec3& a, const Vec3& b, const Vec3& c) {
        const Vec3 pa = a - apex, pb = b - apex, pc = c - apex;
        const double tet6 = dot(pa, cross(pb, pc));
        sixVolume += tet6;
        weightedCentre += tet6 * (pa + pb + pc);
    });
    result.volume = sixVolume / 6.0;
    result.centroid = sixVolume != 0.0 ? apex + weightedCentre / (4.0 * sixVolume) : apex;

    // Second moment C = integral of r r^T dV over tetrahedra (centroid, a, b, c):
    // for a tetrahedron with one corner at the origin and the others at p, q, s,
    // C = V/20 (p p^T + q q^T + s s^T + (p+q+s)(p+q+s)^T).
    Mat3 secondMoment;
    forEachFaceTriangle(poly, [&](const Vec3& a, const Vec3& b, const Vec3& c) {
        const Vec3 p = a - result.centroid, q = b - result.centroid, s = c - result.centroid;
        const double weight = dot(p, cross(q, s)) / 6.0 / 20.0;
        const Vec3 sum = p + q + s;
        addOuterProduct(secondMoment, p, p, weight);
        addOuterProduct(secondMoment, q, q, weight);
        addOuterProduct(secondMoment, s, s, weight);
        addOuterProduct(secondMoment, sum, sum, weight);
    });

    // Inertia per unit density: J = tr(C) I - C.
    const double trace = secondMoment.m[0][0] + secondMoment.m[1][1] + secondMoment.m[2][2];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) result.inertia.m[i][j] = (i == j ? trace : 0.0) - secondMoment.m[i][j];
    return result;
}

}  // namespace rockfrac
