#!/usr/bin/python3
# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): The CGAL Symmetry_transform developers
"""Renders the manual's figures of principal symmetries from the PLY files of the example.

usage (from anywhere; Debian's python3, for which python3-vtk9 is built):

    /usr/bin/python3 doc/Symmetry_transform/render_figures.py [--build-dir DIR]
        [--resolution N] [--planes K] [--render-only] [MESH ...]

It builds the example principal_symmetries (Release) in DIR (default: build/ of the
repository), runs it on meshes of CGAL's sample data (package libcgal-demo, unpacked into
DIR/data by scripts/setup.sh, which it calls if needed) at grid resolution N (default 64),
and renders the K strongest planes of each mesh (default 4), two per row, into
doc/Symmetry_transform/fig/principal_symmetries_<mesh>.png: faces coloured by support, dark
where the reflection maps the face far from the surface, bright where it maps it onto it;
the plane as a translucent blue square. MESH names files of DIR/data/meshes without ".off"
(default: bull armadillo couplingdown). Re-running it overwrites the figures; with
--render-only it renders the PLY files of the last run (in DIR/doc_figures) again.

Debian packages: those that scripts/setup.sh installs, and
    apt-get install python3-vtk9 xvfb xauth
Debian's VTK draws through X (no off-screen-only build): without a DISPLAY the script runs
itself again under xvfb-run, so no screen is needed.
"""

import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
FIG_DIR = os.path.join(ROOT, "doc", "Symmetry_transform", "fig")

# A camera per mesh: the direction from the shape towards the camera and the up direction,
# in the mesh's coordinates (the sample meshes are not all upright along the same axis).
# The camera looks at the centre of the shape's bounding box from far enough to see all of it.
VIEWS = {
    "bull": {"towards": (-0.45, 0.15, 1.0), "up": (0, 1, 0)},
    "armadillo": {"towards": (-0.6, 0.25, -1.0), "up": (0, 1, 0)},
    "couplingdown": {"towards": (0.8, 0.6, 1.0), "up": (0, 1, 0)},
}
DEFAULT_VIEW = {"towards": (0.6, 0.4, 1.0), "up": (0, 1, 0)}

PLANE_RGB = (64, 160, 255)  # the colour the example gives the plane's square
# The example's colour ramp for the support (close to matplotlib's "inferno").
RAMP = [(0, 0, 4), (87, 16, 110), (188, 55, 84), (249, 142, 9), (252, 255, 164)]

PANEL_W, PANEL_H, LEGEND_H = 440, 340, 56


def run(command, **kwargs):
    print("+ " + " ".join(command), flush=True)
    return subprocess.run(command, check=True, **kwargs)


def build_example(build_dir):
    """Builds the example (configuring the build tree and unpacking the data if needed)."""
    data_dir = os.path.join(build_dir, "data")
    if not os.path.isfile(os.path.join(data_dir, "meshes", "bull.off")):
        run(["bash", os.path.join(ROOT, "scripts", "setup.sh")], env=dict(os.environ, DATA_DIR=data_dir))
    run(["cmake", "-S", ROOT, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
         "-DSYMMETRY_TRANSFORM_BUILD_EXAMPLES=ON", "-DSYMMETRY_TRANSFORM_DATA_DIR=" + data_dir],
        stdout=subprocess.DEVNULL)
    run(["cmake", "--build", build_dir, "--target", "principal_symmetries", "-j", str(os.cpu_count() or 2)])
    return os.path.join(build_dir, "demo", "Symmetry_transform", "principal_symmetries"), data_dir


def ply_comments(path):
    """The comment lines of a PLY header."""
    comments = []
    with open(path, "rb") as f:
        for line in f:
            line = line.decode("ascii", "replace").strip()
            if line == "end_header":
                break
            if line.startswith("comment "):
                comments.append(line[len("comment "):])
    return comments


