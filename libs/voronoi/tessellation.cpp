#include "voronoi/tessellation.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>
#include <voro++/voro++.hh>

#include "core/error.hpp"
#include "voronoi/meshTopology.hpp"
#include "voronoi/polyhedron.hpp"
#include "voronoi/seeding.hpp"

namespace rockfrac {

namespace {

constexpr double pi = 3.14159265358979323846;

// Voro++ decides whether a vertex lies on a cutting plane with an absolute
// tolerance (1e-11, in squared length units), so it is fed coordinates in
// which a cell is about 1 long: x' = (x - origin) / scale with scale the cube
// root of the mean cell volume. Vertices come back relative to their seed and
// are mapped to metres as seed + scale * r, keeping full precision.
struct ScaledFrame {
    Vec3 origin;
    double scale = 1.0;

    Vec3 toScaled(const Vec3& x) const { return (x - origin) / scale; }
};

// Voro++ numbers the container's own six walls -1..-6; ours follow.
constexpr int firstDomainWallId = -7;

// The Voronoi cell of one seed, before it is copied into the mesh arrays.
struct CellResult {
    std::vector<Vec3> vertices;   // metres
    std::vector<int> faceOffset;  // local CSR, starts at 0
    std::vector<int> faceVertices;
    std::vector<int> neighbours;  // seed index or boundaryFace
    std::vector<Vec3> faceNormal;
    std::vector<double> faceArea;
    CellMassProperties mass;
};

void checkSeedsInside(const Domain& domain, const std::vector<Vec3>& seeds)
{
    if (seeds.empty()) throw UserError("no seeds to tessellate: ask for at least 2 cells");
    for (std::size_t i = 0; i < seeds.size(); ++i)
        if (!domain.contains(seeds[i])) {
            std::ostringstream msg;
            msg << "seed " << i << " at (" << seeds[i].x << " " << seeds[i].y << " " << seeds[i].z
                << ") lies outside the domain; give seeds inside it";
            throw UserError(msg.str());
        }
}

// Container around the domain's bounding box (with a margin, so its own walls
// never coincide with a domain plane), with blocks holding about five seeds
// each, the density Voro++'s documentation recommends.
std::unique_ptr<voro::container> makeContainer(const Domain& domain, const ScaledFrame& frame)
{
    const BoundingBox& box = domain.boundingBox();
    const Vec3 lower = frame.toScaled(box.lower), upper = frame.toScaled(box.upper);
    const double margin = 0.05 + 0.01 * std::max({upper.x - lower.x, upper.y - lower.y, upper.z - lower.z});
    const double blockSide = std::cbrt(5.0);  // a cell has unit volume in the scaled frame
    int blocks[3];
    for (int i = 0; i < 3; ++i)
        blocks[i] = std::max(1, static_cast<int>(std::ceil((upper[i] - lower[i] + 2 * margin) / blockSide)));
    const int initialMemory = 8;
    return std::make_unique<voro::container>(lower.x - margin, upper.x + margin, lower.y - margin,
                                             upper.y + margin, lower.z - margin, upper.z + margin, blocks[0],
                                             blocks[1], blocks[2], false, false, false, initialMemory);
}

// The domain's planes as Voro++ walls (in the scaled frame).
std::vector<std::unique_ptr<voro::wall>> makePlaneWalls(const Domain& domain, const ScaledFrame& frame)
{
    std::vector<std::unique_ptr<voro::wall>> walls;
    int id = firstDomainWallId;
    for (const HalfSpace& h : domain.planes()) {
        // n.x <= c  <=>  n.x' <= (c - n.origin) / scale
        const double offset = (h.offset - dot(h.normal, frame.origin)) / frame.scale;
        walls.push_back(std::make_unique<voro::wall_plane>(h.normal.x, h.normal.y, h.normal.z, offset, id--));
    }
    return walls;
}

// Buffers reused from cell to cell by one thread.
struct Scratch {
    std::vector<double> relative;
    std::vector<int> faceList, neighbours;
    std::vector<char> facetMarks;
};

// The rim of a disc as the regular polygon of `facetCount` sides
// circumscribed about the circle. Voro++'s own wall_cylinder cuts each cell
// by the single tangent plane nearest its seed, which leaves the rim cells
// bulging out of the cylinder: 0.6-0.8 % too much volume for the 300-cell BDT
// disc. Clipping each cell by the polygon's facets instead gives the exact
// volume of the prism, pi r^2 t (N/pi tan(pi/N)) = pi r^2 t (1 + 2.0e-4) for
// N = 128, and neighbouring rim cells share the same facet planes.
class RimFacets {
public:
    static constexpr int facetCount = 128;

