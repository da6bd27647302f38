#include "voronoi/voronoiMeshIO.hpp"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/atomicFile.hpp"
#include "core/checksum.hpp"
#include "core/dictionary.hpp"
#include "core/error.hpp"
#include "voronoi/meshTopology.hpp"

namespace rockfrac {

namespace {

namespace fs = std::filesystem;

using Bytes = std::vector<unsigned char>;

// ---- Files and messages -----------------------------------------------------

const char* const rerunAdvice = "re-run voronoiMesh";

// How a file is named in messages: relative to the case, as the user knows it.
std::string displayName(const fs::path& caseDir, const char* file)
{
    return (caseDir / voronoiMeshDirectory / file).lexically_normal().string();
}

[[noreturn]] void fail(const std::string& file, const std::string& what)
{
    throw UserError(file + ": " + what + "; " + rerunAdvice);
}

// Write `bytes` to `path` atomically (core/atomicFile.hpp): a reader never
// sees a half-written mesh file.
void writeAtomically(const fs::path& path, const std::string& /*label*/, const char* data, std::size_t size)
{
    writeFileAtomically(path,
                        [&](std::ostream& out) { out.write(data, static_cast<std::streamsize>(size)); });
}

Bytes readWholeFile(const fs::path& path, const std::string& label)
{
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    if (ec) throw UserError(label + ": cannot read (" + ec.message() + "); run voronoiMesh first");
    Bytes bytes(size);
    std::ifstream in(path, std::ios::binary);
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size));
    if (!in || static_cast<std::uintmax_t>(in.gcount()) != size) fail(label, "read error");
    return bytes;
}

// ---- Little-endian encoding -------------------------------------------------
// Byte by byte with shifts, so the files are the same on any host; compilers
// turn these into plain loads and stores on little-endian machines.

void storeU64(std::uint64_t v, unsigned char* p)
{
    for (int i = 0; i < 8; ++i) p[i] = static_cast<unsigned char>(v >> (8 * i));
}
std::uint64_t loadU64(const unsigned char* p)
{
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= static_cast<std::uint64_t>(p[i]) << (8 * i);
    return v;
}
void storeU32(std::uint32_t v, unsigned char* p)
{
    for (int i = 0; i < 4; ++i) p[i] = static_cast<unsigned char>(v >> (8 * i));
}
std::uint32_t loadU32(const unsigned char* p)
{
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(p[i]) << (8 * i);
    return v;
}
std::uint64_t bitsOf(double x)
{
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    return bits;
}
double doubleOf(std::uint64_t bits)
{
    double x;
    std::memcpy(&x, &bits, sizeof x);
    return x;
}

// Appends arrays to a byte buffer of known final size.
class Encoder {
public:
    explicit Encoder(Bytes& out) : out_(out) {}
    void u32(std::uint32_t v) { storeU32(v, grow(4)); }
    void u64(std::uint64_t v) { storeU64(v, grow(8)); }
    void ints(const std::vector<int>& a)
    {
        unsigned char* p = grow(4 * a.size());
        for (int v : a) storeU32(static_cast<std::uint32_t>(v), p), p += 4;
    }
    void doubles(const std::vector<double>& a)
    {
        unsigned char* p = grow(8 * a.size());
        for (double v : a) storeU64(bitsOf(v), p), p += 8;
    }
    void vectors(const std::vector<Vec3>& a)
    {
        unsigned char* p = grow(24 * a.size());
        for (const Vec3& v : a)
            for (int i = 0; i < 3; ++i) storeU64(bitsOf(v[i]), p), p += 8;
    }
    void matrices(const std::vector<Mat3>& a)
    {
        unsigned char* p = grow(72 * a.size());
        for (const Mat3& m : a)
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) storeU64(bitsOf(m.m[i][j]), p), p += 8;
    }

private:
    unsigned char* grow(std::size_t n)
    {
        out_.resize(out_.size() + n);
        return out_.data() + out_.size() - n;
    }
    Bytes& out_;
};

