#!/usr/bin/python3
# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): The CGAL Symmetry_transform developers
"""Renders the manual's figures of alignment and viewpoint selection from the examples' output.

usage (from anywhere; Debian's python3, for which python3-vtk9 is built):

    /usr/bin/python3 doc/Symmetry_transform/render_application_figures.py [--build-dir DIR]
        [--resolution N] [--alignment MESH ...] [--viewpoints MESH ...] [--mesh-dir DIR] [--z-up]

It builds the examples align_to_symmetry_frame and best_viewpoint (Release) in DIR (default:
build/ of the repository), runs them on meshes of CGAL's sample data (DIR/data/meshes, unpacked
by scripts/setup.sh, which it calls if needed; or DIR/MESH.off with --mesh-dir) at grid
resolution N (default 64), parses what they print and renders:

- doc/Symmetry_transform/fig/alignment_frames.png: each --alignment mesh (default: bull cow),
  translucent, with its symmetry frame (thick red, green and blue arrows for axes 1, 2 and 3,
  from the centre of symmetry) and its PCA frame (thin light arrows in the same hues, from the
  centre of mass), as printed by align_to_symmetry_frame;
- doc/Symmetry_transform/fig/viewpoint_<mesh>.png for each --viewpoints mesh (default: bull
  cow): the score sphere that best_viewpoint writes (dark: low score S(v), bright: high; the
  best and worst directions marked), the mesh seen from the best direction and from the worst.

Re-running it overwrites the figures. Debian packages: as for render_figures.py (whose helpers
it reuses), python3-vtk9, xvfb and xauth; without a DISPLAY it runs itself under xvfb-run.
"""

import argparse
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import render_figures as rf  # noqa: E402  (its helpers: run, text, rectangle, RAMP, VIEWS, ...)

ROOT, FIG_DIR = rf.ROOT, rf.FIG_DIR

# Directions towards the camera and up directions for the meshes not in render_figures.VIEWS.
VIEWS = dict(rf.VIEWS)
VIEWS.update({
    "cow": {"towards": (0.55, 0.35, 1.0), "up": (0, 1, 0)},
    "triceratops": {"towards": (0.6, 0.4, 1.0), "up": (0, 1, 0)},
})

AXIS_RGB = [(0.85, 0.1, 0.1), (0.1, 0.65, 0.1), (0.1, 0.25, 0.9)]  # symmetry axes 1, 2, 3
PCA_RGB = [(1.0, 0.6, 0.6), (0.6, 0.9, 0.5), (0.55, 0.75, 1.0)]    # PCA axes, lighter
MESH_RGB = (0.78, 0.76, 0.72)
BEST_RGB, WORST_RGB = (0.2, 0.9, 1.0), (1.0, 1.0, 1.0)

PANEL_W, PANEL_H, LEGEND_H = 440, 360, 64


def build_examples(build_dir):
    data_dir = os.path.join(build_dir, "data")
    if not os.path.isfile(os.path.join(data_dir, "meshes", "bull.off")):
        rf.run(["bash", os.path.join(ROOT, "scripts", "setup.sh")], env=dict(os.environ, DATA_DIR=data_dir))
    rf.run(["cmake", "-S", ROOT, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
            "-DSYMMETRY_TRANSFORM_BUILD_EXAMPLES=ON", "-DSYMMETRY_TRANSFORM_DATA_DIR=" + data_dir],
           stdout=subprocess.DEVNULL)
    rf.run(["cmake", "--build", build_dir, "--target", "align_to_symmetry_frame", "best_viewpoint",
            "-j", str(os.cpu_count() or 2)])
    return os.path.join(build_dir, "demo", "Symmetry_transform"), data_dir


def output_of(command):
    """Runs command, echoing and returning its standard output."""
    out = rf.run(command, stdout=subprocess.PIPE, text=True).stdout
    sys.stdout.write(out)
    return out


NUMBER = r"([-+0-9.eE]+)"
TRIPLE = r"\(\s*" + NUMBER + r"\s+" + NUMBER + r"\s+" + NUMBER + r"\s*\)"


