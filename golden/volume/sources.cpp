#include "volume/sources.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tmu::volume {

namespace {

uint8_t to_voxel(double v) {
  return static_cast<uint8_t>(std::clamp(std::floor(v + 0.5), 0.0, 255.0));
}

}  // namespace

double marschner_lobb(double x, double y, double z, const MarschnerLobb& p) {
  constexpr double kPi = std::numbers::pi;
  const double r = std::sqrt(x * x + y * y);
  const double rho = std::cos(2 * kPi * p.f_m * std::cos(kPi * r / 2));
  return (1 - std::sin(kPi * z / 2) + p.alpha * (1 + rho)) / (2 * (1 + p.alpha));
}

VoxelGrid marschner_lobb_grid(uint32_t n) { return marschner_lobb_grid(n, n, n, {}); }

VoxelGrid marschner_lobb_grid(uint32_t nx, uint32_t ny, uint32_t nz, const MarschnerLobb& p) {
  VoxelGrid g(nx, ny, nz);
  auto c = [](uint32_t i, uint32_t n) { return -1.0 + 2.0 * i / (n - 1); };
  for (uint32_t k = 0; k < nz; ++k) {
    for (uint32_t j = 0; j < ny; ++j) {
      for (uint32_t i = 0; i < nx; ++i)
        g.at(i, j, k) = to_voxel(255 * marschner_lobb(c(i, nx), c(j, ny), c(k, nz), p));
    }
  }
  return g;
}

std::array<double, 3> sphere_centre(const VoxelGrid& g) {
  return {(g.nx - 1) / 2.0, (g.ny - 1) / 2.0, (g.nz - 1) / 2.0};
}

VoxelGrid sphere_grid(uint32_t nx, uint32_t ny, uint32_t nz, double radius, double slope) {
  VoxelGrid g(nx, ny, nz);
  const auto c = sphere_centre(g);
  for (uint32_t k = 0; k < nz; ++k) {
    for (uint32_t j = 0; j < ny; ++j) {
      for (uint32_t i = 0; i < nx; ++i) {
        const double d = std::hypot(i - c[0], j - c[1], k - c[2]);
        g.at(i, j, k) = to_voxel(128 + slope * (radius - d));
      }
    }
  }
  return g;
}

}  // namespace tmu::volume
