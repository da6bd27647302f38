#pragma once
// Meshes for the fem unit tests, built through the gmsh API.
#include <gmsh.h>
#include <omp.h>

#include <cmath>

#include "fem/tetMesh.hpp"

namespace rockfrac::fem::test {

// gmsh for the lifetime of one test case, silent. gmsh meshes with one thread and
// sets the process-wide OpenMP thread count to it (in initialize and generate), so the
// caller's count is restored after each of those calls.
struct GmshSession {
    GmshSession() : callerThreads(omp_get_max_threads())
    {
        gmsh::initialize(0, nullptr, false);
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::model::add("test");
        omp_set_num_threads(callerThreads);
    }
    ~GmshSession()
    {
        gmsh::finalize();
        omp_set_num_threads(callerThreads);
    }
    // Meshes the current model in 3D and returns its tets, keeping the thread count.
    // Meshing runs on one thread so the mesh does not depend on OMP_NUM_THREADS.
    TetMesh generate() const
    {
        omp_set_num_threads(1);
        gmsh::model::mesh::generate(3);
        omp_set_num_threads(callerThreads);
        return tetMeshFromGmshModel();
    }
    const int callerThreads;
    GmshSession(const GmshSession&) = delete;
    GmshSession& operator=(const GmshSession&) = delete;
};

// Unstructured tets in the box [0, lx] x [0, ly] x [0, lz] with target size h
// (Delaunay in 3D gives an irregular mesh).
inline TetMesh boxMesh(const GmshSession& session, double lx, double ly, double lz, double h)
{
    gmsh::model::occ::addBox(0, 0, 0, lx, ly, lz);
    gmsh::model::occ::synchronize();
    gmsh::option::setNumber("Mesh.CharacteristicLengthMax", h);
    gmsh::option::setNumber("Mesh.CharacteristicLengthMin", 0.5 * h);
    return session.generate();
}

// A single regular tetrahedron with edge a.
inline TetMesh regularTet(double a)
{
    TetMesh mesh;
    mesh.nodes = {{0, 0, 0},
                  {a, 0, 0},
                  {0.5 * a, 0.5 * std::sqrt(3.0) * a, 0},
                  {0.5 * a, std::sqrt(3.0) / 6.0 * a, std::sqrt(2.0 / 3.0) * a}};
    mesh.tets = {{0, 1, 2, 3}};
    mesh.tetTags = {0};
    return mesh;
}

}  // namespace rockfrac::fem::test