// Reads arrays from a payload whose size was checked beforehand, rejecting
// non-finite numbers (no NaN or infinity can come out of a valid mesh).
class Decoder {
public:
    Decoder(const Bytes& bytes, std::size_t start, std::string label)
        : p_(bytes.data() + start), end_(bytes.data() + bytes.size()), label_(std::move(label))
    {
    }
    std::vector<int> ints(std::size_t n)
    {
        const unsigned char* p = take(4 * n);
        std::vector<int> a(n);
        for (std::size_t i = 0; i < n; ++i) a[i] = static_cast<std::int32_t>(loadU32(p + 4 * i));
        return a;
    }
    std::vector<double> doubles(std::size_t n, const char* what)
    {
        const unsigned char* p = take(8 * n);
        std::vector<double> a(n);
        for (std::size_t i = 0; i < n; ++i) a[i] = finite(doubleOf(loadU64(p + 8 * i)), what);
        return a;
    }
    std::vector<Vec3> vectors(std::size_t n, const char* what)
    {
        const std::vector<double> d = doubles(3 * n, what);
        std::vector<Vec3> a(n);
        for (std::size_t i = 0; i < n; ++i) a[i] = {d[3 * i], d[3 * i + 1], d[3 * i + 2]};
        return a;
    }
    std::vector<Mat3> matrices(std::size_t n, const char* what)
    {
        const std::vector<double> d = doubles(9 * n, what);
        std::vector<Mat3> a(n);
        for (std::size_t i = 0; i < n; ++i)
            for (int k = 0; k < 9; ++k) a[i].m[k / 3][k % 3] = d[9 * i + k];
        return a;
    }

private:
    const unsigned char* take(std::size_t n)
    {
        if (static_cast<std::size_t>(end_ - p_) < n) fail(label_, "payload shorter than its counts");
        const unsigned char* p = p_;
        p_ += n;
        return p;
    }
    double finite(double x, const char* what) const
    {
        if (!std::isfinite(x)) fail(label_, std::string("non-finite value in ") + what);
        return x;
    }
    const unsigned char* p_;
    const unsigned char* end_;
    std::string label_;
};

// ---- Binary file layout -----------------------------------------------------

constexpr char magic[16] = {'r', 'o', 'c', 'k', 'f', 'r', 'a', 'c', '-', 'v', 'o', 'r', 'o', 'n', 'o', 'i'};
constexpr std::size_t headerBytes = 64;

enum class FileKind : std::uint32_t { cells = 1, vertices = 2, faces = 3, bonds = 4 };

struct FileSpec {
    FileKind kind;
    const char* name;
};
constexpr FileSpec cellsFile{FileKind::cells, "cells"};
constexpr FileSpec verticesFile{FileKind::vertices, "vertices"};
constexpr FileSpec facesFile{FileKind::faces, "faces"};
constexpr FileSpec bondsFile{FileKind::bonds, "bonds"};

// Everything meshInfo records.
struct MeshInfo {
    std::uint64_t nCells = 0, nVertices = 0, nFaces = 0, nFaceVertices = 0, nBondedFaces = 0, nBonds = 0;
    std::uint64_t seed = 0;
    double pruningDistance = 0, dilationRadius = 0, domainVolume = 0;
    std::uint64_t checksums[4] = {0, 0, 0, 0};  // by FileKind - 1
};

// The two counts in each file's header and the payload size they imply
// (counts are below 2^31, so no product overflows 64 bits).
struct Counts {
    std::uint64_t first = 0, second = 0;
};
Counts countsFor(FileKind kind, const MeshInfo& info)
{
    switch (kind) {
        case FileKind::cells:
            return {info.nCells, 0};
        case FileKind::vertices:
            return {info.nVertices, 0};
        case FileKind::faces:
            return {info.nFaces, info.nFaceVertices};
        case FileKind::bonds:
            return {info.nBondedFaces, info.nBonds};
    }
    return {};
}
std::uint64_t payloadBytes(FileKind kind, const MeshInfo& info)
{
    switch (kind) {
        // seeds, centroids (3), volume (1), inertia (9) doubles; two offsets
        case FileKind::cells:
            return 8 * 16 * info.nCells + 4 * 2 * (info.nCells + 1);
        case FileKind::vertices:
            return 24 * info.nVertices;
        // offsets, vertex indices, neighbours; normal (3) and area doubles
        case FileKind::faces:
            return 4 * (info.nFaces + 1) + 4 * info.nFaceVertices + 4 * info.nFaces + 32 * info.nFaces;
        case FileKind::bonds:
            return 8 * info.nBondedFaces;
    }
    return 0;
}

