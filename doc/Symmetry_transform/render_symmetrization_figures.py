#!/usr/bin/python3
# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): The CGAL Symmetry_transform developers
"""Renders the manual's figure of symmetrization from the PLY files of the demo program.

usage (from anywhere; Debian's python3, for which python3-vtk9 is built):

    /usr/bin/python3 doc/Symmetry_transform/render_symmetrization_figures.py [--build-dir DIR] [MESH ...]

It builds the program symmetrize (Release, through render_figures.py) in DIR (default: build/ of
the repository), runs it on meshes of CGAL's sample data (DIR/data/meshes, unpacked by
scripts/setup.sh, which it calls if needed) with the strongest plane detected at its defaults,
and renders doc/Symmetry_transform/fig/symmetrization.png: one row per mesh, the input beside the
symmetrized mesh, both with their vertices coloured by the displacement (dark blue 0, yellow 1 %
of the radius or more), edges drawn, the plane's trace on the surface in red. MESH names files of
DIR/data/meshes without ".off" (default: cow bull). It then builds complete_by_symmetry, runs it on
DIR/data/points_3/oni.pwn with the points of one side removed (x < -0.08, y > 0.05: 262 of 1435)
and renders doc/Symmetry_transform/fig/completion.png: that input beside the completed set, the
added points orange.

Re-running it overwrites the figure. Debian packages: as for render_figures.py (whose helpers it
reuses, with those of render_application_figures.py and render_remeshing_figures.py),
python3-vtk9, xvfb and xauth; without a DISPLAY it runs itself under xvfb-run.
"""

import argparse
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import render_figures as rf  # noqa: E402  (its helpers: run, build_example, text, rectangle, VIEWS, ...)
import render_application_figures as raf  # noqa: E402  (its helper save)
import render_remeshing_figures as rrf  # noqa: E402  (its views, trace_actor and panel size)

ROOT, FIG_DIR = rf.ROOT, rf.FIG_DIR
PANEL_W, PANEL_H, LEGEND_H = rrf.PANEL_W, rrf.PANEL_H, rrf.LEGEND_H
# The demo's ramp of the displacement (colour_ramps.h, blue_to_yellow: 0 to 1 % of the radius).
RAMP = rrf.RAMP


def build_program(build_dir, name):
    """Configures DIR and unpacks the data as render_figures.py does, then builds the program `name`."""
    _, data_dir = rf.build_example(build_dir)
    rf.run(["cmake", "--build", build_dir, "--target", name, "-j", str(os.cpu_count() or 2)])
    return os.path.join(build_dir, "demo", "Symmetry_transform", name), data_dir


def parse_run(out):
    """The plane (a, b, c, d), the mean displacement over the radius and the symmetry distance
    errors before and after, as the program prints them."""
    plane = tuple(float(x) for x in re.search(r"plane (\S+) (\S+) (\S+) (\S+)", out).groups())
    mean = float(re.search(r"over the radius: mean (\S+),", out).group(1))
    before = float(re.search(r"error before: (\S+)", out).group(1))
    after = float(re.search(r"error after: (\S+)", out).group(1))
    return plane, mean, before, after


def panel(window, actors, caption, viewport, camera):
    """A framed renderer of `actors` with a caption, in `viewport` (x0, y0, x1, y1) of the window."""
    ren = vtk.vtkRenderer()
    ren.SetBackground(1, 1, 1)
    ren.SetViewport(*viewport)
    ren.SetUseFXAA(True)
    for actor in actors:
        ren.AddActor(actor)
    ren.AddActor2D(rf.text(caption, 15, 10, PANEL_H - 24, background=True))
    ren.AddActor2D(rf.rectangle((0.8, 0.8, 0.8), 0, 0, PANEL_W - 1, PANEL_H - 1, filled=False))
    ren.SetActiveCamera(camera)
    window.AddRenderer(ren)
    return ren


def mesh_panel(window, mesh, plane, caption, column, row, rows, camera):
    height = rows * PANEL_H + LEGEND_H
    viewport = (column / 2., (LEGEND_H + (rows - 1 - row) * PANEL_H) / height,
                (column + 1) / 2., (LEGEND_H + (rows - row) * PANEL_H) / height)
    actors = [rrf.surface_actor(mesh, on_points=True, edge_width=0.6), rrf.trace_actor(mesh, plane)]
    return panel(window, actors, caption, viewport, camera)


def camera_for(name, mesh):
    view = rrf.VIEWS.get(name, rf.DEFAULT_VIEW)
    bounds = mesh.GetBounds()
    centre = [(bounds[2 * i] + bounds[2 * i + 1]) / 2. for i in range(3)]
    camera = vtk.vtkCamera()
    camera.SetFocalPoint(centre)
    camera.SetPosition([c + t for c, t in zip(centre, view["towards"])])
    camera.SetViewUp(view["up"])
    camera.SetViewAngle(25)
    return camera, bounds, view.get("zoom", 1.15)


