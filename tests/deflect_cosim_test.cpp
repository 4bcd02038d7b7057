// The bump deflection unit with its MBR (001 §4.4, §6.2): golden vs rtl and golden vs hls bit
// for bit, the access codes and the cache's counters included, on the block's directed hard
// cases and random items under back-pressure, with the map memory's latency fixed and
// jittered; the coherent stream a render sends (its hit rate, the same accesses in every
// model); a flat bump map returns the normals; throughput (one result per clock on hits,
// each miss costing the memory's latency); and the teeth (RTL mutants: a tag compare that
// ignores a bit, a wrong octant sign; an injected wrong bit).
#include <Vtmu_deflect.h>
#include <Vtmu_deflect_mutant_quadrant.h>
#include <Vtmu_deflect_mutant_tag.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <sstream>

#include "blocks/deflect_block.hpp"
#include "harness/cosim.hpp"
#include "harness/vector_file.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir() { return testing::temp_dir("tmu_deflect_cosim_test"); }
constexpr auto options = testing::cosim_options;

uint64_t counter(const RunResult& r, const std::string& name) {
  const auto v = counter_value(r.counters, name);
  if (!v) ADD_FAILURE() << "no counter " << name;
  return v.value_or(0);
}

DeflectBlock make_block(int latency, int jitter) {
  BlockOptions o;
  o.dfl_map_latency = latency;
  o.dfl_map_jitter = jitter;
  return DeflectBlock(o);
}

// Runs `items` (no directed ones) through golden and the engines, no back-pressure unless
// asked for.
CosimResult run_items(const DeflectBlock& block, const std::vector<Txn>& items,
                      const std::string& file, std::vector<std::string> engines,
                      double in_idle = 0.0, double out_stall = 0.0) {
  const fs::path path = temp_dir() / file;
  write_vectors(path.string(), block.inputs(), items);
  CosimOptions c = options(3, 0, std::move(engines));
  c.vectors_in = path.string();
  c.in_idle = in_idle;
  c.out_stall = out_stall;
  std::stringstream log;
  const CosimResult r = run_cosim(block, c, log);
  EXPECT_TRUE(r.pass) << log.str();
  return r;
}

// --- golden = hls = rtl ----------------------------------------------------------------------

// Directed hard cases and random items (uniform angles and coherent streams) under
// back-pressure, the rtl twice for the X check, with the memory's default latency (4), the
// shortest (1) and a jittered one (2 + 0..5). The union of the coverage hits every case; the
// memory's block fetches are golden's misses.
TEST(DeflectCosimTest, GoldenHlsRtlAtSeveralMemoryLatencies) {
  Coverage all;
  uint64_t seed = 40;
  for (const auto& [latency, jitter] : {std::pair{4, 0}, std::pair{1, 0}, std::pair{2, 5}}) {
    ++seed;
    const DeflectBlock block = make_block(latency, jitter);
    SCOPED_TRACE(::testing::Message() << "latency " << latency << " jitter " << jitter);
    std::stringstream log;
    const CosimResult r = run_cosim(block, options(seed, 20000, {"hls", "rtl"}), log);
    EXPECT_TRUE(r.pass) << log.str();
    for (const char* engine : {"hls", "rtl"}) {
      const RunResult& run = r.runs.at(engine);
      EXPECT_EQ(counter(run, "block_fetches"), counter(r.runs.at("golden"), "misses")) << engine;
      EXPECT_GE(counter(run, "stall_cycles"),
                counter(run, "block_fetches") * static_cast<uint64_t>(latency))
          << engine;
    }
    for (const auto& [name, n] : r.coverage) all[name] += n;
  }
  for (const auto& [name, n] : all) EXPECT_GT(n, 0u) << "coverage case not hit: " << name;
}

// The directed cases alone hit every named case (so the coverage does not rest on luck).
TEST(DeflectCosimTest, DirectedItemsHitEveryCase) {
  const DeflectBlock block = make_block(4, 0);
  std::stringstream log;
  const CosimResult r = run_cosim(block, options(1, 0, {"rtl"}), log);
  EXPECT_TRUE(r.pass) << log.str();
  for (const auto& [name, n] : r.coverage) EXPECT_GT(n, 0u) << "not hit by directed: " << name;
}

// Heavy back-pressure on both sides with a slow, jittery memory: the output holds while
// stalled (the RTL's assertion), nothing is lost or repeated.
TEST(DeflectCosimTest, HeavyBackPressureSlowMemory) {
  const DeflectBlock block = make_block(7, 9);
  CosimOptions o = options(77, 8000, {"hls", "rtl"});
  o.in_idle = 0.6;
  o.out_stall = 0.7;
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  EXPECT_TRUE(r.pass) << log.str();
}

// --- the render's view -----------------------------------------------------------------------

