// The TEXRAM trilinear unit: golden vs hls vs rtl, bit for bit, memory counters included, over
// every texel configuration x filter x border mode, on non-square, one-texel and 1024 x 1024
// textures; its throughput on page hits; and proof that the comparison has teeth (RTL
// mutants: a wrong border operator, a wrong rounding constant, extra bank reads).
#include <Vtmu_trilinear.h>
#include <Vtmu_trilinear_mutant_mirror.h>
#include <Vtmu_trilinear_mutant_reads.h>
#include <Vtmu_trilinear_mutant_round.h>
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <iostream>
#include <set>
#include <sstream>

#include "blocks/trilinear_block.hpp"
#include "harness/cosim.hpp"
#include "harness/vector_file.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

namespace fs = std::filesystem;
using texram::Border;
using texram::Combine;
using texram::Filter;
using texram::TexelKind;

fs::path temp_dir() { return testing::temp_dir("tmu_trilinear_cosim_test"); }
constexpr auto options = testing::cosim_options;
constexpr int32_t kOne = 256;

constexpr std::array<TexelKind, 5> kKinds = {TexelKind::kLuminance, TexelKind::kIndex,
                                             TexelKind::kTrueColour, TexelKind::kSingle,
                                             TexelKind::kCcc};
constexpr std::array<Filter, 3> kFilters = {Filter::kNearest, Filter::kBilinear,
                                            Filter::kTrilinear};
constexpr std::array<Border, 4> kBorders = {Border::kWrap, Border::kClamp, Border::kBorder,
                                            Border::kMirror};
constexpr std::array<Combine, 3> kCombines = {Combine::kOne, Combine::kConstant, Combine::kShade};

uint64_t counter(const RunResult& r, const std::string& name) {
  const auto v = counter_value(r.counters, name);
  if (!v) ADD_FAILURE() << "no counter " << name;
  return v.value_or(0);
}

std::string counters_text(const RunResult& r) {
  return "accesses " + std::to_string(counter(r, "accesses")) + ", bank reads " +
         std::to_string(counter(r, "bank_reads")) + ", page faults " +
         std::to_string(counter(r, "page_faults"));
}

// Runs golden vs the engines over setup, directed and `count` random items.
CosimResult cosim(const TrilinearBlock& block, uint64_t seed, size_t count,
                  std::vector<std::string> engines = {"hls", "rtl"}) {
  std::stringstream log;
  const CosimResult r = run_cosim(block, options(seed, count, std::move(engines)), log);
  EXPECT_TRUE(r.pass) << block.describe() << "\n" << log.str();
  return r;
}

// --- every configuration -------------------------------------------------------------------

// Every kind x filter x border of u, with the border of v, the combine and the texture (size
// and content) varying from run to run; the union of the coverage over all of them must hit
// every case. 60 runs of 2000 random items (and the directed ones) under the default
// back-pressure (in-idle 0.25, out-stall 0.25).
TEST(TrilinearCosimTest, EveryKindFilterAndBorder) {
  Coverage all;
  std::set<std::string> sizes;
  uint64_t seed = 100;
  for (size_t k = 0; k < kKinds.size(); ++k) {
    for (size_t f = 0; f < kFilters.size(); ++f) {
      for (size_t b = 0; b < kBorders.size(); ++b) {
        ++seed;
        BlockOptions o;
        o.seed = seed;
        o.tri_kind = kKinds[k];
        o.tri_filter = kFilters[f];
        o.tri_border_u = kBorders[b];
        o.tri_border_v = kBorders[(b + k + f) % kBorders.size()];
        o.tri_combine = kCombines[seed % kCombines.size()];
        o.tri_log2_w = static_cast<int>(seed % 7);  // 1 .. 64 texels, never the same shape
        o.tri_log2_h = static_cast<int>((seed / 7) % 7);
        const TrilinearBlock block(o);
        SCOPED_TRACE(block.describe());
        const CosimResult r = cosim(block, seed, 2000);
        for (const auto& [name, n] : r.coverage) all[name] += n;
        sizes.insert(std::to_string(*o.tri_log2_w) + "x" + std::to_string(*o.tri_log2_h));
      }
    }
  }
  for (TexelKind k : kKinds) EXPECT_GT(all["kind " + std::string(name(k))], 0u);
  for (Filter f : kFilters) EXPECT_GT(all["filter " + std::string(name(f))], 0u);
  for (Border b : kBorders) {
    EXPECT_GT(all["border u " + std::string(name(b))], 0u);
    EXPECT_GT(all["border v " + std::string(name(b))], 0u);
  }
  for (Combine c : kCombines) EXPECT_GT(all["combine " + std::string(name(c))], 0u);
  for (const auto& [name, n] : all) EXPECT_GT(n, 0u) << "coverage case not hit: " << name;
  std::cout << "60 configurations, " << sizes.size() << " texture shapes; coverage over all:\n";
  for (const auto& [name, n] : all) {
    if (name.rfind("texture ", 0) != 0) std::cout << "  " << name << ": " << n << "\n";
  }
}

