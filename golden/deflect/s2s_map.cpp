#include "deflect/s2s_map.hpp"

#include <algorithm>
#include <cmath>

namespace tmu::deflect {

int entry_bits(const SphereGrid& grid) { return 2 * grid.phi_bits - 3; }

S2sMap::S2sMap(const SphereGrid& grid) : grid_(grid) {
  const uint32_t q = grid.quarter();
  const double d = grid.step();
  entries_.resize(size_t{q} * q);
  for (uint32_t kt = 0; kt < q; ++kt) {
    for (uint32_t k = 0; k < q; ++k) {
      const double dx = std::sin(kt * d);
      const double dy = std::cos(kt * d) * std::sin(k * d);
      const double dz = std::cos(kt * d) * std::cos(k * d);
      const auto l_phi = static_cast<uint32_t>(std::floor(std::atan2(dx, dz) / d + 0.5));
      const auto l_theta = static_cast<uint32_t>(std::floor(std::asin(dy) / d + 0.5));
      entries_[size_t{kt} * q + k] =
          (std::min(l_phi, q) << grid.mag_bits()) | std::min(l_theta, q - 1);
    }
  }
}

std::array<uint32_t, kBlockEntries> S2sMap::block(uint32_t index) const {
  const uint32_t row = index / blocks_per_row(), col = index % blocks_per_row();
  std::array<uint32_t, kBlockEntries> out{};
  for (uint32_t o = 0; o < kBlockEntries; ++o) {
    out[o] = entry(row * kBlockSide + o / kBlockSide, col * kBlockSide + o % kBlockSide);
  }
  return out;
}

MapAddress map_address(const SphereGrid& g, uint32_t phi_prime, uint32_t theta_prime) {
  const uint32_t q = g.quarter();
  const uint32_t p = phi_prime & g.phi_mask();
  MapAddress a;
  a.k_theta = theta_mag(g, theta_prime);
  a.sx = theta_negative(g, theta_prime) && a.k_theta != 0;  // -0 reads as zero
  switch (p >> g.mag_bits()) {
    case 0:
      a.k = p;
      a.sy = true;
      break;
    case 1:
      a.k = 2 * q - p;
      a.sy = true;
      a.sz = true;
      break;
    case 2:
      a.k = p - 2 * q;
      a.sz = true;
      break;
    default:
      a.k = 4 * q - p;
      break;
  }
  if (a.k < q) {
    a.block = (a.k_theta / kBlockSide) * (q / kBlockSide) + a.k / kBlockSide;
    a.offset = (a.k_theta % kBlockSide) * kBlockSide + a.k % kBlockSide;
  }
  return a;
}

MapAddress deflect_address(const SphereGrid& g, SphereAngle normal, SphereAngle bump) {
  const uint32_t phi_prime =
      static_cast<uint32_t>(static_cast<int32_t>(bump.phi) - theta_steps(g, normal.theta)) &
      g.phi_mask();
  return map_address(g, phi_prime, bump.theta);
}

MapAccess MapBuffer::access(const MapAddress& a) const {
  if (a.k == grid_.quarter()) return MapAccess::kBypass;
  return valid_ && tag_ == a.block ? MapAccess::kHit : MapAccess::kMiss;
}

void MapBuffer::fill(uint32_t tag, const std::array<uint32_t, kBlockEntries>& block) {
  valid_ = true;
  tag_ = tag;
  block_ = block;
}

SphereAngle MapBuffer::deflected(SphereAngle normal, const MapAddress& a) const {
  const uint32_t q = grid_.quarter();
  uint32_t l_phi = q, l_theta = std::min(q - a.k_theta, q - 1);  // z = 0: no look-up
  if (a.k != q) {
    const uint32_t e = block_[a.offset];
    l_phi = e >> grid_.mag_bits();
    l_theta = e & (q - 1);
  }
  return {(expand_phi(grid_, a.sx, a.sz, l_phi) + normal.phi) & grid_.phi_mask(),
          make_theta(grid_, a.sy, l_theta)};
}

Deflected DeflectionUnit::deflect(SphereAngle normal, SphereAngle bump) {
  const MapAddress a = deflect_address(map_.grid(), normal, bump);
  Deflected out;
  out.access = mbr_.access(a);
  if (out.access == MapAccess::kMiss) mbr_.fill(a.block, map_.block(a.block));
  out.normal = mbr_.deflected(normal, a);
  return out;
}

}  // namespace tmu::deflect
