"""Labelling a collection on a Dask LocalCluster of 2 workers gives the records of the C++ batch
command, and a run started again does only the files not yet recorded."""

import json
import subprocess

import pytest

from conftest import BUILD, DATA, required
from symmetry_transform import label

# Small meshes and point sets of CGAL's sample data, degenerate ones among them (a single
# triangle, a flat quad), and one file that cannot be read.
MESHES = ["triangle.off", "quad.off", "tetrahedron.off", "pyramid.off", "cube_quad.off", "cube-ouvert.off", "bull.off",
          "pinion.off"]
POINTS = ["cube.xyz", "oneH.xyz", "oni.pwn"]


def records(path):
    """The records of a JSON Lines file by file, without their times."""
    result = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            record = json.loads(line)
            record.pop("seconds", None)
            record.pop("cpu_seconds", None)
            result[record["file"]] = record
    return result


@pytest.fixture
def collection(tmp_path):
    folder = tmp_path / "shapes"
    (folder / "points").mkdir(parents=True)
    for name in MESHES:
        (folder / name).symlink_to(required(DATA / "meshes" / name))
    for name in POINTS:
        (folder / "points" / name).symlink_to(required(DATA / "points_3" / name))
    (folder / "broken.off").write_text("OFF\n3 1 0\n0 0 0\n")
    return folder


def cpp_records(folder, output):
    batch = required(BUILD / "demo" / "Symmetry_transform" / "principal_symmetries_batch")
    subprocess.run([str(batch), str(folder), "--output", str(output), "--jobs", "2", "--resolution", "32"],
                   check=True, capture_output=True)
    return records(output)


def test_dask_records_equal_the_cpp_batch_and_a_restart_does_the_rest(collection, tmp_path):
    expected = cpp_records(collection, tmp_path / "cpp.jsonl")
    assert len(expected) == len(MESHES) + len(POINTS) + 1
    assert expected[str(collection / "broken.off")]["status"] == "error"

    output = tmp_path / "dask.jsonl"
    summary = label.label([str(collection)], str(output), workers=2, quiet=True, grid_resolution=32)
    assert summary == {"files": len(expected), "done_before": 0, "errors": 1}
    assert records(output) == expected

    # A run killed half-way: half the records, then a line cut short.
    lines = output.read_text(encoding="utf-8").splitlines(keepends=True)
    half = len(lines) // 2
    output.write_text("".join(lines[:half]) + lines[half][: len(lines[half]) // 2], encoding="utf-8")
    summary = label.label([str(collection)], str(output), workers=2, quiet=True, grid_resolution=32)
    assert summary["done_before"] == half and summary["files"] == len(expected)
    assert records(output) == expected
    assert len(output.read_text(encoding="utf-8").splitlines()) == len(expected)


def test_time_limit_gives_an_error_record_after_the_retries(collection, tmp_path):
    output = tmp_path / "slow.jsonl"
    bull = str(collection / "bull.off")
    summary = label.label([bull], str(output), workers=1, quiet=True, timeout=0.01, retries=1)
    assert summary["errors"] == 1
    record = records(output)[bull]
    assert record["status"] == "error" and "time limit of 0.01 s" in record["reason"]
