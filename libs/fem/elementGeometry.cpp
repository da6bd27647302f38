// Shape-function gradients of linear tetrahedra.
#include "fem/elementGeometry.hpp"

namespace rockfrac::fem {

namespace {

// With edge vectors d_k = x_k - x_0 and det = d1 . (d2 x d3) = 6V, the gradients
// of the barycentric shape functions are the rows of the inverse Jacobian:
// grad N1 = (d2 x d3)/det, grad N2 = (d3 x d1)/det, grad N3 = (d1 x d2)/det, and
// grad N0 = -(grad N1 + grad N2 + grad N3) because the N_a sum to one.
void shapeGradients(const Vec3 x[4], double* gradients)
{
    const Vec3 d1 = x[1] - x[0], d2 = x[2] - x[0], d3 = x[3] - x[0];
    const double det = dot(d1, cross(d2, d3));
    const Vec3 g[4] = {{}, cross(d2, d3) / det, cross(d3, d1) / det, cross(d1, d2) / det};
    const Vec3 g0 = -(g[1] + g[2] + g[3]);
    const Vec3 all[4] = {g0, g[1], g[2], g[3]};
    for (int a = 0; a < 4; ++a)
        for (int j = 0; j < 3; ++j) gradients[3 * a + j] = all[a][j];
}

}  // namespace

ElementGeometry makeElementGeometry(const TetMesh& mesh)
{
    checkTetQuality(mesh);
    ElementGeometry geometry;
    const std::size_t n = mesh.numTets();
    geometry.nodeIds.resize(4 * n);
    geometry.gradients.resize(12 * n);
    geometry.volumes = tetVolumes(mesh);
    geometry.heights = tetSmallestHeights(mesh);
    for (std::size_t e = 0; e < n; ++e) {
        Vec3 x[4];
        for (int a = 0; a < 4; ++a) {
            geometry.nodeIds[4 * e + a] = mesh.tets[e][a];
            x[a] = mesh.nodes[mesh.tets[e][a]];
        }
        shapeGradients(x, &geometry.gradients[12 * e]);
    }
    return geometry;
}

}  // namespace rockfrac::fem
