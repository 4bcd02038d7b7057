#include "volume/volume_ideal.hpp"

#include <algorithm>
#include <cmath>

namespace tmu::volume {

namespace {

double voxel(const VoxelGrid& g, long x, long y, long z) {
  return g.voxels[static_cast<size_t>(x) +
                  g.nx * (static_cast<size_t>(y) + g.ny * static_cast<size_t>(z))];
}

}  // namespace

double ideal_node_gradient(const VoxelGrid& g, long x, long y, long z, int axis) {
  const long n[3] = {static_cast<long>(g.nx), static_cast<long>(g.ny), static_cast<long>(g.nz)};
  long p[3] = {x, y, z};
  const long i = p[axis];
  long lo[3] = {x, y, z}, hi[3] = {x, y, z};
  lo[axis] = std::max(i - 1, 0L);
  hi[axis] = std::min(i + 1, n[axis] - 1);
  // Central difference inside, the one-sided difference on a face.
  return (voxel(g, hi[0], hi[1], hi[2]) - voxel(g, lo[0], lo[1], lo[2])) /
         static_cast<double>(hi[axis] - lo[axis]);
}

IdealResample ideal_resample(const VoxelGrid& g, const Point& point) {
  const long n[3] = {static_cast<long>(g.nx), static_cast<long>(g.ny), static_cast<long>(g.nz)};
  long i0[3], i1[3];
  double t[3];
  for (int a = 0; a < 3; ++a) {
    const double p = std::clamp(point[a], 0.0, static_cast<double>(n[a] - 1));
    i0[a] = std::min(static_cast<long>(std::floor(p)), n[a] - 1);
    i1[a] = std::min(i0[a] + 1, n[a] - 1);
    t[a] = p - static_cast<double>(i0[a]);
  }
  IdealResample r;
  for (int k = 0; k < 8; ++k) {
    const long x = (k & 1) ? i1[0] : i0[0], y = (k & 2) ? i1[1] : i0[1],
               z = (k & 4) ? i1[2] : i0[2];
    const double w =
        ((k & 1) ? t[0] : 1 - t[0]) * ((k & 2) ? t[1] : 1 - t[1]) * ((k & 4) ? t[2] : 1 - t[2]);
    r.value += w * voxel(g, x, y, z);
    for (int a = 0; a < 3; ++a) r.gradient[a] += w * ideal_node_gradient(g, x, y, z, a);
  }
  return r;
}

Point ideal_location(const Point& start, const Point& step, double n) {
  return {start[0] + n * step[0], start[1] + n * step[1], start[2] + n * step[2]};
}

}  // namespace tmu::volume
