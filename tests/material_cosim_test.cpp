// The material unit (002 §4.2; golden/perlin/material_unit.hpp): golden vs hls vs rtl, bit for
// bit, in both fractal configurations (pipelined, shared), on the block's directed hard cases
// (every material with the kind switched mid-stream, the index wrap, fire's table edges and
// clamps, brick joints and the half-brick shift, the gases' cut-off and levels, saturating
// register writes, table writes read at once, the SolidCoord extremes) and random items under
// back-pressure; the X-initial check; the throughput on simulated cycles; fire's e^-v table
// built in integers by the RTL against golden's double exp() for all 512 entries; the item
// helpers the renderer uses; and proof that the comparison has teeth (RTL mutants: the brick's
// half-period shift on the odd rows, fire's index wrapping instead of saturating).
#include <Vtmu_material_fire.h>
#include <Vtmu_material_mutant_brick.h>
#include <Vtmu_material_mutant_fire.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <sstream>

#include "blocks/material_block.hpp"
#include "harness/cosim.hpp"
#include "perlin/material_unit.hpp"
#include "perlin/materials.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

constexpr auto options = testing::cosim_options;
using perlin::MaterialKind;
using perlin::MaterialReg;
using perlin::MaterialRegs;

MaterialBlock material_block(bool shared, uint64_t seed = 1) {
  BlockOptions o;
  o.seed = seed;
  o.fractal_shared = shared;
  return MaterialBlock(o);
}

void expect_every_case_hit(const CosimResult& r) {
  for (const auto& [name, n] : r.coverage) EXPECT_GT(n, 0u) << "coverage case not hit: " << name;
}

// --- the spec's pieces --------------------------------------------------------------------

// Fire's e^-v table: the RTL builds it at elaboration in integers
// (rtl/perlin/tmu_material_fire.sv), golden with double exp(). Every one of the 512 entries read
// from the Verilated table equals fire_entry(k).
TEST(MaterialBlockTest, FireTableOfTheRtlIsGoldens) {
  VerilatedContext ctx;
  Vtmu_material_fire table(&ctx, "TOP");
  for (uint32_t k = 0; k < perlin::kFireTableEntries; ++k) {
    table.k_i = static_cast<uint16_t>(k);
    table.eval();
    ASSERT_EQ(table.entry_o, perlin::fire_entry(k)) << "entry " << k;
  }
  table.final();
}

// The same construction in C++ (the RTL's constant function, step by step) gives golden's
// entries, and every exact value lies at least 0.001 from a rounding tie: the margin the
// integer evaluation's error (below 2^-26 at 48 fraction bits) cannot cross.
TEST(MaterialBlockTest, FireTableIntegerConstruction) {
  __extension__ typedef unsigned __int128 u128;
  constexpr int kP = 48;
  u128 term = u128{1} << kP, e1 = 0;
  for (int n = 0; n < 12; ++n) {
    e1 = n % 2 == 0 ? e1 + term : e1 - term;
    term /= static_cast<u128>(32 * (n + 1));
  }
  u128 acc = u128{1} << kP;
  const u128 half = u128{1} << (kP - 1);
  for (uint32_t k = 0; k < perlin::kFireTableEntries; ++k) {
    const auto entry = static_cast<uint32_t>(((acc << 12) + half) >> kP);
    ASSERT_EQ(entry, perlin::fire_entry(k)) << "entry " << k;
    const double exact = std::exp(-static_cast<double>(k) / 32.0) * 4096.0;
    EXPECT_GT(std::abs(exact - std::floor(exact) - 0.5), 0.001) << "entry " << k;
    acc = (acc * e1 + half) >> kP;
  }
}

// material_load_items writes every register and entry: replayed into a MaterialUnit they give
// the same registers and tables (also registers whose mortars need the periods first).
TEST(MaterialBlockTest, LoadItemsReproduceTheState) {
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
      ASSERT_FALSE(is_material_sample(t));
      if (t.f[kMatOp] == kMatOpReg) {
        unit.write_reg(static_cast<MaterialReg>(t.f[kMatReg]),
                       static_cast<uint32_t>(t.f[kMatValue]));
      } else {
        unit.write_table(static_cast<uint32_t>(t.f[kMatTable]),
                         static_cast<uint32_t>(t.f[kMatIndex]),
                         static_cast<uint32_t>(t.f[kMatRgb]));
      }
    }
    EXPECT_EQ(unit.regs(), regs);
    EXPECT_EQ(unit.tables().main, tables.main);
    EXPECT_EQ(unit.tables().mortar, tables.mortar);
  }
  // The helpers' masks: coordinates to SolidCoord, an index above 255 still ignored.
  const Txn s = material_sample_item(-1, (1 << 23) - 1, -(1 << 23));
  EXPECT_TRUE(is_material_sample(s));
  EXPECT_EQ(material_coords(s), (std::array<int32_t, 3>{-1, (1 << 23) - 1, -(1 << 23)}));
  EXPECT_EQ(material_table_item(3, 1000, 0x1FFFFFF).f[kMatIndex], 255u);
  EXPECT_EQ(material_table_item(3, 1000, 0x1FFFFFF).f[kMatTable], 1u);
  EXPECT_EQ(material_reg_item(MaterialReg::kGw, 0x12345).f[kMatValue], 0x2345u);
}

