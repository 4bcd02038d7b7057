// Verilator against Icarus Verilog on the same RTL and the same stimulus: the noise unit and
// the pipelined fractal unit, one thread and two threads of Verilator, and Icarus (tb/icarus).
// Each is the block's engine through the harness, its model time alone (Icarus: the vvp run,
// not the compilation). Prints each rate and its ratio to Icarus.
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "bench/ratio_reporter.hpp"
#include "blocks/registry.hpp"

namespace tmu::bench {
namespace {

// Icarus runs about a thousand transactions a second: 4096 keep one iteration near seconds.
constexpr size_t kItems = 4096;

void block_at(benchmark::State& state, const std::string& block_name, const std::string& level) {
  const auto block = tb::make_block(block_name, tb::BlockOptions{});
  std::mt19937_64 rng(9);
  const std::vector<tb::Txn> items = block->random_items(rng, kItems);
  const auto engine = block->engine(level);
  for (auto _ : state) {
    const tb::RunResult r = engine->run(items, tb::RunOptions{});
    if (!r.error.empty()) state.SkipWithError(r.error.c_str());
    state.SetIterationTime(r.seconds);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(items.size()));
}

void BM_NoiseVerilator(benchmark::State& s) { block_at(s, "perlin", "rtl"); }
void BM_NoiseVerilatorThreads(benchmark::State& s) { block_at(s, "perlin", "rtl-threads"); }
void BM_NoiseIcarus(benchmark::State& s) { block_at(s, "perlin", "icarus"); }
void BM_FractalVerilator(benchmark::State& s) { block_at(s, "turbulence", "rtl"); }
void BM_FractalVerilatorThreads(benchmark::State& s) { block_at(s, "turbulence", "rtl-threads"); }
void BM_FractalIcarus(benchmark::State& s) { block_at(s, "turbulence", "icarus"); }
BENCHMARK(BM_NoiseVerilator)->Unit(benchmark::kMillisecond)->UseManualTime();
BENCHMARK(BM_NoiseVerilatorThreads)->Unit(benchmark::kMillisecond)->UseManualTime();
BENCHMARK(BM_NoiseIcarus)->Unit(benchmark::kMillisecond)->UseManualTime();
BENCHMARK(BM_FractalVerilator)->Unit(benchmark::kMillisecond)->UseManualTime();
BENCHMARK(BM_FractalVerilatorThreads)->Unit(benchmark::kMillisecond)->UseManualTime();
BENCHMARK(BM_FractalIcarus)->Unit(benchmark::kMillisecond)->UseManualTime();

}  // namespace
}  // namespace tmu::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  tmu::bench::RatioReporter reporter(
      {{"BM_NoiseVerilator/manual_time", "BM_NoiseIcarus/manual_time"},
       {"BM_NoiseVerilatorThreads/manual_time", "BM_NoiseIcarus/manual_time"},
       {"BM_FractalVerilator/manual_time", "BM_FractalIcarus/manual_time"},
       {"BM_FractalVerilatorThreads/manual_time", "BM_FractalIcarus/manual_time"}});
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
}
