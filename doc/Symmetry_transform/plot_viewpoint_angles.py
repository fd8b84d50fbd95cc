#!/usr/bin/python3
# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): The CGAL Symmetry_transform developers
"""Plots, per set of shapes, the histogram of the angle between the best view and the nearest axis
of the symmetry frame, from the tables that viewpoint_experiment prints.

usage (Debian's python3 with python3-matplotlib):

    /usr/bin/python3 doc/Symmetry_transform/plot_viewpoint_angles.py LABEL=TABLE [LABEL=TABLE ...]

TABLE is the standard output of `viewpoint_experiment --set ...`; the column read is the one of
the planes as detect_principal_symmetries() returns them. Writes
doc/Symmetry_transform/fig/viewpoint_angles.png, the band of the thesis's "20-35 degrees
off-axis" (section 4.3.3) and the 15-40 degrees band, 5 degrees wider on each side, shaded.
"""

import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FIG = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fig", "viewpoint_angles.png")
COLUMN = "best view's angle to the nearest frame axis (deg)"
WIDER_BAND = (15, 40)  # degrees: 5 degrees wider on each side than the thesis's
THESIS_BAND = (20, 35)  # degrees: "the best viewpoint ... was always 20-35 degrees off-axis"
BIN_DEGREES = 5
MOST_DEGREES = 60  # the largest angle to the nearest of three orthogonal axes is 54.7 degrees


def angles(path):
    """The column COLUMN of the markdown table in the file, and the summary's count of shapes within
    15-40 degrees (the table rounds to 0.1 degree: 40.04 prints as 40.0 but lies outside)."""
    column, values, inside = None, [], None
    with open(path) as f:
        for line in f:
            summary = re.search(r"from the nearest frame axis on (\d+) of", line)
            if summary:
                inside = int(summary.group(1))
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if column is None and COLUMN in cells:
                column = cells.index(COLUMN)
            elif column is not None and len(cells) > column and not cells[column].startswith("-"):
                try:
                    values.append(float(cells[column]))
                except ValueError:
                    pass
    if not values or inside is None:
        sys.exit(path + ": no table with the column '" + COLUMN + "' and its summary line")
    return values, inside


def main(arguments):
    if not arguments or any("=" not in a for a in arguments):
        sys.exit(__doc__)
    sets = [(a.split("=", 1)[0], angles(a.split("=", 1)[1])) for a in arguments]
    edges = list(range(0, MOST_DEGREES + BIN_DEGREES, BIN_DEGREES))
    fig, axes = plt.subplots(1, len(sets), figsize=(4.2 * len(sets), 3.2), sharey=True, squeeze=False)
    for ax, (label, (values, inside)) in zip(axes[0], sets):
        ax.axvspan(*WIDER_BAND, color="tab:green", alpha=0.12, label="%d-%d deg" % WIDER_BAND)
        ax.axvspan(*THESIS_BAND, color="tab:green", alpha=0.18, label="%d-%d deg (thesis)" % THESIS_BAND)
        ax.hist(values, bins=edges, weights=[1 / len(values)] * len(values), color="tab:blue", edgecolor="white")
        ax.set_title("%s: %d of %d in %d-%d deg" % ((label, inside, len(values)) + WIDER_BAND), fontsize=10)
        ax.set_xlabel("best view to nearest frame axis (deg)")
        ax.set_xlim(0, MOST_DEGREES)
    axes[0][0].set_ylabel("fraction of the shapes")
    axes[0][0].legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(FIG, dpi=110)
    print("wrote " + FIG)


if __name__ == "__main__":
    main(sys.argv[1:])
