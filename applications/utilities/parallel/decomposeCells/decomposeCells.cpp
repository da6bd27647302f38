// decomposeCells: how a Voronoi cell mesh splits into subdomains, and what each must exchange.
//
// Reads  constant/voronoiMesh/, system/decomposeParDict (numberOfSubdomains, method, weights)
// Writes postProcessing/decomposeCells/decomposition.dat   one row per subdomain
//        VTK/decomposition.vtu                             cells coloured by subdomain
//
// The decomposition a parallel bondedDemFoam run starts from (the same method, weights and
// tie-breaking), with the halo it implies: the ghost cells each subdomain must see (within the
// two cells' reaches plus the contact margin 2 r_d and a skin r_d) and the interfaces cut
// between subdomains. `-subdomains N` overrides numberOfSubdomains for a study of the halo at
// other sizes (docs/applications/decomposeCells.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/application.hpp"
#include "core/atomicFile.hpp"
#include "core/error.hpp"
#include "io/vtkOutput.hpp"
#include "parallel/decomposition.hpp"
#include "voronoi/voronoiMeshIO.hpp"

using namespace rockfrac;
namespace fs = std::filesystem;

namespace {

const AppInfo info{
    "decomposeCells",
    "Splits the case's Voronoi cells into subdomains as system/decomposeParDict says\n"
    "(recursive coordinate bisection weighted by each cell's cost) and reports, per subdomain,\n"
    "its cells, weight, ghost cells and cut interfaces: the load balance and the halo a\n"
    "parallel run exchanges. Writes a table and the cells coloured by subdomain for ParaView.",
    "[options]",
    {"decomposeCells -case tutorials/BDT/granite",
     "decomposeCells -case tutorials/BDT/granite -subdomains 16"},
    {{"-subdomains", "N", "use N subdomains instead of the dictionary's numberOfSubdomains"},
     {"-margin", "m", "interaction margin beyond the two cells' reaches [m] (default: 3 r_d of the mesh)"},
     {"-noVTK", "", "do not write VTK/decomposition.vtu"}},
};

int parseCount(const std::string& text, const char* option)
{
    std::size_t used = 0;
    long value = -1;
    try {
        value = std::stol(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || value < 1 || value > (1 << 20))
        throw UserError(std::string(option) + " " + text + ": expected a whole number in [1, 1048576]");
    return static_cast<int>(value);
}

double parseLength(const std::string& text, const char* option)
{
    std::size_t used = 0;
    double value = -1;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || !(value >= 0.0) || !std::isfinite(value))
        throw UserError(std::string(option) + " " + text + ": expected a length >= 0 in metres");
    return value;
}

}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, [](Application& app) {
        DecomposeParameters p = readDecomposeParDict(app.casePath());
        if (const auto n = app.optionIf("-subdomains")) p.n_subdomains = parseCount(*n, "-subdomains");
        const VoronoiMesh mesh = readVoronoiMesh(app.casePath());
        const int n = mesh.nCells();
        const double margin =
            app.has("-margin") ? parseLength(app.option("-margin"), "-margin") : 3.0 * mesh.dilationRadius;

        // Cost: 1 + the bond ends of the cell (its bond evaluations per step), an estimate
        // of the cell's work before a run has measured it; reach: the farthest vertex.
        std::vector<double> weights(n, 1.0), reach(n, 0.0);
        if (p.cost_weights)
            for (const VoronoiBond& b : mesh.bonds) {
                weights[b.cellI] += 1.0;
                weights[b.cellJ] += 1.0;
            }
        for (int c = 0; c < n; ++c)
            for (int v = mesh.cellVertexOffset[c]; v < mesh.cellVertexOffset[c + 1]; ++v)
                reach[c] = std::max(reach[c], norm(mesh.vertices[v] - mesh.centroids[c]));
        std::vector<std::pair<int, int>> interfaces;
        for (int c = 0; c < n; ++c)
            for (int f = mesh.cellFaceOffset[c]; f < mesh.cellFaceOffset[c + 1]; ++f)
                if (mesh.faceNeighbour[f] > c) interfaces.emplace_back(c, mesh.faceNeighbour[f]);

        const std::vector<int> part_of = p.method->decompose(mesh.centroids, weights, p.n_subdomains);
        const HaloReport halo =
            haloReport(mesh.centroids, reach, weights, interfaces, part_of, p.n_subdomains, margin);

        std::printf("%d cells, %zu interfaces into %d subdomains (%s, %s weights), margin %.4g mm\n", n,
                    interfaces.size(), p.n_subdomains, p.method->type(), p.cost_weights ? "cost" : "uniform",
                    1e3 * margin);
        std::printf("%10s %8s %12s %8s %8s %11s\n", "subdomain", "cells", "weight", "ghosts", "cut",
                    "neighbours");
        for (int s = 0; s < p.n_subdomains; ++s) {
            const SubdomainHalo& h = halo.subdomains[s];
            std::printf("%10d %8d %12.6g %8d %8d %11d\n", s, h.cells, h.weight, h.ghost_cells,
                        h.cut_interfaces, h.neighbours);
        }
        std::printf(
            "Imbalance (max/mean - 1): %.4g %%; ghost cells per cell: %.4g; cut interfaces: %ld of %zu\n",
            100.0 * halo.imbalance, static_cast<double>(halo.ghost_cells) / n, halo.cut_interfaces,
            interfaces.size());
        if (app.dryRun()) {
            std::printf("Dry run: nothing written.\n");
            return 0;
        }
        const fs::path table = app.path("postProcessing/decomposeCells/decomposition.dat");
        writeFileAtomically(table, [&](std::ostream& out) {
            out << "# decomposeCells: " << p.n_subdomains << " subdomains, method " << p.method->type()
                << ", weights " << (p.cost_weights ? "cost" : "uniform") << ", margin " << margin
                << " m, imbalance " << halo.imbalance
                << "\n# subdomain\tcells\tweight\tghostCells\tcutInterfaces\tneighbours\n";
            for (int s = 0; s < p.n_subdomains; ++s) {
                const SubdomainHalo& h = halo.subdomains[s];
                out << s << '\t' << h.cells << '\t' << h.weight << '\t' << h.ghost_cells << '\t'
                    << h.cut_interfaces << '\t' << h.neighbours << '\n';
            }
        });
        std::string written = "postProcessing/decomposeCells/decomposition.dat";
        if (!app.has("-noVTK")) {
            PolyhedronSet cells;
            cells.points = mesh.vertices;
            cells.cellFaceOffset = mesh.cellFaceOffset;
            cells.faceVertexOffset = mesh.faceVertexOffset;
            cells.faceVertices = mesh.globalFaceVertices();
            writePolyhedraVtu(app.path("VTK/decomposition.vtu"), cells,
                              {Field::integer("processor", part_of), Field::scalar("weight", weights)}, 0.0);
            written += ", VTK/decomposition.vtu";
        }
        std::printf("End: written %s\n", written.c_str());
        return 0;
    });
}
