// What is the coordinate generator's own (001 §5; the conformance suite checks what every
// block shares): the table memory the port loads evaluates as CoordTables, with the identity
// example of rtl/deflect/tmu_coord_gen.sv's header and the port's rules; one item per clock;
// tables no variant verilates through hls, without an rtl level.
#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "blocks/coord_gen/coord_gen_block.hpp"
#include "deflect/coord_table_memory.hpp"
#include "harness/cosim.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

using deflect::CoordTableMemory;
using deflect::CoordTables;
using deflect::TableConfig;
using deflect::ViewFrame;

// The memory the port loads from CoordTables::writes() evaluates every normal of the grid as
// CoordTables::eval does (eval_coords is the specification's arithmetic, shared), on the
// identity view and on random frames; the identity example of rtl/deflect/tmu_coord_gen.sv.
TEST(CoordGenTest, PortLoadedTablesEvaluateAsCoordTables) {
  const TableConfig config;
  std::mt19937_64 rng(77);
  std::vector<ViewFrame> frames = {ViewFrame{}};
  for (int i = 0; i < 3; ++i) frames.push_back(random_view_frame(rng));
  for (const ViewFrame& f : frames) {
    const CoordTables tables(config, f);
    CoordTableMemory memory(config);
    memory.load(tables);
    for (uint32_t phi = 0; phi < config.grid.phi_count(); ++phi) {
      for (uint32_t theta = 0; theta < 2 * config.grid.quarter(); ++theta) {
        const deflect::MapCoords a = tables.eval({phi, theta}), b = memory.eval({phi, theta});
        ASSERT_TRUE(a.un == b.un && a.vn == b.vn && a.ur == b.ur && a.vr == b.vr && a.wr == b.wr)
            << "phi " << phi << " theta " << theta;
      }
    }
  }
  CoordTableMemory identity(config);
  identity.load(CoordTables(config, ViewFrame{}));
  const deflect::MapCoords c = identity.eval({0, 0});
  EXPECT_EQ(c.un, 0);
  EXPECT_EQ(c.vn, 0);
  EXPECT_EQ(c.ur, 0);
  EXPECT_EQ(c.wr, 16129);
  // The port's rules: -2^(W-1) stored as the limit, writes beyond a table ignored.
  EXPECT_TRUE(identity.write({deflect::kF2, 5, -512}));
  EXPECT_EQ(identity.entry(deflect::kF2, 5), -511);
  EXPECT_FALSE(identity.write({deflect::kF3, 128, 1}));
  EXPECT_FALSE(identity.write({7, 0, 1}));
}

// One item per clock, writes and requests alike: no stalls, the pipeline's three registers
// and the harness's 16 drain cycles on top.
TEST(CoordGenTest, OneItemPerClock) {
  BlockOptions b;
  b.seed = 3;
  testing::expect_full_rate(CoordGenBlock(b), 20'000, {{"rtl", 3 + 16 + 1}, {"hls", 20}});
}

// A grid and width no variant verilates (A = 8, W = 9): golden = hls on the directed and
// random items, every case hit; the block has no rtl level there (icarus instead), and asking
// for one names the levels there are.
TEST(CoordGenTest, UnverilatedTablesRunOnHlsOnly) {
  BlockOptions b;
  b.coord_tables = TableConfig{deflect::SphereGrid{8}, 9};
  const CoordGenBlock block(b);
  EXPECT_EQ(block.repro_options(), "--coord-tables 8,9");
  std::stringstream log;
  const CosimResult r = run_cosim(block, testing::cosim_options(5, 20'000, {"hls"}), log);
  EXPECT_TRUE(r.pass) << log.str();
  for (const auto& [name, n] : r.coverage) EXPECT_GT(n, 0u) << "not hit: " << name;
  EXPECT_EQ(block.levels(), (std::vector<std::string>{"golden", "hls", "icarus"}));
  try {
    (void)block.engine("rtl");
    FAIL() << "an rtl engine for tables that are not verilated";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no engine 'rtl' (levels: golden, hls, icarus)"), std::string::npos)
        << what;
  }
  b.coord_tables.value_bits = 11;  // the port carries 10 bits
  EXPECT_THROW(CoordGenBlock{b}, std::invalid_argument);
}

}  // namespace
}  // namespace tmu::tb