// A coherent stream (slowly varying normals and bumps, as a scanline sends them): hits
// dominate. Golden, hls and rtl report the same hits, misses and bypasses, and the memory
// saw exactly golden's misses as fetches; the stall cost is the latency per miss.
TEST(DeflectCosimTest, CoherentStreamHitRate) {
  const DeflectBlock block = make_block(4, 0);
  std::mt19937_64 rng(2024);
  const std::vector<Txn> items = deflect_coherent_items(rng, 20000);
  const CosimResult r = run_items(block, items, "coherent.csv", {"hls", "rtl"});
  const RunResult& golden = r.runs.at("golden");
  const RunResult& rtl = r.runs.at("rtl");
  for (const char* name : {"hits", "misses", "bypasses"}) {
    EXPECT_EQ(counter(rtl, name), counter(golden, name)) << name;
    EXPECT_EQ(counter(r.runs.at("hls"), name), counter(golden, name)) << name;
  }
  const uint64_t hits = counter(golden, "hits"), misses = counter(golden, "misses");
  const uint64_t bypasses = counter(golden, "bypasses");
  EXPECT_EQ(counter(rtl, "block_fetches"), misses);
  EXPECT_EQ(counter(rtl, "stall_cycles"), 4 * misses);
  const double hit_rate = static_cast<double>(hits) / static_cast<double>(hits + misses);
  std::cout << "coherent stream: " << items.size() << " items, " << hits << " hits, " << misses
            << " misses, " << bypasses << " bypasses: hit rate " << hit_rate << "; rtl "
            << rtl.cycles << " cycles (" << counter(rtl, "stall_cycles") << " waiting for blocks), "
            << static_cast<double>(items.size()) / static_cast<double>(rtl.cycles)
            << " results per clock\n";
  // The stream's look-ups move to another 4 x 4 block only every few items.
  EXPECT_GT(hit_rate, 0.8);
}

// A flat bump map (every texel (0, +0)) returns every normal exactly, from all models.
TEST(DeflectCosimTest, FlatBumpStreamReturnsTheNormals) {
  const DeflectBlock block = make_block(4, 0);
  std::mt19937_64 rng(9);
  std::vector<Txn> items;
  for (int i = 0; i < 3000; ++i) {
    const uint64_t r = rng();
    const auto mag = static_cast<uint32_t>((r >> 16) % 128);
    const deflect::SphereGrid g;
    items.push_back(deflect_item(
        {static_cast<uint32_t>(r % 512), deflect::make_theta(g, (r >> 32) & 1, mag)}, {0, 0}));
  }
  const CosimResult r = run_items(block, items, "flat.csv", {"hls", "rtl"}, 0.2, 0.2);
  const RunResult& rtl = r.runs.at("rtl");
  ASSERT_EQ(rtl.outputs.size(), items.size());
  for (size_t i = 0; i < items.size(); ++i) {
    ASSERT_EQ(rtl.outputs[i].f[kDflOutPhi], items[i].f[kDflNormalPhi]) << "item " << i;
    ASSERT_EQ(rtl.outputs[i].f[kDflOutTheta], items[i].f[kDflNormalTheta]) << "item " << i;
    ASSERT_NE(rtl.outputs[i].f[kDflOutAccess], static_cast<uint64_t>(deflect::MapAccess::kBypass));
  }
}

// --- throughput ------------------------------------------------------------------------------

// Without stalls, hits and bypasses leave one per clock and each miss costs exactly the
// memory's latency: cycles = items + latency x misses + the pipeline's 2 + 16 drain cycles.
TEST(DeflectCosimTest, OnePerClockAndMissesCostTheLatency) {
  for (int latency : {1, 4, 9}) {
    const DeflectBlock block = make_block(latency, 0);
    std::mt19937_64 rng(5);
    const std::vector<Txn> items = deflect_coherent_items(rng, 5000);
    const CosimResult r = run_items(block, items, "speed.csv", {"hls", "rtl"});
    const uint64_t misses = counter(r.runs.at("golden"), "misses");
    const RunResult& rtl = r.runs.at("rtl");
    EXPECT_EQ(rtl.cycles, items.size() + static_cast<uint64_t>(latency) * misses + 2 + 16)
        << "latency " << latency;
    EXPECT_EQ(counter(rtl, "stall_cycles"), static_cast<uint64_t>(latency) * misses);
    std::cout << "latency " << latency << ": " << items.size() << " items, " << misses
              << " misses, rtl " << rtl.cycles << " cycles, hls " << r.runs.at("hls").cycles
              << " cycles\n";
  }
}

// --- teeth -----------------------------------------------------------------------------------

template <class Model>
CosimResult run_mutant(const DeflectBlock& block, uint64_t seed, size_t count,
                       std::stringstream& log) {
  CosimOptions o = options(seed, count, {"rtl"});
  o.x_check = false;
  return run_cosim(block, o, log, [&block](const std::string& level) -> std::unique_ptr<Engine> {
    if (level != "rtl") return nullptr;
    return make_deflect_rtl_engine<Model>("rtl", block.map(), block.timing());
  });
}

// The tag compare ignores the block address's lowest bit: neighbouring blocks alias, a miss
// reads as a hit of the wrong block. The directed cache sequences alone catch it, with a
// waveform of the failure.
TEST(DeflectCosimTest, TagMutantIsCaughtWithAWaveform) {
  const DeflectBlock block = make_block(4, 0);
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_deflect_mutant_tag>(block, 9, 0, log);
  EXPECT_NE(log.str().find("counter block_fetches: expected"), std::string::npos) << log.str();
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim deflect --seed 9");
}

// The octant reduction takes z's sign from phi''s top bit alone: quadrants 1 and 3 swap their
// z signs (the expansion takes l for 2Q - l, 2Q + l for 4Q - l): wrong angles.
TEST(DeflectCosimTest, QuadrantMutantIsCaught) {
  const DeflectBlock block = make_block(4, 0);
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_deflect_mutant_quadrant>(block, 9, 0, log);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("MISMATCH rtl vs golden"), std::string::npos) << log.str();
}

// An injected wrong bit fails the run at that transaction.
TEST(DeflectCosimTest, InjectedFaultFailsTheRun) {
  const DeflectBlock block = make_block(4, 0);
  CosimOptions o = options(5, 300, {"rtl"});
  o.inject_fault = 250;
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("first at transaction 250"), std::string::npos) << log.str();
}

}  // namespace
}  // namespace tmu::tb