def render_figure(runs, png):
    """runs: (mesh name, before ply, after ply, parsed run) per row."""
    rows = len(runs)
    width, height = 2 * PANEL_W, rows * PANEL_H + LEGEND_H
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    for r, (name, before_ply, after_ply, (plane, mean, before, after)) in enumerate(runs):
        before_mesh, after_mesh = rrf.load(before_ply), rrf.load(after_ply)
        camera, bounds, zoom = camera_for(name, before_mesh)
        first = mesh_panel(window, before_mesh, plane, "%s: SDE %.2g" % (name, before), 0, r, rows, camera)
        mesh_panel(window, after_mesh, plane, "symmetrized: SDE %.2g, mean move %.2g R" % (after, mean), 1, r, rows, camera)
        first.ResetCamera(bounds)
        camera.Zoom(zoom)
    names = ".off, ".join(name for name, _, _, _ in runs)  # the legend adds the last ".off"
    legend = rf.colour_bar_legend(width, height, LEGEND_H, RAMP, 1.0, "%.1f %%", width / 2. - 20, 240, names,
                                  "displacement (of the radius)", 14)
    window.AddRenderer(legend)
    raf.save(window, png)


def partial_oni(data_dir, path):
    """oni.pwn without the points of one side: x < -0.08 and y > 0.05."""
    with open(os.path.join(data_dir, "points_3", "oni.pwn")) as f, open(path, "w") as out:
        for line in f:
            x, y = (float(v) for v in line.split()[:2])
            if not (x < -0.08 and y > 0.05):
                out.write(line)


def points_actor(ply):
    glyphs = vtk.vtkVertexGlyphFilter()
    glyphs.SetInputData(rrf.load(ply))
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(glyphs.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("RGBA")
    mapper.SetColorModeToDirectScalars()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetPointSize(5)
    actor.GetProperty().LightingOff()  # the colours as written: grey input, orange added
    return actor


def render_completion(input_ply, completed_ply, added, png):
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(2 * PANEL_W, PANEL_H)
    camera = vtk.vtkCamera()
    camera.SetPosition(0.9, 0.4, 2.5)
    camera.SetViewUp(0, 1, 0)
    for column, (ply, caption) in enumerate([(input_ply, "oni.pwn, part of one side removed"),
                                             (completed_ply, "completed: %d points added (orange)" % added)]):
        ren = panel(window, [points_actor(ply)], caption, (column / 2., 0, (column + 1) / 2., 1), camera)
        if column == 0:
            ren.ResetCamera()
    raf.save(window, png)


def completion_figure(build_dir, work):
    program, data_dir = build_program(build_dir, "complete_by_symmetry")
    partial = os.path.join(work, "oni_partial.xyz")
    partial_oni(data_dir, partial)
    input_ply, completed_ply = os.path.join(work, "oni_partial.ply"), os.path.join(work, "oni_completed.ply")
    # The input alone, as the program writes it when nothing is added (coverage of the whole radius).
    rf.run([program, partial, "--coverage", "2", "--output", input_ply], stdout=subprocess.PIPE)
    out = rf.run([program, partial, "--output", completed_ply], stdout=subprocess.PIPE, text=True).stdout
    sys.stdout.write(out)
    added = int(re.search(r"(\d+) points added", out).group(1))
    render_completion(input_ply, completed_ply, added, os.path.join(FIG_DIR, "completion.png"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("meshes", nargs="*", default=["cow", "bull"])
    parser.add_argument("--build-dir", default=os.path.join(ROOT, "build"))
    args = parser.parse_args()

    program, data_dir = build_program(os.path.abspath(args.build_dir), "symmetrize")
    work = os.path.join(os.path.abspath(args.build_dir), "doc_figures")
    os.makedirs(work, exist_ok=True)
    os.makedirs(FIG_DIR, exist_ok=True)
    runs = []
    for name in args.meshes:
        output = os.path.join(work, "symmetrization_%s.ply" % name)
        out = rf.run([program, os.path.join(data_dir, "meshes", name + ".off"), "--output", output],
                     stdout=subprocess.PIPE, text=True).stdout
        sys.stdout.write(out)
        runs.append((name, output[:-4] + "_before.ply", output, parse_run(out)))
    render_figure(runs, os.path.join(FIG_DIR, "symmetrization.png"))
    completion_figure(os.path.abspath(args.build_dir), work)


if __name__ == "__main__":
    vtk = rrf.vtk = raf.vtk = rf.vtk_with_display(__file__)
    main()
