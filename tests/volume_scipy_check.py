#!/usr/bin/env python3
"""The volume ideal (golden/volume/volume_ideal.hpp) against scipy.ndimage.map_coordinates.

Reads DIR/voxels.bin (X x Y x Z bytes, x fastest) and DIR/points.txt (first line X Y Z, then
per point: x y z value gx gy gz as the ideal computed them), evaluates trilinear interpolation
(map_coordinates, order=1, mode='nearest': voxel centres at integers) of the voxels and of
numpy.gradient(edge_order=1) (central differences inside, one-sided on the faces), and exits 1
when any differs from the ideal by more than 1e-9. Run by VolumeIdealTest (tests/volume_test.cpp).
"""
import sys

import numpy as np
import scipy.ndimage as ndi


def main(d):
    lines = open(f"{d}/points.txt").read().split("\n")
    nx, ny, nz = (int(t) for t in lines[0].split())
    vol = np.fromfile(f"{d}/voxels.bin", dtype=np.uint8).astype(np.float64)
    vol = vol.reshape(nz, ny, nx)  # [z][y][x]
    rows = np.array([[float(t) for t in l.split()] for l in lines[1:] if l.strip()])
    coords = np.stack([rows[:, 2], rows[:, 1], rows[:, 0]])  # (z, y, x)
    value = ndi.map_coordinates(vol, coords, order=1, mode="nearest")
    gz, gy, gx = np.gradient(vol, edge_order=1)
    grads = [ndi.map_coordinates(g, coords, order=1, mode="nearest") for g in (gx, gy, gz)]
    err = max(np.max(np.abs(value - rows[:, 3])),
              *(np.max(np.abs(grads[a] - rows[:, 4 + a])) for a in range(3)))
    print(f"volume ideal vs scipy map_coordinates: {len(rows)} points, largest difference {err:.3g}")
    return 0 if err <= 1e-9 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
