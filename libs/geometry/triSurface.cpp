#include "geometry/triSurface.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <tuple>

#include "core/atomicFile.hpp"
#include "core/error.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

namespace {

// Welds vertices with bitwise identical coordinates (STL repeats them per triangle).
class VertexWelder {
public:
    int index(const Vec3& p, TriSurface& surface)
    {
        const auto key = std::make_tuple(p.x, p.y, p.z);
        auto it = ids_.find(key);
        if (it != ids_.end()) return it->second;
        const int id = static_cast<int>(surface.points.size());
        surface.points.push_back(p);
        ids_.emplace(key, id);
        return id;
    }

private:
    std::map<std::tuple<double, double, double>, int> ids_;
};

bool finite(const Vec3& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

void addTriangle(TriSurface& surface, VertexWelder& welder, const Vec3 (&v)[3], const fs::path& file,
                 long facet)
{
    for (const auto& p : v)
        if (!finite(p))
            throw UserError(file.string() + ": facet " + std::to_string(facet) +
                            " has a non-finite coordinate (NaN or Inf); repair the scan and export it again");
    surface.triangles.push_back(
        {welder.index(v[0], surface), welder.index(v[1], surface), welder.index(v[2], surface)});
}

TriSurface readBinaryStl(const std::string& bytes, const fs::path& file)
{
    if (bytes.size() < 84)
        throw UserError(file.string() + ": truncated binary STL (" + std::to_string(bytes.size()) +
                        " bytes, the header alone is 84)");
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    const std::uint64_t expected = 84ull + 50ull * count;
    if (bytes.size() < expected)
        throw UserError(file.string() + ": truncated binary STL: header announces " + std::to_string(count) +
                        " facets (" + std::to_string(expected) + " bytes) but the file has " +
                        std::to_string(bytes.size()) + " bytes");
    TriSurface surface;
    VertexWelder welder;
    for (std::uint32_t f = 0; f < count; ++f) {
        const char* record = bytes.data() + 84 + 50ull * f + 12;  // skip the normal
        Vec3 v[3];
        for (int k = 0; k < 3; ++k) {
            float xyz[3];
            std::memcpy(xyz, record + 12 * k, 12);
            v[k] = {xyz[0], xyz[1], xyz[2]};
        }
        addTriangle(surface, welder, v, file, f + 1);
    }
    return surface;
}

TriSurface readAsciiStl(const std::string& text, const fs::path& file)
{
    TriSurface surface;
    VertexWelder welder;
    std::istringstream in(text);
    std::string line;
    long lineNo = 0, facet = 0;
    Vec3 v[3];
    int nVertex = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        std::istringstream words(line);
        std::string word;
        if (!(words >> word)) continue;
        if (word == "facet") {
            nVertex = 0;
            ++facet;
        } else if (word == "vertex") {
            std::string sx, sy, sz;
            if (!(words >> sx >> sy >> sz) || nVertex >= 3)
                throw UserError(file.string() + ":" + std::to_string(lineNo) +
                                ": malformed 'vertex' line; expected 'vertex x y z' (three per facet)");
            char* end = nullptr;
            double xyz[3];
            const std::string* s[3] = {&sx, &sy, &sz};
            for (int k = 0; k < 3; ++k) {
                xyz[k] = std::strtod(s[k]->c_str(), &end);
                if (end == s[k]->c_str())
                    throw UserError(file.string() + ":" + std::to_string(lineNo) + ": '" + *s[k] +
                                    "' is not a number; expected 'vertex x y z'");
            }
            v[nVertex++] = {xyz[0], xyz[1], xyz[2]};
        } else if (word == "endfacet") {
            if (nVertex != 3)
                throw UserError(file.string() + ":" + std::to_string(lineNo) + ": facet " +
                                std::to_string(facet) + " has " + std::to_string(nVertex) +
                                " vertices; expected 3");
            addTriangle(surface, welder, v, file, facet);
        }
    }
    return surface;
}

}  // namespace

TriSurface readStl(const fs::path& file)
{
    std::error_code ec;
    if (fs::is_directory(file, ec))
        throw UserError("cannot read STL '" + file.string() +
                        "': it is a directory; give the path of an STL file");
    if (fs::exists(file, ec) && !fs::is_regular_file(file, ec))
        throw UserError("cannot read STL '" + file.string() +
                        "': not a regular file (a device or a pipe); give the path of an STL file");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw UserError("cannot read STL '" + file.string() + "': no such file or not readable");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return parseStl(bytes, file);
}