    RimFacets(const Cylinder& cylinder, const ScaledFrame& frame, int wallId)
        : axisPoint_(frame.toScaled(cylinder.axisPoint)),
          axis_(cylinder.axisDirection),
          radius_(cylinder.radius / frame.scale),
          wallId_(wallId)
    {
        const Vec3 helper = std::fabs(axis_.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
        u_ = normalised(cross(helper, axis_));
        w_ = cross(axis_, u_);
    }

    // Clip a computed cell (seed at `seed`, scaled frame). A facet plane that
    // leaves every vertex of the convex cell inside cannot cut it, so only the
    // facets some vertex lies beyond are applied: a vertex at distance rho > r
    // from the axis and angle theta is beyond facet k iff
    // |theta - theta_k| < acos(r / rho). False if the cell vanished.
    bool clip(voro::voronoicell_neighbor& cell, const Vec3& seed, Scratch& scratch) const
    {
        std::vector<char>& beyond = scratch.facetMarks;
        beyond.assign(facetCount, 0);
        bool any = false;
        cell.vertices(scratch.relative);
        for (std::size_t v = 0; v < scratch.relative.size(); v += 3) {
            const Vec3 d = seed +
                           Vec3{scratch.relative[v], scratch.relative[v + 1], scratch.relative[v + 2]} -
                           axisPoint_;
            const double a = dot(d, u_), b = dot(d, w_);
            const double rho = std::sqrt(a * a + b * b);
            if (rho <= radius_) continue;
            const double theta = std::atan2(b, a), halfWindow = std::acos(radius_ / rho);
            const double step = 2.0 * pi / facetCount;
            for (int k = static_cast<int>(std::ceil((theta - halfWindow) / step));
                 k <= static_cast<int>(std::floor((theta + halfWindow) / step)); ++k)
                beyond[((k % facetCount) + facetCount) % facetCount] = 1;
            any = true;
        }
        if (!any) return true;
        for (int k = 0; k < facetCount; ++k)
            if (beyond[k] && !cutByFacet(cell, seed, k)) return false;
        return true;
    }

private:
    // Facet k: n_k.(x - axisPoint) <= r with n_k at angle 2 pi k / N; relative
    // to the seed, n_k.r <= r + n_k.(axisPoint - seed), which Voro++'s nplane
    // takes as twice the right-hand side.
    bool cutByFacet(voro::voronoicell_neighbor& cell, const Vec3& seed, int k) const
    {
        const double theta = 2.0 * pi * k / facetCount;
        const Vec3 n = std::cos(theta) * u_ + std::sin(theta) * w_;
        const double offset = radius_ + dot(n, axisPoint_ - seed);
        return cell.nplane(n.x, n.y, n.z, 2.0 * offset, wallId_);
    }

    Vec3 axisPoint_, axis_, u_, w_;
    double radius_;
    int wallId_;
};

// The domain's planes when there are more than Voro++ takes as walls (its max_wall_size is
// 2048; the hull of a dense scan has thousands of facets): each computed cell is clipped by
// the planes some vertex of it lies beyond, as the rim facets do, instead of the container
// cutting it by walls while it is built. The same cell; the order of the cuts differs, so the
// wall path stays for domains of up to maxPlaneWalls planes (every tutorial's: bit for bit).
class PlaneClipper {
public:
    PlaneClipper(const std::vector<HalfSpace>& planes, const ScaledFrame& frame, int firstWallId)
        : firstWallId_(firstWallId)
    {
        for (const HalfSpace& h : planes)
            planes_.push_back({h.normal, (h.offset - dot(h.normal, frame.origin)) / frame.scale});
    }