def load_panel(path):
    """The shape (all faces but the last two) and the plane's square (the last two) of a PLY
    file of the example, and the caption read from its header."""
    reader = vtk.vtkPLYReader()
    reader.SetFileName(path)
    reader.Update()
    mesh = reader.GetOutput()
    n = mesh.GetNumberOfCells()
    colours = mesh.GetCellData().GetArray("RGBA")
    if n < 3 or colours is None or any(tuple(int(c) for c in colours.GetTuple(i)[:3]) != PLANE_RGB
                                       for i in (n - 2, n - 1)):
        sys.exit(path + ": not a file of the example principal_symmetries (face colours, plane square last)")

    def cells(first, last):
        ids = vtk.vtkIdList()
        for i in range(first, last):
            ids.InsertNextId(i)
        extract = vtk.vtkExtractCells()
        extract.SetInputData(mesh)
        extract.SetCellList(ids)
        surface = vtk.vtkGeometryFilter()
        surface.SetInputConnection(extract.GetOutputPort())
        surface.Update()
        return surface.GetOutput()

    caption = ""
    for comment in ply_comments(path):
        m = re.match(r"plane (\d+): .*; symmetry ([0-9.eE+-]+); support ([0-9.eE+-]+)", comment)
        if m:
            caption = "plane %s   symmetry %.2f   support %.0f %%" % (m.group(1), float(m.group(2)),
                                                                   100 * float(m.group(3)))
    return cells(0, n - 2), cells(n - 2, n), caption


def shape_actor(shape):
    # Smooth normals for the shading; the colours stay per face.
    normals = vtk.vtkPolyDataNormals()
    normals.SetInputData(shape)
    normals.SetFeatureAngle(60)
    normals.ConsistencyOn()
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    mapper.SetScalarModeToUseCellFieldData()
    mapper.SelectColorArray("RGBA")
    mapper.SetColorModeToDirectScalars()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetAmbient(0.25)
    actor.GetProperty().SetDiffuse(0.8)
    return actor


def plane_actors(square):
    rgb = [c / 255. for c in PLANE_RGB]
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(square)
    mapper.ScalarVisibilityOff()
    face = vtk.vtkActor()
    face.SetMapper(mapper)
    face.GetProperty().SetColor(rgb)
    face.GetProperty().SetOpacity(0.3)
    face.GetProperty().SetAmbient(0.6)
    face.GetProperty().SetDiffuse(0.4)
    edges = vtk.vtkFeatureEdges()  # the square's outline
    edges.SetInputData(square)
    edges.BoundaryEdgesOn()
    edges.FeatureEdgesOff()
    edges.NonManifoldEdgesOff()
    edges.ManifoldEdgesOff()
    edges.ColoringOff()
    edge_mapper = vtk.vtkPolyDataMapper()
    edge_mapper.SetInputConnection(edges.GetOutputPort())
    outline = vtk.vtkActor()
    outline.SetMapper(edge_mapper)
    outline.GetProperty().SetColor([0.6 * c for c in rgb])
    outline.GetProperty().SetLineWidth(2)
    outline.GetProperty().LightingOff()
    return [face, outline]


def text(message, size, x, y, justify_right=False, background=False):
    """A line of text at (x, y) pixels of its viewport."""
    actor = vtk.vtkTextActor()
    actor.SetInput(message)
    prop = actor.GetTextProperty()
    prop.SetFontSize(size)
    prop.SetColor(0.1, 0.1, 0.1)
    prop.SetFontFamilyToArial()
    if justify_right:
        prop.SetJustificationToRight()
    if background:  # stays readable over the plane
        prop.SetBackgroundColor(1, 1, 1)
        prop.SetBackgroundOpacity(0.75)
    actor.GetPositionCoordinate().SetCoordinateSystemToViewport()
    actor.GetPositionCoordinate().SetValue(x, y)
    return actor


def rectangle(rgb, x, y, w, h, filled=True):
    """A rectangle, filled or its outline, at (x, y) pixels of its viewport."""
    points = vtk.vtkPoints()
    for px, py in ((x, y), (x + w, y), (x + w, y + h), (x, y + h)):
        points.InsertNextPoint(px, py, 0)
    cells = vtk.vtkCellArray()
    rectangle = vtk.vtkPolyData()
    rectangle.SetPoints(points)
    if filled:
        cells.InsertNextCell(4, [0, 1, 2, 3])
        rectangle.SetPolys(cells)
    else:
        cells.InsertNextCell(5, [0, 1, 2, 3, 0])
        rectangle.SetLines(cells)
    coordinate = vtk.vtkCoordinate()
    coordinate.SetCoordinateSystemToViewport()
    mapper = vtk.vtkPolyDataMapper2D()
    mapper.SetInputData(rectangle)
    mapper.SetTransformCoordinate(coordinate)
    actor = vtk.vtkActor2D()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(rgb)
    return actor