TriSurface parseStl(const std::string& bytes, const fs::path& file)
{
    if (bytes.empty())
        throw UserError(file.string() + ": empty file; expected an ASCII or binary STL surface");

    // ASCII files start with "solid" and contain "facet"; some binary headers
    // also start with "solid", so a file whose size matches the binary layout
    // exactly, or that has no "facet" keyword, is read as binary.
    bool binary = true;
    if (bytes.compare(0, 5, "solid") == 0) {
        std::uint32_t count = 0;
        if (bytes.size() >= 84) std::memcpy(&count, bytes.data() + 80, 4);
        const bool sizeMatchesBinary = bytes.size() >= 84 && bytes.size() == 84ull + 50ull * count;
        binary = sizeMatchesBinary || bytes.find("facet") == std::string::npos;
    }
    TriSurface surface = binary ? readBinaryStl(bytes, file) : readAsciiStl(bytes, file);
    if (surface.triangles.empty())
        throw UserError(file.string() + ": no triangles found; expected an ASCII or binary STL surface");
    return surface;
}

void writeStl(const fs::path& file, const TriSurface& surface, const std::string& solidName)
{
    writeFileAtomically(file, [&](std::ostream& out) {
        out << "solid " << solidName << "\n" << std::setprecision(17);
        for (const auto& t : surface.triangles) {
            const Vec3& a = surface.points[t[0]];
            const Vec3& b = surface.points[t[1]];
            const Vec3& c = surface.points[t[2]];
            const Vec3 n = normalised(cross(b - a, c - a));
            out << "  facet normal " << n.x << " " << n.y << " " << n.z << "\n    outer loop\n";
            for (const Vec3* p : {&a, &b, &c})
                out << "      vertex " << p->x << " " << p->y << " " << p->z << "\n";
            out << "    endloop\n  endfacet\n";
        }
        out << "endsolid " << solidName << "\n";
    });
}

std::string SurfaceCheck::reason() const
{
    std::string r;
    auto add = [&r](int n, const char* what) {
        if (n == 0) return;
        if (!r.empty()) r += ", ";
        r += std::to_string(n) + " " + what;
    };
    add(boundaryEdges, "open (boundary) edges: the surface has holes");
    add(nonManifoldEdges, "non-manifold edges shared by more than two triangles");
    add(misorientedEdges, "edges with inconsistent triangle orientation");
    return r;
}

SurfaceCheck checkSurface(const TriSurface& surface)
{
    // Count each undirected edge and its directed uses.
    std::map<std::pair<int, int>, std::pair<int, int>> edges;  // (min,max) -> (uses min->max, uses max->min)
    SurfaceCheck check;
    for (const auto& t : surface.triangles) {
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
            ++check.degenerateTriangles;
            continue;
        }
        for (int k = 0; k < 3; ++k) {
            const int a = t[k], b = t[(k + 1) % 3];
            auto& uses = edges[{std::min(a, b), std::max(a, b)}];
            (a < b ? uses.first : uses.second)++;
        }
    }
    for (const auto& [edge, uses] : edges) {
        const int total = uses.first + uses.second;
        if (total == 1)
            ++check.boundaryEdges;
        else if (total > 2)
            ++check.nonManifoldEdges;
        else if (uses.first != 1)
            ++check.misorientedEdges;
    }
    return check;
}

void symmetricEigen(const Mat3& A, Vec3& values, Mat3& vectors)
{
    Eigen::Matrix3d m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m(i, j) = A(i, j);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(m);
    for (int i = 0; i < 3; ++i) {
        values[i] = solver.eigenvalues()(i);
        for (int j = 0; j < 3; ++j) vectors(j, i) = solver.eigenvectors()(j, i);
    }
}

