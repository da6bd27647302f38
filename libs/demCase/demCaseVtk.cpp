// bondedDemFoam case: VTK output of cells and bonds.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "demCase/demCase.hpp"
#include "io/vtkOutput.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

// ---- VTK ------------------------------------------------------------------------

CellShapes captureCellShapes(const VoronoiMesh& mesh, const DemModel& model)
{
    CellShapes s;
    s.cellVertexOffset = mesh.cellVertexOffset;
    s.cellFaceOffset = mesh.cellFaceOffset;
    s.faceVertexOffset = mesh.faceVertexOffset;
    s.faceVertices.resize(mesh.faceVertices.size());
    s.bodyVertices.resize(mesh.vertices.size());
    const CellArrays& cells = model.cells();
    for (int c = 0; c < mesh.nCells(); ++c) {
        const Mat3 R = rotationMatrix(cells.orientation[c]);
        for (int v = mesh.cellVertexOffset[c]; v < mesh.cellVertexOffset[c + 1]; ++v)
            s.bodyVertices[v] = transposeTimes(R, mesh.vertices[v] - cells.position[c]);
        for (int f = mesh.cellFaceOffset[c]; f < mesh.cellFaceOffset[c + 1]; ++f)
            for (int k = mesh.faceVertexOffset[f]; k < mesh.faceVertexOffset[f + 1]; ++k)
                s.faceVertices[k] = mesh.cellVertexOffset[c] + mesh.faceVertices[k];
    }
    return s;
}

void writeDemVtk(const fs::path& caseDir, int index, const DemModel& model, const CellShapes& shapes,
                 bool restarted)
{
    const CellArrays& cells = model.cells();
    const double time = model.time();
    const std::string suffix = "_" + std::to_string(index);

    PolyhedronSet polyhedra;
    polyhedra.cellFaceOffset = shapes.cellFaceOffset;
    polyhedra.faceVertexOffset = shapes.faceVertexOffset;
    polyhedra.faceVertices = shapes.faceVertices;
    polyhedra.points.resize(shapes.bodyVertices.size());
    std::vector<int> ids(cells.size());
    for (int c = 0; c < cells.size(); ++c) {
        ids[c] = c;
        const Mat3 R = rotationMatrix(cells.orientation[c]);
        for (int v = shapes.cellVertexOffset[c]; v < shapes.cellVertexOffset[c + 1]; ++v)
            polyhedra.points[v] = cells.position[c] + R * shapes.bodyVertices[v];
    }
    const fs::path vtk = caseDir / "VTK";
    writePolyhedraVtu(vtk / ("cells" + suffix + ".vtu"), polyhedra,
                      {Field::integer("cellId", ids), Field::scalar("damage", model.cellDamage()),
                       Field::vector("velocity", cells.velocity)},
                      time);

    // Bonds: through the anchor points along the bond normal, from the plane of
    // cell i's centroid to that of cell j's, coloured by D.
    const InterfaceArrays& faces = model.interfaces();
    const BondArrays& bonds = model.bonds();
    std::vector<Vec3> points;
    std::vector<std::array<int, 2>> lines;
    std::vector<double> damage;
    points.reserve(2 * bonds.size());
    for (int k = 0; k < faces.size(); ++k) {
        const int i = faces.cell_i[k], j = faces.cell_j[k];
        const Mat3 Ri = rotationMatrix(cells.orientation[i]), Rj = rotationMatrix(cells.orientation[j]);
        const Vec3 ni = Ri * faces.normal_i[k], nj = Rj * faces.normal_j[k];
        for (int b = faces.bond_offset[k]; b < faces.bond_offset[k + 1]; ++b) {
            const int first = static_cast<int>(points.size());
            points.push_back(cells.position[i] + Ri * bonds.anchor_i[b] - faces.length_i[k] * ni);
            points.push_back(cells.position[j] + Rj * bonds.anchor_j[b] - faces.length_j[k] * nj);
            lines.push_back({first, first + 1});
            damage.push_back(bonds.damage[b]);
        }
    }
    writeLinesVtp(vtk / ("bonds" + suffix + ".vtp"), points, lines, {Field::scalar("D", damage)}, {}, time);

    for (const auto& [name, ext] :
         {std::pair<std::string, std::string>{"cells", ".vtu"}, {"bonds", ".vtp"}}) {
        SeriesFile series(vtk / (name + ext + ".series"));
        if (!restarted && index == 0) series.truncateFrom(-1.0);
        series.add(name + suffix + ext, time);
        series.write();
    }
}

}  // namespace rockfrac