def parse_frames(out):
    """{"symmetry": (centre, [axis 1, 2, 3]), "pca": (...)} from align_to_symmetry_frame's output."""
    frames, current = {}, None
    for line in out.splitlines():
        if line.startswith("Symmetry frame ("):
            current = frames.setdefault("symmetry", [None, []])
        elif line.startswith("PCA frame ("):
            current = frames.setdefault("pca", [None, []])
        elif current is not None:
            m = re.match(r"\s+(centre|axis \d) " + TRIPLE, line)
            if m:
                v = tuple(float(m.group(i)) for i in (2, 3, 4))
                if m.group(1) == "centre":
                    current[0] = v
                else:
                    current[1].append(v)
    if set(frames) != {"symmetry", "pca"} or any(c is None or len(a) != 3 for c, a in frames.values()):
        sys.exit("cannot read the frames in the output of align_to_symmetry_frame")
    return frames


def parse_views(out):
    """(best direction, best score, worst direction, worst score) from best_viewpoint's output."""
    best = re.search(r"^\s+1\s+v = " + TRIPLE + r"\s+S = " + NUMBER, out, re.M)
    worst = re.search(r"^Worst view.*v = " + TRIPLE + r"\s+S = " + NUMBER, out, re.M)
    if not best or not worst:
        sys.exit("cannot read the best and worst views in the output of best_viewpoint")
    return (tuple(float(best.group(i)) for i in (1, 2, 3)), float(best.group(4)),
            tuple(float(worst.group(i)) for i in (1, 2, 3)), float(worst.group(4)))


# -- geometry helpers ------------------------------------------------------------------------------

