"""Symmetry transforms of 3D shapes, from NumPy arrays (CGAL Symmetry_transform).

A shape is given as ``vertices`` (an n x 3 array of float32 or float64) and ``faces`` (an m x 3
array of int32 or int64 vertex indices), or as points with ``faces=None`` and, optionally,
``normals`` (n x 3). ``read_mesh()`` and ``read_points()`` read files as the package's demo
programs do, with the same soup repair.

The options are the named parameters of the C++ functions, as keyword arguments of the same
names (``grid_resolution=32``, ``random_seed=1``, ...), with the same defaults; an option a
function does not take raises ``TypeError``, a bad value ``ValueError``. Long calls release the
GIL, call ``callback(progress)`` with the progress in [0, 1] (returning ``False`` cancels them:
``Cancelled`` is raised) and stop on Ctrl-C (``KeyboardInterrupt``).

    import symmetry_transform as st
    V, F = st.read_mesh("bull.off")
    for plane in st.principal_symmetries(V, F, grid_resolution=32):
        print(plane)
"""

from __future__ import annotations

import json
import warnings
from dataclasses import dataclass
from typing import Callable, Iterable, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._core import Cancelled, Descriptor

__all__ = [
    "Cancelled", "Descriptor", "PrincipalSymmetry", "RotationalSymmetry", "SymmetryFrame", "Viewpoint",
    "read_mesh", "read_points", "principal_symmetries", "rotational_symmetries", "symmetry_frame",
    "symmetry_distance_error", "descriptor", "descriptor_distance", "best_viewpoints", "segment",
    "symmetric_remesh", "bop_symmetries",
]

Progress = Optional[Callable[[float], Optional[bool]]]
Plane = Union["PrincipalSymmetry", Tuple[Sequence[float], float]]

# The keyword options of each function: the named parameters its C++ function reads.
_DETECTION = ("grid_resolution", "gaussian_width", "number_of_samples", "number_of_refinement_samples",
              "number_of_iterations", "max_number_of_planes", "symmetry_threshold", "laplacian_threshold",
              "random_seed", "number_of_threads")
_OPTIONS = {
    "principal_symmetries": _DETECTION + ("sde_samples",),
    "symmetry_distance_error": ("sde_samples", "random_seed", "number_of_threads"),
    "rotational_symmetries": _DETECTION + ("max_order",),
    "bop_symmetries": _DETECTION + ("max_order",),
    "symmetry_frame": _DETECTION,
    "best_viewpoints": _DETECTION,
    "descriptor": _DETECTION,
    "segment": ("max_segmentation_depth", "max_number_of_segments", "random_seed", "number_of_threads"),
    "symmetric_remesh": _DETECTION + ("max_number_of_proxies",),
}


def _options(function: str, options: dict) -> dict:
    unknown = sorted(set(options) - set(_OPTIONS[function]))
    if unknown:
        raise TypeError(f"{function}() got unexpected keyword argument(s) {', '.join(unknown)}; "
                        f"it takes {', '.join(_OPTIONS[function])}")
    return options


def _arrays(*arrays):
    """NumPy arrays of what the caller gave (lists too), None kept: the extension checks them."""
    return tuple(None if a is None else np.asarray(a) for a in arrays)


def _vector(values) -> str:
    return "(" + ", ".join(f"{v:.6g}" for v in values) + ")"


@dataclass(frozen=True, eq=False)  # NumPy fields: no element-wise ==
class PrincipalSymmetry:
    """A plane of (partial) mirror symmetry: the points x with ``normal @ x + offset == 0``.

    ``symmetry`` is its symmetry measure (1 for a perfect mirror), ``support`` the fraction of the
    surface it maps onto the surface, ``sde`` its symmetry distance error (the mean distance of
    the mirrored surface to the surface, over the length of the bounding box diagonal).
    """
    normal: np.ndarray
    offset: float
    symmetry: float
    support: float
    sde: float

    def __repr__(self) -> str:
        return (f"PrincipalSymmetry(normal={_vector(self.normal)}, offset={self.offset:.6g}, "
                f"symmetry={self.symmetry:.4f}, support={self.support:.4f}, sde={self.sde:.3g})")


@dataclass(frozen=True, eq=False)  # NumPy fields: no element-wise ==
class RotationalSymmetry:
    """An axis of rotational symmetry through ``point`` along the unit vector ``axis``, of order
    ``order`` (rotations by multiples of 2 pi / order map the shape onto itself; 0: continuous,
    a surface of revolution)."""
    axis: np.ndarray
    point: np.ndarray
    order: int
    symmetry: float
    support: float

    def __repr__(self) -> str:
        order = "continuous" if self.order == 0 else f"{self.order}-fold"
        return (f"RotationalSymmetry({order}, axis={_vector(self.axis)}, point={_vector(self.point)}, "
                f"symmetry={self.symmetry:.4f}, support={self.support:.4f})")


@dataclass(frozen=True, eq=False)  # NumPy fields: no element-wise ==
class SymmetryFrame:
    """A shape's centre of symmetry and its principal symmetry axes (the rows of ``axes``)."""
    center: np.ndarray
    axes: np.ndarray

    def to_canonical(self, points: np.ndarray) -> np.ndarray:
        """The points in the frame: their coordinates along the axes, from the centre."""
        return (np.asarray(points, dtype=float) - self.center) @ self.axes.T

    def __repr__(self) -> str:
        return f"SymmetryFrame(center={_vector(self.center)}, axes=[{', '.join(_vector(a) for a in self.axes)}])"