// The directed corner cases alone (lambda at and beyond both ends, the port's extremes, far
// outside, texel centres and edges, fractions 0 and max, level weights 0, half and max) in
// every border mode of both axes, on a non-square texture, trilinear and nearest.
TEST(TrilinearCosimTest, DirectedCornersInEveryBorderMode) {
  for (Border bu : kBorders) {
    for (Border bv : kBorders) {
      BlockOptions o;
      o.seed = 7;
      o.tri_kind = TexelKind::kTrueColour;
      o.tri_filter = bu == bv ? Filter::kNearest : Filter::kTrilinear;
      o.tri_border_u = bu;
      o.tri_border_v = bv;
      o.tri_log2_w = 5;
      o.tri_log2_h = 2;
      const TrilinearBlock block(o);
      SCOPED_TRACE(block.describe());
      cosim(block, 7, 0);
    }
  }
}

// --- sizes ---------------------------------------------------------------------------------

// One texel, one row, one column, and flat non-square textures, in every kind.
TEST(TrilinearCosimTest, OneTexelAndNonSquareTextures) {
  const std::array<std::pair<int, int>, 6> shapes = {
      {{0, 0}, {8, 0}, {0, 8}, {6, 1}, {1, 5}, {3, 7}}};
  uint64_t seed = 300;
  for (const auto& [lw, lh] : shapes) {
    for (TexelKind kind : kKinds) {
      BlockOptions o;
      o.seed = ++seed;
      o.tri_kind = kind;
      o.tri_filter = kFilters[seed % 3];
      o.tri_log2_w = lw;
      o.tri_log2_h = lh;
      const TrilinearBlock block(o);
      SCOPED_TRACE(block.describe());
      cosim(block, seed, 1000);
    }
  }
}

// The largest texture the TEXRAM holds (000 §5: 1024 x 1024), fewer samples: a smooth field
// in true colour (4 planes) and luminance, trilinear.
TEST(TrilinearCosimTest, Texture1024x1024) {
  for (TexelKind kind : {TexelKind::kTrueColour, TexelKind::kLuminance}) {
    BlockOptions o;
    o.seed = 41;
    o.tri_kind = kind;
    o.tri_filter = Filter::kTrilinear;
    o.tri_border_u = Border::kMirror;
    o.tri_border_v = Border::kWrap;
    o.tri_log2_w = 10;
    o.tri_log2_h = 10;
    o.tri_pattern = "smooth";
    const TrilinearBlock block(o);
    SCOPED_TRACE(block.describe());
    const CosimResult r = cosim(block, 41, 3000);
    std::cout << block.describe() << ": " << counters_text(r.runs.at("golden")) << "\n";
  }
}

// --- throughput ----------------------------------------------------------------------------

// The cycles of `samples` rasterized spans on a texture: rows of u steps of a quarter texel
// at a fixed v and lambda, no stalls.
struct Throughput {
  size_t samples = 0;
  uint64_t cycles = 0;
  uint64_t slow_accesses = 0;
};

Throughput span_throughput(TexelKind kind, Filter filter, int32_t lambda) {
  BlockOptions o;
  o.seed = 5;
  o.tri_kind = kind;
  o.tri_filter = filter;
  o.tri_log2_w = 8;
  o.tri_log2_h = 8;
  o.tri_pattern = "smooth";
  const TrilinearBlock block(o);
  std::vector<Txn> items = block.setup_items();
  size_t samples = 0;
  for (int32_t row = 0; row < 16; ++row) {
    for (int32_t i = 0; i < 250; ++i, ++samples) {
      items.push_back(trilinear_sample_item(8 * kOne + i * kOne / 4, (20 + 7 * row) * kOne + 77,
                                            lambda, 0x80808080u));
    }
  }
  const fs::path file = temp_dir() / "span.csv";
  write_vectors(file.string(), block.inputs(), items);
  CosimOptions c = options(5, 0, {"hls", "rtl"});
  c.vectors_in = file.string();
  c.in_idle = 0.0;
  c.out_stall = 0.0;
  std::stringstream log;
  const CosimResult r = run_cosim(block, c, log);
  EXPECT_TRUE(r.pass) << log.str();
  return {samples, r.runs.at("rtl").cycles, counter(r.runs.at("golden"), "slow_accesses")};
}

