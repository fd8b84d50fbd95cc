"""Labelling a collection on a Dask LocalCluster: the throughput of 2 workers of one thread against
1 such worker, and the records against those of the C++ batch command on the same files (equal but
for their times). Each run starts with an empty output and includes the cluster's start.

    build/python-venv/bin/python benchmark/Symmetry_transform/python_label_throughput.py \
        --batch build/demo/Symmetry_transform/principal_symmetries_batch \
        --output /tmp/label build/data/meshes build/data/points_3
"""

import argparse
import json
import os
import subprocess
import time

from symmetry_transform import label


def records(path: str) -> dict:
    result = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            record = json.loads(line)
            for timing in ("seconds", "cpu_seconds"):
                record.pop(timing, None)
            result[record["file"]] = record
    return result


def timed(function) -> float:
    start = time.perf_counter()
    function()
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("inputs", nargs="+", metavar="FILE|FOLDER")
    parser.add_argument("--batch", required=True, help="the C++ program principal_symmetries_batch")
    parser.add_argument("--output", required=True, help="a folder for the records")
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)
    outputs = {name: os.path.join(args.output, name + ".jsonl") for name in ("cpp", "dask1", "dask2")}
    for path in outputs.values():
        if os.path.exists(path):
            os.remove(path)
    seconds = {
        "cpp": timed(lambda: subprocess.run([args.batch, *args.inputs, "--output", outputs["cpp"], "--jobs", "2"],
                                            check=True, capture_output=True)),
        "dask1": timed(lambda: label.label(args.inputs, outputs["dask1"], workers=1, quiet=True)),
        "dask2": timed(lambda: label.label(args.inputs, outputs["dask2"], workers=2, quiet=True)),
    }
    expected = records(outputs["cpp"])
    for name in ("dask1", "dask2"):
        found = records(outputs[name])
        differing = [f for f in expected if found.get(f) != expected[f]]
        print(f"{name}: {len(found)} records for {len(expected)} files, {len(differing)} differ from the C++ batch's"
              + (f" (first: {differing[0]})" if differing else ""))
    files = len(expected)
    errors = sum(r["status"] == "error" for r in expected.values())
    print(f"{files} files ({errors} error records); wall time: C++ batch (2 jobs) {seconds['cpp']:.1f} s, "
          f"Dask 1 worker {seconds['dask1']:.1f} s, 2 workers {seconds['dask2']:.1f} s; "
          f"throughput 2 workers / 1 worker {seconds['dask1'] / seconds['dask2']:.2f}")


if __name__ == "__main__":
    main()
