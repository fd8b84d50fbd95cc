#!/usr/bin/env python3
# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Statistics of the records of principal_symmetries_batch (JSON Lines), for RESULTS.md: per-shape
# time (median, 95th percentile, max; wall and processor time), the symmetry distance error of the
# strongest plane, and the errors with their reasons.
#
# usage: batch_statistics.py RECORDS.jsonl [RECORDS.jsonl ...]

import json
import sys


def percentile(values, p):
    """The p-th percentile of sorted values, by linear interpolation."""
    if not values:
        return float("nan")
    k = (len(values) - 1) * p / 100.0
    lo = int(k)
    hi = min(lo + 1, len(values) - 1)
    return values[lo] + (values[hi] - values[lo]) * (k - lo)


def describe(name, values, unit, digits):
    values = sorted(values)
    fmt = "{:." + str(digits) + "f}"
    print(f"| {name} | {len(values)} | " + " | ".join(fmt.format(percentile(values, p)) + unit for p in (50, 95, 100))
          + " | " + fmt.format(values[0]) + unit + " |")


def main(paths):
    records = [json.loads(line) for path in paths for line in open(path) if line.strip()]
    by_file = {r["file"]: r for r in records}  # the last record of a file wins
    records = list(by_file.values())
    ok = [r for r in records if r["status"] == "ok"]
    errors = [r for r in records if r["status"] != "ok"]
    print(f"{len(records)} files: {len(ok)} ok, {len(errors)} errors, "
          f"{sum(1 for r in ok if not r['planes'])} ok without a plane\n")
    print("| | files | median | 95th percentile | max | min |")
    print("|---|---:|---:|---:|---:|---:|")
    for kind in ("mesh", "points"):
        of_kind = [r for r in ok if r["shape"]["kind"] == kind]
        if of_kind:
            describe(f"processor time, {kind}", [r["cpu_seconds"] for r in of_kind], " s", 2)
    describe("processor time, all", [r["cpu_seconds"] for r in ok], " s", 2)
    describe("wall time, all", [r["seconds"] for r in ok], " s", 2)
    strongest = [r["planes"][0]["sde"] for r in ok if r["planes"]]
    describe("SDE of the strongest plane", strongest, "", 4)
    for kind in ("mesh", "points"):
        values = [r["planes"][0]["sde"] for r in ok if r["planes"] and r["shape"]["kind"] == kind]
        if values:
            describe(f"SDE of the strongest plane, {kind}", values, "", 4)
    print(f"\nstrongest plane's SDE below 0.001: {sum(1 for s in strongest if s < 1e-3)}, "
          f"below 0.01: {sum(1 for s in strongest if s < 1e-2)}, of {len(strongest)}")
    repaired = [r for r in ok if r["shape"]["kind"] == "mesh" and any(r["shape"]["repairs"].values())]
    print(f"meshes repaired: {len(repaired)} of {sum(1 for r in ok if r['shape']['kind'] == 'mesh')}")
    with_normals = [r for r in ok if r["shape"]["kind"] == "points" and r["shape"]["normals"]]
    print(f"point sets with normals: {len(with_normals)} of {sum(1 for r in ok if r['shape']['kind'] == 'points')}")
    slowest = sorted(ok, key=lambda r: -r["cpu_seconds"])[:5]
    print("slowest (processor time): " + ", ".join(f"{r['file'].split('/')[-1]} {r['cpu_seconds']:.2f} s" for r in slowest))
    for r in errors:
        print(f"error: {r['file']}: {r['reason']}")


if __name__ == "__main__":
    main(sys.argv[1:])
