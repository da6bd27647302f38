// checkVtk <file> <polyhedra|tets|lines|triangles|points> <count> [volume <expected> <relTol>]
//
// Exit 0 when the file reads back with the expected number of items of that
// kind (and, for polyhedra and tets, the expected total volume computed from
// the geometry itself); otherwise prints what differs and exits 1.
#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

double signedTetVolume(const double* a, const double* b, const double* c, const double* d)
{
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
            u[2] * (v[0] * w[1] - v[1] * w[0])) /
           6.0;
}

// Volume of every polyhedron from its outward faces (fan triangulation, divergence theorem).
double polyhedraVolume(vtkUnstructuredGrid* grid)
{
    double total = 0;
    const double origin[3] = {0, 0, 0};
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
        vtkNew<vtkIdList> faces;
        grid->GetFaceStream(c, faces);
        vtkIdType k = 1;  // faces->GetId(0) is the face count
        for (vtkIdType f = 0; f < faces->GetId(0); ++f) {
            const vtkIdType n = faces->GetId(k);
            double p0[3], p1[3], p2[3];
            grid->GetPoint(faces->GetId(k + 1), p0);
            for (vtkIdType i = 1; i + 1 < n; ++i) {
                grid->GetPoint(faces->GetId(k + 1 + i), p1);
                grid->GetPoint(faces->GetId(k + 2 + i), p2);
                total += signedTetVolume(origin, p0, p1, p2);
            }
            k += n + 1;
        }
    }
    return total;
}

double tetsVolume(vtkUnstructuredGrid* grid)
{
    double total = 0;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
        vtkNew<vtkIdList> ids;
        grid->GetCellPoints(c, ids);
        double p[4][3];
        for (int k = 0; k < 4; ++k) grid->GetPoint(ids->GetId(k), p[k]);
        total += std::abs(signedTetVolume(p[0], p[1], p[2], p[3]));
    }
    return total;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 4 && argc != 7) {
        std::fprintf(stderr,
                     "usage: checkVtk <file> <polyhedra|tets|lines|triangles|points> <count> "
                     "[volume <expected> <relTol>]\n");
        return 2;
    }
    const std::string file = argv[1], kind = argv[2];
    const long expected = std::atol(argv[3]);
    long count = -1;
    double volume = NAN;
    if (kind == "polyhedra" || kind == "tets") {
        vtkNew<vtkXMLUnstructuredGridReader> reader;
        reader->SetFileName(file.c_str());
        reader->Update();
        vtkUnstructuredGrid* grid = reader->GetOutput();
        count = grid->GetNumberOfCells();
        const int type = kind == "polyhedra" ? VTK_POLYHEDRON : VTK_TETRA;
        for (vtkIdType c = 0; c < count; ++c)
            if (grid->GetCellType(c) != type) {
                std::fprintf(stderr, "checkVtk: %s: cell %lld is not of type %s\n", file.c_str(),
                             static_cast<long long>(c), kind.c_str());
                return 1;
            }
        volume = kind == "polyhedra" ? polyhedraVolume(grid) : tetsVolume(grid);
    } else {
        vtkNew<vtkXMLPolyDataReader> reader;
        reader->SetFileName(file.c_str());
        reader->Update();
        vtkPolyData* poly = reader->GetOutput();
        count = kind == "lines"       ? poly->GetNumberOfLines()
                : kind == "triangles" ? poly->GetNumberOfPolys()
                                      : poly->GetNumberOfPoints();
    }
    if (count != expected) {
        std::fprintf(stderr, "checkVtk: %s has %ld %s, expected %ld\n", file.c_str(), count, kind.c_str(),
                     expected);
        return 1;
    }
    if (argc == 7) {
        const double want = std::atof(argv[5]), tol = std::atof(argv[6]);
        if (!(std::abs(volume - want) <= tol * std::abs(want))) {
            std::fprintf(stderr, "checkVtk: %s volume %.8g, expected %.8g within %.3g %%\n", file.c_str(),
                         volume, want, 100 * tol);
            return 1;
        }
        std::printf("checkVtk: %s: %ld %s, volume %.8g (expected %.8g)\n", file.c_str(), count, kind.c_str(),
                    volume, want);
    } else {
        std::printf("checkVtk: %s: %ld %s\n", file.c_str(), count, kind.c_str());
    }
    return 0;
}