def normalised(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def read_off(path):
    """A polygon mesh from an OFF file (VTK 9.1 has no OFF reader); face colours are ignored."""
    with open(path) as f:
        lines = [line.split("#")[0].split() for line in f]
    lines = [line for line in lines if line]
    header = lines[0]
    if not header[0].endswith("OFF"):
        sys.exit(path + ": not an OFF file")
    counts = header[1:] if len(header) > 1 else lines.pop(1)
    nv, nf = int(counts[0]), int(counts[1])
    points = vtk.vtkPoints()
    for line in lines[1:1 + nv]:
        points.InsertNextPoint(float(line[0]), float(line[1]), float(line[2]))
    polys = vtk.vtkCellArray()
    for line in lines[1 + nv:1 + nv + nf]:
        k = int(line[0])
        polys.InsertNextCell(k, [int(t) for t in line[1:1 + k]])
    mesh = vtk.vtkPolyData()
    mesh.SetPoints(points)
    mesh.SetPolys(polys)
    return mesh


def mesh_actor(mesh, opacity=1.0):
    normals = vtk.vtkPolyDataNormals()
    normals.SetInputData(mesh)
    normals.SetFeatureAngle(60)
    normals.ConsistencyOn()
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    prop.SetColor(MESH_RGB)
    prop.SetOpacity(opacity)
    prop.SetAmbient(0.25)
    prop.SetDiffuse(0.75)
    prop.SetSpecular(0.1)
    return actor


def arrow_actor(origin, direction, length, rgb, thickness):
    """An arrow from origin along direction; thickness scales its shaft and tip (of the length)."""
    source = vtk.vtkArrowSource()
    source.SetShaftRadius(0.03 * thickness)
    source.SetTipRadius(0.08 * thickness)
    source.SetTipLength(0.18)
    source.SetShaftResolution(24)
    source.SetTipResolution(24)
    x = normalised(direction)
    helper = (1, 0, 0) if abs(x[0]) < 0.9 else (0, 1, 0)
    y = normalised(cross(x, helper))
    z = cross(x, y)
    matrix = vtk.vtkMatrix4x4()
    for r in range(3):
        matrix.SetElement(r, 0, x[r] * length)
        matrix.SetElement(r, 1, y[r] * length)
        matrix.SetElement(r, 2, z[r] * length)
        matrix.SetElement(r, 3, origin[r])
    transform = vtk.vtkTransform()
    transform.SetMatrix(matrix)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.SetUserTransform(transform)
    actor.GetProperty().SetColor(rgb)
    actor.GetProperty().SetAmbient(0.35)
    actor.GetProperty().SetDiffuse(0.7)
    return actor


def ball_actor(centre, radius, rgb):
    source = vtk.vtkSphereSource()
    source.SetCenter(centre)
    source.SetRadius(radius)
    source.SetThetaResolution(24)
    source.SetPhiResolution(16)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(rgb)
    actor.GetProperty().SetAmbient(0.4)
    return actor


def new_window(width, height):
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetAlphaBitPlanes(1)
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    return window


def panel(window, column, columns, height, caption):
    ren = vtk.vtkRenderer()
    ren.SetBackground(1, 1, 1)
    ren.SetViewport(column / columns, LEGEND_H / height, (column + 1) / columns, 1)
    ren.SetUseDepthPeeling(1)
    ren.SetMaximumNumberOfPeels(16)
    ren.SetOcclusionRatio(0.)
    ren.SetUseFXAA(True)
    ren.AddActor2D(rf.text(caption, 15, 10, PANEL_H - 24, background=True))
    ren.AddActor2D(rf.rectangle((0.8, 0.8, 0.8), 0, 0, PANEL_W - 1, PANEL_H - 1, filled=False))
    window.AddRenderer(ren)
    return ren


def place_camera(ren, focal, towards, up, bounds, zoom=1.0, view_angle=25):
    camera = vtk.vtkCamera()
    towards = normalised(towards)
    if abs(dot(normalised(up), towards)) > 0.95:  # up along the view: take another up
        up = (1, 0, 0) if abs(towards[0]) < 0.9 else (0, 0, 1)
    camera.SetFocalPoint(focal)
    camera.SetPosition([f + t for f, t in zip(focal, towards)])
    camera.SetViewUp(up)
    camera.SetViewAngle(view_angle)
    ren.SetActiveCamera(camera)
    ren.ResetCamera(bounds)
    camera.SetFocalPoint(focal)  # ResetCamera centres on the bounds: keep looking at the focal point
    camera.Zoom(zoom)
    ren.ResetCameraClippingRange(bounds)
    return camera


def save(window, png):
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


def bounds_radius(bounds):
    return 0.5 * sum((bounds[2 * i + 1] - bounds[2 * i]) ** 2 for i in range(3)) ** 0.5


# -- figure 1: alignment ---------------------------------------------------------------------------

def render_alignment(items, resolution, png):
    """items: [(mesh name, vtkPolyData, frames)]."""
    columns = len(items)
    width, height = PANEL_W * columns, PANEL_H + LEGEND_H
    window = new_window(width, height)
    for column, (name, mesh, frames) in enumerate(items):
        ren = panel(window, column, columns, height, "%s.off   %d^3" % (name, resolution))
        bounds = mesh.GetBounds()
        radius = bounds_radius(bounds)
        ren.AddActor(mesh_actor(mesh, opacity=0.35))
        centre, axes = frames["symmetry"]
        pca_centre, pca_axes = frames["pca"]
        for i in range(3):
            ren.AddActor(arrow_actor(centre, axes[i], 0.75 * radius, AXIS_RGB[i], 1.0))
            ren.AddActor(arrow_actor(pca_centre, pca_axes[i], 0.6 * radius, PCA_RGB[i], 0.55))
        ren.AddActor(ball_actor(centre, 0.025 * radius, (0.15, 0.15, 0.15)))
        ren.AddActor(ball_actor(pca_centre, 0.018 * radius, (0.6, 0.6, 0.6)))
        # Frame the mesh and the arrows' tips.
        tips = [c + 0.75 * radius * a for ax in axes for c, a in zip(centre, ax)]
        xs = [bounds[0], bounds[1]] + tips[0::3]
        ys = [bounds[2], bounds[3]] + tips[1::3]
        zs = [bounds[4], bounds[5]] + tips[2::3]
        box = (min(xs), max(xs), min(ys), max(ys), min(zs), max(zs))
        view = VIEWS.get(name, rf.DEFAULT_VIEW)
        focal = [(box[2 * i] + box[2 * i + 1]) / 2. for i in range(3)]
        place_camera(ren, focal, view["towards"], view["up"], box, zoom=1.25)

    legend = vtk.vtkRenderer()
    legend.SetBackground(1, 1, 1)
    legend.SetViewport(0, 0, 1, LEGEND_H / height)
    x = 12
    legend.AddActor2D(rf.text("symmetry frame (centre of symmetry):", 14, x, LEGEND_H - 26))
    legend.AddActor2D(rf.text("PCA frame (centre of mass):", 14, x, 8))
    for i in range(3):
        x0 = 290 + 120 * i
        legend.AddActor2D(rf.rectangle(AXIS_RGB[i], x0, LEGEND_H - 22, 34, 8))
        legend.AddActor2D(rf.text("axis %d" % (i + 1), 14, x0 + 40, LEGEND_H - 26))
        legend.AddActor2D(rf.rectangle(PCA_RGB[i], x0, 13, 34, 4))
        legend.AddActor2D(rf.text("axis %d" % (i + 1), 14, x0 + 40, 8))
    window.AddRenderer(legend)
    save(window, png)


# -- figure 2: viewpoints --------------------------------------------------------------------------

def read_sphere(path):
    reader = vtk.vtkPLYReader()
    reader.SetFileName(path)
    reader.Update()
    sphere = reader.GetOutput()
    colours = sphere.GetPointData().GetArray("RGB") or sphere.GetPointData().GetArray("RGBA")
    if colours is None:
        sys.exit(path + ": no vertex colours (not a score sphere of best_viewpoint)")
    m = None
    for comment in rf.ply_comments(path):
        m = re.search(r"radius " + NUMBER + r" centred at " + NUMBER + " " + NUMBER + " " + NUMBER, comment) or m
    if not m:
        sys.exit(path + ": no centre and radius in the header (not a score sphere of best_viewpoint)")
    return sphere, colours.GetName(), tuple(float(m.group(i)) for i in (2, 3, 4)), float(m.group(1))


def sphere_actor(sphere, colour_array):
    normals = vtk.vtkPolyDataNormals()
    normals.SetInputData(sphere)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray(colour_array)
    mapper.SetColorModeToDirectScalars()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetAmbient(0.45)
    actor.GetProperty().SetDiffuse(0.6)
    return actor


def render_viewpoints(name, mesh, sphere_ply, views, resolution, png, up=None):
    """up: the up direction of the views (default: the mesh's entry in VIEWS, else y)."""
    best, best_score, worst, worst_score = views
    sphere, colour_array, centre, radius = read_sphere(sphere_ply)
    bounds = mesh.GetBounds()
    view = dict(VIEWS.get(name, rf.DEFAULT_VIEW))
    if up:
        view["up"] = up
    columns = 3
    width, height = PANEL_W * columns, PANEL_H + LEGEND_H
    window = new_window(width, height)

    # Left: the sphere, seen from between the best and the worst direction (v and -v are the
    # same view: the worst is taken on the best's side), both marked.
    if dot(best, worst) < 0:
        worst = tuple(-c for c in worst)
    ren = panel(window, 0, columns, height, "score sphere S(v)")
    ren.AddActor(sphere_actor(sphere, colour_array))
    for direction, rgb in ((best, BEST_RGB), (worst, WORST_RGB)):
        ren.AddActor(arrow_actor(centre, direction, 1.4 * radius, rgb, 0.6))
        ren.AddActor(ball_actor([c + radius * d for c, d in zip(centre, direction)], 0.06 * radius, rgb))
    towards = normalised([b + w for b, w in zip(best, worst)])
    sphere_bounds = [centre[i // 2] + (1.4 if i % 2 else -1.4) * radius for i in range(6)]
    place_camera(ren, centre, towards, view["up"], sphere_bounds, zoom=1.65)

    # Middle and right: the mesh seen from the best and from the worst direction.
    for column, (direction, score, label) in enumerate(((best, best_score, "best"), (worst, worst_score, "worst")), 1):
        caption = "%s view  v = (%.2f %.2f %.2f)  S = %.2f" % ((label,) + tuple(direction) + (score,))
        ren = panel(window, column, columns, height, caption)
        ren.AddActor(mesh_actor(mesh))
        place_camera(ren, centre, direction, view["up"], bounds, zoom=1.15)

    legend = vtk.vtkRenderer()
    legend.SetBackground(1, 1, 1)
    legend.SetViewport(0, 0, 1, LEGEND_H / height)
    ramp = vtk.vtkColorTransferFunction()
    for i, c in enumerate(rf.RAMP):
        ramp.AddRGBPoint(worst_score + (best_score - worst_score) * i / (len(rf.RAMP) - 1.), *[v / 255. for v in c])
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(ramp)
    bar.SetOrientationToHorizontal()
    bar.SetNumberOfLabels(3)
    bar.SetLabelFormat("%.2f")
    bar.SetUnconstrainedFontSize(True)
    label = bar.GetLabelTextProperty()
    label.SetFontSize(14)
    label.SetColor(0.1, 0.1, 0.1)
    label.ShadowOff()
    label.ItalicOff()
    label.BoldOff()
    bar.SetBarRatio(0.45)
    bar.DrawFrameOff()
    bar_x = 460
    bar.GetPositionCoordinate().SetCoordinateSystemToViewport()
    bar.GetPositionCoordinate().SetValue(bar_x, 2)
    bar.GetPosition2Coordinate().SetCoordinateSystemToViewport()
    bar.GetPosition2Coordinate().SetValue(260, LEGEND_H - 8)
    legend.AddActor2D(bar)
    legend.AddActor2D(rf.text("%s.off   %d^3" % (name, resolution), 18, 12, LEGEND_H / 2 - 8))
    legend.AddActor2D(rf.text("score S(v), worst to best", 15, bar_x - 30, LEGEND_H / 2 - 6, justify_right=True))
    x = bar_x + 290
    for rgb, text in ((BEST_RGB, "best direction"), (WORST_RGB, "worst direction")):
        legend.AddActor2D(rf.rectangle(rgb, x, LEGEND_H / 2 - 4, 34, 8))
        legend.AddActor2D(rf.rectangle((0.4, 0.4, 0.4), x, LEGEND_H / 2 - 4, 34, 8, filled=False))
        legend.AddActor2D(rf.text(text, 15, x + 42, LEGEND_H / 2 - 8))
        x += 190
    window.AddRenderer(legend)
    save(window, png)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build-dir", default=os.path.join(ROOT, "build"))
    parser.add_argument("--resolution", type=int, default=64)
    parser.add_argument("--alignment", nargs="*", default=["bull", "cow"])
    parser.add_argument("--viewpoints", nargs="*", default=["bull", "cow"])
    parser.add_argument("--mesh-dir", help="read MESH.off from this folder instead of the sample data "
                        "(e.g. the man-made objects that viewpoint_experiment --set man-made --export DIR writes)")
    parser.add_argument("--z-up", action="store_true", help="z is up in the views (the man-made objects stand on z)")
    args = parser.parse_args()

    build_dir = os.path.abspath(args.build_dir)
    examples, data_dir = build_examples(build_dir)
    work = os.path.join(build_dir, "doc_figures")
    os.makedirs(work, exist_ok=True)
    os.makedirs(FIG_DIR, exist_ok=True)

    def off(name):
        return os.path.join(args.mesh_dir or os.path.join(data_dir, "meshes"), name + ".off")

    items = []
    for name in args.alignment:
        out = output_of([os.path.join(examples, "align_to_symmetry_frame"), off(name), "--resolution",
                         str(args.resolution), "--output", os.path.join(work, name + "_aligned.ply")])
        items.append((name, read_off(off(name)), parse_frames(out)))
    if items:
        render_alignment(items, args.resolution, os.path.join(FIG_DIR, "alignment_frames.png"))

    for name in args.viewpoints:
        sphere = os.path.join(work, name + "_score_sphere.ply")
        out = output_of([os.path.join(examples, "best_viewpoint"), off(name), "--resolution", str(args.resolution),
                         "--output", sphere])
        render_viewpoints(name, read_off(off(name)), sphere, parse_views(out), args.resolution,
                          os.path.join(FIG_DIR, "viewpoint_%s.png" % name), up=(0, 0, 1) if args.z_up else None)


if __name__ == "__main__":
    vtk = rf.vtk_with_display(__file__)
    main()
