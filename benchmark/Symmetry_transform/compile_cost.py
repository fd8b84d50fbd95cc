#!/usr/bin/env python3
# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
"""What a user pays to compile a program of the package.

Compiles the small programs of compile_cost/ (one per public header, the README's program, and a
program calling segmentation and symmetric remeshing) with the Release flags that the CMake target
CGAL::Symmetry_transform gives (NAME_precompiled: with CGAL::Symmetry_transform_precompiled, whose
own source, compiled once per build tree, is precompiled_core), and prints, for each, the user CPU
time and the peak memory of the compiler against those of compile_cost/reader.cpp, which only reads
a Surface_mesh, compiled in the same run: absolute seconds do not carry from one machine to another,
the ratios do.

    python3 benchmark/Symmetry_transform/compile_cost.py [--build DIR] [--cgal-dir DIR]
        [--programs reader,readme,...] [--repeats N] [--jobs J] [--output FILE.md]

Each round compiles the reader first and last, the other programs in between; a program's ratio in
a round is its time over the mean of the reader's two, and the table gives the medians over the
rounds. --jobs 2 compiles two programs at a time (faster, and each a little slower). Python's
standard library only: any python3 runs it.
"""

import argparse
import json
import os
import pathlib
import platform
import re
import shlex
import statistics
import subprocess
import sys
import time

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
BASELINE = "reader"
SOURCES = sorted(p.stem for p in (HERE / "compile_cost").glob("*.cpp"))
PROGRAMS = SOURCES + [s + "_precompiled" for s in SOURCES if s != BASELINE] + ["precompiled_core"]


def configure(build, cgal_dir):
    """Configures BUILD (compile_cost/CMakeLists.txt) and returns its compile commands by program."""
    command = ["cmake", "-S", str(HERE / "compile_cost"), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
               "-DCMAKE_EXPORT_COMPILE_COMMANDS=ON"]
    if cgal_dir:
        command.append("-DCGAL_DIR=" + str(cgal_dir))
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    commands = {}
    for entry in json.loads((build / "compile_commands.json").read_text()):
        arguments = entry["arguments"] if "arguments" in entry else shlex.split(entry["command"])
        # The object library compile_cost_NAME writes CMakeFiles/compile_cost_NAME.dir/...
        target = re.search(r"CMakeFiles/compile_cost_(\w+)\.dir/", " ".join(arguments))
        if target:
            commands[target.group(1)] = (arguments, entry["directory"])
    return commands


def compile_all(tasks, commands, jobs):
    """Compiles the programs of `tasks` (a list), `jobs` at a time; returns (user s, peak MB) each."""
    results = [None] * len(tasks)
    running = {}
    pending = list(enumerate(tasks))
    while pending or running:
        while pending and len(running) < jobs:
            index, name = pending.pop(0)
            arguments, directory = commands[name]
            process = subprocess.Popen(arguments, cwd=directory, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
            running[process.pid] = (index, name, process)
        pid, status, usage = os.wait4(-1, 0)
        index, name, process = running.pop(pid)
        if status != 0:
            sys.exit(f"compile_cost: {name} does not compile:\n{process.stderr.read().decode()}")
        # wait4 counts the compiler proper (cc1plus), a child of the driver.
        results[index] = (usage.ru_utime, usage.ru_maxrss / 1024.)
    return results


def measure(commands, programs, repeats, jobs):
    """Per program, the lists over the rounds of (user s, peak MB, time ratio, memory ratio)."""
    others = [p for p in programs if p != BASELINE]
    rows = {p: [] for p in programs}
    for round_index in range(repeats):
        tasks = [BASELINE] + others + [BASELINE]
        results = compile_all(tasks, commands, jobs)
        base_seconds = statistics.mean([results[0][0], results[-1][0]])
        base_memory = statistics.mean([results[0][1], results[-1][1]])
        for name, (seconds, memory) in zip(tasks[1:-1], results[1:-1]):
            rows[name].append((seconds, memory, seconds / base_seconds, memory / base_memory))
        rows[BASELINE].append((base_seconds, base_memory, 1., 1.))
        print(f"round {round_index + 1}/{repeats}: reader {base_seconds:.1f} s", file=sys.stderr)
    return rows


def table(rows, programs, repeats, jobs):
    lines = [f"Compile cost, {time.strftime('%Y-%m-%d')}, {platform.node()} ({os.cpu_count()} CPUs), "
             f"{repeats} round(s), {jobs} at a time; medians over the rounds.", "",
             "| program | user CPU (s) | × reader | package share (s) | peak memory (MB) | × reader |",
             "|---|---:|---:|---:|---:|---:|"]
    base = statistics.median(r[0] for r in rows[BASELINE])
    for name in programs:
        seconds, memory, ratio, memory_ratio = (statistics.median(r[i] for r in rows[name]) for i in range(4))
        lines.append(f"| {name} | {seconds:.1f} | {ratio:.2f} | {seconds - base:.1f} | {memory:.0f} | {memory_ratio:.2f} |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default=str(ROOT / "build-compile-cost"), help="build folder (configured here)")
    parser.add_argument("--cgal-dir", help="CGAL_DIR, for a CGAL other than the system's")
    parser.add_argument("--programs", default=",".join(PROGRAMS), help="comma-separated, from: " + ", ".join(PROGRAMS))
    parser.add_argument("--repeats", type=int, default=1, help="rounds (default 1)")
    parser.add_argument("--jobs", type=int, default=1, help="compilations at a time (default 1)")
    parser.add_argument("--output", help="also write the table to this file")
    args = parser.parse_args()
    programs = [p for p in args.programs.split(",") if p]
    unknown = [p for p in programs if p not in PROGRAMS]
    if unknown or args.repeats < 1 or args.jobs < 1:
        parser.error(f"unknown program(s) {unknown}" if unknown else "--repeats and --jobs must be positive")
    programs = [BASELINE] + [p for p in programs if p != BASELINE]
    commands = configure(pathlib.Path(args.build).resolve(), args.cgal_dir)
    text = table(measure(commands, programs, args.repeats, args.jobs), programs, args.repeats, args.jobs)
    print(text)
    if args.output:
        pathlib.Path(args.output).write_text(text + "\n")


if __name__ == "__main__":
    main()
