// What is the deflection unit's own (001 §4.4, §6.2; the conformance suite checks what every
// block shares, at the map memory's default latency): golden = hls = rtl, requests included,
// with the fastest memory and a slow jittery one; the coherent stream a render sends (its hit
// rate); a flat bump map returns the normals; one result per clock on hits and bypasses, each
// miss costing the memory's latency.
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <random>
#include <sstream>

#include "blocks/deflect/deflect_block.hpp"
#include "harness/cosim.hpp"
#include "harness/vector_file.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

namespace fs = std::filesystem;
using D = desc::deflect;

uint64_t counter(const Counters& c, const std::string& name) {
  const auto v = counter_value(c, name);
  if (!v) ADD_FAILURE() << "no counter " << name;
  return v.value_or(0);
}

DeflectBlock block_of(int latency, int jitter) {
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
  const fs::path path = testing::temp_dir("tmu_deflect_test") / file;
  write_vectors(path.string(), block.inputs(), items);
  CosimOptions c = testing::cosim_options(3, 0, std::move(engines));
  c.vectors_in = path.string();
  c.in_idle = in_idle;
  c.out_stall = out_stall;
  std::stringstream log;
  const CosimResult r = run_cosim(block, c, log);
  EXPECT_TRUE(r.pass) << log.str();
  return r;
}

// The memory answering in the next cycle, and a slow one with jitter (7 + 0..9 cycles) under
// heavy back-pressure: the outputs, the requests and the fetches are golden's; every look-up
// waits at least the latency per fetch.
TEST(DeflectTest, FastestAndSlowJitteryMemory) {
  for (const auto& [latency, jitter] : {std::pair{1, 0}, std::pair{7, 9}}) {
    SCOPED_TRACE(::testing::Message() << "latency " << latency << " jitter " << jitter);
    CosimOptions o = testing::cosim_options(41, 8000, {"hls", "rtl"});
    o.in_idle = latency == 1 ? 0.25 : 0.6;
    o.out_stall = latency == 1 ? 0.25 : 0.7;
    std::stringstream log;
    const CosimResult r = run_cosim(block_of(latency, jitter), o, log);
    EXPECT_TRUE(r.pass) << log.str();
    for (const char* engine : {"hls", "rtl"}) {
      const Counters& c = r.runs.at(engine).counters;
      EXPECT_GE(counter(c, "stall_cycles"),
                counter(c, "block_fetches") * static_cast<uint64_t>(latency))
          << engine;
    }
  }
}

// A coherent stream (slowly varying normals and bumps, as a scanline sends them): hits
// dominate, and the stall cost is the latency per miss.
TEST(DeflectTest, CoherentStreamHitRate) {
  const DeflectBlock block = block_of(4, 0);
  std::mt19937_64 rng(2024);
  const std::vector<Txn> items = deflect_coherent_items(rng, 20000);
  const CosimResult r = run_items(block, items, "coherent.csv", {"hls", "rtl"});
  const Counters access = map_access_counters(r.runs.at("golden").outputs);
  const uint64_t hits = counter(access, "hits"), misses = counter(access, "misses");
  const RunResult& rtl = r.runs.at("rtl");
  EXPECT_EQ(counter(rtl.counters, "block_fetches"), misses);
  EXPECT_EQ(counter(rtl.counters, "stall_cycles"), 4 * misses);
  const double hit_rate = static_cast<double>(hits) / static_cast<double>(hits + misses);
  std::cout << "coherent stream: " << items.size() << " items, " << hits << " hits, " << misses
            << " misses, " << counter(access, "bypasses") << " bypasses: hit rate " << hit_rate
            << "; rtl " << rtl.cycles << " cycles, "
            << static_cast<double>(items.size()) / static_cast<double>(rtl.cycles)
            << " results per clock\n";
  // The stream's look-ups move to another 4 x 4 block only every few items.
  EXPECT_GT(hit_rate, 0.8);
}

// A flat bump map (every texel (0, +0)) returns every normal exactly, from all models.
TEST(DeflectTest, FlatBumpStreamReturnsTheNormals) {
  const DeflectBlock block = block_of(4, 0);
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
    const deflect::SphereAngle n = deflect_normal(items[i]), got = deflect_output(rtl.outputs[i]);
    ASSERT_EQ(got.phi, n.phi) << "item " << i;
    ASSERT_EQ(got.theta, n.theta) << "item " << i;
    ASSERT_NE(rtl.outputs[i].f[D::out_access], uint64_t(deflect::MapAccess::kBypass));
  }
}

// Without stalls, hits and bypasses leave one per clock and each miss costs exactly the
// memory's latency: cycles = items + latency x misses + the pipeline's 2 + 16 drain cycles.
TEST(DeflectTest, OnePerClockAndMissesCostTheLatency) {
  for (int latency : {1, 4, 9}) {
    const DeflectBlock block = block_of(latency, 0);
    std::mt19937_64 rng(5);
    const std::vector<Txn> items = deflect_coherent_items(rng, 5000);
    const CosimResult r = run_items(block, items, "speed.csv", {"hls", "rtl"});
    const uint64_t misses = counter(map_access_counters(r.runs.at("golden").outputs), "misses");
    const RunResult& rtl = r.runs.at("rtl");
    EXPECT_EQ(rtl.cycles, items.size() + static_cast<uint64_t>(latency) * misses + 2 + 16)
        << "latency " << latency;
    EXPECT_EQ(counter(rtl.counters, "stall_cycles"), static_cast<uint64_t>(latency) * misses);
    std::cout << "latency " << latency << ": " << items.size() << " items, " << misses
              << " misses, rtl " << rtl.cycles << " cycles, hls " << r.runs.at("hls").cycles
              << " cycles\n";
  }
}

}  // namespace
}  // namespace tmu::tb
