// Golden model of the bump deflection (001 §4.4, Fig. 5; §6.2, Fig. 7): the bump texel D,
// stored as angles about the horizontal polar axis u of the bump map's (u, v, w) frame, is
// rotated onto the surface by two offsets and one look-up in a spherical-to-spherical map
// held in a cache RAM of 4 x 4 blocks. This file is the specification the hls and rtl
// models match.
//
// Frames. The surface's normal N = (phi_N, theta_N) (sphere_grid.hpp, eq. 12). The bump
// frame on the surface: w = N, u = the horizontal tangent R_y(phi_N) x, v in the plane of N
// and y; a bump texel (phi_D, theta_D) is the unit vector with
//   D_u = sin(theta_D),  D_w = cos(theta_D) cos(phi_D),  D_v = -cos(theta_D) sin(phi_D)
// (x-polar angles; the flat texel (0, 0) is D = w). The bump-map tool writes this form.
// The rotation into object space is R_y(phi_N) R_x(-theta_N), done as
//   1. phi' = phi_D - theta_N (steps, modulo 4Q), theta' = theta_D: the roll about x;
//   2. one look-up (phi'', theta'') = M(phi', theta'): the same vector re-expressed in the
//      y-polar angles of eq. 12;
//   3. phi = phi'' + phi_N (modulo 4Q), theta = theta'': the yaw about y.
//
// The map M stores the first octant only (x, y, z >= 0) and is extended by symmetry:
//   sx = the sign of theta' (none for a zero: -0 reads as zero), k_theta = |theta'|; by
//   the top two bits of phi':
//     0: k = phi'        sy = 1, sz = 0       2: k = phi' - 2Q   sy = 0, sz = 1
//     1: k = 2Q - phi'   sy = 1, sz = 1       3: k = 4Q - phi'   sy = 0, sz = 0
//   so k = 0 .. Q. For k < Q the stored entry (l_phi, l_theta) = ENTRY[k_theta][k]:
//     D = (sin(k_theta d), cos(k_theta d) sin(k d), cos(k_theta d) cos(k d)),
//     l_phi = round(atan2(D_x, D_z) / d) in 0 .. Q, l_theta = min(round(asin(D_y) / d), Q - 1)
//   (d the grid step; the entries are computed in double precision once, and loaded into the
//   map memory, so rtl and golden read the same bits). k = Q (the z = 0 plane) needs no
//   look-up: (l_phi, l_theta) = (Q, min(Q - k_theta, Q - 1)). Then
//     phi'' = expand_phi(sx, sz, l_phi), theta'' = (sy, l_theta).
//   An entry is l_phi << (A - 2) | l_theta: 2A - 3 bits (15 for the 512 x 256 grid).
//
// Cache. The map memory holds (Q/4)^2 blocks of 4 x 4 entries, block
// b = (k_theta >> 2) (Q/4) + (k >> 2), entry (k_theta & 3) 4 + (k & 3) at bits 15 o .. of the
// block word (240 bits for A = 9). The memory buffer register (MBR) holds one block and its
// tag; it is empty after reset. A look-up whose block is in the MBR is a hit; otherwise a
// miss loads the block (the unit stalls for the memory's latency). k = Q bypasses the MBR
// and leaves it unchanged. Each result reports hit, miss or bypass, so the cache's behaviour
// is compared bit for bit too.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "deflect/sphere_grid.hpp"

namespace tmu::deflect {

constexpr int kBlockSide = 4;
constexpr int kBlockEntries = kBlockSide * kBlockSide;

enum class MapAccess : uint8_t { kHit = 0, kMiss = 1, kBypass = 2 };

int entry_bits(const SphereGrid& grid);

// The first-octant spherical-to-spherical map as the map memory holds it.
class S2sMap {
 public:
  explicit S2sMap(const SphereGrid& grid);
  const SphereGrid& grid() const { return grid_; }
  uint32_t entry(uint32_t k_theta, uint32_t k) const {
    return entries_[k_theta * grid_.quarter() + k];
  }
  uint32_t block_count() const { return blocks_per_row() * blocks_per_row(); }
  uint32_t blocks_per_row() const { return grid_.quarter() / kBlockSide; }
  std::array<uint32_t, kBlockEntries> block(uint32_t index) const;

 private:
  SphereGrid grid_;
  std::vector<uint32_t> entries_;  // Q x Q, row k_theta
};

// The octant reduction of (phi', theta').
struct MapAddress {
  bool sx = false, sy = false, sz = false;
  uint32_t k = 0, k_theta = 0;     // k = 0 .. Q, k_theta = 0 .. Q-1
  uint32_t block = 0, offset = 0;  // valid for k < Q
};
MapAddress map_address(const SphereGrid& grid, uint32_t phi_prime, uint32_t theta_prime);

// The look-up address of a request: the roll phi' = phi_D - theta_N, then the reduction.
MapAddress deflect_address(const SphereGrid& grid, SphereAngle normal, SphereAngle bump);

struct Deflected {
  SphereAngle normal;
  MapAccess access = MapAccess::kHit;
};

// The MBR and the deflection split where the map memory is, so that the golden unit (which
// runs the steps back to back) and the hls model (which waits for the memory between them)
// share every decision: access(a) tells whether block a.block must be filled first (kMiss);
// fill() loads it; deflected() is then the result, from the MBR's entry or the z = 0 column.
class MapBuffer {
 public:
  explicit MapBuffer(const SphereGrid& grid) : grid_(grid) {}
  MapAccess access(const MapAddress& a) const;
  void fill(uint32_t tag, const std::array<uint32_t, kBlockEntries>& block);
  SphereAngle deflected(SphereAngle normal, const MapAddress& a) const;
  void reset() { valid_ = false; }

 private:
  SphereGrid grid_;
  bool valid_ = false;
  uint32_t tag_ = 0;
  std::array<uint32_t, kBlockEntries> block_{};
};

// The unit with its MBR: results depend on the order of the requests.
class DeflectionUnit {
 public:
  explicit DeflectionUnit(const S2sMap& map) : map_(map), mbr_(map.grid()) {}
  Deflected deflect(SphereAngle normal, SphereAngle bump);
  void reset() { mbr_.reset(); }

 private:
  const S2sMap& map_;
  MapBuffer mbr_;
};

}  // namespace tmu::deflect