// The directed items alone hit every coverage case (in both configurations: the same items).
TEST(MaterialBlockTest, DirectedItemsHitEveryCase) {
  CosimOptions o = options(1, 0, {});
  std::stringstream log;
  const CosimResult r = run_cosim(material_block(false), o, log);
  EXPECT_TRUE(r.pass) << log.str();
  expect_every_case_hit(r);
  std::cout << log.str().substr(log.str().find("coverage:"));
}

// The worked example of tmu_material.sv's header through every engine: marble, g_t = 0,
// g_v = 1.0: v = 127.5 reads entry 127, v = 128.0 wraps to entry 0.
TEST(MaterialBlockTest, HeaderExample) {
  std::vector<Txn> items;
  MaterialRegs r;
  r.g_t = 0;
  r.g_v = 1 << 8;
  perlin::ColourTables tables;
  for (uint32_t i = 0; i < perlin::kColourEntries; ++i) tables.main[i] = 0x010203 * i;
  items = material_load_items(r, tables);
  items.push_back(material_sample_item(0, 0x07F800, 0));
  items.push_back(material_sample_item(0, 0x080000, 0));
  for (const bool shared : {false, true}) {
    const MaterialBlock block = material_block(shared);
    for (const std::string level : {"golden", "hls", "rtl"}) {
      const RunResult res = block.engine(level)->run(items, RunOptions{});
      ASSERT_TRUE(res.error.empty()) << level << ": " << res.error;
      ASSERT_EQ(res.outputs.size(), 2u) << level;
      EXPECT_EQ(res.outputs[0].f[kMatOutRgb], tables.main[127]) << level;
      EXPECT_EQ(res.outputs[1].f[kMatOutRgb], tables.main[0]) << level;
    }
  }
}

// --- both configurations ------------------------------------------------------------------

class MaterialCosimTest : public ::testing::TestWithParam<bool> {};

