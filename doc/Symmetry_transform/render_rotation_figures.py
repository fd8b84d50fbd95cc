#!/usr/bin/python3
# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): The CGAL Symmetry_transform developers
"""Renders the manual's figure of rotational symmetries from the PLY files of the example.

usage (from anywhere; Debian's python3, for which python3-vtk9 is built):

    /usr/bin/python3 doc/Symmetry_transform/render_rotation_figures.py [--build-dir DIR]
        [--resolution N] [--render-only] [MESH ...]

It builds the example rotational_symmetries (Release, through render_figures.py) in DIR
(default: build/ of the repository), runs it on meshes of CGAL's sample data (DIR/data/meshes,
unpacked by scripts/setup.sh, which it calls if needed) at grid resolution N (default 64), and
renders doc/Symmetry_transform/fig/rotational_symmetries.png: one panel per mesh, the surface
grey and half transparent, each axis the coloured cylinder the example draws, a caption with the
orders found. MESH names files of DIR/data/meshes without ".off" (default: pinion cross rotor
turbine couplingdown anchor blade cylinder). With --render-only it renders the PLY files of the
last run (in DIR/doc_figures) again.

Debian packages: as for render_figures.py, whose helpers it reuses (python3-vtk9, xvfb, xauth);
without a DISPLAY it runs itself under xvfb-run.
"""

import argparse
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import render_figures as rf  # noqa: E402  (its helpers: run, build_example, text, rectangle, ply_comments, ...)
import render_application_figures as raf  # noqa: E402  (save: the window as a PNG file)

ROOT, FIG_DIR = rf.ROOT, rf.FIG_DIR
MESHES = ["pinion", "cross", "rotor", "turbine", "couplingdown", "anchor", "blade", "cylinder"]
VIEWS = dict(rf.VIEWS)
VIEWS.update({
    "pinion": {"towards": (1.0, 0.5, 0.8), "up": (0, 0, 1)},
    "cross": {"towards": (0.7, 0.5, 1.0), "up": (0, 1, 0)},
    "rotor": {"towards": (0.9, 0.6, 0.8), "up": (0, 0, 1)},
    "turbine": {"towards": (1.0, 0.7, 0.6), "up": (0, 0, 1)},
    "blade": {"towards": (0.5, 0.3, 1.0), "up": (1, 0, 0), "zoom": 1.1},
    "cylinder": {"towards": (0.8, 0.9, 1.0), "up": (0, 0, 1)},
})
MESH_RGB = (200, 200, 200)  # the colour the example gives the mesh; the axes have others
PANEL_W, PANEL_H = 330, 300


def build_example(build_dir):
    """Configures DIR and unpacks the data as render_figures.py does, then builds rotational_symmetries."""
    _, data_dir = rf.build_example(build_dir)
    rf.run(["cmake", "--build", build_dir, "--target", "rotational_symmetries", "-j", str(os.cpu_count() or 2)])
    return os.path.join(build_dir, "demo", "Symmetry_transform", "rotational_symmetries"), data_dir


def caption(path):
    """'10-fold, 10 x 2-fold' from the example's PLY comments ('axis i: order k; ...')."""
    counts = {}
    for comment in rf.ply_comments(path):
        m = re.match(r"axis \d+: order (\d+);", comment)
        if m:
            counts[int(m.group(1))] = counts.get(int(m.group(1)), 0) + 1
    if not counts:
        return "no rotational symmetry"
    parts = []
    for order in sorted(counts, key=lambda k: 1000 if k == 0 else k, reverse=True):
        name = "continuous" if order == 0 else "%d-fold" % order
        parts.append(name if counts[order] == 1 else "%d x %s" % (counts[order], name))
    return ", ".join(parts)


