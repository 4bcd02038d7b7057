// The cube environment map's addressing unit as a co-simulation block (`texsim cosim
// cube-map`): a reflection vector to a face and a texel coordinate on it (000 §7;
// golden/deflect/cube_map.hpp).
//
// Input items: x, y, z (UnitComp SQ2.14, as the coordinate generator's uR, vR, wR) and
// face_log2 (MipLog2: the face's side is 2^face_log2 texels, 0..10; a per-request
// configuration). Output: face (CubeFace, 0..5: +X, -X, +Y, -Y, +Z, -Z) and u, v (TexCoord
// SQ16.8). The dividers' seed table has the golden default's 7 index bits, as the Verilated
// model.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "blocks/registry.hpp"
#include "formats/formats.hpp"
#include "harness/block.hpp"
#include "harness/rtl_runner.hpp"

namespace tmu::tb {

enum CubeMapField { kCubeX, kCubeY, kCubeZ, kCubeLog2 };
enum CubeMapOutField { kCubeFace, kCubeU, kCubeV };

class CubeMapBlock : public Block {
 public:
  explicit CubeMapBlock(const BlockOptions& options);

  std::string name() const override { return "cube-map"; }
  const Schema& inputs() const override;
  const Schema& outputs() const override;
  bool produces_output(const Txn&) const override { return true; }
  std::vector<Txn> directed_items() const override;
  std::vector<Txn> random_items(std::mt19937_64& rng, size_t count) const override;
  std::unique_ptr<Engine> engine(const std::string& level) const override;
  std::vector<std::string> coverage_cases() const override;
  void cover(const std::vector<Txn>& items, size_t index, const Txn& output,
             Coverage& coverage) const override;
  std::vector<Port> ports() const override;

  static constexpr int kSeedBits = 7;  // the dividers' seed-table index bits (verilated)

 private:
  // cover() collects the seed-table indices seen so far (it sees every item in order).
  mutable size_t cover_next_ = 0;
  mutable std::set<uint32_t> seen_seed_;
};

// An item from the components' values and the face's log2 size.
Txn cube_item(int32_t x, int32_t y, int32_t z, int face_log2);
int16_t cube_x(const Txn& item);
int16_t cube_y(const Txn& item);
int16_t cube_z(const Txn& item);
int cube_face_log2(const Txn& item);

// The major axis and the face coordinates of golden's rule (cube_map.hpp steps 1-2), for
// coverage and the tests: face 0..5, sc, tc and ma = |major|.
struct CubeFaceCoords {
  uint32_t face = 0;
  int32_t sc = 0, tc = 0, ma = 0;
};
CubeFaceCoords cube_face_coords(int32_t x, int32_t y, int32_t z);

// The divider's seed-table index for the major component (golden divide_ratio's i for
// den = ma; 0 for ma = 0).
uint32_t cube_seed_index(uint32_t ma, int seed_bits);

// The rtl engine for any Verilated model with the unit's ports (tests use mutants).
template <class Model>
std::unique_ptr<Engine> make_cube_map_rtl_engine(const std::string& name);

}  // namespace tmu::tb

#include "blocks/cube_map_rtl.inl"
