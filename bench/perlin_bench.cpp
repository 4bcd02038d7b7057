// The golden noise unit's speed against a plain double-precision improved noise (Perlin 2002)
// on the same points, noise and four-octave turbulence, and the turbulence block at every
// model level. Prints each rate and its ratio against its peer.
//   build/bench/tmu_perlin_bench [--benchmark_filter=...]
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "bench/improved_noise.hpp"
#include "bench/ratio_reporter.hpp"
#include "blocks/registry.hpp"
#include "perlin/noise.hpp"

namespace tmu::bench {
namespace {

constexpr int64_t kPoints = 1 << 18;

// Random points in [-64, 64)^3 on SolidCoord's grid, as raw values and as doubles.
struct Points {
  std::vector<int64_t> raw;  // u, v, w interleaved
  std::vector<double> real;
};
const Points& points() {
  static const Points p = [] {
    Points q;
    std::mt19937_64 rng(3);
    std::uniform_int_distribution<int64_t> any(-64 * 4096, 64 * 4096 - 1);
    for (int64_t i = 0; i < 3 * kPoints; ++i) {
      q.raw.push_back(any(rng));
      q.real.push_back(static_cast<double>(q.raw.back()) / 4096);
    }
    return q;
  }();
  return p;
}

void BM_NoiseGolden(benchmark::State& state) {
  const Points& p = points();
  const perlin::NoiseConfig c;
  for (auto _ : state) {
    int64_t acc = 0;
    for (size_t i = 0; i < p.raw.size(); i += 3)
      acc += perlin::noise(c, p.raw[i], p.raw[i + 1], p.raw[i + 2]);
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * kPoints);
}
void BM_NoiseImprovedDouble(benchmark::State& state) {
  const Points& p = points();
  const ImprovedNoise n;
  for (auto _ : state) {
    double acc = 0;
    for (size_t i = 0; i < p.real.size(); i += 3)
      acc += n.noise(p.real[i], p.real[i + 1], p.real[i + 2]);
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * kPoints);
}
void BM_TurbulenceGolden(benchmark::State& state) {
  const Points& p = points();
  const perlin::NoiseConfig c;
  for (auto _ : state) {
    int64_t acc = 0;
    for (size_t i = 0; i < p.raw.size(); i += 3)
      acc += perlin::fractal_sums(c, p.raw[i], p.raw[i + 1], p.raw[i + 2]).turbulence;
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * kPoints);
}
void BM_TurbulenceImprovedDouble(benchmark::State& state) {
  const Points& p = points();
  const ImprovedNoise n;
  for (auto _ : state) {
    double acc = 0;
    for (size_t i = 0; i < p.real.size(); i += 3)
      acc += n.turbulence(p.real[i], p.real[i + 1], p.real[i + 2]);
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * kPoints);
}
BENCHMARK(BM_NoiseGolden)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_NoiseImprovedDouble)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_TurbulenceGolden)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_TurbulenceImprovedDouble)->Unit(benchmark::kMillisecond)->UseRealTime();

// The turbulence block through the harness at each level (wall time: hls runs in a child).
void turbulence_block(benchmark::State& state, const std::string& level, bool shared) {
  tb::BlockOptions o;
  o.fractal_shared = shared;
  const auto block = tb::make_block("fractal", o);
  std::mt19937_64 rng(5);
  const std::vector<tb::Txn> items = block->random_items(rng, static_cast<size_t>(1) << 16);
  const auto engine = block->engine(level);
  for (auto _ : state) {
    const tb::RunResult r = engine->run(items, tb::RunOptions{});
    if (!r.error.empty()) state.SkipWithError("run failed");
    benchmark::DoNotOptimize(r.outputs.data());
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(items.size()));
}
void BM_TurbulenceBlockGolden(benchmark::State& s) { turbulence_block(s, "golden", false); }
void BM_TurbulenceBlockHls(benchmark::State& s) { turbulence_block(s, "hls", false); }
void BM_TurbulenceBlockRtl(benchmark::State& s) { turbulence_block(s, "rtl", false); }
void BM_TurbulenceBlockRtlShared(benchmark::State& s) { turbulence_block(s, "rtl", true); }
BENCHMARK(BM_TurbulenceBlockGolden)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_TurbulenceBlockHls)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_TurbulenceBlockRtl)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_TurbulenceBlockRtlShared)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace tmu::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  const std::string block = "BM_TurbulenceBlockGolden/real_time";
  tmu::bench::RatioReporter reporter(
      {{"BM_NoiseGolden/real_time", "BM_NoiseImprovedDouble/real_time"},
       {"BM_TurbulenceGolden/real_time", "BM_TurbulenceImprovedDouble/real_time"},
       {"BM_TurbulenceBlockHls/real_time", block},
       {"BM_TurbulenceBlockRtl/real_time", block},
       {"BM_TurbulenceBlockRtlShared/real_time", block}});
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
}
