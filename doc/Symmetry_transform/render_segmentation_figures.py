#!/usr/bin/python3
# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): The CGAL Symmetry_transform developers
"""Renders the manual's figures of symmetry-based segmentation from the PLY files of the example.

usage (from anywhere; Debian's python3, for which python3-vtk9 is built):

    /usr/bin/python3 doc/Symmetry_transform/render_segmentation_figures.py [--build-dir DIR]
        [--resolution N] [--segments K[,K...]] [MESH ...]

It builds the example symmetry_segmentation (Release, through render_figures.py) in DIR
(default: build/ of the repository), runs it on meshes of CGAL's sample data (DIR/data/meshes,
unpacked by scripts/setup.sh, which it calls if needed) at grid resolution N (default 32) with
at most K segments (default 2, 4 and 8; depth 3; the thesis's Figure 5.11), the last run also
with --sdf (CGAL's SDF segmentation with its defaults), and renders, for each mesh,
doc/Symmetry_transform/fig/segmentation_<mesh>.png: one panel per K and a last one for CGAL's
SDF segmentation, faces coloured by segment as the example writes them. MESH names files of
DIR/data/meshes without ".off" (default: bull camel).

Re-running it overwrites the figures. Debian packages: as for render_figures.py (whose helpers
it reuses, with the PLY reader of render_remeshing_figures.py and the PNG writer of
render_application_figures.py), python3-vtk9, xvfb and xauth;
without a DISPLAY it runs itself under xvfb-run.
"""

import argparse
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import render_figures as rf  # noqa: E402  (its helpers: run, text, rectangle, VIEWS, vtk_with_display, ...)
import render_application_figures as raf  # noqa: E402  (save: the window as a PNG file)
import render_remeshing_figures as rrf  # noqa: E402  (its PLY reader, load)

ROOT, FIG_DIR = rf.ROOT, rf.FIG_DIR

VIEWS = dict(rf.VIEWS)
VIEWS.update({
    "camel": {"towards": (0.9, 0.35, 1.0), "up": (0, 1, 0)},
    "dino": {"towards": (0.2, 0.35, 1.0), "up": (0, 1, 0)},
})

PANEL_W, PANEL_H, LEGEND_H = 340, 300, 40


def build_example(build_dir):
    """Configures DIR and unpacks the data as render_figures.py does, then builds symmetry_segmentation."""
    _, data_dir = rf.build_example(build_dir)
    rf.run(["cmake", "--build", build_dir, "--target", "symmetry_segmentation", "-j", str(os.cpu_count() or 2)])
    return os.path.join(build_dir, "demo", "Symmetry_transform", "symmetry_segmentation"), data_dir


def parse_run(out):
    """(our segments, our seconds, SDF segments or None, SDF seconds or None) from the example's output."""
    ours = re.search(r"(\d+) segments \(depth <= \d+, grid \d+\^3\) in ([0-9.eE+-]+) s", out)
    sdf = re.search(r"CGAL's SDF segmentation: (\d+) segments in ([0-9.eE+-]+) s", out)
    return (int(ours.group(1)), float(ours.group(2)),
            int(sdf.group(1)) if sdf else None, float(sdf.group(2)) if sdf else None)


def segment_actor(mesh):
    """The mesh with its faces in the colours the example gave them, no edges (dense meshes)."""
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(mesh)
    mapper.SetScalarModeToUseCellFieldData()
    mapper.SelectColorArray("RGBA")
    mapper.SetColorModeToDirectScalars()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetAmbient(0.3)
    actor.GetProperty().SetDiffuse(0.75)
    return actor


def render_figure(mesh_name, panels, png):
    """panels: (ply path, caption), in one row."""
    width, height = len(panels) * PANEL_W, PANEL_H + LEGEND_H
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    meshes = [rrf.load(path) for path, _ in panels]
    bounds = meshes[0].GetBounds()
    view = VIEWS.get(mesh_name, rf.DEFAULT_VIEW)
    camera = vtk.vtkCamera()
    centre = [(bounds[2 * i] + bounds[2 * i + 1]) / 2. for i in range(3)]
    camera.SetFocalPoint(centre)
    camera.SetPosition([c + t for c, t in zip(centre, view["towards"])])
    camera.SetViewUp(view["up"])
    camera.SetViewAngle(25)
    for c, ((_, caption), mesh) in enumerate(zip(panels, meshes)):
        ren = vtk.vtkRenderer()
        ren.SetBackground(1, 1, 1)
        ren.SetViewport(c / len(panels), LEGEND_H / height, (c + 1) / len(panels), 1.)
        ren.SetUseFXAA(True)
        ren.AddActor(segment_actor(mesh))
        ren.AddActor2D(rf.text(caption, 14, 8, PANEL_H - 22, background=True))
        ren.AddActor2D(rf.rectangle((0.8, 0.8, 0.8), 0, 0, PANEL_W - 1, PANEL_H - 1, filled=False))
        ren.SetActiveCamera(camera)
        window.AddRenderer(ren)
        if c == 0:
            ren.ResetCamera(bounds)
            camera.Zoom(view.get("zoom", 1.15))
    legend = vtk.vtkRenderer()
    legend.SetBackground(1, 1, 1)
    legend.SetViewport(0, 0, 1, LEGEND_H / height)
    legend.AddActor2D(rf.text(mesh_name + ".off: faces coloured by segment", 16, 10, 12))
    window.AddRenderer(legend)
    raf.save(window, png)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("meshes", nargs="*", default=["bull", "camel"])
    parser.add_argument("--build-dir", default=os.path.join(ROOT, "build"))
    parser.add_argument("--resolution", type=int, default=32)
    parser.add_argument("--segments", default="2,4,8")
    args = parser.parse_args()

    example, data_dir = build_example(os.path.abspath(args.build_dir))
    work = os.path.join(os.path.abspath(args.build_dir), "doc_figures")
    os.makedirs(work, exist_ok=True)
    os.makedirs(FIG_DIR, exist_ok=True)
    counts = [int(k) for k in args.segments.split(",")]
    for name in args.meshes:
        panels = []
        for i, k in enumerate(counts):
            output = os.path.join(work, "segmentation_%s_%d.ply" % (name, k))
            command = [example, os.path.join(data_dir, "meshes", name + ".off"), "--resolution", str(args.resolution),
                       "--depth", "3", "--segments", str(k), "--output", output]
            last = i + 1 == len(counts)
            out = rf.run(command + (["--sdf"] if last else []), stdout=subprocess.PIPE, text=True).stdout
            sys.stdout.write(out)
            segments, seconds, sdf_segments, sdf_seconds = parse_run(out)
            panels.append((output, "ours, <= %d: %d segments, %.2f s" % (k, segments, seconds)))
            if last:
                sdf_panel = (output[:-4] + "_sdf.ply", "CGAL SDF: %d segments, %.2f s" % (sdf_segments, sdf_seconds))
        panels.append(sdf_panel)
        render_figure(name, panels, os.path.join(FIG_DIR, "segmentation_%s.png" % name))


if __name__ == "__main__":
    vtk = rf.vtk_with_display(__file__)
    rrf.vtk = raf.vtk = vtk  # the modules' helpers use their own global
    main()