// 1-plane textures: one sample per clock when every access hits; each fault adds a clock.
// 4-plane textures: four accesses, four clocks per sample.
TEST(TrilinearCosimTest, OneSamplePerClockOnPageHits) {
  // 256 CLUT writes (one per clock), the pipeline's latency and the 16 drain cycles.
  constexpr uint64_t kOverhead = 256 + 12 + 16;
  for (Filter filter : {Filter::kBilinear, Filter::kTrilinear}) {
    const Throughput t = span_throughput(TexelKind::kLuminance, filter, kOne / 2);
    const double per_clock =
        static_cast<double>(t.samples) / static_cast<double>(t.cycles - kOverhead);
    std::cout << "luminance " << name(filter) << ": " << t.samples << " samples, " << t.cycles
              << " cycles, " << t.slow_accesses << " slow accesses: " << per_clock
              << " samples per clock ("
              << static_cast<double>(t.samples) /
                     static_cast<double>(t.cycles - kOverhead - t.slow_accesses)
              << " without the faults' extra periods)\n";
    EXPECT_LE(t.cycles, kOverhead + t.samples + t.slow_accesses + 2);
    EXPECT_GE(per_clock, 0.95);
  }
  const Throughput t = span_throughput(TexelKind::kTrueColour, Filter::kTrilinear, kOne / 2);
  std::cout << "rgba trilinear: " << t.samples << " samples, " << t.cycles << " cycles, "
            << t.slow_accesses << " slow accesses\n";
  EXPECT_LE(t.cycles, kOverhead + 4 * t.samples + t.slow_accesses + 2);
}

// --- teeth ---------------------------------------------------------------------------------

template <class Model>
CosimResult run_mutant(const TrilinearBlock& block, uint64_t seed, size_t count,
                       std::stringstream& log) {
  CosimOptions o = options(seed, count, {"rtl"});
  o.x_check = false;
  return run_cosim(block, o, log, [&block](const std::string& level) -> std::unique_ptr<Engine> {
    if (level != "rtl") return nullptr;
    return make_trilinear_rtl_engine<Model>("rtl", block.env());
  });
}

TrilinearBlock mutant_block(TexelKind kind, Filter filter, Border border) {
  BlockOptions o;
  o.seed = 9;
  o.tri_kind = kind;
  o.tri_filter = filter;
  o.tri_border_u = o.tri_border_v = border;
  o.tri_log2_w = 5;
  o.tri_log2_h = 4;
  return TrilinearBlock(o);
}

// Mirror acts as wrap: wrong colours (and wrong cells) once a tap crosses an edge.
TEST(TrilinearCosimTest, MirrorMutantIsCaughtWithAWaveform) {
  const TrilinearBlock block =
      mutant_block(TexelKind::kLuminance, Filter::kBilinear, Border::kMirror);
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_trilinear_mutant_mirror>(block, 9, 1000, log);
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim trilinear --seed 9");
}

// The blend adds a quarter instead of half an LSB before its one rounding.
TEST(TrilinearCosimTest, RoundingMutantIsCaught) {
  const TrilinearBlock block =
      mutant_block(TexelKind::kTrueColour, Filter::kTrilinear, Border::kWrap);
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_trilinear_mutant_round>(block, 9, 1000, log);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("MISMATCH rtl vs golden"), std::string::npos) << log.str();
}

// Nearest reads the banks of all four taps: every colour right (the extra taps weigh
// nothing), but the memory's counters show the extra reads.
TEST(TrilinearCosimTest, ExtraReadsMutantIsCaughtByTheCounters) {
  const TrilinearBlock block =
      mutant_block(TexelKind::kLuminance, Filter::kNearest, Border::kClamp);
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_trilinear_mutant_reads>(block, 9, 1000, log);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("counter bank_reads: expected"), std::string::npos) << log.str();
  EXPECT_NE(log.str().find("MISMATCH rtl vs golden: 0 of"), std::string::npos)
      << log.str();  // outputs right
}

// An injected wrong bit fails the run at that transaction.
TEST(TrilinearCosimTest, InjectedFaultFailsTheRun) {
  const TrilinearBlock block = mutant_block(TexelKind::kIndex, Filter::kTrilinear, Border::kBorder);
  CosimOptions o = options(5, 500, {"hls", "rtl"});
  o.inject_fault = 300;
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("first at transaction 300"), std::string::npos) << log.str();
}

// A memory holding fewer cells than the layout needs: the read beyond a bank fails the run.
TEST(TrilinearCosimTest, ReadBeyondABankFailsTheRun) {
  const TrilinearBlock block =
      mutant_block(TexelKind::kLuminance, Filter::kBilinear, Border::kWrap);
  TrilinearEnv env = block.env();
  texram::TexramTexture small = *env.texture;
  for (auto& bank : small.banks) bank.resize(bank.size() / 2);
  env.texture = std::make_shared<const texram::TexramTexture>(std::move(small));
  std::vector<Txn> items = block.setup_items();
  items.push_back(trilinear_sample_item(31 * kOne, 15 * kOne, 0));  // the last cells of level 0
  const RunResult r = make_trilinear_rtl_engine<Vtmu_trilinear>("rtl", env)->run(items, {});
  EXPECT_NE(r.error.find("texram memory: read of bank"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace tmu::tb
