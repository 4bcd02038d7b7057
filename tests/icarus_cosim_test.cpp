// The same RTL under Icarus Verilog, a second simulator (tb/icarus, docs/harness.md "Icarus
// Verilog"): every block with an icarus engine against golden, bit for bit, under random
// back-pressure (a few thousand transactions each); the encoder and the coordinate generator
// at a variant's and at other widths (the RTL's parameters); the Icarus 11 compatibility
// rewrite rule by rule; and proof that the comparison has teeth: a mutated copy of the
// specular combine under Icarus must fail.
#include <gtest/gtest.h>

#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "blocks/registry.hpp"
#include "blocks/specular_combine/specular_combine_block.hpp"
#include "harness/cosim.hpp"
#include "icarus/icarus_engine.hpp"
#include "icarus/testbench.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

// The block's icarus engine, or why there is none.
std::string icarus_missing(const Block& block) {
  try {
    (void)block.engine("icarus");
    return "";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}

// Setup items (the CLUT load) and `count` random items, no directed ones (the specular
// combine's directed sweep alone is 65536 items), under the tests' usual 25 % stalls.
CosimResult run_icarus(const Block& block, size_t count, uint64_t seed, std::string& log,
                       const EngineFactory& override_engine = nullptr) {
  CosimOptions o = testing::cosim_options(seed, count, {"icarus"});
  o.directed = false;
  std::ostringstream out;
  CosimResult r = run_cosim(block, o, out, override_engine);
  log = out.str();
  return r;
}

struct Case {
  std::string name;  // of the test
  std::string block;
  size_t count;  // random items: Icarus runs the noise units at a few hundred a second
  BlockOptions options;
};
// The case's name in test listings (ctest shows it after the test's name).
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

BlockOptions shared_fractal() {
  BlockOptions o;
  o.fractal_shared = true;
  return o;
}

BlockOptions coord_tables(int phi_bits, int value_bits) {
  BlockOptions o;
  o.coord_tables = {deflect::SphereGrid{phi_bits}, value_bits};
  return o;
}

BlockOptions encoder(int seed_bits, int lut_exp, int lut_mant) {
  BlockOptions o;
  o.encoder.seed_bits = seed_bits;
  o.encoder.lut_exp = lut_exp;
  o.encoder.lut_mant = lut_mant;
  return o;
}

class IcarusCosimTest : public ::testing::TestWithParam<Case> {};

TEST_P(IcarusCosimTest, MatchesGoldenBitForBit) {
  const auto block = make_block(GetParam().block, GetParam().options);
  if (const std::string why = icarus_missing(*block); !why.empty()) {
    ASSERT_NE(why.find("iverilog not found"), std::string::npos) << why;
    GTEST_SKIP() << why;
  }
  std::string log;
  const CosimResult r = run_icarus(*block, GetParam().count, 7, log);
  EXPECT_TRUE(r.pass) << log;
  ASSERT_TRUE(r.runs.count("icarus"));
  const RunResult& run = r.runs.at("icarus");
  EXPECT_TRUE(run.error.empty()) << run.error;
  EXPECT_EQ(run.outputs.size(), r.transactions);
  EXPECT_GT(run.cycles, r.transactions);  // 25 % bubbles and stalls: more cycles than outputs
  EXPECT_GT(run.seconds, 0.0);
}

INSTANTIATE_TEST_SUITE_P(
    Blocks, IcarusCosimTest,
    ::testing::Values(Case{"specular_combine", "specular_combine", 3000, {}},
                      Case{"perlin", "perlin", 1000, {}},
                      Case{"turbulence_pipelined", "turbulence", 300, {}},
                      Case{"turbulence_shared", "turbulence", 300, shared_fractal()},
                      Case{"ccc_decoder", "ccc_decoder", 3000, {}},
                      Case{"normal_encoder", "normal-encoder", 2000, {}},
                      // a verilated variant's parameters, and widths that are not verilated:
                      // the RTL's parameters in the generated testbench
                      Case{"normal_encoder_e1m7", "normal_encoder", 1000, encoder(7, 1, 7)},
                      Case{"normal_encoder_8_3_6", "normal-encoder", 1000, encoder(8, 3, 6)},
                      Case{"coord_gen", "coord_gen", 2000, {}},
                      Case{"coord_gen_a7w8", "coord_gen", 1000, coord_tables(7, 8)},
                      Case{"coord_gen_a8w9", "coord-gen", 1000, coord_tables(8, 9)},
                      Case{"cube_address", "cube_address", 2000, {}},
                      // after the setup's 268 writes (registers and both tables)
                      Case{"material_pipelined", "material", 300, {}},
                      Case{"material_shared", "material", 300, shared_fractal()},
                      Case{"material_fire", "material_fire", 2000, {}}),
    [](const ::testing::TestParamInfo<Case>& test) { return test.param.name; });

// A variant's Verilog parameters reach the top through the generated testbench: the material
// unit's shared fractal unit (SharedFractal=1, the same top) takes 4 clocks a sample under
// Icarus as under Verilator. Its outputs equal the pipelined one's, so only the cycles show it.
TEST(IcarusCosimTest, VariantParametersReachTheTop) {
  const auto block = make_block("material", shared_fractal());
  if (const std::string why = icarus_missing(*block); !why.empty()) GTEST_SKIP() << why;
  CosimOptions o = testing::cosim_options(7, 100, {"rtl", "icarus"});
  o.directed = false;
  o.in_idle = 0.0;
  o.out_stall = 0.0;
  std::ostringstream log;
  const CosimResult r = run_cosim(*block, o, log);
  ASSERT_TRUE(r.pass) << log.str();
  EXPECT_EQ(r.runs.at("icarus").output_cycles, r.runs.at("rtl").output_cycles) << log.str();
  EXPECT_GT(r.runs.at("icarus").cycles, 268 + 3 * r.transactions) << log.str();
}

// The specular combine under Icarus as its icarus level runs it (the testbench generated from
// its ports), with one piece of text of its RTL replaced.
IcarusModel specular_combine_mutant(IcarusMutation mutation) {
  IcarusModel m{"specular_combine_tb", "tmu_specular_combine"};
  m.text = icarus_testbench(desc::specular_combine::table(), m.top, m.testbench);
  m.mutation = std::move(mutation);
  return m;
}

// The comparison has teeth: the specular combine's sum wraps instead of saturating at 255
// (rtl/blocks.cmake's mutant specular_combine/wrap, here in the Icarus copy).
TEST(IcarusMutantTest, SpecularCombineWrapIsCaught) {
  const SpecularCombineBlock block;
  if (const std::string why = icarus_missing(block); !why.empty()) GTEST_SKIP() << why;
  const IcarusModel mutant = specular_combine_mutant(
      {"texram/tmu_specular_combine.sv", "sum[ChW] ? '1 : sum[ChW-1:0]", "sum[ChW-1:0]"});
  std::string log;
  const CosimResult r =
      run_icarus(block, 2500, 7, log, [&](const std::string& level) -> std::unique_ptr<Engine> {
        if (level != "icarus") return nullptr;
        return make_icarus_engine("icarus", mutant, block.inputs(), block.outputs());
      });
  EXPECT_FALSE(r.pass);
  EXPECT_EQ(r.failing_engine, "icarus");
  ASSERT_TRUE(r.runs.count("icarus"));
  EXPECT_TRUE(r.runs.at("icarus").error.empty()) << r.runs.at("icarus").error;
  const size_t at = log.find("MISMATCH icarus");
  ASSERT_NE(at, std::string::npos) << log;
  std::cout << log.substr(at, 700) << "...\n";
}

// A mutation whose text is gone fails loudly rather than running the unmutated block.
TEST(IcarusMutantTest, StaleMutationIsAnError) {
  const SpecularCombineBlock block;
  if (const std::string why = icarus_missing(block); !why.empty()) GTEST_SKIP() << why;
  const IcarusModel mutant =
      specular_combine_mutant({"texram/tmu_specular_combine.sv", "no such text", "x"});
  const RunResult r =
      make_icarus_engine("icarus", mutant, block.inputs(), block.outputs())->run({}, {});
  EXPECT_NE(r.error.find("did not apply"), std::string::npos) << r.error;
}

// The Icarus 11 compatibility rewrite, rule by rule (icarus_engine.hpp).
TEST(IcarusCompatTest, RewritesOnlyWhatIcarus11Rejects) {
  // Rule 1: int unsigned parameters.
  EXPECT_EQ(icarus_compat_source("a.sv", "  parameter int unsigned A = 8,\n"),
            "  parameter bit [31:0] A = 8,\n");
  EXPECT_EQ(icarus_compat_source("a.sv", "  localparam int unsigned W = A + 1;\n"),
            "  localparam bit [31:0] W = A + 1;\n");
  EXPECT_EQ(icarus_compat_source("a.sv", "  int unsigned n;\n"), "  int unsigned n;\n");
  // Rule 2: an elaboration-time $error alone on its line.
  EXPECT_EQ(icarus_compat_source("a.sv", "  if (A < 1) begin : gen_check\n    $error(\"A\");\n"),
            "  if (A < 1) begin : gen_check\n    initial $error(\"A\");\n");
  EXPECT_EQ(icarus_compat_source("a.sv", "    else $error(\"A\");\n"), "    else $error(\"A\");\n");
  // Rule 3: the package's typedef ranges, and only the package's.
  const std::string pkg =
      "  localparam int unsigned FooW = 12;\n  typedef logic signed [FooW-1:0] foo_t;\n";
  EXPECT_EQ(icarus_compat_source("tmu_pkg.sv", pkg),
            "  localparam bit [31:0] FooW = 12;\n  typedef logic signed [12-1:0] foo_t;\n");
  EXPECT_EQ(icarus_compat_source("x/other.sv", pkg),
            "  localparam bit [31:0] FooW = 12;\n  typedef logic signed [FooW-1:0] foo_t;\n");
}

}  // namespace
}  // namespace tmu::tb
