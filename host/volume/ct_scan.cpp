#include "volume/ct_scan.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace tmu::host {
namespace {

// The scanner's point spread function: a Gaussian of 0.8 voxel, cut at 2 voxels.
constexpr double kScanBlurSigma = 0.8;
constexpr int kScanBlurRadius = 2;

// splitmix64: a reproducible stream on every platform (std's distributions are not).
uint64_t scan_mix(uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

double scan_uniform(uint64_t key) {  // (0, 1)
  return (static_cast<double>(scan_mix(key) >> 11) + 0.5) * 0x1.0p-53;
}

// A standard normal deviate (Box-Muller) for voxel `index` of stream `seed`.
double scan_gaussian(uint32_t seed, uint64_t index) {
  const uint64_t key = (uint64_t{seed} << 40) ^ (index << 1);
  return std::sqrt(-2 * std::log(scan_uniform(key))) *
         std::cos(2 * std::numbers::pi * scan_uniform(key | 1));
}

}  // namespace

double engine_density(double x, double y, double z) {
  constexpr double kAluminium = 0.45, kSteel = 1.0;
  const auto in_block = [&] {
    return std::abs(x) <= 0.78 && std::abs(y) <= 0.5 && z >= -0.55 && z <= 0.25;
  };
  // Seven fins on the top, each 0.1 thick, across the block.
  const auto in_fin = [&] {
    if (z <= 0.25 || z > 0.45 || std::abs(y) > 0.46 || std::abs(x) > 0.65) return false;
    const double k = std::round((x + 0.6) / 0.2);
    return std::abs(x - (-0.6 + 0.2 * k)) <= 0.05;
  };
  // The two cylinders along z at x = -0.38 and 0.38: radius from each axis.
  const double r = std::min(std::hypot(x + 0.38, y), std::hypot(x - 0.38, y));
  const bool cylinder_height = z >= -0.55 && z <= 0.45;
  // The crankshaft along x at z = -0.38, out of both ends of the block.
  const double shaft_r = std::hypot(y, z + 0.38);
  // The bolts at (+-0.68, +-0.4): shanks of 0.05 and heads of 0.08 above the top.
  const double bolt_r = std::hypot(std::abs(x) - 0.68, std::abs(y) - 0.4);
  if (shaft_r <= 0.09 && std::abs(x) <= 0.95) return kSteel;
  if (bolt_r <= 0.05 && z >= -0.55 && z <= 0.32) return kSteel;
  if (bolt_r <= 0.08 && z > 0.25 && z <= 0.32) return kSteel;
  if (r >= 0.17 && r < 0.24 && cylinder_height) return kSteel;         // the liners
  if (r < 0.165 && z >= -0.25 && z <= 0.0) return kAluminium;          // the pistons
  if (r < 0.24 && cylinder_height) return 0;                           // the bores
  if (std::hypot(y, z + 0.38) < 0.15 && std::abs(x) <= 0.7) return 0;  // the crankcase
  return in_block() || in_fin() ? kAluminium : 0;
}

volume::VoxelGrid engine_scan(uint32_t nx, uint32_t ny, uint32_t nz, uint32_t seed) {
  volume::VoxelGrid g(nx, ny, nz);
  // Each voxel's mean density: its 2 x 2 x 2 sub-points a quarter voxel either side of its point.
  const auto coord = [](double i, uint32_t n) { return -1.0 + 2.0 * i / (n - 1); };
  std::vector<double> density(g.voxels.size());
  for (uint32_t k = 0; k < nz; ++k) {
    for (uint32_t j = 0; j < ny; ++j) {
      for (uint32_t i = 0; i < nx; ++i) {
        double sum = 0;
        for (int s = 0; s < 8; ++s) {
          sum += engine_density(coord(i + ((s & 1) ? 0.25 : -0.25), nx),
                                coord(j + ((s & 2) ? 0.25 : -0.25), ny),
                                coord(k + ((s & 4) ? 0.25 : -0.25), nz));
        }
        density[g.index(i, j, k)] = sum / 8;
      }
    }
  }
  // The scanner's point spread: a Gaussian of kScanBlurSigma voxels along each axis in turn (the
  // faces continued by their own voxel).
  std::array<double, 2 * kScanBlurRadius + 1> kernel{};
  double total = 0;
  for (int d = -kScanBlurRadius; d <= kScanBlurRadius; ++d) {
    kernel[static_cast<size_t>(d + kScanBlurRadius)] =
        std::exp(-d * d / (2 * kScanBlurSigma * kScanBlurSigma));
    total += kernel[static_cast<size_t>(d + kScanBlurRadius)];
  }
  for (double& w : kernel) w /= total;
  const std::array<uint32_t, 3> n = {nx, ny, nz};
  const std::array<size_t, 3> stride = {1, nx, size_t{nx} * ny};
  std::vector<double> blurred(density.size());
  for (size_t axis = 0; axis < 3; ++axis) {
    for (size_t at = 0; at < density.size(); ++at) {
      const auto i = static_cast<int64_t>(at / stride[axis] % n[axis]);
      double v = 0;
      for (int d = -kScanBlurRadius; d <= kScanBlurRadius; ++d) {
        const int64_t q = std::clamp<int64_t>(i + d, 0, n[axis] - 1);
        v += kernel[static_cast<size_t>(d + kScanBlurRadius)] *
             density[at + static_cast<size_t>(q - i) * stride[axis]];
      }
      blurred[at] = v;
    }
    density.swap(blurred);
  }
  for (size_t at = 0; at < density.size(); ++at) {
    const double v = 20 + 200 * density[at] + 3 * scan_gaussian(seed, at);
    g.voxels[at] = static_cast<uint8_t>(std::clamp(std::floor(v + 0.5), 0.0, 255.0));
  }
  return g;
}

}  // namespace tmu::host