@dataclass(frozen=True, eq=False)  # NumPy fields: no element-wise ==
class Viewpoint:
    """A viewing direction and its viewpoint score (the higher, the better the view)."""
    direction: np.ndarray
    score: float

    def __repr__(self) -> str:
        return f"Viewpoint(direction={_vector(self.direction)}, score={self.score:.4f})"


def read_mesh(path: str) -> Tuple[np.ndarray, np.ndarray]:
    """The vertices (n x 3 float64) and triangles (m x 3 int64) of a mesh file (OFF, PLY, OBJ, STL),
    read as a polygon soup, repaired with CGAL's soup repair and triangulated."""
    return _core.read_mesh(str(path))


def read_points(path: str) -> Tuple[np.ndarray, Optional[np.ndarray]]:
    """The points (n x 3 float64) of a point set file (XYZ, PWN, PLY, OFF, LAS) and their normals,
    or None if it has none."""
    return _core.read_points(str(path))


def principal_symmetries(vertices, faces=None, normals=None, *, callback: Progress = None,
                         **options) -> List[PrincipalSymmetry]:
    """The principal symmetries of a mesh or a point set, strongest first, each with its symmetry
    distance error (``sde_samples`` samples, default 20000)."""
    options = _options("principal_symmetries", options)
    found = _core.principal_symmetries(*_arrays(vertices, faces, normals), options, callback)
    return [PrincipalSymmetry(*plane) for plane in found]


def symmetry_distance_error(vertices, faces, plane: Plane, normals=None, **options) -> float:
    """The symmetry distance error of a plane, given as a PrincipalSymmetry or (normal, offset)."""
    normal, offset = (plane.normal, plane.offset) if isinstance(plane, PrincipalSymmetry) else plane
    return _core.symmetry_distance_error(*_arrays(vertices, faces, normals), np.asarray(normal, dtype=float),
                                         float(offset),
                                         _options("symmetry_distance_error", options))


def rotational_symmetries(vertices, faces=None, normals=None, *, callback: Progress = None,
                          **options) -> List[RotationalSymmetry]:
    """The axes of rotational symmetry of a mesh or a point set, strongest first."""
    options = _options("rotational_symmetries", options)
    found = _core.rotational_symmetries(*_arrays(vertices, faces, normals), options, callback)
    return [RotationalSymmetry(*axis) for axis in found]


def bop_symmetries(vertices, faces, *, callback: Progress = None, **options) -> dict:
    """The symmetry fields of a BOP ``models_info.json`` entry, ready for ``json.dump``:
    ``symmetries_discrete`` (4 x 4 row-major matrices, flattened) and ``symmetries_continuous``
    (axis and offset), with the shape's ``point_group``. The units are those of the vertices."""
    return json.loads(_core.bop_symmetries(*_arrays(vertices, faces), _options("bop_symmetries", options), callback))


def symmetry_frame(vertices, faces=None, normals=None, *, callback: Progress = None, **options) -> SymmetryFrame:
    """The symmetry frame of a mesh or a point set: where principal component analysis fails
    (several equal moments, missing parts), its principal symmetries fix the axes."""
    options = _options("symmetry_frame", options)
    return SymmetryFrame(*_core.symmetry_frame(*_arrays(vertices, faces, normals), options, callback))


def descriptor(vertices, faces, *, callback: Progress = None, **options) -> Descriptor:
    """The symmetry descriptor of a mesh moved into its symmetry frame (``grid_resolution``
    default 32), for ``descriptor_distance()``."""
    return _core.descriptor(*_arrays(vertices, faces), _options("descriptor", options), callback)


def descriptor_distance(a: Descriptor, b: Descriptor) -> float:
    """The distance of two descriptors: 0 for equal ones; the smaller, the more alike the shapes."""
    return _core.descriptor_distance(a, b)


def best_viewpoints(vertices, faces=None, normals=None, *, callback: Progress = None, **options) -> List[Viewpoint]:
    """The best viewing directions of a shape, best first, from its principal symmetries."""
    found = _core.best_viewpoints(*_arrays(vertices, faces, normals), _options("best_viewpoints", options), callback)
    return [Viewpoint(*view) for view in found]


def segment(vertices, faces, *, callback: Progress = None, **options) -> np.ndarray:
    """A segment label (int64) per face, in the order of ``faces``: parts of different symmetries.
    Faces of inconsistent orientation or non-manifold vertices are repaired first, as the demo
    programs do; faces that still form no surface raise ``ValueError``."""
    return _core.segment(*_arrays(vertices, faces), _options("segment", options), callback)


def symmetric_remesh(vertices, faces, planes: Optional[Iterable[Plane]] = None, *, callback: Progress = None,
                     **options) -> Tuple[np.ndarray, np.ndarray]:
    """A coarse remeshing (Variational Shape Approximation) that keeps the given planes of
    symmetry (by default the strongest principal symmetry): its vertices and triangles. Warns
    (RuntimeWarning) if the triangles are no 2-manifold oriented mesh."""
    kept = None
    if planes is not None:
        kept = [(np.asarray(p.normal if isinstance(p, PrincipalSymmetry) else p[0], dtype=float),
                 float(p.offset if isinstance(p, PrincipalSymmetry) else p[1])) for p in planes]
    options = _options("symmetric_remesh", options)
    anchors, triangles, ok = _core.symmetric_remesh(*_arrays(vertices, faces), kept, options, callback)
    if len(triangles) == 0:
        raise ValueError("the remeshing gave no triangle; try more proxies (max_number_of_proxies)")
    if not ok:
        warnings.warn("the remeshed triangles do not form a 2-manifold oriented mesh (a soup); more proxies "
                      "(max_number_of_proxies) usually give one", RuntimeWarning, stacklevel=2)
    return anchors, triangles
