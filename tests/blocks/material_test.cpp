// What is the material unit's own (002 §4.2; the conformance suite, tests/conformance_test.cpp,
// checks what every block shares): the load helper reproduces a register set and both tables,
// the worked example of rtl/perlin/tmu_material.sv's header through every engine, random items
// alone reach every material, and each configuration's rate, one sample per clock pipelined and
// one per 4 clocks shared, with the latency of the first sample.
#include <gtest/gtest.h>

#include <iostream>
#include <random>
#include <sstream>

#include "blocks/material/material_block.hpp"
#include "harness/cosim.hpp"
#include "perlin/material_unit.hpp"
#include "perlin/materials.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

using perlin::MaterialReg;
using perlin::MaterialRegs;
using D = desc::material;

MaterialBlock material_block(bool shared, uint64_t seed = 1) {
  BlockOptions o;
  o.seed = seed;
  o.fractal_shared = shared;
  return MaterialBlock(o);
}

bool is_sample(const Txn& t) { return t.f[0] == D::op_in; }

// material_load_items writes every register and entry: replayed into a MaterialUnit they give
// the same registers and tables (also registers whose mortars need the periods first).
TEST(MaterialTest, LoadItemsReproduceTheState) {
  std::mt19937_64 rng(4);
  for (int i = 0; i < 50; ++i) {
    MaterialRegs regs = random_material_regs(rng);
    if (i == 0) {  // mortars above the default periods' limits
      regs.pw = regs.ph = 20;
      regs.mortar_w = regs.mortar_h = 0xFFFF;
    }
    const perlin::ColourTables tables = random_colour_tables(rng);
    const std::vector<Txn> items = material_load_items(regs, tables);
    ASSERT_EQ(items.size(), 12u + 2 * perlin::kColourEntries);
    perlin::MaterialUnit unit;
    for (const Txn& t : items) {
      ASSERT_EQ(t.f[0], D::op_wr);
      if (t.f[D::wr_op] == 0) {
        unit.write_reg(static_cast<MaterialReg>(t.f[D::wr_reg]),
                       static_cast<uint32_t>(t.f[D::wr_value]));
      } else {
        unit.write_table(static_cast<uint32_t>(t.f[D::wr_table]),
                         static_cast<uint32_t>(t.f[D::wr_index]),
                         static_cast<uint32_t>(t.f[D::wr_rgb]));
      }
    }
    EXPECT_EQ(unit.regs(), regs);
    EXPECT_EQ(unit.tables().main, tables.main);
    EXPECT_EQ(unit.tables().mortar, tables.mortar);
  }
  // The helpers' masks: coordinates to SolidCoord, an index above 255 still ignored.
  const Txn s = material_sample_item(-1, (1 << 23) - 1, -(1 << 23));
  EXPECT_TRUE(is_sample(s));
  EXPECT_EQ(s.f[D::in_u], 0xFFFFFFu);
  EXPECT_EQ(s.f[D::in_v], 0x7FFFFFu);
  EXPECT_EQ(s.f[D::in_w], 0x800000u);
  EXPECT_EQ(material_table_item(3, 1000, 0x1FFFFFF).f[D::wr_index], 255u);
  EXPECT_EQ(material_table_item(3, 1000, 0x1FFFFFF).f[D::wr_table], 1u);
  EXPECT_EQ(material_table_item(3, 1000, 0x1FFFFFF).f[D::wr_rgb], 0xFFFFFFu);
  EXPECT_EQ(material_reg_item(MaterialReg::kGw, 0x12345).f[D::wr_value], 0x2345u);
}

// The worked example of tmu_material.sv's header through every engine: marble, g_t = 0,
// g_v = 1.0: v = 127.5 reads entry 127, v = 128.0 wraps to entry 0.
TEST(MaterialTest, HeaderExample) {
  MaterialRegs r;
  r.g_t = 0;
  r.g_v = 1 << 8;
  perlin::ColourTables tables;
  for (uint32_t i = 0; i < perlin::kColourEntries; ++i) tables.main[i] = 0x010203 * i;
  std::vector<Txn> items = material_load_items(r, tables);
  items.push_back(material_sample_item(0, 0x07F800, 0));
  items.push_back(material_sample_item(0, 0x080000, 0));
  for (const bool shared : {false, true}) {
    const MaterialBlock block = material_block(shared);
    testing::expect_outputs(block, items, D::out_rgb, {tables.main[127], tables.main[0]});
  }
}

// Random items alone (after the setup) reach every material, the kind switched between samples
// and the index wrap: a random run is more than one material's samples (golden only: what the
// items are, not whether the levels agree, which the conformance suite checks).
TEST(MaterialTest, RandomItemsAloneReachEveryMaterial) {
  CosimOptions o = testing::cosim_options(31, 30'000, {});
  o.directed = false;
  std::stringstream log;
  const CosimResult r = run_cosim(material_block(false, 31), o, log);
  ASSERT_TRUE(r.pass) << log.str();
  for (const char* name :
       {"marble", "wood", "brick: in a brick (brick table)", "brick: in a joint (mortar table)",
        "fog", "cloud: F > cutoff", "fire", "sample right after a kind change",
        "index >= 2^15 before mod (wraps)"}) {
    EXPECT_GT(r.coverage.at(name), 0u) << name;
  }
}

class MaterialRateTest : public ::testing::TestWithParam<bool> {};

// The throughput on simulated cycles, without bubbles or stalls: a load (268 writes, one per
// clock) and then samples only: pipelined one sample per clock (latency 13), shared one per 4
// clocks (latency 17), the hls model as the rtl; the outputs are golden's.
TEST_P(MaterialRateTest, CyclesPerSample) {
  const bool shared = GetParam();
  const MaterialBlock block = material_block(shared, 3);
  std::vector<Txn> items = block.setup_items();
  const size_t writes = items.size();
  std::mt19937_64 rng(3);
  size_t n = 0;
  for (const Txn& t : block.random_items(rng, 30'000)) {
    if (is_sample(t)) {
      items.push_back(t);
      ++n;
    }
  }
  const RunResult golden = block.engine("golden")->run(items, RunOptions{});
  ASSERT_EQ(golden.outputs.size(), n);
  for (const std::string level : {"rtl", "hls"}) {
    const RunResult r = block.engine(level)->run(items, RunOptions{});
    ASSERT_TRUE(r.error.empty()) << level << ": " << r.error;
    ASSERT_EQ(r.outputs, golden.outputs) << level;
    const double per_sample = static_cast<double>(r.cycles - writes) / static_cast<double>(n);
    if (level == "rtl") {  // the first sample, accepted in cycle `writes`, leaves its latency later
      EXPECT_EQ(r.output_cycles.at(0), writes + (shared ? 17 : 13)) << level;
    }
    std::cout << level << (shared ? " shared" : " pipelined") << ": " << r.cycles << " cycles, "
              << writes << " writes, " << n << " samples, " << per_sample << " cycles per sample\n";
    if (shared) {
      EXPECT_GE(r.cycles, writes + 4 * n - 3) << level;        // never faster than 4 clocks
      EXPECT_LE(r.cycles, writes + 4 * n + 17 + 16) << level;  // latency 17, drain 16
    } else {
      EXPECT_LE(r.cycles, writes + n + 13 + 16) << level;  // latency 13, drain 16
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Configurations, MaterialRateTest, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& param) {
                           return std::string(param.param ? "Shared" : "Pipelined");
                         });

}  // namespace
}  // namespace tmu::tb
