#!/usr/bin/python3
# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): The CGAL Symmetry_transform developers
"""Plots the manual's figures of the public benchmarks from the CSV files of the benchmark programs.

usage (Debian's python3 with python3-matplotlib):

    /usr/bin/python3 doc/Symmetry_transform/render_benchmark_figures.py \\
        [--retrieval DIR] [--segmentation DIR] [--segmentation-methods M1,M2,...]
        [--segmentation-variant DIR LABEL]

--retrieval DIR: the --output folder of retrieval_benchmark (retrieval_precision_recall.csv and
retrieval_summary.csv); writes doc/Symmetry_transform/fig/retrieval_precision_recall.png: the
precision-recall curves of the PRST, GEDT and product distances, a panel per frame (symmetry, PCA)
and, where the run had --pose-search, per frame with the pose search.

--segmentation DIR: the --output folder of segmentation_benchmark
(segmentation_per_category.csv); writes doc/Symmetry_transform/fig/segmentation_rand_index.png:
1 - Rand Index per category and over all meshes, one bar per method (default: Human, Symmetry,
SDF k, SDF 5), with the values the benchmark's paper reports for humans, randomized cuts and the
shape-diameter method as horizontal lines. --segmentation-variant DIR LABEL adds the Symmetry
bars of another run of segmentation_benchmark (a variant of its parameters), labelled LABEL.

The figures are ours (plots of our measurements); the benchmarks' data are not in the repository
(benchmark/Symmetry_transform/RESULTS.md says how to get them).
"""

import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FIG_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fig")

# 1 - Rand Index over the whole benchmark as the benchmark's paper (Chen et al. 2009) reports it,
# quoted second-hand (not checked against the paper).
LITERATURE = [("humans (paper)", 0.10, ":"), ("randomized cuts (paper)", 0.15, "--"),
              ("shape diameter (paper)", 0.175, "-.")]
COLOURS = {"Human": "#bbbbbb", "Symmetry": "#f4a582", "variant": "#d62728", "SDF k": "#1f77b4", "SDF 5": "#8fbce6"}


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def plot_retrieval(folder):
    rows = read_csv(os.path.join(folder, "retrieval_precision_recall.csv"))
    summary = {(r["frame"], r["distance"]): r for r in read_csv(os.path.join(folder, "retrieval_summary.csv"))}
    panels = [(f, mode) for f in ("symmetry", "pca") for mode in ("", " pose search")
              if (f, "GEDT" + mode) in summary]
    styles = {"PRST": ("#1f77b4", 2.5), "GEDT": ("#2ca02c", 1.5), "PRST x GEDT": ("#d62728", 2.5)}
    fig, axes = plt.subplots(1, len(panels), figsize=(5.2 * len(panels), 4.6), sharey=True)
    axes = axes if len(panels) > 1 else [axes]
    for ax, (frame, mode) in zip(axes, panels):
        for distance, (colour, width) in styles.items():
            points = [(float(r["recall"]), float(r["precision"])) for r in rows
                      if r["frame"] == frame and r["distance"] == distance + mode and float(r["precision"]) > 0]
            s = summary[(frame, distance + mode)]
            label = "%s (NN %.1f %%, DCG %.1f %%)" % (distance.replace(" x ", " \u00d7 "), 100 * float(s["nn"]),
                                                      100 * float(s["dcg"]))
            ax.plot([p[0] for p in points], [p[1] for p in points], color=colour, linewidth=width, label=label)
        ax.set_title("%s frame%s" % ("symmetry" if frame == "symmetry" else "PCA", mode.replace(" pose", ", pose")))
        ax.set_xlabel("recall")
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
        ax.grid(alpha=0.3)
        ax.legend(loc="upper right", fontsize=8.5)
    axes[0].set_ylabel("precision")
    fig.suptitle("Princeton Shape Benchmark, test set: precision-recall (psbPlot's convention)", fontsize=11)
    fig.tight_layout()
    out = os.path.join(FIG_DIR, "retrieval_precision_recall.png")
    fig.savefig(out, dpi=110)
    print("wrote", out)


def plot_segmentation(folder, methods, variant=None):
    rows = read_csv(os.path.join(folder, "segmentation_per_category.csv"))
    if variant:
        label = variant[1]
        rows += [dict(r, method=label) for r in read_csv(os.path.join(variant[0], "segmentation_per_category.csv"))
                 if r["method"] == "Symmetry"]
        methods = methods[:methods.index("Symmetry") + 1] + [label] + methods[methods.index("Symmetry") + 1:]
    value = {(r["category"], r["method"]): float(r["ri_error"]) for r in rows}
    categories = []
    for r in rows:
        if r["category"] not in categories:
            categories.append(r["category"])
    methods = [m for m in methods if any(r["method"] == m for r in rows)]
    width = 0.8 / len(methods)
    fig, ax = plt.subplots(figsize=(13, 4.8))
    for k, method in enumerate(methods):
        xs = [i + (k - (len(methods) - 1) / 2) * width for i in range(len(categories))]
        ax.bar(xs, [value.get((c, method), 0.) for c in categories], width,
               color=COLOURS.get(method, COLOURS["variant"]), label=method, edgecolor="white", linewidth=0.3)
    for name, level, style in LITERATURE:
        ax.axhline(level, color="black", linestyle=style, linewidth=1, label=name)
    ax.set_xticks(range(len(categories)))
    ax.set_xticklabels([c.replace("**", "") for c in categories], rotation=35, ha="right")
    ax.set_xlim(-0.6, len(categories) - 0.4)
    ax.set_ylim(0, 1.3 * max(value.values()))  # room for the legend above the bars
    ax.set_ylabel("1 - Rand Index (lower is better)")
    ax.set_title("Princeton Segmentation Benchmark: 1 - Rand Index against the human segmentations, by category")
    ax.grid(axis="y", alpha=0.3)
    ax.legend(ncol=4, fontsize=8.5, loc="upper left")
    fig.tight_layout()
    out = os.path.join(FIG_DIR, "segmentation_rand_index.png")
    fig.savefig(out, dpi=110)
    print("wrote", out)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--retrieval", help="output folder of retrieval_benchmark")
    parser.add_argument("--segmentation", help="output folder of segmentation_benchmark")
    parser.add_argument("--segmentation-methods", default="Human,Symmetry,SDF k,SDF 5")
    parser.add_argument("--segmentation-variant", nargs=2, metavar=("DIR", "LABEL"))
    args = parser.parse_args()
    if args.retrieval:
        plot_retrieval(args.retrieval)
    if args.segmentation:
        plot_segmentation(args.segmentation, args.segmentation_methods.split(","), args.segmentation_variant)


if __name__ == "__main__":
    main()
