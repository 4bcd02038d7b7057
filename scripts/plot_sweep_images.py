#!/usr/bin/python3
"""Lays out the rendered test pattern of an accuracy sweep: for each width setting, the golden
render above and its error against the ideal model (x16) below.

Usage: scripts/plot_sweep_images.py DIR BLOCK SETTING... OUT.png
  e.g. scripts/plot_sweep_images.py docs/images/sweep trilinear s8w8l8 s6w6l6 s4w4l4 sweep.png
It reads DIR/BLOCK_SETTING.png and DIR/BLOCK_SETTING_error.png (written by `texsim sweep
BLOCK --out DIR`) and DIR/BLOCK_ideal.png.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    folder, block, settings, out = argv[0], argv[1], argv[2:-1], argv[-1]
    columns = ["ideal"] + settings
    fig, axes = plt.subplots(2, len(columns), figsize=(3.2 * len(columns), 5.2), squeeze=False)
    for col, name in enumerate(columns):
        top = plt.imread(f"{folder}/{block}_{name}.png")
        axes[0][col].imshow(top)
        axes[0][col].set_title(name if name == "ideal" else name.replace("s", "S=").replace("w", " W=").replace("l", " L="))
        if name != "ideal":
            axes[1][col].imshow(plt.imread(f"{folder}/{block}_{name}_error.png"))
            axes[1][col].set_title("|golden - ideal| x 16")
        for row in (0, 1):
            axes[row][col].axis("off")
    fig.tight_layout()
    fig.savefig(out, dpi=80)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv[1:])
