#include "volume/slabs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "volume/layout.hpp"

namespace tmu::host {
namespace {

uint32_t slab_owned_start(uint32_t planes, int chips, int k) {
  return static_cast<uint32_t>(uint64_t{planes} * static_cast<uint64_t>(k) /
                               static_cast<uint64_t>(chips));
}

SlabPlan make_slab_plan(const std::array<uint32_t, 3>& size, int chips, int axis,
                        volume::Mode mode) {
  SlabPlan p;
  p.axis = axis;
  p.planes = size[static_cast<size_t>(axis)];
  const auto [before, after] = ghost_planes(mode);
  p.ghost_before = before;
  p.ghost_after = after;
  for (int k = 0; k < chips; ++k) {
    Slab s;
    s.own_begin = slab_owned_start(p.planes, chips, k);
    s.own_end = slab_owned_start(p.planes, chips, k + 1);
    s.begin = s.own_begin >= before ? s.own_begin - before : 0;
    s.end = std::min(p.planes, s.own_end + after);
    p.slabs.push_back(s);
  }
  return p;
}

// The plane index i0 of a raw position along an axis of n voxels, as the unit takes it.
uint32_t slab_corner_plane(int64_t raw, uint32_t n) {
  return volume::axis_corners(static_cast<int32_t>(raw), n, 8).i0;
}

}  // namespace

std::array<uint32_t, 2> ghost_planes(volume::Mode mode) {
  return mode == volume::Mode::kRaw ? std::array<uint32_t, 2>{1, 2} : std::array<uint32_t, 2>{0, 1};
}

std::string slab_problem(const std::array<uint32_t, 3>& size, int chips, int axis,
                         volume::Mode mode) {
  if (chips < 1 || chips > kMaxChips) return fmt::format("{} chips (1..{})", chips, kMaxChips);
  const uint32_t planes = size[static_cast<size_t>(axis)];
  if (planes < 2 * static_cast<uint32_t>(chips)) {
    return fmt::format("{} chips for {} planes along {}: each chip owns at least 2", chips, planes,
                       "xyz"[axis]);
  }
  for (const Slab& s : make_slab_plan(size, chips, axis, mode).slabs) {
    std::array<uint32_t, 3> held = size;
    held[static_cast<size_t>(axis)] = s.end - s.begin;
    try {
      volume::VolumeGeometry(held[0], held[1], held[2]);
    } catch (const std::invalid_argument& e) {
      return fmt::format("a slab of {} x {} x {} voxels does not fit a chip ({}); use more chips",
                         held[0], held[1], held[2], e.what());
    }
  }
  return "";
}

SlabPlan plan_slabs(const std::array<uint32_t, 3>& size, int chips, int axis, volume::Mode mode) {
  if (const std::string why = slab_problem(size, chips, axis, mode); !why.empty())
    throw std::invalid_argument("slabs: " + why);
  return make_slab_plan(size, chips, axis, mode);
}

SlabPlan whole_volume(const std::array<uint32_t, 3>& size, int axis) {
  SlabPlan p;
  p.axis = axis;
  p.planes = size[static_cast<size_t>(axis)];
  p.slabs.push_back({0, p.planes, 0, p.planes});
  return p;
}

volume::VoxelGrid slab_grid(const volume::VoxelGrid& whole, const SlabPlan& plan, size_t chip) {
  const Slab& s = plan.slabs.at(chip);
  std::array<uint32_t, 3> n = {whole.nx, whole.ny, whole.nz};
  n[static_cast<size_t>(plan.axis)] = s.end - s.begin;
  volume::VoxelGrid g(n[0], n[1], n[2]);
  for (uint32_t z = 0; z < n[2]; ++z) {
    for (uint32_t y = 0; y < n[1]; ++y) {
      for (uint32_t x = 0; x < n[0]; ++x) {
        std::array<uint32_t, 3> p = {x, y, z};
        p[static_cast<size_t>(plan.axis)] += s.begin;
        g.at(x, y, z) = whole.at(p[0], p[1], p[2]);
      }
    }
  }
  return g;
}

std::vector<ChipRun> split_by_chip(const SlabPlan& plan, const volume::Ray& ray, uint32_t first,
                                   uint32_t count) {
  std::vector<ChipRun> runs;
  const auto a = static_cast<size_t>(plan.axis);
  size_t chip = 0;
  for (uint32_t n = first; n < first + count; ++n) {
    const uint32_t i0 = slab_corner_plane(ray.start[a] + int64_t{ray.step[a]} * n, plan.planes);
    // The owner: the slab whose owned planes hold i0 (slabs in plane order; a ray's i0 moves
    // one way, so the search starts from the last owner or from the start).
    if (runs.empty() || i0 < plan.slabs[chip].own_begin || i0 >= plan.slabs[chip].own_end) {
      chip = 0;
      while (i0 >= plan.slabs[chip].own_end) ++chip;
      runs.push_back({chip, n, 0});
    }
    ++runs.back().count;
  }
  return runs;
}

volume::Ray chip_ray(const SlabPlan& plan, size_t chip, const volume::Ray& ray, uint32_t first,
                     uint32_t count) {
  volume::Ray r = ray;
  r.count = count;
  for (size_t a = 0; a < 3; ++a)
    r.start[a] = static_cast<int32_t>(ray.start[a] + int64_t{ray.step[a]} * first);
  const auto a = static_cast<size_t>(plan.axis);
  r.start[a] -= static_cast<int32_t>(plan.slabs.at(chip).begin << volume::kPosFrac);
  if (!volume::ray_in_range(r)) throw std::logic_error("slabs: a chip's ray out of range");
  return r;
}

}  // namespace tmu::host
