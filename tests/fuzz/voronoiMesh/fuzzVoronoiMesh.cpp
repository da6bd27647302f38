// libFuzzer target: a constant/voronoiMesh directory built from the input.
//
// Input layout: one flags byte, then the contents of meshInfo, cells, vertices,
// faces and bonds, separated by the 8 bytes "RFSPLIT\n" (a part that is absent
// leaves its file missing). Unless bit 0 of the flags is set, the harness
// rewrites the checksums - bytes 48-55 of each binary file and the four
// *Checksum entries of meshInfo - to the true ones, because a mutated payload
// would otherwise never get past them to the decoders and the topology checks.
// The seeds (corpus/) are a real 6-cell mesh written by writeVoronoiMesh.
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <vector>

#include "../common/fuzzTarget.hpp"
#include "core/checksum.hpp"
#include "core/error.hpp"
#include "voronoi/voronoiMeshIO.hpp"

namespace rockfrac::fuzz {

namespace {

namespace fs = std::filesystem;

const char* const fileNames[5] = {"meshInfo", "cells", "vertices", "faces", "bonds"};
const char* const checksumKeys[4] = {"cellsChecksum", "verticesChecksum", "facesChecksum", "bondsChecksum"};
const std::string separator = "RFSPLIT\n";
constexpr std::size_t headerBytes = 64;

std::vector<std::string> splitParts(const std::string& input)
{
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (parts.size() < 4) {
        const std::size_t end = input.find(separator, start);
        if (end == std::string::npos) break;
        parts.push_back(input.substr(start, end - start));
        start = end + separator.size();
    }
    parts.push_back(input.substr(start));
    return parts;
}

std::string hex(std::uint64_t v)
{
    std::ostringstream s;
    s << "0x" << std::hex << v;
    return s.str();
}

// True checksums into the binary headers and meshInfo.
void fixChecksums(std::vector<std::string>& parts)
{
    std::uint64_t sums[4] = {0, 0, 0, 0};
    for (std::size_t k = 1; k < parts.size(); ++k) {
        std::string& file = parts[k];
        if (file.size() < headerBytes) continue;
        const std::uint64_t sum = fnv1aWords(file.data() + headerBytes, file.size() - headerBytes);
        for (int i = 0; i < 8; ++i) file[48 + i] = static_cast<char>(sum >> (8 * i));
        sums[k - 1] = sum;
    }
    std::istringstream in(parts[0]);
    std::string line, info;
    while (std::getline(in, line))
        if (line.find("Checksum") == std::string::npos) info += line + "\n";
    for (int k = 0; k < 4; ++k) info += std::string(checksumKeys[k]) + " " + hex(sums[k]) + ";\n";
    parts[0] = info;
}

}  // namespace

int fuzzVoronoiMesh(const std::uint8_t* data, std::size_t size)
{
    if (size < 1) return 0;
    const bool keepChecksums = data[0] & 1;
    std::vector<std::string> parts =
        splitParts(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
    if (!keepChecksums) fixChecksums(parts);

    const fs::path caseDir = scratchDirectory() / "voronoiCase";
    const fs::path meshDir = caseDir / voronoiMeshDirectory;
    std::error_code ec;
    fs::remove_all(meshDir, ec);
    fs::create_directories(meshDir);
    for (std::size_t k = 0; k < parts.size(); ++k) writeBytes(meshDir / fileNames[k], parts[k]);
    try {
        const VoronoiMesh mesh = readVoronoiMesh(caseDir);
        if (mesh.nCells() < 1) std::abort();
    } catch (const UserError&) {
    }
    return 0;
}

}  // namespace rockfrac::fuzz

ROCKFRAC_FUZZ_ENTRY(rockfrac::fuzz::fuzzVoronoiMesh)
