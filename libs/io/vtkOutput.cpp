#include "io/vtkOutput.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>

#include "core/atomicFile.hpp"
#include "core/error.hpp"

namespace rockfrac {

namespace fs = std::filesystem;

Field Field::scalar(std::string name, std::vector<double> values)
{
    Field f;
    f.name = std::move(name);
    f.values = std::move(values);
    return f;
}

Field Field::vector(std::string name, const std::vector<Vec3>& values)
{
    Field f;
    f.name = std::move(name);
    f.components = 3;
    f.values.reserve(3 * values.size());
    for (const auto& v : values) {
        f.values.push_back(v.x);
        f.values.push_back(v.y);
        f.values.push_back(v.z);
    }
    return f;
}

Field Field::integer(std::string name, const std::vector<int>& values)
{
    Field f;
    f.name = std::move(name);
    f.values.assign(values.begin(), values.end());
    f.isInteger = true;
    return f;
}

namespace {

vtkSmartPointer<vtkDataArray> toVtkArray(const Field& field, std::size_t nItems, const fs::path& file)
{
    if (field.values.size() != nItems * static_cast<std::size_t>(field.components))
        throw std::logic_error("field '" + field.name + "' for " + file.string() + " has " +
                               std::to_string(field.values.size()) + " values for " + std::to_string(nItems) +
                               " items");
    vtkSmartPointer<vtkDataArray> array;
    if (field.isInteger)
        array = vtkSmartPointer<vtkIntArray>::New();
    else
        array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(field.name.c_str());
    array->SetNumberOfComponents(field.components);
    array->SetNumberOfTuples(static_cast<vtkIdType>(nItems));
    for (std::size_t i = 0; i < field.values.size(); ++i)
        array->SetComponent(static_cast<vtkIdType>(i / field.components),
                            static_cast<int>(i % field.components), field.values[i]);
    return array;
}

vtkNew<vtkPoints> toVtkPoints(const std::vector<Vec3>& points)
{
    vtkNew<vtkPoints> vtkPts;
    vtkPts->SetDataTypeToDouble();
    vtkPts->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i)
        vtkPts->SetPoint(static_cast<vtkIdType>(i), points[i].x, points[i].y, points[i].z);
    return vtkPts;
}

void addTimeValue(vtkDataObject* data, double timeValue)
{
    vtkNew<vtkDoubleArray> time;
    time->SetName("TimeValue");
    time->SetNumberOfTuples(1);
    time->SetValue(0, timeValue);
    data->GetFieldData()->AddArray(time);
}

template <class Writer, class Data>
void writeXml(const fs::path& file, Data* data)
{
    // VTK's writers report success even when their own file stream was cut short (a full
    // disk left a torn 16 kB frame): VTK writes to memory, and the bytes go to disk through
    // writeFileAtomically, which checks the stream and the written size before the rename.
    vtkNew<Writer> writer;
    writer->WriteToOutputStringOn();
    writer->SetInputData(data);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetCompressorTypeToZLib();
    const int warnings = vtkObject::GetGlobalWarningDisplay();
    vtkObject::GlobalWarningDisplayOff();
    const bool written = writer->Write() == 1;
    vtkObject::SetGlobalWarningDisplay(warnings);
    if (!written) throw UserError("cannot write '" + file.string() + "': VTK could not encode the data");
    const std::string bytes = writer->GetOutputString();
    writeFileAtomically(file, [&](std::ostream& out) {
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    });
}

}  // namespace

void writePolyhedraVtu(const fs::path& file, const PolyhedronSet& cells, const std::vector<Field>& cellFields,
                       double timeValue)
{
    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(toVtkPoints(cells.points));
    const int nCells = cells.nCells();
    grid->Allocate(nCells);
    std::vector<vtkIdType> faceStream, pointIds;
    for (int c = 0; c < nCells; ++c) {
        faceStream.clear();
        pointIds.clear();
        const int nFaces = cells.cellFaceOffset[c + 1] - cells.cellFaceOffset[c];
        for (int f = cells.cellFaceOffset[c]; f < cells.cellFaceOffset[c + 1]; ++f) {
            const int begin = cells.faceVertexOffset[f], end = cells.faceVertexOffset[f + 1];
            faceStream.push_back(end - begin);
            for (int k = begin; k < end; ++k) {
                faceStream.push_back(cells.faceVertices[k]);
                pointIds.push_back(cells.faceVertices[k]);
            }
        }
        std::sort(pointIds.begin(), pointIds.end());
        pointIds.erase(std::unique(pointIds.begin(), pointIds.end()), pointIds.end());
        grid->InsertNextCell(VTK_POLYHEDRON, static_cast<vtkIdType>(pointIds.size()), pointIds.data(), nFaces,
                             faceStream.data());
    }
    for (const auto& field : cellFields)
        grid->GetCellData()->AddArray(toVtkArray(field, static_cast<std::size_t>(nCells), file));
    addTimeValue(grid, timeValue);
    writeXml<vtkXMLUnstructuredGridWriter>(file, grid.GetPointer());
}