// Header + payload, with the payload's checksum recorded in `info`.
Bytes makeFile(FileKind kind, MeshInfo& info, const Bytes& payload)
{
    Bytes file;
    file.reserve(headerBytes + payload.size());
    Encoder out(file);
    file.insert(file.end(), magic, magic + 16);
    out.u32(VoronoiMesh::formatVersion);
    out.u32(static_cast<std::uint32_t>(kind));
    const Counts counts = countsFor(kind, info);
    out.u64(counts.first);
    out.u64(counts.second);
    out.u64(0);  // reserved
    const std::uint64_t sum = fnv1aWords(payload.data(), payload.size());
    info.checksums[static_cast<int>(kind) - 1] = sum;
    out.u64(sum);
    out.u64(payload.size());
    file.insert(file.end(), payload.begin(), payload.end());
    return file;
}

// Check size, header and checksum of a binary file; returns its bytes.
Bytes readCheckedFile(const fs::path& caseDir, const FileSpec& spec, const MeshInfo& info)
{
    const std::string label = displayName(caseDir, spec.name);
    Bytes bytes = readWholeFile(caseDir / voronoiMeshDirectory / spec.name, label);
    const std::uint64_t expected = headerBytes + payloadBytes(spec.kind, info);
    auto truncated = [&] {
        fail(label, "truncated: expected " + std::to_string(expected) + " bytes, found " +
                        std::to_string(bytes.size()));
    };
    if (bytes.size() < headerBytes) truncated();
    if (std::memcmp(bytes.data(), magic, 16) != 0)
        fail(label, "not a rockfrac Voronoi mesh file (bad magic)");
    const std::uint32_t version = loadU32(&bytes[16]);
    if (version != VoronoiMesh::formatVersion)
        fail(label, "format version " + std::to_string(version) + ", this build reads version " +
                        std::to_string(VoronoiMesh::formatVersion));
    if (loadU32(&bytes[20]) != static_cast<std::uint32_t>(spec.kind))
        fail(label, "holds another kind of mesh data than its name says");
    const Counts counts = countsFor(spec.kind, info);
    if (loadU64(&bytes[24]) != counts.first || loadU64(&bytes[32]) != counts.second)
        fail(label, "its counts disagree with meshInfo (files from different runs?)");
    if (bytes.size() < expected) truncated();
    if (bytes.size() > expected || loadU64(&bytes[56]) != expected - headerBytes)
        fail(label, "expected " + std::to_string(expected) + " bytes, found " + std::to_string(bytes.size()));
    const std::uint64_t sum = fnv1aWords(bytes.data() + headerBytes, bytes.size() - headerBytes);
    if (sum != loadU64(&bytes[48]) || sum != info.checksums[static_cast<int>(spec.kind) - 1])
        fail(label, "checksum mismatch (corrupt, or not from the run meshInfo describes)");
    return bytes;
}

// ---- meshInfo (ASCII, FoamFile style) ---------------------------------------

std::string formatDouble(double x)
{
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);  // shortest exact round trip
    return std::string(buffer, result.ptr);
}

std::string formatHex(std::uint64_t x)
{
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, x, 16);
    return "0x" + std::string(buffer, result.ptr);
}

std::string meshInfoText(const MeshInfo& info)
{
    std::ostringstream s;
    s << "/*--------------------------------*- rockfrac -*-----------------------------*\\\n"
         "  Bonded Voronoi mesh written by voronoiMesh (docs/file-formats.md)\n"
         "\\*---------------------------------------------------------------------------*/\n"
         "FoamFile\n{\n    format      binary;\n    class       voronoiMeshInfo;\n    object      "
         "meshInfo;\n}\n\n";
    s << "formatVersion   " << VoronoiMesh::formatVersion << ";\n"
      << "byteOrder       littleEndian;\n"
      << "nCells          " << info.nCells << ";\n"
      << "nVertices       " << info.nVertices << ";\n"
      << "nFaces          " << info.nFaces << ";\n"
      << "nFaceVertices   " << info.nFaceVertices << ";\n"
      << "nBondedFaces    " << info.nBondedFaces << ";\n"
      << "nBonds          " << info.nBonds << ";\n"
      << "seed            " << info.seed << ";\n"
      << "pruningDistance " << formatDouble(info.pruningDistance) << ";   // [m]\n"
      << "dilationRadius  " << formatDouble(info.dilationRadius) << ";   // [m]\n"
      << "domainVolume    " << formatDouble(info.domainVolume) << ";   // [m^3]\n";
    const char* names[4] = {"cellsChecksum   ", "verticesChecksum", "facesChecksum   ", "bondsChecksum   "};
    for (int k = 0; k < 4; ++k) s << names[k] << " " << formatHex(info.checksums[k]) << ";\n";
    return s.str();
}