def colour_bar_legend(width, height, legend_h, ramp, top, label_format, bar_x, bar_w, mesh_name, caption,
                      caption_y):
    """The legend strip of a figure: the mesh's name at the left and a horizontal colour bar, whose
    colours `ramp` (RGB 0-255) are spread evenly over [0, top], with `caption` to its left."""
    ren = vtk.vtkRenderer()
    ren.SetBackground(1, 1, 1)
    ren.SetViewport(0, 0, 1, legend_h / height)
    colours = vtk.vtkColorTransferFunction()
    for i, c in enumerate(ramp):
        colours.AddRGBPoint(top * i / (len(ramp) - 1.), *[v / 255. for v in c])
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(colours)
    bar.SetOrientationToHorizontal()
    bar.SetNumberOfLabels(3)
    bar.SetLabelFormat(label_format)
    bar.SetUnconstrainedFontSize(True)
    label = bar.GetLabelTextProperty()
    label.SetFontSize(14)
    label.SetColor(0.1, 0.1, 0.1)
    label.ShadowOff()
    label.ItalicOff()
    label.BoldOff()
    bar.SetBarRatio(0.45)
    bar.DrawFrameOff()
    bar.GetPositionCoordinate().SetCoordinateSystemToViewport()
    bar.GetPositionCoordinate().SetValue(bar_x, 2)
    bar.GetPosition2Coordinate().SetCoordinateSystemToViewport()
    bar.GetPosition2Coordinate().SetValue(bar_w, legend_h - 8)
    ren.AddActor2D(bar)
    ren.AddActor2D(text(mesh_name + ".off", 18, 12, legend_h / 2 - 8))
    ren.AddActor2D(text(caption, 15, bar_x - 12, caption_y, justify_right=True))
    return ren


def legend_renderer(width, height, mesh_name):
    ren = colour_bar_legend(width, height, LEGEND_H, RAMP, 1.0, "%.1f", width / 2. - 60, 220, mesh_name,
                            "support of the reflection", 12)
    ren.AddActor2D(rectangle([0.7 + 0.3 * c / 255. for c in PLANE_RGB], width - 150, 10, 20, 16))
    ren.AddActor2D(text("plane", 15, width - 122, 12))
    return ren


