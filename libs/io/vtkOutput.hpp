#pragma once
// VTK XML output for ParaView, written through VTK's own writers.
//
// Each file carries a "TimeValue" field array; SeriesFile maintains the
// matching "<name>.vtu.series" (or .vtp.series) JSON index that ParaView reads
// as a time series. Every file is written atomically (temporary name + rename).
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "core/vec3.hpp"

namespace rockfrac {

// A named field with 1 (scalar) or 3 (vector) components per item.
struct Field {
    std::string name;
    int components = 1;
    std::vector<double> values;  // size = n_items * components

    static Field scalar(std::string name, std::vector<double> values);
    static Field vector(std::string name, const std::vector<Vec3>& values);
    static Field integer(std::string name, const std::vector<int>& values);  // stored as Int32
    bool isInteger = false;
};

// Convex polyhedra: points and, per cell, its faces as lists of point ids
// (CSR: cell c has faces cellFaceOffset[c]..[c+1], face f has point ids
// faceVertices[faceVertexOffset[f]..[f+1])). Written as VTK_POLYHEDRON (42).
struct PolyhedronSet {
    std::vector<Vec3> points;
    std::vector<int> cellFaceOffset;
    std::vector<int> faceVertexOffset;
    std::vector<int> faceVertices;
    int nCells() const { return static_cast<int>(cellFaceOffset.size()) - 1; }
};

void writePolyhedraVtu(const std::filesystem::path& file, const PolyhedronSet& cells,
                       const std::vector<Field>& cellFields, double timeValue);

// Line segments (bonds, contacts) with per-line and per-point fields.
void writeLinesVtp(const std::filesystem::path& file, const std::vector<Vec3>& points,
                   const std::vector<std::array<int, 2>>& lines, const std::vector<Field>& lineFields,
                   const std::vector<Field>& pointFields, double timeValue);

// Points only (seeds, centroids).
void writePointsVtp(const std::filesystem::path& file, const std::vector<Vec3>& points,
                    const std::vector<Field>& pointFields, double timeValue);

// Triangulated surface.
void writeTrianglesVtp(const std::filesystem::path& file, const std::vector<Vec3>& points,
                       const std::vector<std::array<int, 3>>& triangles, double timeValue);

// Linear tetrahedra with cell and point fields.
void writeTetsVtu(const std::filesystem::path& file, const std::vector<Vec3>& points,
                  const std::vector<std::array<int, 4>>& tets, const std::vector<Field>& cellFields,
                  const std::vector<Field>& pointFields, double timeValue);

// "<name>.vtu.series": the list of (file, time) ParaView reads as one data set.
// On restart the entries at or after the restart time are dropped and the new
// ones appended, so a continued run extends the series instead of clobbering it.
class SeriesFile {
public:
    explicit SeriesFile(std::filesystem::path seriesPath);
    void truncateFrom(double time);                      // drop entries with time >= time
    void add(const std::string& fileName, double time);  // relative to the series file
    void write() const;                                  // atomically
    const std::vector<std::pair<std::string, double>>& entries() const { return entries_; }

private:
    std::filesystem::path path_;
    std::vector<std::pair<std::string, double>> entries_;
};

}  // namespace rockfrac