// meshInfo's entries, read by the case dictionary reader (core/dictionary.hpp): each
// one word or number, converted exactly as written (from_chars, as the writer's to_chars).
class EntryReader {
public:
    EntryReader(Dictionary dict, std::string label) : dict_(std::move(dict)), label_(std::move(label)) {}

    const Entry& entry(const char* key) const
    {
        const Entry* e = dict_.findEntry(key);
        if (!e) fail(label_, std::string("missing entry '") + key + "'");
        return *e;
    }
    const std::string& word(const char* key) const
    {
        const Entry& e = entry(key);
        if (e.isDict() || e.values.size() != 1 || !(e.values[0].isWord() || e.values[0].isNumber()))
            bad(key, "must be one word or number");
        return e.values[0].text;
    }
    // A count: an integer in [0, 2^31) so every index fits an int.
    std::uint64_t count(const char* key) const
    {
        const std::uint64_t v = unsignedInt(key, 10);
        if (v > static_cast<std::uint64_t>(INT_MAX)) bad(key, "is too large");
        return v;
    }
    std::uint64_t unsignedInt(const char* key, int base) const
    {
        const std::string& text = word(key);
        const char* first = text.data();
        if (base == 16) {
            if (text.compare(0, 2, "0x") != 0) bad(key, "must be a hexadecimal number 0x...");
            first += 2;
        }
        std::uint64_t v = 0;
        const auto result = std::from_chars(first, text.data() + text.size(), v, base);
        if (result.ec != std::errc() || result.ptr != text.data() + text.size())
            bad(key, "must be an unsigned integer");
        return v;
    }
    double real(const char* key) const
    {
        const std::string& text = word(key);
        double v = 0;
        const auto result = std::from_chars(text.data(), text.data() + text.size(), v);
        if (result.ec != std::errc() || result.ptr != text.data() + text.size() || !std::isfinite(v))
            bad(key, "must be a finite number");
        return v;
    }
    [[noreturn]] void bad(const char* key, const std::string& what) const
    {
        fail(label_ + ":" + std::to_string(entry(key).valueLocation.line),
             std::string("'") + key + "' " + what);
    }

private:
    Dictionary dict_;
    std::string label_;
};

// meshInfo as a dictionary (no #include: it is written, not edited); a syntax error is
// the dictionary reader's message with the advice to re-run voronoiMesh.
Dictionary parseMeshInfo(const Bytes& bytes, const std::string& label)
{
    ParseLimits limits;
    limits.allowIncludes = false;
    try {
        return Dictionary::parse(std::string(bytes.begin(), bytes.end()), label, limits);
    } catch (const UserError& e) {
        throw UserError(std::string(e.what()) + "; " + rerunAdvice);
    }
}