def section_actor(shape, square):
    """The curves where the plane cuts the shape."""
    points = square.GetPoints()
    corner = [points.GetPoint(i) for i in range(3)]
    u = [corner[1][k] - corner[0][k] for k in range(3)]
    v = [corner[2][k] - corner[0][k] for k in range(3)]
    plane = vtk.vtkPlane()
    plane.SetOrigin(corner[0])
    plane.SetNormal(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    cutter = vtk.vtkCutter()
    cutter.SetInputData(shape)
    cutter.SetCutFunction(plane)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(cutter.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor([0.45 * c / 255. for c in PLANE_RGB])
    actor.GetProperty().SetLineWidth(3)
    actor.GetProperty().LightingOff()
    return actor


def render_figure(mesh_name, ply_files, png):
    panels = [load_panel(f) for f in ply_files]
    columns = 2 if len(panels) > 1 else 1
    rows = (len(panels) + columns - 1) // columns
    width, height = PANEL_W * columns, PANEL_H * rows + LEGEND_H
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetAlphaBitPlanes(1)
    window.SetMultiSamples(0)
    window.SetSize(width, height)

    # One camera for all panels, framing the shape (the planes may reach past the frame).
    bounds = panels[0][0].GetBounds()
    view = VIEWS.get(mesh_name, DEFAULT_VIEW)
    camera = vtk.vtkCamera()
    centre = [(bounds[2 * i] + bounds[2 * i + 1]) / 2. for i in range(3)]
    camera.SetFocalPoint(centre)
    camera.SetPosition([c + t for c, t in zip(centre, view["towards"])])
    camera.SetViewUp(view["up"])
    camera.SetViewAngle(25)

    for i, (shape, square, caption) in enumerate(panels):
        row, column = divmod(i, columns)
        ren = vtk.vtkRenderer()
        ren.SetBackground(1, 1, 1)
        ren.SetViewport(column / columns, (LEGEND_H + (rows - 1 - row) * PANEL_H) / height,
                        (column + 1) / columns, (LEGEND_H + (rows - row) * PANEL_H) / height)
        ren.SetUseDepthPeeling(1)
        ren.SetMaximumNumberOfPeels(16)
        ren.SetOcclusionRatio(0.)
        ren.SetUseFXAA(True)
        ren.AddActor(shape_actor(shape))
        for actor in plane_actors(square) + [section_actor(shape, square)]:
            ren.AddActor(actor)
        ren.AddActor2D(text(caption, 15, 10, PANEL_H - 24, background=True))
        ren.AddActor2D(rectangle((0.8, 0.8, 0.8), 0, 0, PANEL_W - 1, PANEL_H - 1, filled=False))
        ren.SetActiveCamera(camera)
        window.AddRenderer(ren)
        if i == 0:
            ren.ResetCamera(bounds)
            camera.Zoom(view.get("zoom", 1.1))
    # Every square lies within 2 half-diagonals of the shape's box from its centre.
    half_diagonal = 0.5 * sum((bounds[2 * i + 1] - bounds[2 * i]) ** 2 for i in range(3)) ** 0.5
    distance = camera.GetDistance()
    camera.SetClippingRange(max(distance - 2.5 * half_diagonal, 0.01 * distance), distance + 2.5 * half_diagonal)
    window.AddRenderer(legend_renderer(width, height, mesh_name))
    window.Render()

    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetCompressionLevel(9)
    writer.SetFileName(png)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print("wrote %s (%d KB)" % (png, (os.path.getsize(png) + 1023) // 1024), flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("meshes", nargs="*", default=["bull", "armadillo", "couplingdown"])
    parser.add_argument("--build-dir", default=os.path.join(ROOT, "build"))
    parser.add_argument("--resolution", type=int, default=64)
    parser.add_argument("--planes", type=int, default=4)
    parser.add_argument("--render-only", action="store_true",
                        help="render the PLY files of the last run again, without building or running the example")
    args = parser.parse_args()

    if not args.render_only:
        example, data_dir = build_example(os.path.abspath(args.build_dir))
    work = os.path.join(os.path.abspath(args.build_dir), "doc_figures")
    os.makedirs(work, exist_ok=True)
    os.makedirs(FIG_DIR, exist_ok=True)
    for name in args.meshes:
        if not args.render_only:
            for old in [f for f in os.listdir(work) if re.fullmatch(re.escape(name) + r"_\d+\.ply", f)]:
                os.remove(os.path.join(work, old))
            run([example, os.path.join(data_dir, "meshes", name + ".off"), "--resolution", str(args.resolution),
                 "--planes", str(args.planes), "--output", os.path.join(work, name)])
        files = sorted((f for f in os.listdir(work) if re.fullmatch(re.escape(name) + r"_\d+\.ply", f)),
                       key=lambda f: int(f[len(name) + 1:-4]))
        if not files:
            print("%s: no plane found, no figure" % name)
            continue
        render_figure(name, [os.path.join(work, f) for f in files],
                      os.path.join(FIG_DIR, "principal_symmetries_%s.png" % name))


def vtk_with_display(script):
    """Imports VTK (into this module too) and returns it. Debian's VTK needs an X server even off
    screen: without a DISPLAY, `script` runs again under xvfb-run and this call does not return."""
    global vtk
    if not os.environ.get("DISPLAY") and not os.environ.get("RENDER_FIGURES_UNDER_XVFB"):
        os.environ["RENDER_FIGURES_UNDER_XVFB"] = "1"
        try:
            os.execvp("xvfb-run", ["xvfb-run", "-a", "-s", "-screen 0 1920x1080x24",
                                   sys.executable, os.path.abspath(script)] + sys.argv[1:])
        except FileNotFoundError:
            sys.exit("No DISPLAY and no xvfb-run: apt-get install xvfb xauth")
    try:
        import vtk as module
    except ImportError:
        sys.exit("No VTK for %s: apt-get install python3-vtk9, and run this script with Debian's "
                 "/usr/bin/python3" % sys.executable)
    vtk = module
    return vtk


if __name__ == "__main__":
    vtk_with_display(__file__)
    main()
