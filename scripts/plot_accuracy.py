#!/usr/bin/python3
"""Plots each block's sweep (the CSV tables `texsim sweep all` writes) as error against cells
and error against time, one PNG per block, the default setting marked.

usage: plot_accuracy.py DIR    (reads DIR/<block>.csv, writes DIR/<block>.png)
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # no display: files only
import matplotlib.pyplot as plt  # noqa: E402

# Per block: the column naming a setting, the default setting, the error column (lower is
# better), the columns whose sum is the area, and the time column with how to turn it into a
# time (a rate is inverted). A block without an area column gets one plot. xlog: both x axes
# logarithmic (counts spanning decades, such as triangles); title: the figure's, when the
# default's words (area, time) would mislead.
SPECS = {
    "trilinear": dict(
        label="S,W,L", default="8,8,8", error="mean err", error_name="mean error (8-bit levels)",
        cells=["logic"], cells_name="logic cells (memories as RAM macros)",
        time="golden Ms/s", time_name="golden us per sample", invert=True),
    "footprint_setup": dict(
        label="D,T,F", default="12,7,8", error="lambda mean err",
        error_name="lambda mean error (levels)", cells=["cells"], cells_name="cells",
        time="golden M setups/s", time_name="golden us per setup", invert=True),
    "footprint": dict(
        label="variant", default="footprint N<=16", error="mean err",
        error_name="mean error vs supersampled (8-bit levels)", cells=None, cells_name=None,
        time="cycles/px", time_name="cycles per pixel", invert=False),
    "deflection": dict(
        label="A,E,M,W", default="9,4,5,10", error="R mean deg",
        error_name="reflection vector mean error (degrees)",
        cells=["enc cells", "defl cells", "coord cells"],
        cells_name="cells: encoder + deflection + coordinates", time="cyc/px",
        time_name="cycles per bumped pixel", invert=False),
    "mipgen": dict(
        label="carry", default="20", error="max abs err",
        error_name="largest error of any level (8-bit levels)", cells=["logic"],
        cells_name="logic cells (FIFOs as RAM macros)", time="FIFO bits",
        time_name="line FIFO bits", invert=False),
    "clipmap": dict(
        label="tile,rule", default="64 per-sample", error="mean err",
        error_name="mean error vs every level resident (8-bit levels)", cells=["resident texels"],
        cells_name="texels resident", time="loads/frame", time_name="texels loaded per frame",
        invert=False),
    "nurbs": dict(
        label="threshold", default="DC 4", error="mean err",
        error_name="mean error vs the reference (8-bit levels)",
        cells=["triangles"], cells_name="triangles", time="front end s",
        time_name="front-end seconds (tessellation + rasterization)", invert=False, xlog=True,
        title="nurbs: error against triangles and front-end time (order tc)"),
    "volume": dict(
        label="W,step", default="8,1", error="value RMS",
        error_name="resampled value RMS error vs ideal (voxel values)", cells=None,
        cells_name=None, time="frame ms", time_name="unit ms per frame (30 ns an access)",
        invert=False, xlog=True,
        title="volume: error against the unit's time (weight bits W, step in voxels)"),
    "perlin": dict(
        label="F,S,B,X", default="8,8,8,4", error="P mean", error_name="noise mean error",
        cells=["noise cells"], cells_name="noise unit cells", time="golden ns/sample",
        time_name="golden ns per sample", invert=False),
}


def number(text):
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def points(rows, spec):
    """(label, error, cells or None, time) for every row with the figures the plots need."""
    out = []
    for row in rows:
        error, time = number(row[spec["error"]]), number(row[spec["time"]])
        # An error of 0 (every texel resident) has no place on the log scale.
        if error is None or time is None or error <= 0 or (spec["invert"] and time == 0):
            continue
        cells = None
        if spec["cells"]:
            parts = [number(row[c]) for c in spec["cells"]]
            cells = None if None in parts else sum(parts)
        if spec["invert"]:
            time = 1.0 / time
        out.append((row[spec["label"]], error, cells, time))
    return out


def scatter(ax, pts, x_of, x_name, spec):
    for label, error, cells, time in pts:
        x = x_of(cells, time)
        if x is None:
            continue
        is_default = label == spec["default"]
        ax.scatter([x], [error], marker="*" if is_default else "o", s=140 if is_default else 30,
                   color="tab:red" if is_default else "tab:blue", zorder=3)
        ax.annotate(label + (" (default)" if is_default else ""), (x, error), fontsize=7,
                    xytext=(4, 3), textcoords="offset points")
    ax.set_xlabel(x_name)
    if spec.get("xlog"):
        ax.set_xscale("log")
    ax.set_ylabel(spec["error_name"])
    ax.set_yscale("log")
    ax.grid(True, which="both", alpha=0.3)


def plot(block, spec, directory):
    with open(os.path.join(directory, block + ".csv"), newline="") as f:
        pts = points(list(csv.DictReader(f)), spec)
    if not pts:
        raise SystemExit(f"plot_accuracy.py: {block}.csv: no row has the figures to plot")
    panels = 2 if spec["cells"] else 1
    fig, axes = plt.subplots(1, panels, figsize=(6 * panels, 4.2), squeeze=False)
    if spec["cells"]:
        scatter(axes[0][0], pts, lambda c, t: c, spec["cells_name"], spec)
    scatter(axes[0][-1], pts, lambda c, t: t, spec["time_name"], spec)
    fig.suptitle(spec.get("title") or
                 f"{block}: error against " + ("area and time" if spec["cells"] else "time"))
    fig.tight_layout()
    path = os.path.join(directory, block + ".png")
    fig.savefig(path, dpi=100)
    plt.close(fig)
    print("wrote", path)


def main():
    if len(sys.argv) != 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(sys.argv) == 2 else 2
    directory = sys.argv[1]
    for block, spec in SPECS.items():
        plot(block, spec, directory)
    return 0


if __name__ == "__main__":
    sys.exit(main())