MeshInfo readMeshInfo(const fs::path& caseDir)
{
    const std::string label = displayName(caseDir, "meshInfo");
    const Bytes bytes = readWholeFile(caseDir / voronoiMeshDirectory / "meshInfo", label);
    const EntryReader entries(parseMeshInfo(bytes, label), label);

    if (entries.unsignedInt("formatVersion", 10) != static_cast<std::uint64_t>(VoronoiMesh::formatVersion))
        entries.bad("formatVersion", "is not " + std::to_string(VoronoiMesh::formatVersion) +
                                         ", the only version this build reads");
    if (entries.word("byteOrder") != "littleEndian") entries.bad("byteOrder", "must be littleEndian");

    MeshInfo info;
    info.nCells = entries.count("nCells");
    info.nVertices = entries.count("nVertices");
    info.nFaces = entries.count("nFaces");
    info.nFaceVertices = entries.count("nFaceVertices");
    info.nBondedFaces = entries.count("nBondedFaces");
    info.nBonds = entries.count("nBonds");
    info.seed = entries.unsignedInt("seed", 10);
    info.pruningDistance = entries.real("pruningDistance");
    info.dilationRadius = entries.real("dilationRadius");
    info.domainVolume = entries.real("domainVolume");
    const char* checksumKeys[4] = {"cellsChecksum", "verticesChecksum", "facesChecksum", "bondsChecksum"};
    for (int k = 0; k < 4; ++k) info.checksums[k] = entries.unsignedInt(checksumKeys[k], 16);

    if (info.nCells < 1) entries.bad("nCells", "must be at least 1");
    if (info.pruningDistance < 0) entries.bad("pruningDistance", "must not be negative");
    if (info.dilationRadius < 0) entries.bad("dilationRadius", "must not be negative");
    if (!(info.domainVolume > 0)) entries.bad("domainVolume", "must be positive");
    return info;
}

// ---- Validation of the decoded arrays -----------------------------------------

// offsets[0] = 0, steps of at least minStep, last = total.
void checkOffsets(const std::vector<int>& offsets, int total, int minStep, const std::string& label,
                  const char* what)
{
    if (offsets.front() != 0 || offsets.back() != total)
        fail(label, std::string(what) + " do not run from 0 to " + std::to_string(total));
    for (std::size_t i = 1; i < offsets.size(); ++i)
        if (offsets[i] - offsets[i - 1] < minStep) {  // offsets are within [0, 2^31): no overflow
            fail(label, std::string(what) + " entry " + std::to_string(i - 1) + " has fewer than " +
                            std::to_string(minStep) + " items");
        }
}

void checkFaces(const VoronoiMesh& mesh, const std::string& label)
{
    for (int c = 0; c < mesh.nCells(); ++c) {
        const int nCellVertices = mesh.cellVertexOffset[c + 1] - mesh.cellVertexOffset[c];
        for (int f = mesh.cellFaceOffset[c]; f < mesh.cellFaceOffset[c + 1]; ++f) {
            for (int k = mesh.faceVertexOffset[f]; k < mesh.faceVertexOffset[f + 1]; ++k)
                if (mesh.faceVertices[k] < 0 || mesh.faceVertices[k] >= nCellVertices)
                    fail(label, "face " + std::to_string(f) + " refers to vertex " +
                                    std::to_string(mesh.faceVertices[k]) + " of a cell with " +
                                    std::to_string(nCellVertices) + " vertices");
            const int neighbour = mesh.faceNeighbour[f];
            if (neighbour != boundaryFace && (neighbour < 0 || neighbour >= mesh.nCells() || neighbour == c))
                fail(label, "face " + std::to_string(f) + " has an invalid neighbour cell " +
                                std::to_string(neighbour));
            if (!(mesh.faceArea[f] >= 0)) fail(label, "face " + std::to_string(f) + " has a negative area");
        }
    }
}

std::vector<FacePair> checkedFacePairs(const VoronoiMesh& mesh, const std::vector<int>& raw,
                                       const std::string& label)
{
    const std::vector<int> owner = faceOwners(mesh);
    std::vector<char> bonded(mesh.nFaces(), 0);
    std::vector<FacePair> pairs(raw.size() / 2);
    for (std::size_t p = 0; p < pairs.size(); ++p) {
        const FacePair pair{raw[2 * p], raw[2 * p + 1]};
        const std::string which = "bonded face pair " + std::to_string(p);
        if (pair.faceI < 0 || pair.faceI >= mesh.nFaces() || pair.faceJ < 0 || pair.faceJ >= mesh.nFaces())
            fail(label, which + " refers to a face out of range");
        if (owner[pair.faceI] >= owner[pair.faceJ] || mesh.faceNeighbour[pair.faceI] != owner[pair.faceJ] ||
            mesh.faceNeighbour[pair.faceJ] != owner[pair.faceI])
            fail(label, which + " is not an interface between two neighbouring cells");
        if (bonded[pair.faceI] || bonded[pair.faceJ]) fail(label, which + " bonds a face twice");
        bonded[pair.faceI] = bonded[pair.faceJ] = 1;
        pairs[p] = pair;
    }
    return pairs;
}