def split_by_colour(mesh):
    """The surface (faces of the mesh's colour) and the axes (the other faces) of a PLY file of the example."""
    colours = mesh.GetCellData().GetArray("RGBA")
    is_axis = vtk.vtkUnsignedCharArray()
    is_axis.SetName("is_axis")
    for i in range(mesh.GetNumberOfCells()):
        is_axis.InsertNextValue(tuple(int(c) for c in colours.GetTuple(i)[:3]) != MESH_RGB)
    mesh.GetCellData().AddArray(is_axis)
    parts = []
    for value in (0, 1):  # the surface, then the axes
        threshold = vtk.vtkThreshold()
        threshold.SetInputData(mesh)
        threshold.SetInputArrayToProcess(0, 0, 0, vtk.vtkDataObject.FIELD_ASSOCIATION_CELLS, "is_axis")
        threshold.SetLowerThreshold(value - 0.5)
        threshold.SetUpperThreshold(value + 0.5)
        threshold.SetThresholdFunction(vtk.vtkThreshold.THRESHOLD_BETWEEN)
        geometry = vtk.vtkGeometryFilter()
        geometry.SetInputConnection(threshold.GetOutputPort())
        geometry.Update()
        parts.append(geometry.GetOutput())
    return parts


def actor(polydata, opacity):
    """The shading of render_figures.py's shapes, `opacity` opaque."""
    result = rf.shape_actor(polydata)
    result.GetProperty().SetOpacity(opacity)
    return result


def panel(window, name, ply, column, row, columns, rows):
    reader = vtk.vtkPLYReader()
    reader.SetFileName(ply)
    reader.Update()
    surface, axes = split_by_colour(reader.GetOutput())
    ren = vtk.vtkRenderer()
    ren.SetBackground(1, 1, 1)
    ren.SetViewport(column / columns, (rows - 1 - row) / rows, (column + 1) / columns, (rows - row) / rows)
    ren.SetUseDepthPeeling(1)
    ren.SetMaximumNumberOfPeels(16)
    ren.SetOcclusionRatio(0.)
    ren.AddActor(actor(surface, 0.45))  # half transparent: the axes show through the shape
    ren.AddActor(actor(axes, 1.0))
    bounds = surface.GetBounds()
    view = VIEWS.get(name, rf.DEFAULT_VIEW)
    camera = ren.GetActiveCamera()
    centre = [(bounds[2 * i] + bounds[2 * i + 1]) / 2. for i in range(3)]
    camera.SetFocalPoint(centre)
    camera.SetPosition([c + t for c, t in zip(centre, view["towards"])])
    camera.SetViewUp(view["up"])
    camera.SetViewAngle(25)
    ren.ResetCamera(bounds)
    camera.Zoom(view.get("zoom", 1.0))
    ren.ResetCameraClippingRange()
    ren.AddActor2D(rf.text(name + ".off", 16, 10, PANEL_H - 24))
    ren.AddActor2D(rf.text(caption(ply), 14, 10, 8, background=True))
    ren.AddActor2D(rf.rectangle((0.8, 0.8, 0.8), 0, 0, PANEL_W - 1, PANEL_H - 1, filled=False))
    window.AddRenderer(ren)


def render(names, work, png):
    columns = min(4, len(names))
    rows = (len(names) + columns - 1) // columns
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetAlphaBitPlanes(1)
    window.SetMultiSamples(0)
    window.SetSize(PANEL_W * columns, PANEL_H * rows)
    for i, name in enumerate(names):
        panel(window, name, os.path.join(work, name + ".ply"), i % columns, i // columns, columns, rows)
    raf.save(window, png)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("meshes", nargs="*", default=MESHES)
    parser.add_argument("--build-dir", default=os.path.join(ROOT, "build"))
    parser.add_argument("--resolution", type=int, default=64)
    parser.add_argument("--render-only", action="store_true",
                        help="render the PLY files of the last run again, without building or running the example")
    args = parser.parse_args()
    work = os.path.join(os.path.abspath(args.build_dir), "doc_figures", "rotational")
    os.makedirs(work, exist_ok=True)
    if not args.render_only:
        example, data_dir = build_example(os.path.abspath(args.build_dir))
        for name in args.meshes:
            rf.run([example, os.path.join(data_dir, "meshes", name + ".off"), "--resolution", str(args.resolution),
                    "--output", os.path.join(work, name + ".ply")])
    render(args.meshes, work, os.path.join(FIG_DIR, "rotational_symmetries.png"))


if __name__ == "__main__":
    vtk = raf.vtk = rf.vtk_with_display(__file__)
    main()
