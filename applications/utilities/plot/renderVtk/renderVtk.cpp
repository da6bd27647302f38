// renderVtk: a picture of a VTK file for reports, rendered headless by VTK.
//
//   renderVtk -case C VTK/cells_4000.vtu -field damage -out results/bdt.png
//
// Colours the cells (or points) of a .vtu/.vtp by a field (blue = low, red =
// high, as in the paper's damage figures), with a scalar bar, and writes a PNG
// atomically. It needs an X display: the rockfrac scripts run it under xvfb-run
// when no DISPLAY is set. The camera looks along -y by default (the face of a
// Brazilian disc; plates are horizontal).
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkDataSet.h>
#include <vtkDataSetMapper.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWindowToImageFilter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cstdio>
#include <cstdlib>

#include "core/application.hpp"
#include "core/atomicFile.hpp"

using namespace rockfrac;
namespace fs = std::filesystem;

namespace {

const AppInfo info{
    "renderVtk",
    "Renders a VTK XML file (.vtu or .vtp) to a PNG, coloured by a cell or point field, headless\n"
    "(under xvfb-run when there is no display). For reports: the broken specimen coloured by damage.",
    "[options] <file.vtu|file.vtp>",
    {"renderVtk -case tutorials/BDT/granite VTK/cells_4000.vtu -field damage -out damage.png",
     "xvfb-run -a renderVtk VTK/voronoiMesh.vtu -field volume -view z -out mesh.png"},
    {{"-field", "name", "cell or point field to colour by (default: none, grey)"},
     {"-out", "file.png", "PNG to write (default: <file>.png beside the input)"},
     {"-view", "x|y|z|iso", "look along -x, -y (default), -z, or obliquely"},
     {"-range", "'lo hi'", "colour range (default: the field's range)"},
     {"-title", "text", "title printed on the picture"},
     {"-size", "'w h'", "image size in pixels (default 900 700)"}},
    1,
    1,
    false,
};

vtkSmartPointer<vtkDataSet> readDataSet(const fs::path& file)
{
    if (!fs::exists(file)) throw UserError("cannot read '" + file.string() + "': no such file");
    if (file.extension() == ".vtu") {
        vtkNew<vtkXMLUnstructuredGridReader> reader;
        reader->SetFileName(file.string().c_str());
        reader->Update();
        return vtkSmartPointer<vtkDataSet>(reader->GetOutput());
    }
    if (file.extension() == ".vtp") {
        vtkNew<vtkXMLPolyDataReader> reader;
        reader->SetFileName(file.string().c_str());
        reader->Update();
        return vtkSmartPointer<vtkDataSet>(reader->GetOutput());
    }
    throw UserError("'" + file.string() + "' is neither .vtu nor .vtp");
}

}  // namespace

