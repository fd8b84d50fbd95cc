"""Shapes built with NumPy, symmetric by construction, and where the C++ build and CGAL's sample
data are: SYMMETRY_TRANSFORM_BUILD_DIR (default build/ of the checkout) holds the C++ programs
whose output the tests compare with, SYMMETRY_TRANSFORM_DATA_DIR (default its data/) the meshes."""

import os
from pathlib import Path

import numpy as np
import pytest

REPOSITORY = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get("SYMMETRY_TRANSFORM_BUILD_DIR", REPOSITORY / "build"))
DATA = Path(os.environ.get("SYMMETRY_TRANSFORM_DATA_DIR", BUILD / "data"))


def required(path: Path) -> Path:
    if not path.exists():
        pytest.fail(f"{path} is missing: run bash scripts/test.sh, which builds the C++ programs and unpacks "
                    "CGAL's sample data, or set SYMMETRY_TRANSFORM_BUILD_DIR / SYMMETRY_TRANSFORM_DATA_DIR")
    return path


@pytest.fixture
def bull():
    import symmetry_transform as st
    return st.read_mesh(str(required(DATA / "meshes" / "bull.off")))


def box(a=1.0, b=0.7, c=0.4):
    """A box centred on the origin, its faces outward: mirrors x = 0, y = 0, z = 0."""
    V = np.array([[x, y, z] for x in (-a, a) for y in (-b, b) for z in (-c, c)], dtype=float)
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    F = np.array([t for q in quads for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))], dtype=np.int64)
    return V, F


def tapered_house():
    """A house-shaped prism that narrows upward along z: its only mirror is x = 0."""
    section = np.array([[-1, 0], [1, 0], [1, 1], [0, 1.8], [-1, 1]], dtype=float)
    bottom = np.c_[section, np.zeros(5)]
    top = np.c_[0.5 * section + [0, 0.2], np.full(5, 2.0)]
    V = np.vstack([bottom, top])
    F = [(0, 2, 1), (0, 3, 2), (0, 4, 3), (5, 6, 7), (5, 7, 8), (5, 8, 9)]
    for i in range(5):
        j = (i + 1) % 5
        F += [(i, j, 5 + j), (i, 5 + j, 5 + i)]
    return V, np.array(F, dtype=np.int64)


def propeller(blades=5):
    """A chiral propeller: `blades` tilted boxes about the z axis, rotations by 2 pi / blades only
    (each blade lies above its radial axis, so that no half-turn about that axis maps it onto itself)."""
    V0, F0 = box(1.0, 0.15, 0.04)
    V0 = V0 + [1.1, 0, 0.12]
    tilt = np.radians(30)
    about_x = np.array([[1, 0, 0], [0, np.cos(tilt), -np.sin(tilt)], [0, np.sin(tilt), np.cos(tilt)]])
    V0 = V0 @ about_x.T
    vertices, faces = [], []
    for k in range(blades):
        angle = 2 * np.pi * k / blades
        about_z = np.array([[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0], [0, 0, 1]])
        faces.append(F0 + len(V0) * k)
        vertices.append(V0 @ about_z.T)
    return np.vstack(vertices), np.vstack(faces)


def random_rotation(rng):
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    q = q @ np.diag(np.sign(np.diag(r)))
    return q if np.linalg.det(q) > 0 else -q


def angle_degrees(u, v):
    """The angle of two lines (unoriented directions)."""
    c = abs(np.dot(u, v)) / (np.linalg.norm(u) * np.linalg.norm(v))
    return np.degrees(np.arccos(min(1.0, c)))
