#!/usr/bin/python3
"""Draws the volume unit's voxel layout (docs/volume.md, "The layout and its proof") as a
picture for the document: one slice of voxels coloured by bank with each voxel's cell in its
brick's page, the brick borders, and the four accesses of Fig. 15 that read this slice for one
resample location, each a set of four voxels in four different banks.

The rule drawn is the one the document states and golden/volume/layout.cpp implements
(VolumeLayoutTest proves it conflict-free); this script only draws it.

usage: plot_volume_layout.py OUT.png
"""
import sys

import matplotlib

matplotlib.use("Agg")  # no display: files only
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402

BRICK_X, BRICK_Y = 16, 8  # voxels of a brick in x and y (16 in z): 512 cells of each bank
BANK_COLOURS = ["#8dd3c7", "#ffffb3", "#bebada", "#fb8072"]


def bank(x, y):
    return (x & 1) + 2 * (y & 1)


def cell_in_page(x, y, z):
    return 32 * (z & 15) + 8 * ((y >> 1) & 3) + ((x >> 1) & 7)


def draw_slice(ax, width, height, z):
    for y in range(height):
        for x in range(width):
            ax.add_patch(Rectangle((x, y), 1, 1, facecolor=BANK_COLOURS[bank(x, y)],
                                   edgecolor="white", linewidth=0.5))
            ax.text(x + 0.5, y + 0.5, str(cell_in_page(x, y, z)), ha="center", va="center",
                    fontsize=5.5)
    for bx in range(0, width + 1, BRICK_X):
        ax.plot([bx, bx], [0, height], color="black", linewidth=2)
    for by in range(0, height + 1, BRICK_Y):
        ax.plot([0, width], [by, by], color="black", linewidth=2)
    ax.set_xlim(0, width)
    ax.set_ylim(height, 0)
    ax.set_aspect("equal")
    ax.set_xlabel("x")
    ax.set_ylabel("y")


def draw_accesses(ax, i0, j0):
    """The accesses of one location (i0 + f, j0 + f, k0 + f) that read slice k0."""
    accesses = [
        ("1: value", "o", [(i0, j0), (i0 + 1, j0), (i0, j0 + 1), (i0 + 1, j0 + 1)]),
        ("3: x-gradient", "s", [(i0 - 1, j0), (i0 + 2, j0), (i0 - 1, j0 + 1), (i0 + 2, j0 + 1)]),
        ("5: y-gradient", "^", [(i0, j0 - 1), (i0 + 1, j0 - 1), (i0, j0 + 2), (i0 + 1, j0 + 2)]),
    ]
    offsets = {"o": (-0.2, -0.2), "s": (0.2, -0.2), "^": (0, 0.22)}
    for name, marker, voxels in accesses:
        banks = sorted(bank(x, y) for x, y in voxels)
        assert banks == [0, 1, 2, 3], name  # the picture must show what the proof proves
        dx, dy = offsets[marker]
        ax.scatter([x + 0.5 + dx for x, _ in voxels], [y + 0.5 + dy for _, y in voxels],
                   marker=marker, s=55, facecolors="none", edgecolors="black", linewidths=1.4,
                   label=f"access {name}: banks {', '.join(str(b) for b in banks)}")
    ax.add_patch(Rectangle((i0 + 0.5, j0 + 0.5), 1, 1, fill=False, linestyle="--",
                           edgecolor="black"))
    ax.legend(loc="upper left", bbox_to_anchor=(0, -0.12), fontsize=8, frameon=False)


def main():
    if len(sys.argv) != 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(sys.argv) == 2 else 2
    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 5.2),
                                      gridspec_kw={"width_ratios": [2.2, 1]})
    draw_slice(left, 32, 16, 0)
    left.set_title("slice z = 0: bank (colour) and cell in the brick's page (number);\n"
                   "bricks of 16 x 8 x 16 voxels (thick lines) are one 512-cell page per bank")
    draw_slice(right, 8, 8, 0)
    draw_accesses(right, 3, 3)
    right.set_title("one location (dashed: its cell of corners):\n"
                    "the accesses that read this slice")
    handles = [Rectangle((0, 0), 1, 1, facecolor=c) for c in BANK_COLOURS]
    left.legend(handles, [f"bank {b}" for b in range(4)], loc="upper left",
                bbox_to_anchor=(0, -0.12), ncol=4, fontsize=8, frameon=False)
    fig.tight_layout()
    fig.savefig(sys.argv[1], dpi=100)
    print("wrote", sys.argv[1])
    return 0


if __name__ == "__main__":
    sys.exit(main())
