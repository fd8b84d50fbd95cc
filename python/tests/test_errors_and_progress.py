"""Bad arrays and options raise ValueError or TypeError with the library's message; progress is
reported, a callback cancels, Ctrl-C interrupts."""

import os
import signal
import threading

import numpy as np
import pytest

import symmetry_transform as st
from conftest import box


@pytest.mark.parametrize("vertices, faces, message", [
    (np.zeros((4, 2)), None, r"vertices must be an array of shape \(n, 3\), not \(4, 2\)"),
    (np.zeros(12), None, r"vertices must be an array of shape \(n, 3\), not \(12,\)"),
    (np.zeros((4, 3), dtype=np.int64), None, "vertices must hold floats"),
    (np.array([[0, 0, 0], [1, 0, 0], [np.nan, 1, 0]]), np.array([[0, 1, 2]]), "vertices row 2 is not finite"),
    (box()[0], box()[1].astype(float), "faces must hold integers"),
    (box()[0], np.array([[0, 1, 8]]), r"faces row 0 has the vertex index 8, out of \[0, 8\)"),
    (box()[0], np.array([[0, 1, -1]]), "faces row 0 has the vertex index -1"),
    (box()[0], np.zeros((0, 3), dtype=np.int64), "faces is empty"),
])
def test_bad_arrays_raise_value_error(vertices, faces, message):
    with pytest.raises(ValueError, match=message):
        st.principal_symmetries(vertices, faces)


def test_bad_options():
    V, F = box()
    with pytest.raises(TypeError, match="unexpected keyword argument.*grid_size"):
        st.principal_symmetries(V, F, grid_size=32)
    with pytest.raises(ValueError, match="grid_resolution"):
        st.principal_symmetries(V, F, grid_resolution=4)
    with pytest.raises(ValueError, match="random_seed must be an integer"):
        st.principal_symmetries(V, F, random_seed=1.5)
    with pytest.raises(ValueError, match="gaussian_width must be a number"):
        st.principal_symmetries(V, F, gaussian_width="wide")
    with pytest.raises(ValueError, match="number_of_threads must not be negative"):
        st.principal_symmetries(V, F, number_of_threads=-1)
    # NumPy's integers and floats are numbers too.
    numpy_options = st.principal_symmetries(V, F, grid_resolution=np.int64(32), gaussian_width=np.float32(1.5))
    assert np.allclose(numpy_options[0].normal, st.principal_symmetries(V, F, grid_resolution=32)[0].normal)
    with pytest.raises(ValueError, match="normals has 3 rows for 8 points"):
        st.principal_symmetries(V, normals=np.ones((3, 3)))


def test_faces_are_repaired_into_a_surface_or_refused():
    V, F = box()
    flipped = np.vstack([F[:-1], F[-1:, ::-1]])  # one face of inconsistent orientation
    assert st.segment(V, flipped, max_segmentation_depth=1).shape == (len(F),)
    with pytest.raises(ValueError, match="the faces do not form a surface"):
        st.segment(V, np.vstack([F, [[0, 0, 1]]]))  # a face through one vertex twice


def test_progress_rises_to_one_and_a_false_answer_cancels():
    V, F = box()
    seen = []
    st.principal_symmetries(V, F, grid_resolution=32, callback=lambda p: seen.append(p))
    assert seen[0] == 0.0 and seen[-1] == 1.0 and seen == sorted(seen)
    with pytest.raises(st.Cancelled):
        st.principal_symmetries(V, F, grid_resolution=32, callback=lambda p: p < 0.2)


def test_callback_error_propagates():
    V, F = box()

    def failing(progress):
        raise ZeroDivisionError("from the callback")
    with pytest.raises(ZeroDivisionError, match="from the callback"):
        st.rotational_symmetries(V, F, grid_resolution=32, callback=failing)


def test_ctrl_c_interrupts_a_long_call(bull):
    V, F = bull
    timer = threading.Timer(0.2, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        st.principal_symmetries(V, F, grid_resolution=64, number_of_samples=4000000)
    timer.join()


def test_calls_release_the_gil(bull):
    V, F = bull
    results = []
    threads = [threading.Thread(target=lambda: results.append(st.principal_symmetries(V, F, grid_resolution=32,
                                                                                      number_of_threads=1)))
               for _ in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert len(results) == 2 and [p.normal.tolist() for p in results[0]] == [p.normal.tolist() for p in results[1]]
