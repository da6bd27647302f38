// GJK's distance between random convex polytopes against a brute-force distance.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "dem/gjk.hpp"
#include "dem/quat.hpp"

using namespace rockfrac;

namespace {

double pointSegment(const Vec3& p, const Vec3& a, const Vec3& b)
{
    const Vec3 ab = b - a;
    const double t = std::clamp(dot(p - a, ab) / norm2(ab), 0.0, 1.0);
    return norm(p - (a + t * ab));
}

double pointTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    const Vec3 normal = normalised(cross(b - a, c - a));
    const Vec3 projected = p - dot(p - a, normal) * normal;
    // Inside test by the signs of the sub-triangle normals.
    const double s1 = dot(cross(b - a, projected - a), normal);
    const double s2 = dot(cross(c - b, projected - b), normal);
    const double s3 = dot(cross(a - c, projected - c), normal);
    if ((s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0))
        return std::fabs(dot(p - a, normal));
    return std::min({pointSegment(p, a, b), pointSegment(p, b, c), pointSegment(p, c, a)});
}

double segmentSegment(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2)
{
    // Dense search along the first segment, refined: brute force, independent of GJK.
    double best = 1e300;
    double lo = 0.0, hi = 1.0;
    for (int level = 0; level < 6; ++level) {
        double best_t = lo;
        for (int i = 0; i <= 200; ++i) {
            const double t = lo + (hi - lo) * i / 200.0;
            const double d = pointSegment(p1 + t * (q1 - p1), p2, q2);
            if (d < best) {
                best = d;
                best_t = t;
            }
        }
        const double width = (hi - lo) / 100.0;
        lo = std::max(0.0, best_t - width);
        hi = std::min(1.0, best_t + width);
    }
    return best;
}

// Distance between the hulls of two separated point sets: the minimum over
// vertex–triangle, triangle–vertex and edge–edge pairs of all point subsets.
double bruteForceDistance(const std::vector<Vec3>& A, const std::vector<Vec3>& B)
{
    double best = 1e300;
    auto vertexTriangles = [&](const std::vector<Vec3>& points, const std::vector<Vec3>& others) {
        for (const Vec3& p : points) {
            for (const Vec3& o : others) best = std::min(best, norm(p - o));
            for (std::size_t i = 0; i < others.size(); ++i)
                for (std::size_t j = i + 1; j < others.size(); ++j)
                    for (std::size_t k = j + 1; k < others.size(); ++k)
                        best = std::min(best, pointTriangle(p, others[i], others[j], others[k]));
        }
    };
    vertexTriangles(A, B);
    vertexTriangles(B, A);
    for (std::size_t i = 0; i < A.size(); ++i)
        for (std::size_t j = i + 1; j < A.size(); ++j)
            for (std::size_t k = 0; k < B.size(); ++k)
                for (std::size_t l = k + 1; l < B.size(); ++l)
                    best = std::min(best, segmentSegment(A[i], A[j], B[k], B[l]));
    return best;
}

// Largest gap between the projections of the two sets over many directions (> 0: separated).
double bestSeparatingGap(const std::vector<Vec3>& A, const std::vector<Vec3>& B, std::mt19937& random)
{
    std::normal_distribution<double> normal;
    double best = -1e300;
    for (int trial = 0; trial < 20000; ++trial) {
        const Vec3 u = normalised(Vec3{normal(random), normal(random), normal(random)});
        double max_a = -1e300, min_b = 1e300;
        for (const Vec3& a : A) max_a = std::max(max_a, dot(a, u));
        for (const Vec3& b : B) min_b = std::min(min_b, dot(b, u));
        best = std::max(best, min_b - max_a);
    }
    return best;
}

}  // namespace

TEST_CASE("GJK distance against brute force for random polytope pairs", "[dem][gjk]")
{
    std::mt19937 random(12345);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    int separated = 0, intersecting = 0;
    for (int trial = 0; trial < 150; ++trial) {
        const int na = 4 + trial % 6, nb = 4 + (trial / 6) % 6;
        std::vector<Vec3> A(na), B(nb);
        for (Vec3& v : A) v = {uniform(random), uniform(random), 0.5 * uniform(random)};
        const Vec3 offset{1.5 * uniform(random), 1.5 * uniform(random), 1.5 * uniform(random)};
        for (Vec3& v : B) v = offset + Vec3{0.7 * uniform(random), uniform(random), uniform(random)};
        // Place B with a rotation to exercise the support mapping.
        ConvexVertexSet a, b;
        a.vertices = A.data();
        a.n_vertices = na;
        const Mat3 R = rotationMatrix(quatFromRotationVector({0.3 * trial, -0.2, 0.1 * trial}));
        std::vector<Vec3> B_local(nb);
        const Vec3 shift{0.1, -0.2, 0.3};
        for (int i = 0; i < nb; ++i) B_local[i] = transposeTimes(R, B[i] - shift);
        b.vertices = B_local.data();
        b.n_vertices = nb;
        b.position = shift;
        b.rotation = R;
        const GjkResult gjk = gjkDistance(a, b, {1.0, 0.0, 0.0});
        INFO("trial " << trial);
        if (gjk.intersecting) {
            ++intersecting;
            CHECK(bestSeparatingGap(A, B, random) < 1e-9);
            continue;
        }
        ++separated;
        const double brute = bruteForceDistance(A, B);
        CHECK(gjk.distance == Approx(brute).epsilon(1e-6).margin(1e-9));
        CHECK(norm(gjk.point_a - gjk.point_b) == Approx(gjk.distance).epsilon(1e-9));
        // The witness points certify optimality: the slab between them separates the sets.
        const Vec3 u = (gjk.point_b - gjk.point_a) / gjk.distance;
        for (const Vec3& v : A) CHECK(dot(v - gjk.point_a, u) <= 1e-9);
        for (const Vec3& v : B) CHECK(dot(v - gjk.point_b, u) >= -1e-9);
    }
    CHECK(separated > 30);
    CHECK(intersecting > 10);
}
