// The cube environment map's addressing unit as a co-simulation block, `texsim cosim
// cube_address` (alias cube-map): a reflection vector to a face and a texel coordinate on it,
// dividing by the largest component (000 §7; golden/deflect/cube_map.hpp,
// rtl/deflect/tmu_cube_address.sv, hls/deflect/cube_address_sc.hpp).
//
// Channels (cube_address.json): in (x, y, z UnitComp SQ2.14, as the coordinate
// generator's uR, vR, wR, and face_log2 MipLog2: the face's side is 2^face_log2 texels, 0..10,
// a per-request configuration) gives one out (face CubeFace 0..5: +X, -X, +Y, -Y, +Z, -Z; u, v
// TexCoord SQ16.8) each. The dividers' seed table has the golden default's 7 index bits, the
// RTL's default SeedBits.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "blocks/cube_address/cube_address_ports.hpp"
#include "blocks/registry.hpp"
#include "harness/describe.hpp"
#include "harness/described_block.hpp"

TMU_DESCRIBE(cube_address)

namespace tmu::tb {

class CubeAddressBlock : public DescribedBlockOf<CubeAddressBlock> {
 public:
  explicit CubeAddressBlock(const BlockOptions& options = {});
  TMU_BLOCK_PIECES;

  static constexpr int kSeedBits = 7;  // the dividers' seed-table index bits (verilated)

 private:
  // cover() collects the seed-table indices seen so far (it sees every item in order).
  mutable size_t cover_next_ = 0;
  mutable std::set<uint32_t> seen_seed_;
};

// An item from the components' values and the face's log2 size; the renderer builds its items
// with it.
Txn cube_item(int32_t x, int32_t y, int32_t z, int face_log2);

// The major axis and the face coordinates of golden's rule (cube_map.hpp steps 1-2), for
// coverage and the tests: face 0..5, sc, tc and ma = |major|.
struct CubeFaceCoords {
  uint32_t face = 0;
  int32_t sc = 0, tc = 0, ma = 0;
};
CubeFaceCoords cube_face_coords(int32_t x, int32_t y, int32_t z);

}  // namespace tmu::tb