// ---- The four binary files ----------------------------------------------------

Bytes encodeCells(const VoronoiMesh& mesh)
{
    Bytes payload;
    Encoder out(payload);
    out.vectors(mesh.seeds);
    out.vectors(mesh.centroids);
    out.doubles(mesh.volumes);
    out.matrices(mesh.inertia);
    out.ints(mesh.cellVertexOffset);
    out.ints(mesh.cellFaceOffset);
    return payload;
}

void decodeCells(const Bytes& file, const MeshInfo& info, const std::string& label, VoronoiMesh& mesh)
{
    const std::size_t n = info.nCells;
    Decoder in(file, headerBytes, label);
    mesh.seeds = in.vectors(n, "seeds");
    mesh.centroids = in.vectors(n, "centroids");
    mesh.volumes = in.doubles(n, "volumes");
    mesh.inertia = in.matrices(n, "inertia");
    mesh.cellVertexOffset = in.ints(n + 1);
    mesh.cellFaceOffset = in.ints(n + 1);
    for (std::size_t c = 0; c < n; ++c)
        if (!(mesh.volumes[c] > 0)) fail(label, "cell " + std::to_string(c) + " has no volume");
    checkOffsets(mesh.cellVertexOffset, static_cast<int>(info.nVertices), 4, label, "cell vertex offsets");
    checkOffsets(mesh.cellFaceOffset, static_cast<int>(info.nFaces), 4, label, "cell face offsets");
}

Bytes encodeVertices(const VoronoiMesh& mesh)
{
    Bytes payload;
    Encoder(payload).vectors(mesh.vertices);
    return payload;
}

Bytes encodeFaces(const VoronoiMesh& mesh)
{
    Bytes payload;
    Encoder out(payload);
    out.ints(mesh.faceVertexOffset);
    out.ints(mesh.faceVertices);
    out.ints(mesh.faceNeighbour);
    out.vectors(mesh.faceNormal);
    out.doubles(mesh.faceArea);
    return payload;
}

void decodeFaces(const Bytes& file, const MeshInfo& info, const std::string& label, VoronoiMesh& mesh)
{
    Decoder in(file, headerBytes, label);
    mesh.faceVertexOffset = in.ints(info.nFaces + 1);
    mesh.faceVertices = in.ints(info.nFaceVertices);
    mesh.faceNeighbour = in.ints(info.nFaces);
    mesh.faceNormal = in.vectors(info.nFaces, "face normals");
    mesh.faceArea = in.doubles(info.nFaces, "face areas");
    checkOffsets(mesh.faceVertexOffset, static_cast<int>(info.nFaceVertices), 3, label,
                 "face vertex offsets");
    checkFaces(mesh, label);
}

// Bonds as the bonded face pairs: consecutive bonds with the same faces are
// one pair, and must be one bond per vertex of faceI.
std::vector<int> bondedFacePairs(const VoronoiMesh& mesh)
{
    std::vector<int> raw;
    for (std::size_t b = 0; b < mesh.bonds.size();) {
        const VoronoiBond& bond = mesh.bonds[b];
        if (bond.faceI < 0 || bond.faceI >= mesh.nFaces())
            throw std::invalid_argument("writeVoronoiMesh: bond with a face index out of range");
        const std::size_t n = mesh.faceVertexOffset[bond.faceI + 1] - mesh.faceVertexOffset[bond.faceI];
        for (std::size_t k = 0; k < n; ++k)
            if (b + k >= mesh.bonds.size() || mesh.bonds[b + k].faceI != bond.faceI ||
                mesh.bonds[b + k].faceJ != bond.faceJ)
                throw std::invalid_argument(
                    "writeVoronoiMesh: bonds must come one per vertex of a face pair");
        raw.push_back(bond.faceI);
        raw.push_back(bond.faceJ);
        b += n;
    }
    return raw;
}

