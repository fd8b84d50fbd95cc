#!/usr/bin/python3
# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): The CGAL Symmetry_transform developers
"""Plots the histograms of the thesis's Figure 4.4 from the alignment experiment's error files.

usage (Debian's python3 with python3-matplotlib):

    /usr/bin/python3 doc/Symmetry_transform/plot_alignment_histograms.py DEMO_ERRORS MAN_MADE_ERRORS [--rules R1,R2]

DEMO_ERRORS and MAN_MADE_ERRORS are the files that
`alignment_experiment --set demo|man-made --errors FILE` writes: one line per scan and rule,
"set rule shape corner t_symmetry r_symmetry paired_symmetry t_pca r_pca paired_pca". Writes
doc/Symmetry_transform/fig/alignment_histograms.png: for each set (a row), the histograms of the
translational error (% of the radius) and of the rotational error (degrees, the largest angle
between corresponding axes) of the symmetry frame (one curve per rule) and of the PCA frame (green), as
fractions of the scans, like the thesis's Figure 4.4 (more weight on the left is better).
"""

import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FIG = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fig", "alignment_histograms.png")
TRANSLATION_BINS = [0, 2.5, 5, 7.5, 10, 12.5, 15, 20, 25, 30, 40, 60]
ROTATION_BINS = [0, 2, 5, 10, 15, 20, 30, 45, 60, 90]


def read(path, rule):
    rows = []
    with open(path) as f:
        for line in f:
            fields = line.split()
            if len(fields) == 10 and fields[1] == rule:
                rows.append([float(x) for x in fields[4:]])
    if not rows:
        sys.exit(path + ": no scan of rule " + rule)
    return rows


def histogram(values, edges):
    """Fractions of the values in [edges[i], edges[i+1]), the last bin taking everything above."""
    counts = [0] * (len(edges) - 1)
    for v in values:
        i = len(edges) - 2
        while i > 0 and v < edges[i]:
            i -= 1
        counts[i] += 1
    return [c / len(values) for c in counts]


COLOURS = ["tab:blue", "tab:orange", "tab:purple"]


def panel(ax, edges, series, pca, xlabel, title):
    """One plot: a curve per rule of the symmetry frame, and the PCA frame's."""
    centres = [(a + b) / 2 for a, b in zip(edges[:-1], edges[1:])]
    for (rule, values), colour in zip(series, COLOURS):
        ax.plot(centres, histogram(values, edges), "o-", color=colour, label=f"symmetry frame, rule {rule}")
    ax.plot(centres, histogram(pca, edges), "s-", color="tab:green", label="centre of mass / PCA axes")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("fraction of scans")
    ax.set_title(title, fontsize=10)
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("demo")
    parser.add_argument("man_made")
    parser.add_argument("--rules", default="greedy", help="comma-separated rules, at most 3")
    args = parser.parse_args()
    rules = args.rules.split(",")[:3]
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    for row, (path, name) in enumerate([(args.demo, "CGAL's sample meshes"), (args.man_made, "man-made shapes")]):
        runs = [(rule, read(path, rule)) for rule in rules]
        n = len(runs[0][1])
        panel(axes[row][0], TRANSLATION_BINS, [(rule, [r[0] for r in rows]) for rule, rows in runs],
              [r[3] for r in runs[0][1]], "translational error (% of the radius; last bin: 40 and more)",
              f"{name}, {n} scans: (a) translation")
        panel(axes[row][1], ROTATION_BINS, [(rule, [r[1] for r in rows]) for rule, rows in runs],
              [r[4] for r in runs[0][1]], "rotational error (degrees, largest angle between corresponding axes)",
              f"{name}, {n} scans: (b) rotation")
    axes[0][0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(FIG, dpi=90)
    print("wrote", FIG)


if __name__ == "__main__":
    main()