MassProperties massProperties(const TriSurface& surface)
{
    // Each triangle with the origin spans a signed tetrahedron; summing their
    // volume, first and second moments gives those of the enclosed solid.
    // Shift to a point near the solid first to keep round-off small.
    Vec3 origin;
    for (const auto& p : surface.points) origin += p;
    if (!surface.points.empty()) origin /= static_cast<double>(surface.points.size());

    double volume = 0;
    Vec3 first;
    double second[3][3] = {};  // ∫ x_i x_j dV about `origin`
    for (const auto& t : surface.triangles) {
        const Vec3 a = surface.points[t[0]] - origin, b = surface.points[t[1]] - origin,
                   c = surface.points[t[2]] - origin;
        const double v = dot(a, cross(b, c)) / 6.0;
        volume += v;
        first += v * (a + b + c) / 4.0;
        // ∫_tet x_i x_j dV = v/20 (Σ_k p_k,i p_k,j + s_i s_j), s = a + b + c (origin vertex is 0)
        const Vec3 s = a + b + c;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                second[i][j] += v / 20.0 * (a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + s[i] * s[j]);
    }
    MassProperties props;
    props.volume = volume;
    const Vec3 centroidLocal = volume != 0 ? first / volume : Vec3{};
    props.centroid = centroidLocal + origin;
    // Inertia tensor I = ∫ (|r|² δ_ij − r_i r_j) dV about the centroid.
    double central[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            central[i][j] = second[i][j] - volume * centroidLocal[i] * centroidLocal[j];
    const double trace = central[0][0] + central[1][1] + central[2][2];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) props.inertia(i, j) = (i == j ? trace : 0.0) - central[i][j];
    symmetricEigen(props.inertia, props.principalMoments, props.principalAxes);

    props.boundsMin = {1e300, 1e300, 1e300};
    props.boundsMax = {-1e300, -1e300, -1e300};
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (const auto& p : surface.points) {
        for (int i = 0; i < 3; ++i) {
            props.boundsMin[i] = std::min(props.boundsMin[i], p[i]);
            props.boundsMax[i] = std::max(props.boundsMax[i], p[i]);
            double along = 0;
            for (int k = 0; k < 3; ++k) along += (p[k] - props.centroid[k]) * props.principalAxes(k, i);
            lo[i] = std::min(lo[i], along);
            hi[i] = std::max(hi[i], along);
        }
    }
    double extents[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
    std::sort(extents, extents + 3, std::greater<double>());
    props.principalExtents = {extents[0], extents[1], extents[2]};
    return props;
}

void transformSurface(TriSurface& surface, double scale, const Mat3& rotation, const Vec3& translation)
{
    for (auto& p : surface.points) p = rotation * (scale * p) + translation;
}

Mat3 rotationFromDegrees(const Vec3& anglesDeg)
{
    const double k = M_PI / 180.0;
    const double cx = std::cos(k * anglesDeg.x), sx = std::sin(k * anglesDeg.x);
    const double cy = std::cos(k * anglesDeg.y), sy = std::sin(k * anglesDeg.y);
    const double cz = std::cos(k * anglesDeg.z), sz = std::sin(k * anglesDeg.z);
    Mat3 Rx = Mat3::identity(), Ry = Mat3::identity(), Rz = Mat3::identity();
    Rx(1, 1) = cx;
    Rx(1, 2) = -sx;
    Rx(2, 1) = sx;
    Rx(2, 2) = cx;
    Ry(0, 0) = cy;
    Ry(0, 2) = sy;
    Ry(2, 0) = -sy;
    Ry(2, 2) = cy;
    Rz(0, 0) = cz;
    Rz(0, 1) = -sz;
    Rz(1, 0) = sz;
    Rz(1, 1) = cz;
    return Rz * (Ry * Rx);
}

TriSurface discSurface(double diameter, double thickness, const Vec3& centre, int nSegments)
{
    // Axis along y: the faces of the disc are y = ±t/2, the loading diameter is z.
    TriSurface s;
    const double r = 0.5 * diameter, h = 0.5 * thickness;
    const int front = 0, back = 1;
    s.points.push_back(centre + Vec3{0, -h, 0});
    s.points.push_back(centre + Vec3{0, h, 0});
    for (int k = 0; k < nSegments; ++k) {
        const double a = 2 * M_PI * k / nSegments;
        s.points.push_back(centre + Vec3{r * std::cos(a), -h, r * std::sin(a)});
        s.points.push_back(centre + Vec3{r * std::cos(a), h, r * std::sin(a)});
    }
    for (int k = 0; k < nSegments; ++k) {
        const int k1 = (k + 1) % nSegments;
        const int f0 = 2 + 2 * k, b0 = 3 + 2 * k, f1 = 2 + 2 * k1, b1 = 3 + 2 * k1;
        // Outward normals: front face −y, back face +y, mantle radial.
        s.triangles.push_back({front, f0, f1});
        s.triangles.push_back({back, b1, b0});
        s.triangles.push_back({f0, b0, b1});
        s.triangles.push_back({f0, b1, f1});
    }
    return s;
}

}  // namespace rockfrac