void checkArraySizes(const VoronoiMesh& m)
{
    const std::size_t n = m.volumes.size(), nFaces = m.faceNeighbour.size();
    const bool consistent = n >= 1 && m.seeds.size() == n && m.centroids.size() == n &&
                            m.inertia.size() == n && m.cellVertexOffset.size() == n + 1 &&
                            m.cellFaceOffset.size() == n + 1 && m.faceVertexOffset.size() == nFaces + 1 &&
                            m.faceNormal.size() == nFaces && m.faceArea.size() == nFaces &&
                            m.vertices.size() == static_cast<std::size_t>(m.cellVertexOffset.back()) &&
                            nFaces == static_cast<std::size_t>(m.cellFaceOffset.back()) &&
                            m.faceVertices.size() == static_cast<std::size_t>(m.faceVertexOffset.back()) &&
                            m.faceVertices.size() <= static_cast<std::size_t>(INT_MAX);
    if (!consistent) throw std::invalid_argument("writeVoronoiMesh: the mesh arrays have inconsistent sizes");
}

}  // namespace

void writeVoronoiMesh(const fs::path& caseDir, const VoronoiMesh& mesh)
{
    checkArraySizes(mesh);
    const std::vector<int> pairs = bondedFacePairs(mesh);

    MeshInfo info;
    info.nCells = mesh.volumes.size();
    info.nVertices = mesh.vertices.size();
    info.nFaces = mesh.faceNeighbour.size();
    info.nFaceVertices = mesh.faceVertices.size();
    info.nBondedFaces = pairs.size() / 2;
    info.nBonds = mesh.bonds.size();
    info.seed = mesh.seed;
    info.pruningDistance = mesh.pruningDistance;
    info.dilationRadius = mesh.dilationRadius;
    info.domainVolume = mesh.domainVolume;

    const fs::path dir = caseDir / voronoiMeshDirectory;
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw UserError(dir.string() + ": cannot create the directory (" + ec.message() + ")");

    auto writeBinary = [&](const FileSpec& spec, const Bytes& payload) {
        const Bytes file = makeFile(spec.kind, info, payload);
        writeAtomically(dir / spec.name, displayName(caseDir, spec.name),
                        reinterpret_cast<const char*>(file.data()), file.size());
    };
    writeBinary(cellsFile, encodeCells(mesh));
    writeBinary(verticesFile, encodeVertices(mesh));
    writeBinary(facesFile, encodeFaces(mesh));
    Bytes pairBytes;
    Encoder(pairBytes).ints(pairs);
    writeBinary(bondsFile, pairBytes);

    const std::string text = meshInfoText(info);  // last: it vouches for the others
    writeAtomically(dir / "meshInfo", displayName(caseDir, "meshInfo"), text.data(), text.size());
}

VoronoiMeshSizes readVoronoiMeshSizes(const fs::path& caseDir)
{
    const MeshInfo info = readMeshInfo(caseDir);
    return {info.nCells, info.nVertices, info.nFaces, info.nFaceVertices, info.nBondedFaces, info.nBonds};
}

VoronoiMesh readVoronoiMesh(const fs::path& caseDir)
{
    const MeshInfo info = readMeshInfo(caseDir);
    VoronoiMesh mesh;
    mesh.seed = info.seed;
    mesh.pruningDistance = info.pruningDistance;
    mesh.dilationRadius = info.dilationRadius;
    mesh.domainVolume = info.domainVolume;

    decodeCells(readCheckedFile(caseDir, cellsFile, info), info, displayName(caseDir, cellsFile.name), mesh);
    const Bytes vertices = readCheckedFile(caseDir, verticesFile, info);
    mesh.vertices = Decoder(vertices, headerBytes, displayName(caseDir, verticesFile.name))
                        .vectors(info.nVertices, "vertices");
    decodeFaces(readCheckedFile(caseDir, facesFile, info), info, displayName(caseDir, facesFile.name), mesh);

    const std::string bondsLabel = displayName(caseDir, bondsFile.name);
    const Bytes bonds = readCheckedFile(caseDir, bondsFile, info);
    const std::vector<int> raw = Decoder(bonds, headerBytes, bondsLabel).ints(2 * info.nBondedFaces);
    mesh.bonds = bondsForFacePairs(mesh, checkedFacePairs(mesh, raw, bondsLabel));
    if (mesh.bonds.size() != info.nBonds)
        fail(bondsLabel, "the bonded faces give " + std::to_string(mesh.bonds.size()) +
                             " bonds, meshInfo says " + std::to_string(info.nBonds));
    return mesh;
}

}  // namespace rockfrac
