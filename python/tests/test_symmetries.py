"""Known answers from shapes symmetric by construction, moved far away and rotated; agreement with
the C++ demo on bull.off; every function on a real mesh."""

import re
import subprocess
import warnings

import numpy as np
import pytest

import symmetry_transform as st
from conftest import BUILD, DATA, angle_degrees, box, propeller, random_rotation, required, tapered_house


def test_box_planes_are_its_three_mirrors():
    V, F = box()
    planes = st.principal_symmetries(V, F, grid_resolution=32, max_number_of_planes=3)
    assert len(planes) == 3
    for axis in np.eye(3):
        best = min(planes, key=lambda p: angle_degrees(p.normal, axis))
        assert angle_degrees(best.normal, axis) < 0.01
        assert abs(best.offset) < 1e-4
        assert best.support > 0.99 and best.sde < 1e-4


def test_mirror_of_a_shape_moved_a_million_radii_away_moves_with_it():
    V, F = tapered_house()
    rng = np.random.default_rng(7)
    R, t = random_rotation(rng), np.array([3.0e6, -1.0e6, 2.0e6])
    moved = V @ R.T + t
    strongest = st.principal_symmetries(moved, F, grid_resolution=32)[0]
    normal = R @ [1.0, 0.0, 0.0]
    assert angle_degrees(strongest.normal, normal) < 0.01
    # The mirror x = 0 moved: n.(x - t) = 0, so its offset is -n.t.
    assert abs(abs(strongest.offset) - abs(np.dot(normal, t))) < 1e-4 * np.linalg.norm(V, axis=1).max()
    assert np.sign(strongest.offset) == -np.sign(np.dot(strongest.normal, t))


def test_float32_int32_and_lists_give_the_float64_answer():
    V, F = tapered_house()
    wide = st.principal_symmetries(V, F, grid_resolution=32)[0]
    narrow = st.principal_symmetries(V.astype(np.float32), F.astype(np.int32), grid_resolution=32)[0]
    assert angle_degrees(wide.normal, narrow.normal) < 1e-3
    listed = st.principal_symmetries(V.tolist(), F.tolist(), grid_resolution=32)[0]
    assert np.array_equal(listed.normal, wide.normal) and listed.offset == wide.offset


@pytest.mark.parametrize("blades", [3, 5])
def test_propeller_has_a_rotation_of_its_order_and_no_mirror(blades):
    V, F = propeller(blades)
    rotations = st.rotational_symmetries(V, F, grid_resolution=48)
    assert rotations[0].order == blades
    assert angle_degrees(rotations[0].axis, [0, 0, 1]) < 0.1
    assert np.linalg.norm(rotations[0].point[:2]) < 1e-3
    # BOP's fields: the rotations of each axis, flattened 4 x 4 matrices, the k-fold's first; the
    # nearly exact half-turns of the thin blades follow them, but the group has only the exact ones.
    bop = st.bop_symmetries(V, F, grid_resolution=48)
    first = np.array(bop["symmetries_discrete"][0]).reshape(4, 4)[:3, :3]
    assert first[2, 2] == pytest.approx(1.0, abs=1e-6)
    assert np.trace(first) == pytest.approx(1 + 2 * np.cos(2 * np.pi / blades), abs=1e-6)
    assert bop["point_group"] == f"C{blades}" and bop["symmetries_continuous"] == []


def test_points_with_normals_give_the_mirrors_of_their_box():
    V, F = box(1.0, 0.7, 0.4)
    rng = np.random.default_rng(3)
    corners = V[F]
    weights = rng.dirichlet([1, 1, 1], size=(len(F), 200))
    points = np.einsum("fsk,fkd->fsd", weights, corners).reshape(-1, 3)
    normals = np.repeat(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), 200, axis=0)
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    planes = st.principal_symmetries(points, normals=normals, grid_resolution=32, max_number_of_planes=3)
    for axis in np.eye(3):
        assert min(angle_degrees(p.normal, axis) for p in planes) < 0.5


def demo_planes(mesh):
    """The planes the C++ demo prints: normal, d, symmetry and SDE, to their printed digits."""
    demo = required(BUILD / "demo" / "Symmetry_transform" / "principal_symmetries")
    out = subprocess.run([str(demo), str(mesh), "--planes", "10", "--output", "/dev/null"], capture_output=True,
                         text=True, check=True).stdout
    row = re.compile(r"^\s+\d+\s+\(\s*(\S+)\s+(\S+)\s+(\S+)\)\s+(\S+)\s+\S+\s+(\S+)\s+\S+\s+(\S+)$", re.M)
    return [tuple(float(x) for x in m.groups()) for m in row.finditer(out)]


def test_bull_planes_agree_with_the_cpp_demo_to_its_digits(bull):
    V, F = bull
    expected = demo_planes(DATA / "meshes" / "bull.off")
    found = st.principal_symmetries(V, F, max_number_of_planes=10)
    assert len(found) == len(expected) > 0
    for p, (nx, ny, nz, d, symmetry, sde) in zip(found, expected):
        assert np.allclose(p.normal, [nx, ny, nz], atol=0.0005 + 1e-12)
        assert p.offset == pytest.approx(d, abs=0.0005 + 1e-12)
        assert p.symmetry == pytest.approx(symmetry, abs=0.0005 + 1e-12)
        assert p.sde == pytest.approx(sde, rel=5e-4)


def test_every_function_on_a_real_mesh(bull):
    V, F = bull
    strongest = st.principal_symmetries(V, F, max_number_of_planes=1)[0]
    frame = st.symmetry_frame(V, F)
    assert np.allclose(frame.axes @ frame.axes.T, np.eye(3), atol=1e-9)
    # The first axis of the frame is the normal of the strongest plane, through the centre.
    assert angle_degrees(frame.axes[0], strongest.normal) < 0.01
    assert abs(np.dot(strongest.normal, frame.center) + strongest.offset) < 1e-6
    assert np.allclose(frame.to_canonical(frame.center[None]), 0.0)
    # Descriptors are compared in the shapes' frames: a moved bull is nearer to the bull than a cow.
    rng = np.random.default_rng(11)
    a = st.descriptor(V, F)
    moved = st.descriptor(V @ random_rotation(rng).T + [5.0, -2.0, 1.0], F)
    cow = st.descriptor(*st.read_mesh(str(required(DATA / "meshes" / "cow.off"))))
    assert st.descriptor_distance(a, a) == 0.0
    assert st.descriptor_distance(a, moved) < 0.2 * st.descriptor_distance(a, cow)
    views = st.best_viewpoints(V, F, grid_resolution=32)
    assert views and all(np.isclose(np.linalg.norm(v.direction), 1.0) for v in views)
    assert all(views[i].score >= views[i + 1].score for i in range(len(views) - 1))
    labels = st.segment(V, F, max_segmentation_depth=1)
    assert labels.shape == (len(F),) and labels.min() == 0 and len(np.unique(labels)) >= 2
    with warnings.catch_warnings():  # a soup rather than a mesh is a warning, not a failure
        warnings.simplefilter("ignore", RuntimeWarning)
        anchors, triangles = st.symmetric_remesh(V, F, max_number_of_proxies=50)
    assert anchors.shape[1] == 3 and triangles.max() < len(anchors) and len(triangles) > 50
    assert st.symmetry_distance_error(V, F, strongest) == pytest.approx(strongest.sde, rel=1e-12)
    assert "PrincipalSymmetry(normal=(" in repr(strongest)