// The directed cases and random items through the rtl (twice, for the X check) and 20000
// through the hls model, under back-pressure; every case hit.
TEST_P(MaterialCosimTest, GoldenVsHlsVsRtl) {
  const bool shared = GetParam();
  const MaterialBlock block = material_block(shared, 20260101);
  {
    std::stringstream log;
    const CosimResult r =
        run_cosim(block, options(20260101, shared ? 50'000 : 200'000, {"rtl"}), log);
    EXPECT_TRUE(r.pass) << log.str();
    expect_every_case_hit(r);
    std::cout << log.str().substr(0, log.str().find("coverage:"));
  }
  std::stringstream log;
  const CosimResult r =
      run_cosim(material_block(shared, 17), options(17, 20'000, {"hls", "rtl"}), log);
  EXPECT_TRUE(r.pass) << log.str();
  expect_every_case_hit(r);
}

// Random items alone (after the setup): every material and the random writes between samples.
TEST_P(MaterialCosimTest, RandomItemsAlone) {
  CosimOptions o = options(31, 30'000, {"hls", "rtl"});
  o.directed = false;
  std::stringstream log;
  const CosimResult r = run_cosim(material_block(GetParam(), 31), o, log);
  EXPECT_TRUE(r.pass) << log.str();
  for (const char* name :
       {"marble", "wood", "brick: in a brick (brick table)", "brick: in a joint (mortar table)",
        "fog", "cloud: F > cutoff", "fire", "sample right after a kind change",
        "index >= 2^15 before mod (wraps)"}) {
    EXPECT_GT(r.coverage.at(name), 0u) << name;
  }
}

TEST_P(MaterialCosimTest, HeavyBackPressure) {
  CosimOptions o = options(7, 10'000, {"hls", "rtl"});
  o.in_idle = 0.6;
  o.out_stall = 0.6;
  std::stringstream log;
  EXPECT_TRUE(run_cosim(material_block(GetParam(), 7), o, log).pass) << log.str();
}

// The output never ready for long stretches: the pipeline and the FIFO beside the fractal unit
// hold, drop nothing, and writes wait for the samples before them.
TEST_P(MaterialCosimTest, OutputMostlyStalled) {
  CosimOptions o = options(8, 3'000, {"hls", "rtl"});
  o.in_idle = 0.0;
  o.out_stall = 0.95;
  std::stringstream log;
  EXPECT_TRUE(run_cosim(material_block(GetParam(), 8), o, log).pass) << log.str();
}

// X: the rtl run repeated with other random initial values of every flop gives the same
// outputs on the same cycles (the registers reset, the tables are loaded by the setup, the
// data registers and the FIFO are read only while valid).
TEST_P(MaterialCosimTest, RandomInitialValuesDoNotLeak) {
  CosimOptions o = options(11, 10'000, {"rtl"});
  ASSERT_TRUE(o.x_check);
  std::stringstream log;
  const CosimResult r = run_cosim(material_block(GetParam(), 11), o, log);
  EXPECT_TRUE(r.pass) << log.str();
  EXPECT_NE(log.str().find("x-check  rtl with random initial values"), std::string::npos)
      << log.str();
  EXPECT_NE(log.str().find(": identical"), std::string::npos) << log.str();
}

// The throughput on simulated cycles, without bubbles or stalls: a load (268 writes, one per
// clock) and then samples only: pipelined one sample per clock (latency 13), shared one per 4
// clocks (latency 17), the hls model as the rtl; the outputs are golden's.
TEST_P(MaterialCosimTest, CyclesPerSample) {
  const bool shared = GetParam();
  const MaterialBlock block = material_block(shared, 3);
  std::vector<Txn> items = block.setup_items();
  const size_t writes = items.size();
  std::mt19937_64 rng(3);
  size_t n = 0;
  for (const Txn& t : block.random_items(rng, 30'000)) {
    if (is_material_sample(t)) {
      items.push_back(t);
      ++n;
    }
  }
  const RunResult golden = block.engine("golden")->run(items, RunOptions{});
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

INSTANTIATE_TEST_SUITE_P(Configurations, MaterialCosimTest, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& param) {
                           return std::string(param.param ? "Shared" : "Pipelined");
                         });

// --- teeth ---------------------------------------------------------------------------------

template <class Model>
CosimResult run_mutant(uint64_t seed, size_t count, bool directed, std::stringstream& log) {
  CosimOptions o = options(seed, count, {"rtl"});
  o.directed = directed;
  o.x_check = false;
  return run_cosim(material_block(false, seed), o, log,
                   [](const std::string& level) -> std::unique_ptr<Engine> {
                     if (level != "rtl") return nullptr;
                     return make_material_rtl_engine<Model>("rtl");
                   });
}

// The half-period shift on the odd rows instead of the even ones: the directed brick rows
// catch it.
TEST(MaterialMutantTest, BrickShiftMutantIsCaughtWithAWaveform) {
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_material_mutant_brick>(9, 0, true, log);
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim material --seed 9");
}

// Fire's index wraps mod 2^15 instead of saturating: the directed offsets +-2^15 catch it.
TEST(MaterialMutantTest, FireClampMutantIsCaughtWithAWaveform) {
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_material_mutant_fire>(9, 0, true, log);
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim material --seed 9");
}

// ... and random items alone catch both too.
TEST(MaterialMutantTest, MutantsAreCaughtByRandomItemsAlone) {
  {
    std::stringstream log;
    EXPECT_FALSE((run_mutant<Vtmu_material_mutant_brick>(5, 30'000, false, log).pass));
    EXPECT_NE(log.str().find("MISMATCH rtl vs golden"), std::string::npos) << log.str();
  }
  std::stringstream log;
  EXPECT_FALSE((run_mutant<Vtmu_material_mutant_fire>(5, 30'000, false, log).pass));
  EXPECT_NE(log.str().find("MISMATCH rtl vs golden"), std::string::npos) << log.str();
}

TEST(MaterialMutantTest, InjectedFaultFailsTheRun) {
  for (const bool shared : {false, true}) {
    CosimOptions o = options(5, 1000, {"hls", "rtl"});
    o.directed = false;
    o.inject_fault = 500;
    std::stringstream log;
    const CosimResult r = run_cosim(material_block(shared, 5), o, log);
    EXPECT_FALSE(r.pass);
    EXPECT_NE(log.str().find("first at transaction 500"), std::string::npos) << log.str();
  }
}

}  // namespace
}  // namespace tmu::tb
