#pragma once
// Hand-built Voronoi meshes for the DEM tests: a block of nx x ny x nz boxes,
// with every field a tessellation fills (centroids, volumes, inertia, vertices,
// faces, bonds), so the tests do not depend on the tessellation library.
#include <array>

#include "voronoi/voronoiMesh.hpp"

namespace rockfrac::test {

// Box cells of size (sx, sy, sz) starting at origin; bonded = glue every shared face
// at its four corners (A/n = face area / 4, l_i = l_j = half the cell size). A
// bond_grid of (nu, nv) > (2, 2) glues each face at an nu x nv lattice of points
// instead (corners included), to mimic the ~35 bonds per cell of a Voronoi mesh.
inline VoronoiMesh boxBlockMesh(int nx, int ny, int nz, const Vec3& size, double dilation_radius,
                                bool bonded = true, const Vec3& origin = {},
                                std::array<int, 2> bond_grid = {2, 2})
{
    VoronoiMesh mesh;
    mesh.dilationRadius = dilation_radius;
    auto cellIndex = [&](int i, int j, int k) { return (k * ny + j) * nx + i; };
    const int n_cells = nx * ny * nz;
    const double volume = size.x * size.y * size.z;
    // Inertia per unit density of a box (the tensor, not the covariance).
    Mat3 inertia;
    inertia(0, 0) = volume * (size.y * size.y + size.z * size.z) / 12.0;
    inertia(1, 1) = volume * (size.x * size.x + size.z * size.z) / 12.0;
    inertia(2, 2) = volume * (size.x * size.x + size.y * size.y) / 12.0;
    // The six faces: outward normal, and the corner bits (x, y, z) of their vertices.
    const std::array<Vec3, 6> normals{Vec3{-1, 0, 0}, Vec3{1, 0, 0},  Vec3{0, -1, 0},
                                      Vec3{0, 1, 0},  Vec3{0, 0, -1}, Vec3{0, 0, 1}};
    const int face_corners[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                    {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    const double face_area[6] = {size.y * size.z, size.y * size.z, size.x * size.z,
                                 size.x * size.z, size.x * size.y, size.x * size.y};
    mesh.cellVertexOffset.push_back(0);
    mesh.cellFaceOffset.push_back(0);
    mesh.faceVertexOffset.push_back(0);
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const Vec3 low = origin + Vec3{i * size.x, j * size.y, k * size.z};
                mesh.centroids.push_back(low + 0.5 * size);
                mesh.seeds.push_back(low + 0.5 * size);
                mesh.volumes.push_back(volume);
                mesh.inertia.push_back(inertia);
                for (int corner = 0; corner < 8; ++corner)
                    mesh.vertices.push_back(low + Vec3{(corner & 1) * size.x, ((corner >> 1) & 1) * size.y,
                                                       ((corner >> 2) & 1) * size.z});
                mesh.cellVertexOffset.push_back(static_cast<int>(mesh.vertices.size()));
                const int neighbour[6] = {i > 0 ? cellIndex(i - 1, j, k) : boundaryFace,
                                          i < nx - 1 ? cellIndex(i + 1, j, k) : boundaryFace,
                                          j > 0 ? cellIndex(i, j - 1, k) : boundaryFace,
                                          j < ny - 1 ? cellIndex(i, j + 1, k) : boundaryFace,
                                          k > 0 ? cellIndex(i, j, k - 1) : boundaryFace,
                                          k < nz - 1 ? cellIndex(i, j, k + 1) : boundaryFace};
                for (int f = 0; f < 6; ++f) {
                    for (int v : face_corners[f]) mesh.faceVertices.push_back(v);
                    mesh.faceVertexOffset.push_back(static_cast<int>(mesh.faceVertices.size()));
                    mesh.faceNeighbour.push_back(neighbour[f]);
                    mesh.faceNormal.push_back(normals[f]);
                    mesh.faceArea.push_back(face_area[f]);
                }
                mesh.cellFaceOffset.push_back(static_cast<int>(mesh.faceNeighbour.size()));
            }
    if (!bonded) return mesh;
    // Bonds on the +x, +y, +z faces of each cell (so cellI < cellJ).
    const int n_points = bond_grid[0] * bond_grid[1];
    for (int c = 0; c < n_cells; ++c)
        for (int f = 1; f < 6; f += 2) {
            const int d = mesh.faceNeighbour[6 * c + f];
            if (d == boundaryFace) continue;
            const int axis = f / 2, u_axis = (axis + 1) % 3, v_axis = (axis + 2) % 3;
            for (int point = 0; point < n_points; ++point) {
                const double u = double(point % bond_grid[0]) / (bond_grid[0] - 1);
                const double v = double(point / bond_grid[0]) / (bond_grid[1] - 1);
                VoronoiBond bond;
                bond.cellI = c;
                bond.cellJ = d;
                bond.faceI = 6 * c + f;
                bond.faceJ = 6 * d + f - 1;
                bond.point = mesh.centroids[c] - 0.5 * size;
                bond.point[axis] += size[axis];
                bond.point[u_axis] += u * size[u_axis];
                bond.point[v_axis] += v * size[v_axis];
                bond.normalI = normals[f];
                bond.lI = bond.lJ = 0.5 * size[axis];
                bond.area = face_area[f] / n_points;
                mesh.bonds.push_back(bond);
            }
        }
    return mesh;
}

}  // namespace rockfrac::test
