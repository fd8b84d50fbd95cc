#!/usr/bin/python3
# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): The CGAL Symmetry_transform developers
"""Renders the manual's figures of symmetric remeshing from the PLY files of the example.

usage (from anywhere; Debian's python3, for which python3-vtk9 is built):

    /usr/bin/python3 doc/Symmetry_transform/render_remeshing_figures.py [--build-dir DIR]
        [--resolution N] [--proxies K[,K...]] [MESH ...]

It builds the example symmetric_remeshing (Release, with principal_symmetries, through
render_figures.py) in DIR (default: build/ of the repository),
runs it on meshes of CGAL's sample data (DIR/data/meshes, unpacked by scripts/setup.sh, which
it calls if needed) with the strongest plane detected at grid resolution N (default 64) and K
proxies (default 50 and 100), and renders, for each mesh, doc/Symmetry_transform/fig/
remeshing_<mesh>.png: one row per K, the symmetric VSA (K proxies) beside CGAL's VSA (K
proxies), the faces coloured by their symmetry error as the example writes it (the distance from
the mirror image of the face's centroid to the surface: dark blue symmetric, yellow 2 % of the
diagonal or more; the thesis's Figure 5.6), edges drawn, the plane's trace on the surface in
red. MESH names files of DIR/data/meshes without ".off" (default: cow bull).

Re-running it overwrites the figures. Debian packages: as for render_figures.py (whose helpers
it reuses, with those of render_application_figures.py), python3-vtk9, xvfb and xauth; without a DISPLAY it runs itself under xvfb-run.
"""

import argparse
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import render_figures as rf  # noqa: E402  (its helpers: run, build_example, text, rectangle, VIEWS, ...)
import render_application_figures as raf  # noqa: E402  (its helper save)

ROOT, FIG_DIR = rf.ROOT, rf.FIG_DIR

# The cow seen from the front, above and aside, so that both sides of its plane show; the bull
# as in render_figures.py.
VIEWS = dict(rf.VIEWS)
VIEWS["cow"] = {"towards": (1.0, 0.8, 0.45), "up": (0, 1, 0)}

# The example's ramp of the symmetry error (0 to 2 % of the diagonal).
RAMP = [(20, 30, 110), (30, 150, 160), (120, 200, 80), (250, 230, 40)]
PANEL_W, PANEL_H, LEGEND_H = 460, 360, 60


def build_example(build_dir):
    """Configures DIR and unpacks the data as render_figures.py does, then builds symmetric_remeshing."""
    _, data_dir = rf.build_example(build_dir)
    rf.run(["cmake", "--build", build_dir, "--target", "symmetric_remeshing", "-j", str(os.cpu_count() or 2)])
    return os.path.join(build_dir, "demo", "Symmetry_transform", "symmetric_remeshing"), data_dir


def parse_run(out):
    """The plane (a, b, c, d) and the table rows {name: (vertices, faces, rms, symmetry)} printed
    by the example."""
    plane = None
    m = re.search(r"plane ([-0-9.eE+]+) ([-0-9.eE+]+) ([-0-9.eE+]+) ([-0-9.eE+]+)", out)
    if m:
        plane = tuple(float(m.group(i)) for i in range(1, 5))
    rows = {}
    for line in out.splitlines():
        m = re.match(r"\s+(symmetric VSA|CGAL VSA),\s+K = (\d+)\s+(\d+)\s+(\d+)\s+\S+\s+(\S+)\s+\S+\s+(\S+)\s+(\S+)", line)
        if m:
            rows[(m.group(1), int(m.group(2)))] = (int(m.group(3)), int(m.group(4)), float(m.group(5)),
                                                   float(m.group(7)))
    return plane, rows


def load(path):
    reader = vtk.vtkPLYReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def surface_actor(mesh, on_points=False, edge_width=1.0):
    """The surface in the colours of its faces (or of its vertices, `on_points`), edges drawn."""
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(mesh)
    if on_points:
        mapper.SetScalarModeToUsePointFieldData()
    else:
        mapper.SetScalarModeToUseCellFieldData()
    mapper.SelectColorArray("RGBA")
    mapper.SetColorModeToDirectScalars()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    prop.SetAmbient(0.3)
    prop.SetDiffuse(0.75)
    prop.EdgeVisibilityOn()
    prop.SetEdgeColor(0.12, 0.12, 0.12)
    prop.SetLineWidth(edge_width)
    return actor