int main(int argc, char** argv)
{
    return runApplication(info, argc, argv, [](Application& app) {
        // The input first: a missing or broken file is the message that helps, with or
        // without a display. VTK's own warnings would add lines to the one-line error.
        vtkObject::GlobalWarningDisplayOff();
        const fs::path input = app.path(app.args()[0]);
        vtkSmartPointer<vtkDataSet> data = readDataSet(input);
        if (!data || data->GetNumberOfCells() == 0)
            throw UserError("'" + input.string() + "' has no cells to render (empty or not a VTK XML file)");
        if (!std::getenv("DISPLAY"))
            throw UserError(
                "no X display to render on; run it as 'xvfb-run -a renderVtk ...' (package xvfb)");
        const fs::path out = app.optionIf("-out") ? app.path(*app.optionIf("-out"))
                                                  : fs::path(input).replace_extension(".png");

        vtkNew<vtkDataSetSurfaceFilter> surface;
        surface->SetInputData(data);
        vtkNew<vtkDataSetMapper> mapper;
        mapper->SetInputConnection(surface->GetOutputPort());
        vtkNew<vtkLookupTable> colours;
        colours->SetHueRange(0.667, 0.0);  // blue -> red
        colours->Build();
        mapper->SetLookupTable(colours);
        mapper->ScalarVisibilityOff();

        vtkNew<vtkRenderer> renderer;
        renderer->SetBackground(1, 1, 1);
        if (const auto field = app.optionIf("-field")) {
            vtkDataArray* cellArray = data->GetCellData()->GetArray(field->c_str());
            vtkDataArray* pointArray = data->GetPointData()->GetArray(field->c_str());
            if (!cellArray && !pointArray)
                throw UserError("'" + input.string() + "' has no field '" + *field + "'");
            vtkDataArray* array = cellArray ? cellArray : pointArray;
            double range[2];
            array->GetRange(range, array->GetNumberOfComponents() > 1 ? -1 : 0);
            if (const auto given = app.optionIf("-range"))
                std::sscanf(given->c_str(), "%lf %lf", &range[0], &range[1]);
            mapper->ScalarVisibilityOn();
            if (cellArray)
                mapper->SetScalarModeToUseCellFieldData();
            else
                mapper->SetScalarModeToUsePointFieldData();
            mapper->SelectColorArray(field->c_str());
            if (array->GetNumberOfComponents() > 1) colours->SetVectorModeToMagnitude();
            mapper->SetScalarRange(range);
            vtkNew<vtkScalarBarActor> bar;
            bar->SetLookupTable(colours);
            bar->SetTitle(field->c_str());
            bar->GetTitleTextProperty()->SetColor(0, 0, 0);
            bar->GetLabelTextProperty()->SetColor(0, 0, 0);
            bar->SetNumberOfLabels(5);
            bar->SetWidth(0.08);
            bar->SetPosition(0.9, 0.1);
            renderer->AddActor2D(bar);
        }
        vtkNew<vtkActor> actor;
        actor->SetMapper(mapper);
        actor->GetProperty()->SetEdgeVisibility(true);
        actor->GetProperty()->SetEdgeColor(0.2, 0.2, 0.2);
        actor->GetProperty()->SetColor(0.8, 0.8, 0.8);
        renderer->AddActor(actor);
        if (const auto title = app.optionIf("-title")) {
            vtkNew<vtkTextActor> text;
            text->SetInput(title->c_str());
            text->GetTextProperty()->SetColor(0, 0, 0);
            text->GetTextProperty()->SetFontSize(20);
            text->SetPosition(10, 10);
            renderer->AddActor2D(text);
        }
        const std::string view = app.optionIf("-view").value_or("y");
        vtkCamera* camera = renderer->GetActiveCamera();
        camera->SetFocalPoint(0, 0, 0);
        if (view == "x") {
            camera->SetPosition(1, 0, 0);
            camera->SetViewUp(0, 0, 1);
        } else if (view == "z") {
            camera->SetPosition(0, 0, 1);
            camera->SetViewUp(0, 1, 0);
        } else if (view == "y") {
            camera->SetPosition(0, -1, 0);
            camera->SetViewUp(0, 0, 1);
        } else if (view == "iso") {
            camera->SetPosition(1, -1.2, 0.8);
            camera->SetViewUp(0, 0, 1);
        } else
            throw UserError("-view must be x, y, z or iso, not '" + view + "'");
        renderer->ResetCamera();
        camera->Zoom(1.05);

        int width = 900, height = 700;
        if (const auto size = app.optionIf("-size")) std::sscanf(size->c_str(), "%d %d", &width, &height);
        vtkNew<vtkRenderWindow> window;
        window->SetOffScreenRendering(1);
        window->AddRenderer(renderer);
        window->SetSize(width, height);
        window->Render();
        vtkNew<vtkWindowToImageFilter> image;
        image->SetInput(window);
        image->Update();
        writeViaTemporary(out, [&](const fs::path& tmp) {
            vtkNew<vtkPNGWriter> writer;
            writer->SetFileName(tmp.string().c_str());
            writer->SetInputConnection(image->GetOutputPort());
            writer->Write();
            return fs::exists(tmp) && fs::file_size(tmp) > 0;
        });
        std::printf("renderVtk: %s\n", out.string().c_str());
        return 0;
    });
}