void writeLinesVtp(const fs::path& file, const std::vector<Vec3>& points,
                   const std::vector<std::array<int, 2>>& lines, const std::vector<Field>& lineFields,
                   const std::vector<Field>& pointFields, double timeValue)
{
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(toVtkPoints(points));
    vtkNew<vtkCellArray> cellArray;
    for (const auto& l : lines) {
        const vtkIdType ids[2] = {l[0], l[1]};
        cellArray->InsertNextCell(2, ids);
    }
    poly->SetLines(cellArray);
    for (const auto& field : lineFields) poly->GetCellData()->AddArray(toVtkArray(field, lines.size(), file));
    for (const auto& field : pointFields)
        poly->GetPointData()->AddArray(toVtkArray(field, points.size(), file));
    addTimeValue(poly, timeValue);
    writeXml<vtkXMLPolyDataWriter>(file, poly.GetPointer());
}

void writePointsVtp(const fs::path& file, const std::vector<Vec3>& points,
                    const std::vector<Field>& pointFields, double timeValue)
{
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(toVtkPoints(points));
    vtkNew<vtkCellArray> verts;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const vtkIdType id = static_cast<vtkIdType>(i);
        verts->InsertNextCell(1, &id);
    }
    poly->SetVerts(verts);
    for (const auto& field : pointFields)
        poly->GetPointData()->AddArray(toVtkArray(field, points.size(), file));
    addTimeValue(poly, timeValue);
    writeXml<vtkXMLPolyDataWriter>(file, poly.GetPointer());
}

void writeTrianglesVtp(const fs::path& file, const std::vector<Vec3>& points,
                       const std::vector<std::array<int, 3>>& triangles, double timeValue)
{
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(toVtkPoints(points));
    vtkNew<vtkCellArray> polys;
    for (const auto& t : triangles) {
        const vtkIdType ids[3] = {t[0], t[1], t[2]};
        polys->InsertNextCell(3, ids);
    }
    poly->SetPolys(polys);
    addTimeValue(poly, timeValue);
    writeXml<vtkXMLPolyDataWriter>(file, poly.GetPointer());
}

void writeTetsVtu(const fs::path& file, const std::vector<Vec3>& points,
                  const std::vector<std::array<int, 4>>& tets, const std::vector<Field>& cellFields,
                  const std::vector<Field>& pointFields, double timeValue)
{
    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(toVtkPoints(points));
    grid->Allocate(static_cast<vtkIdType>(tets.size()));
    for (const auto& t : tets) {
        const vtkIdType ids[4] = {t[0], t[1], t[2], t[3]};
        grid->InsertNextCell(VTK_TETRA, 4, ids);
    }
    for (const auto& field : cellFields) grid->GetCellData()->AddArray(toVtkArray(field, tets.size(), file));
    for (const auto& field : pointFields)
        grid->GetPointData()->AddArray(toVtkArray(field, points.size(), file));
    addTimeValue(grid, timeValue);
    writeXml<vtkXMLUnstructuredGridWriter>(file, grid.GetPointer());
}

// ---- SeriesFile ----------------------------------------------------------------

SeriesFile::SeriesFile(fs::path seriesPath) : path_(std::move(seriesPath))
{
    std::ifstream in(path_);
    if (!in) return;  // a new series
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    // The format is our own simple JSON: one {"name": "...", "time": t} per entry.
    static const std::regex entry(R"re(\{\s*"name"\s*:\s*"([^"]*)"\s*,\s*"time"\s*:\s*([-+0-9.eE]+)\s*\})re");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), entry); it != std::sregex_iterator(); ++it)
        entries_.emplace_back((*it)[1].str(), std::stod((*it)[2].str()));
}

void SeriesFile::truncateFrom(double time)
{
    entries_.erase(
        std::remove_if(entries_.begin(), entries_.end(), [time](const auto& e) { return e.second >= time; }),
        entries_.end());
}

void SeriesFile::add(const std::string& fileName, double time)
{
    truncateFrom(time);
    entries_.emplace_back(fileName, time);
}

void SeriesFile::write() const
{
    writeFileAtomically(path_, [&](std::ostream& out) {
        out << "{\n  \"file-series-version\" : \"1.0\",\n  \"files\" : [\n";
        out << std::setprecision(17);
        for (std::size_t i = 0; i < entries_.size(); ++i)
            out << "    { \"name\": \"" << entries_[i].first << "\", \"time\" : " << entries_[i].second
                << " }" << (i + 1 < entries_.size() ? "," : "") << "\n";
        out << "  ]\n}\n";
    });
}

}  // namespace rockfrac
