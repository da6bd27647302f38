// renderVtk: a picture of a VTK file for reports, rendered headless by VTK.
//
//   renderVtk -case C VTK/cells_4000.vtu -field damage -out results/bdt.png
//
// Colours the cells (or points) of a .vtu/.vtp by a field (blue = low, red =
// high, as in the paper's damage figures), with a scalar bar, and writes a PNG
// atomically. It needs an X display: the rockfrac scripts run it under xvfb-run
// when no DISPLAY is set. The camera looks along -y by default (the face of a
// Brazilian disc; plates are horizontal). Beside the PNG it writes a ParaView state
// (<name>-paraview.py: same file, field, colour range and camera), so the picture of
// a report can be opened in ParaView and explored from the same view.
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
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWindowToImageFilter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

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
     {"-size", "'w h'", "image size in pixels (default 900 700)"},
     {"-noState", "", "do not write the ParaView state <out>-paraview.py beside the PNG"}},
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

// A Python string literal (the paths and texts of the state file).
std::string pythonString(const std::string& text)
{
    std::string quoted = "'";
    for (char c : text) {
        if (c == '\\' || c == '\'') quoted += '\\';
        if (c == '\n') {
            quoted += "\\n";
            continue;
        }
        quoted += c;
    }
    return quoted + "'";
}

std::string pythonVector(const double* v, int n)
{
    std::ostringstream s;
    s.precision(17);
    s << '[';
    for (int i = 0; i < n; ++i) s << (i ? ", " : "") << v[i];
    return s.str() + ']';
}

// What the picture shows, for the ParaView state.
struct PictureSettings {
    fs::path input, png;
    std::string field;  // empty: grey
    bool cell_field = true, vector_field = false;
    double range[2] = {0.0, 1.0};
    std::string title;
    int width = 900, height = 700;
};

// A ParaView Python state (paraview.simple, ParaView 5.9 or later): File > Load State
// opens it in the GUI; 'pvpython <file> picture.png' (or pvbatch) renders it again.
std::string paraviewState(const PictureSettings& p, vtkCamera* camera)
{
    std::ostringstream s;
    s.precision(17);
    const std::string input = fs::absolute(p.input).lexically_normal().string();
    s << "# ParaView state written by renderVtk for " << p.png.filename().string() << ": the same file,\n"
      << "# field, colour range and camera. In ParaView: File > Load State, choose this file\n"
      << "# (Python state). Headless: pvpython " << p.png.stem().string() << "-paraview.py picture.png\n"
      << "# The data file is named by its absolute path; edit FileName if the case moved.\n"
      << "import sys\n"
      << "from paraview.simple import *\n\n"
      << "source = " << (p.input.extension() == ".vtp" ? "XMLPolyDataReader" : "XMLUnstructuredGridReader")
      << "(registrationName=" << pythonString(p.input.filename().string()) << ", FileName=["
      << pythonString(input) << "])\n"
      << "view = GetActiveViewOrCreate('RenderView')\n"
      << "view.ViewSize = [" << p.width << ", " << p.height << "]\n"
      << "view.OrientationAxesVisibility = 0\n"
      << "if hasattr(view, 'UseColorPaletteForBackground'):\n"
      << "    view.UseColorPaletteForBackground = 0\n"
      << "view.Background = [1.0, 1.0, 1.0]\n"
      << "display = Show(source, view)\n"
      << "display.SetRepresentationType('Surface With Edges')\n"
      << "display.EdgeColor = [0.2, 0.2, 0.2]\n"
      << "display.DiffuseColor = [0.8, 0.8, 0.8]\n";
    if (!p.field.empty()) {
        s << "ColorBy(display, (" << (p.cell_field ? "'CELLS'" : "'POINTS'") << ", " << pythonString(p.field)
          << (p.vector_field ? ", 'Magnitude'" : "") << "))\n"
          << "lut = GetColorTransferFunction(" << pythonString(p.field) << ")\n"
          << "lut.ApplyPreset('Blue to Red Rainbow', True)\n"
          << "lut.AutomaticRescaleRangeMode = 'Never'\n"
          << "lut.RescaleTransferFunction(" << p.range[0] << ", " << p.range[1] << ")\n"
          << "display.SetScalarBarVisibility(view, True)\n"
          << "bar = GetScalarBar(lut, view)\n"
          << "bar.Title = " << pythonString(p.field) << "\n"
          << "bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]\n";
    }
    if (!p.title.empty())
        s << "title = Text(Text=" << pythonString(p.title) << ")\n"
          << "titleDisplay = Show(title, view)\n"
          << "titleDisplay.Color = [0.0, 0.0, 0.0]\n"
          << "titleDisplay.WindowLocation = 'Lower Left Corner'\n";
    double position[3], focal[3], up[3];
    camera->GetPosition(position);
    camera->GetFocalPoint(focal);
    camera->GetViewUp(up);
    s << "view.CameraPosition = " << pythonVector(position, 3) << "\n"
      << "view.CameraFocalPoint = " << pythonVector(focal, 3) << "\n"
      << "view.CameraViewUp = " << pythonVector(up, 3) << "\n"
      << "view.CameraViewAngle = " << camera->GetViewAngle() << "\n"
      << "Render(view)\n"
      << "if len(sys.argv) > 1 and sys.argv[1].endswith('.png'):\n"
      << "    SaveScreenshot(sys.argv[1], view, ImageResolution=[" << p.width << ", " << p.height << "])\n";
    return s.str();
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

        PictureSettings picture;
        picture.input = input;
        picture.png = out;
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
            picture.field = *field;
            picture.cell_field = cellArray != nullptr;
            picture.vector_field = array->GetNumberOfComponents() > 1;
            picture.range[0] = range[0];
            picture.range[1] = range[1];
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
            picture.title = *title;
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
        picture.width = width;
        picture.height = height;
        vtkNew<vtkRenderWindow> window;
        window->SetOffScreenRendering(1);
        window->AddRenderer(renderer);
        window->SetSize(width, height);
        window->Render();
        vtkNew<vtkWindowToImageFilter> image;
        image->SetInput(window);
        image->Update();
        // The PNG is encoded in memory and written through the checked atomic path.
        vtkNew<vtkPNGWriter> writer;
        writer->WriteToMemoryOn();
        writer->SetInputConnection(image->GetOutputPort());
        writer->Write();
        vtkUnsignedCharArray* png = writer->GetResult();
        if (!png || png->GetNumberOfValues() == 0)
            throw UserError("cannot encode '" + out.string() + "' as PNG");
        writeFileAtomically(out, [&](std::ostream& file) {
            file.write(reinterpret_cast<const char*>(png->GetPointer(0)),
                       static_cast<std::streamsize>(png->GetNumberOfValues()));
        });
        std::printf("renderVtk: %s\n", out.string().c_str());
        if (!app.has("-noState")) {
            const fs::path state = out.parent_path() / (out.stem().string() + "-paraview.py");
            const std::string text = paraviewState(picture, camera);
            writeFileAtomically(state, [&](std::ostream& file) { file << text; });
            std::printf("renderVtk: %s (ParaView state: File > Load State)\n", state.string().c_str());
        }
        return 0;
    });
}