    // Clip a computed cell (seed at `seed`, scaled frame); false if the cell vanished. A plane
    // farther from the seed than the cell's farthest vertex cannot cut it.
    bool clip(voro::voronoicell_neighbor& cell, const Vec3& seed, Scratch& scratch) const
    {
        std::vector<double>& relative = scratch.relative;
        cell.vertices(relative);
        double reach2 = 0.0;
        for (std::size_t v = 0; v < relative.size(); v += 3)
            reach2 = std::max(reach2, relative[v] * relative[v] + relative[v + 1] * relative[v + 1] +
                                          relative[v + 2] * relative[v + 2]);
        const double reach = std::sqrt(reach2);
        for (std::size_t k = 0; k < planes_.size(); ++k) {
            const Vec3& n = planes_[k].normal;
            // n.(seed + r) <= c  <=>  n.r <= c - n.seed, which nplane takes doubled.
            const double limit = planes_[k].offset - dot(n, seed);
            if (limit >= reach) continue;
            bool beyond = false;
            for (std::size_t v = 0; v < relative.size() && !beyond; v += 3)
                beyond = n.x * relative[v] + n.y * relative[v + 1] + n.z * relative[v + 2] > limit;
            if (beyond && !cell.nplane(n.x, n.y, n.z, 2.0 * limit, firstWallId_ - static_cast<int>(k)))
                return false;
        }
        return true;
    }

private:
    std::vector<HalfSpace> planes_;  // scaled frame
    int firstWallId_;
};

// Copy a computed Voro++ cell into metres, faces counter-clockwise seen from
// outside (Voro++ lists them the other way round), and compute its geometry.
void extractCell(voro::voronoicell_neighbor& cell, const Vec3& seed, double scale, Scratch& scratch,
                 CellResult& out)
{
    std::vector<double>& relative = scratch.relative;
    std::vector<int>& faceList = scratch.faceList;
    std::vector<int>& neighbours = scratch.neighbours;
    cell.vertices(relative);
    cell.face_vertices(faceList);
    cell.neighbors(neighbours);

    out.vertices.resize(relative.size() / 3);
    for (std::size_t v = 0; v < out.vertices.size(); ++v)
        out.vertices[v] = seed + scale * Vec3{relative[3 * v], relative[3 * v + 1], relative[3 * v + 2]};

    out.faceOffset.assign(1, 0);
    out.faceVertices.clear();
    out.neighbours.clear();
    std::size_t pos = 0;
    for (int neighbour : neighbours) {
        const int n = faceList[pos];
        for (int k = n; k >= 1; --k) out.faceVertices.push_back(faceList[pos + k]);
        pos += n + 1;
        out.faceOffset.push_back(static_cast<int>(out.faceVertices.size()));
        out.neighbours.push_back(neighbour >= 0 ? neighbour : boundaryFace);
    }

    const PolyhedronView view{out.vertices.data(), out.faceOffset.data(), out.faceVertices.data(),
                              static_cast<int>(out.neighbours.size())};
    out.faceNormal.resize(view.nFaces);
    out.faceArea.resize(view.nFaces);
    for (int f = 0; f < view.nFaces; ++f) {
        const Vec3 areaVector = faceAreaVector(view, f);
        out.faceArea[f] = norm(areaVector);
        out.faceNormal[f] = normalised(areaVector);
    }
    out.mass = massProperties(view);
}

// Compute every cell, in parallel over the container's blocks. Each thread
// has its own voro_compute (its search mask and queue are scratch space) and
// its own cell; the container is only read. Results go to the slot of their
// seed, so the output does not depend on the thread count or schedule.
std::vector<CellResult> computeCells(voro::container& container, const std::vector<Vec3>& seeds,
                                     const ScaledFrame& frame, const RimFacets* rim,
                                     const PlaneClipper* planes)
{
    std::vector<CellResult> cells(seeds.size());
    const int nx = container.nx, ny = container.ny, nz = container.nz;
    const int nBlocks = nx * ny * nz;
    int failedSeed = -1;
#pragma omp parallel
    {
        voro::voro_compute<voro::container> compute(container, nx, ny, nz);
        voro::voronoicell_neighbor cell;
        Scratch scratch;
#pragma omp for schedule(dynamic, 4)
        for (int block = 0; block < nBlocks; ++block) {
            const int k = block / (nx * ny), j = (block / nx) % ny, i = block % nx;
            for (int q = 0; q < container.co[block]; ++q) {
                const int id = container.id[block][q];
                const Vec3 seed = frame.toScaled(seeds[id]);
                const bool exists = compute.compute_cell(cell, block, q, i, j, k) &&
                                    (!planes || planes->clip(cell, seed, scratch)) &&
                                    (!rim || rim->clip(cell, seed, scratch));
                if (exists) {
                    extractCell(cell, seeds[id], frame.scale, scratch, cells[id]);
                } else {
#pragma omp critical(rockfracVoronoiFailure)
                    failedSeed = std::max(failedSeed, id);
                }
            }
        }
    }
    if (failedSeed >= 0) {
        std::ostringstream msg;
        msg << "Voro++ removed the whole cell of seed " << failedSeed
            << " (a seed on the domain boundary?); re-run with another random seed";
        throw UserError(msg.str());
    }
    return cells;
}

// Offsets of the compressed arrays: entry c is where cell c starts.
void computeOffsets(const std::vector<CellResult>& cells, VoronoiMesh& mesh,
                    std::vector<int>& cellFaceVertexStart)
{
    const std::size_t n = cells.size();
    mesh.cellVertexOffset.assign(n + 1, 0);
    mesh.cellFaceOffset.assign(n + 1, 0);
    cellFaceVertexStart.assign(n + 1, 0);
    for (std::size_t c = 0; c < n; ++c) {
        mesh.cellVertexOffset[c + 1] = mesh.cellVertexOffset[c] + static_cast<int>(cells[c].vertices.size());
        mesh.cellFaceOffset[c + 1] = mesh.cellFaceOffset[c] + static_cast<int>(cells[c].neighbours.size());
        cellFaceVertexStart[c + 1] = cellFaceVertexStart[c] + static_cast<int>(cells[c].faceVertices.size());
    }
}

// Concatenate the cells into the mesh's compressed arrays (sized first, then
// filled in parallel, each cell into its own slots).
void assemble(const std::vector<CellResult>& cells, VoronoiMesh& mesh)
{
    std::vector<int> faceVertexStart;
    computeOffsets(cells, mesh, faceVertexStart);
    const int nCells = static_cast<int>(cells.size());
    const int nFaces = mesh.cellFaceOffset.back();
    mesh.vertices.resize(mesh.cellVertexOffset.back());
    mesh.faceVertices.resize(faceVertexStart.back());
    mesh.faceVertexOffset.resize(nFaces + 1);
    mesh.faceVertexOffset[nFaces] = faceVertexStart.back();
    mesh.faceNeighbour.resize(nFaces);
    mesh.faceNormal.resize(nFaces);
    mesh.faceArea.resize(nFaces);
    mesh.volumes.resize(nCells);
    mesh.centroids.resize(nCells);
    mesh.inertia.resize(nCells);
#pragma omp parallel for schedule(static)
    for (int c = 0; c < nCells; ++c) {
        const CellResult& cell = cells[c];
        std::copy(cell.vertices.begin(), cell.vertices.end(),
                  mesh.vertices.begin() + mesh.cellVertexOffset[c]);
        std::copy(cell.faceVertices.begin(), cell.faceVertices.end(),
                  mesh.faceVertices.begin() + faceVertexStart[c]);
        const int firstFace = mesh.cellFaceOffset[c];
        for (std::size_t f = 0; f < cell.neighbours.size(); ++f) {
            mesh.faceVertexOffset[firstFace + f] = faceVertexStart[c] + cell.faceOffset[f];
            mesh.faceNeighbour[firstFace + f] = cell.neighbours[f];
            mesh.faceNormal[firstFace + f] = cell.faceNormal[f];
            mesh.faceArea[firstFace + f] = cell.faceArea[f];
        }
        mesh.volumes[c] = cell.mass.volume;
        mesh.centroids[c] = cell.mass.centroid;
        mesh.inertia[c] = cell.mass.inertia;
    }
}

}  // namespace

VoronoiMesh tessellate(const Domain& domain, const std::vector<Vec3>& seeds, double dilationFraction,
                       std::size_t maxPlaneWalls)
{
    checkSeedsInside(domain, seeds);
    if (!(dilationFraction >= 0.0) || !std::isfinite(dilationFraction))
        throw UserError(
            "the dilation fraction must be a non-negative number (0.1 = 10 % of the mean cell size)");

    const ScaledFrame frame{domain.boundingBox().centre(), std::cbrt(domain.volume() / seeds.size())};
    const int nSeeds = static_cast<int>(seeds.size());
    std::unique_ptr<voro::container> container = makeContainer(domain, frame);
    // Up to maxPlaneWalls planes as Voro++ walls, more clipped cell by cell (PlaneClipper).
    const bool clipPlanes = domain.planes().size() > std::min<std::size_t>(maxPlaneWalls, 2000);
    std::optional<PlaneClipper> clipper;
    std::vector<std::unique_ptr<voro::wall>> walls;
    if (clipPlanes)
        clipper.emplace(domain.planes(), frame, firstDomainWallId);
    else
        walls = makePlaneWalls(domain, frame);
    for (const auto& wall : walls) container->add_wall(*wall);
    for (int i = 0; i < nSeeds; ++i) {
        const Vec3 p = frame.toScaled(seeds[i]);
        container->put(i, p.x, p.y, p.z);
    }

    VoronoiMesh mesh;
    mesh.seeds = seeds;
    mesh.domainVolume = domain.volume();
    std::optional<RimFacets> rim;
    if (domain.cylinder())
        rim.emplace(*domain.cylinder(), frame, firstDomainWallId - static_cast<int>(domain.planes().size()));
    assemble(computeCells(*container, seeds, frame, rim ? &*rim : nullptr, clipper ? &*clipper : nullptr),
             mesh);
    repairNeighbours(mesh);
    mesh.bonds = bondsForFacePairs(mesh, internalFacePairs(mesh));
    mesh.dilationRadius = dilationFraction * meanCellSize(mesh);
    return mesh;
}

VoronoiMesh generateVoronoiMesh(const Domain& domain, int nCells, double pruningDistance, std::uint64_t seed,
                                double dilationFraction, CellOrder order, const SizeField* field)
{
    std::vector<Vec3> seeds = field ? placeSeeds(domain, nCells, pruningDistance, seed, *field)
                                    : placeSeeds(domain, nCells, pruningDistance, seed);
    if (order == CellOrder::morton) orderAlongMortonCurve(seeds);
    VoronoiMesh mesh = tessellate(domain, seeds, dilationFraction);
    mesh.seed = seed;
    mesh.pruningDistance = pruningDistance;
    return mesh;
}

double meanCellSize(const VoronoiMesh& mesh)
{
    if (mesh.volumes.empty()) return 0.0;
    double sum = 0.0;
    for (double v : mesh.volumes) sum += std::cbrt(6.0 * v / pi);
    return sum / mesh.volumes.size();
}

}  // namespace rockfrac