def trace_actor(mesh, plane):
    """The curve where the plane cuts the surface."""
    a, b, c, d = plane
    norm2 = a * a + b * b + c * c
    cut = vtk.vtkPlane()
    cut.SetNormal(a, b, c)
    cut.SetOrigin(-d * a / norm2, -d * b / norm2, -d * c / norm2)
    cutter = vtk.vtkCutter()
    cutter.SetInputData(mesh)
    cutter.SetCutFunction(cut)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(cutter.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.85, 0.1, 0.1)
    actor.GetProperty().SetLineWidth(2.5)
    actor.GetProperty().LightingOff()
    return actor


def legend_renderer(width, height, mesh_name):
    return rf.colour_bar_legend(width, height, LEGEND_H, RAMP, 2.0, "%.0f %%", width / 2. - 20, 240, mesh_name,
                                "symmetry error (of the diagonal)", 14)


def render_figure(mesh_name, panels, plane, png):
    """panels: rows of (ply path, caption), two per row."""
    rows = len(panels)
    width, height = 2 * PANEL_W, rows * PANEL_H + LEGEND_H
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    meshes = [[load(path) for path, _ in row] for row in panels]
    bounds = meshes[0][0].GetBounds()
    view = VIEWS.get(mesh_name, rf.DEFAULT_VIEW)
    camera = vtk.vtkCamera()
    centre = [(bounds[2 * i] + bounds[2 * i + 1]) / 2. for i in range(3)]
    camera.SetFocalPoint(centre)
    camera.SetPosition([c + t for c, t in zip(centre, view["towards"])])
    camera.SetViewUp(view["up"])
    camera.SetViewAngle(25)
    first = True
    for r, row in enumerate(panels):
        for c, (path, caption) in enumerate(row):
            ren = vtk.vtkRenderer()
            ren.SetBackground(1, 1, 1)
            ren.SetViewport(c / 2., (LEGEND_H + (rows - 1 - r) * PANEL_H) / height,
                            (c + 1) / 2., (LEGEND_H + (rows - r) * PANEL_H) / height)
            ren.SetUseFXAA(True)
            mesh = meshes[r][c]
            ren.AddActor(surface_actor(mesh))
            if plane:
                ren.AddActor(trace_actor(mesh, plane))
            ren.AddActor2D(rf.text(caption, 15, 10, PANEL_H - 24, background=True))
            ren.AddActor2D(rf.rectangle((0.8, 0.8, 0.8), 0, 0, PANEL_W - 1, PANEL_H - 1, filled=False))
            ren.SetActiveCamera(camera)
            window.AddRenderer(ren)
            if first:
                ren.ResetCamera(bounds)
                camera.Zoom(view.get("zoom", 1.15))
                first = False
    window.AddRenderer(legend_renderer(width, height, mesh_name))
    raf.save(window, png)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("meshes", nargs="*", default=["cow", "bull"])
    parser.add_argument("--build-dir", default=os.path.join(ROOT, "build"))
    parser.add_argument("--resolution", type=int, default=64)
    parser.add_argument("--proxies", default="50,100")
    args = parser.parse_args()

    example, data_dir = build_example(os.path.abspath(args.build_dir))
    work = os.path.join(os.path.abspath(args.build_dir), "doc_figures")
    os.makedirs(work, exist_ok=True)
    os.makedirs(FIG_DIR, exist_ok=True)
    for name in args.meshes:
        panels, plane = [], None
        for k in [int(k) for k in args.proxies.split(",")]:
            output = os.path.join(work, "remeshing_%s_%d.ply" % (name, k))
            out = rf.run([example, os.path.join(data_dir, "meshes", name + ".off"), "--resolution",
                          str(args.resolution), "--proxies", str(k), "--output", output],
                         stdout=subprocess.PIPE, text=True).stdout
            sys.stdout.write(out)
            plane, rows = parse_run(out)

            def caption(method):
                vertices, faces, rms, symmetry = rows[(method, k)]
                return "%s, K = %d: %d faces, RMS %.1f, sym. %.1f" % (method, k, faces, rms, symmetry)
            panels.append([(output, caption("symmetric VSA")),
                           (output[:-4] + "_cgal_vsa.ply", caption("CGAL VSA"))])
        render_figure(name, panels, plane, os.path.join(FIG_DIR, "remeshing_%s.png" % name))


if __name__ == "__main__":
    vtk = raf.vtk = rf.vtk_with_display(__file__)
    main()
