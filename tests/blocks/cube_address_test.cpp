// What is the cube map addressing unit's own (000 §7; the conformance suite,
// tests/conformance_test.cpp, checks what every block shares): the hard cases with the
// expectations of golden/deflect/cube_map.hpp (edges and corners to the earlier axis, the axes
// and the zero vector to the face's centre) and the worked example of
// rtl/deflect/tmu_cube_address.sv's header through every engine, the coverage's face rule equal
// to golden's, and one vector per clock.
#include <gtest/gtest.h>

#include <random>
#include <sstream>

#include "blocks/cube_address/cube_address_block.hpp"
#include "deflect/cube_map.hpp"
#include "harness/cosim.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

using D = desc::cube_address;

struct Expected {
  int32_t x, y, z;
  int face_log2;
  uint32_t face;
  bool at_centre;  // u = v = the face's centre, 2^(L-1) texels
};

TEST(CubeAddressTest, HardCasesAsSpecified) {
  std::vector<Expected> cases;
  for (int l : {0, 1, 9, 10}) {
    for (uint32_t face = 0; face < 6; ++face) {  // each axis at full scale, either sign
      int32_t r[3] = {0, 0, 0};
      r[face / 2] = face % 2 ? -32768 : 32767;
      cases.push_back({r[0], r[1], r[2], l, face, true});
    }
    cases.push_back({0, 0, 0, l, 0, true});            // the zero vector: +X's centre
    cases.push_back({-5, 5, 0, l, 1, false});          // x-y edge: -X
    cases.push_back({0, -7, 7, l, 3, false});          // y-z edge: -Y
    cases.push_back({-9, 3, 9, l, 1, false});          // x-z edge: -X
    cases.push_back({-3, -3, -3, l, 1, false});        // corner: -X
    cases.push_back({32767, -32768, 0, l, 3, false});  // |-32768| is the larger
  }
  std::vector<Txn> items;
  for (const Expected& c : cases) items.push_back(cube_item(c.x, c.y, c.z, c.face_log2));
  // The header's example (L = 8): R = (16384, 8192, 0) -> +X, u = 32768, v = 16385.
  items.push_back(cube_item(16384, 8192, 0, 8));

  const CubeAddressBlock block;
  for (const std::string level : {"golden", "hls", "rtl"}) {
    const RunResult r = block.engine(level)->run(items, RunOptions{});
    ASSERT_TRUE(r.error.empty()) << level << ": " << r.error;
    ASSERT_EQ(r.outputs.size(), items.size()) << level;
    for (size_t i = 0; i < cases.size(); ++i) {
      const Expected& c = cases[i];
      const Txn& out = r.outputs[i];
      SCOPED_TRACE(::testing::Message()
                   << level << " (" << c.x << ", " << c.y << ", " << c.z << "), L " << c.face_log2);
      EXPECT_EQ(out.f[D::out_face], c.face);
      if (c.at_centre) {
        EXPECT_EQ(out.f[D::out_u], uint64_t{128} << c.face_log2);
        EXPECT_EQ(out.f[D::out_v], uint64_t{128} << c.face_log2);
      }
    }
    const Txn& example = r.outputs.back();
    EXPECT_EQ(example.f[D::out_face], 0u) << level;
    EXPECT_EQ(example.f[D::out_u], 32768u) << level;
    EXPECT_EQ(example.f[D::out_v], 16385u) << level;
  }
}

// The coverage counts faces through cube_face_coords: its face must be golden's, on the
// directed vectors and on random ones.
TEST(CubeAddressTest, FaceCoordsAreGoldens) {
  const CubeAddressBlock block;
  std::mt19937_64 rng(5);
  std::vector<Txn> items = block.directed_items();
  for (const Txn& t : block.random_items(rng, 20000)) items.push_back(t);
  for (const Txn& t : items) {
    const auto x = static_cast<int16_t>(t.f[D::in_x]), y = static_cast<int16_t>(t.f[D::in_y]),
               z = static_cast<int16_t>(t.f[D::in_z]);
    const auto l = static_cast<int>(t.f[D::in_face_log2]);
    ASSERT_EQ(cube_face_coords(x, y, z).face,
              deflect::cube_address(x, y, z, l, CubeAddressBlock::kSeedBits).face)
        << x << " " << y << " " << z;
  }
}

// One vector per clock: without bubbles or stalls the rtl takes the items, its latency (7
// cycles) and the harness's 16 drain cycles; the hls model keeps the same rate.
TEST(CubeAddressTest, OneVectorPerClock) {
  testing::expect_full_rate(CubeAddressBlock(), 20'000, {{"rtl", 7 + 16}, {"hls", 7 + 16}});
}

}  // namespace
}  // namespace tmu::tb
