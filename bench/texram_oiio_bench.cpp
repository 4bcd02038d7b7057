// The golden trilinear unit and footprint assembly, scalar and fast, against the library a user
// would pick instead: OpenImageIO's TextureSystem, on the same texels and the same requests, one
// thread. Prints each rate, its ratio against OIIO measured in the same run, and how far apart
// the golden and OIIO answers are (mean and max absolute difference per channel, 8-bit levels).
// The fast path's answers are checked equal to the scalar golden's on every request before
// anything is timed (the fixture throws otherwise).
//   build/bench/tmu_texram_oiio_bench [--benchmark_filter=...]
//
// The texture: patterns::default_image(256, 256), true colour, wrap on both axes. OIIO reads our
// own pyramid (write_oiio_mip_texture: every level read back through the bank layout into a
// tiled, MIP-mapped float OpenEXR file), so both sides filter the same texels.
//
// What each side includes in its time:
// - golden: texram::sample / footprint::sample on the in-memory 8-bank image: the address
//   generation (levels, weights, border operators, bank addresses), one read per bank and byte
//   plane, the fixed-point blend, eq. 5's combine (multiply by one); the footprint setup
//   (block-floating derivatives, log2 tables) and the average of its probes.
// - fast golden: FastTrilinear / FastFootprint::sample_batch over the same requests, the same
//   arithmetic on the texture prepared once (outside the timing: texram/fast_trilinear.hpp),
//   writing every result to an array; no memory plan.
// - OIIO: TextureSystem::texture() through a texture handle and this thread's Perthread record
//   (no file-name lookup), its tile-cache lookups (every tile resident: the cache is warmed
//   outside the timed loop), its float pipeline on texels stored as float, its statistics.
// - Neither includes file I/O, the request set's construction or the comparison.
// Rates are per CPU second of the one thread (both sides run in this process on one thread,
// so a busy machine slows neither's figure the way wall time would).
//
// Requests (fixed seeds, built once):
// - trilinear: 100 000 of u, v on the SQ16.8 port grid over [-0.5, 1.5) of the texture, lambda
//   on the SQ6.8 grid over [0, top) (every level pair); OIIO gets s = u / 256, t = v / 256 and
//   oiio_trilinear_derivative(lambda), which selects the same two levels and the same blend.
//   The difference is then the golden model's fixed point (golden vs ideal; the ideal model
//   agrees with OIIO within 0.0014 of a level, tests/texram_ideal_oiio_test.cpp).
// - footprint / aniso: 100 000 footprints at random positions and orientations, r1 and r2
//   orthogonal (which one is longer at random), major axis 2^[-1, 7) texels, anisotropy
//   (major / minor) uniform in [1, 8]; the golden unit at N max 8 (log2_max_probes 3), OIIO
//   MipModeAniso with anisotropic = 8 and the same derivatives in its normalized units. The two
//   filters differ (OIIO chooses its own probe count, spacing, weights and level from the
//   ellipse; the patent marches N = 2^round(log2 ratio) equal probes along the longer side), so
//   that difference is informative, not a bound on either's error.
#include <OpenImageIO/texture.h>
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/ratio_reporter.hpp"
#include "common/test_patterns.hpp"
#include "footprint/fast_footprint.hpp"
#include "footprint/footprint.hpp"
#include "texram/fast_trilinear.hpp"
#include "texram/oiio_texture.hpp"
#include "texram/trilinear.hpp"

namespace tmu::bench {
namespace {

constexpr int kSide = 256;
constexpr size_t kRequests = 100000;
constexpr int kLog2MaxProbes = 3;  // golden N max 8 = OIIO's anisotropic

// One OIIO lookup: s, t and the derivatives in normalized texture units.
struct OiioRequest {
  float s = 0, t = 0, dsdx = 0, dtdx = 0, dsdy = 0, dtdy = 0;
};

enum class Mode { kTrilinear, kAniso };

struct Difference {
  double mean = 0, max = 0;  // per channel, 8-bit levels
};

Difference difference(const std::vector<uint32_t>& golden, const std::vector<float>& oiio) {
  Difference d;
  for (size_t i = 0; i < golden.size(); ++i) {
    for (int c = 0; c < 4; ++c) {
      const double e =
          std::abs(texram::channel(golden[i], c) - 255.0 * oiio[4 * i + static_cast<size_t>(c)]);
      d.mean += e;
      d.max = std::max(d.max, e);
    }
  }
  d.mean /= 4.0 * static_cast<double>(golden.size());
  return d;
}

// OIIO's own count: "Average anisotropic probes : X" of its statistics text.
double oiio_average_probes(OIIO::TextureSystem& ts) {
  std::istringstream stats(ts.getstats(1, false));
  const std::string key = "Average anisotropic probes :";
  for (std::string line; std::getline(stats, line);) {
    const size_t at = line.find(key);
    if (at != std::string::npos) return std::stod(line.substr(at + key.size()));
  }
  return std::nan("");
}

class Fixture {
 public:
  Fixture()
      : dir_(std::filesystem::temp_directory_path() /
             ("tmu_oiio_bench_" + std::to_string(::getpid()))),
        texture_(texram::import_image(patterns::default_image(kSide, kSide),
                                      texram::TexelKind::kTrueColour)) {
    sampler_.kind = texram::TexelKind::kTrueColour;
    sampler_.filter = texram::Filter::kTrilinear;
    sampler_.border_u = sampler_.border_v = texram::Border::kWrap;
    footprint_.log2_max_probes = kLog2MaxProbes;
    fast_trilinear_.emplace(texture_, sampler_);
    fast_footprint_.emplace(texture_, sampler_, footprint_);
    std::filesystem::create_directories(dir_);
    path_ = (dir_ / "texture.exr").string();
    texram::write_oiio_mip_texture(path_, texture_, sampler_);

    ts_ = OIIO::TextureSystem::create(false);  // private: no other user shares its cache
    handle_ = ts_->get_texture_handle(OIIO::ustring(path_));
    perthread_ = ts_->get_perthread_info();
    trilinear_opt_.mipmode = OIIO::TextureOpt::MipModeTrilinear;
    trilinear_opt_.interpmode = OIIO::TextureOpt::InterpBilinear;
    trilinear_opt_.swrap = trilinear_opt_.twrap = texram::oiio_wrap(texram::Border::kWrap);
    aniso_opt_ = trilinear_opt_;
    aniso_opt_.mipmode = OIIO::TextureOpt::MipModeAniso;
    aniso_opt_.anisotropic = 1 << kLog2MaxProbes;

    make_trilinear_requests();
    make_footprint_requests();

    // The answers, outside any timed loop; OIIO's pass also loads every tile (warm cache).
    // The fast path must equal the golden on every request it is timed on.
    std::vector<uint32_t> golden, fast(kRequests);
    for (const texram::Request& r : trilinear_)
      golden.push_back(texram::sample(texture_, sampler_, r));
    fast_trilinear_->sample_batch(trilinear_, fast);
    if (fast != golden) throw std::logic_error("fast trilinear differs from the golden");
    trilinear_diff_ = difference(golden, oiio_run(Mode::kTrilinear, trilinear_oiio_));
    golden.clear();
    uint64_t probes = 0;
    for (const footprint::Request& r : footprint_requests_) {
      golden.push_back(footprint::sample(texture_, sampler_, footprint_, r));
      probes += uint64_t{1} << footprint::plan(r, footprint_).log2_n;
    }
    fast_footprint_->sample_batch(footprint_requests_, fast);
    if (fast != golden) throw std::logic_error("fast footprint differs from the golden");
    golden_probes_ = static_cast<double>(probes) / static_cast<double>(kRequests);
    aniso_diff_ = difference(golden, oiio_run(Mode::kAniso, footprint_oiio_));
    oiio_probes_ = oiio_average_probes(*ts_);
  }
  ~Fixture() {
    OIIO::TextureSystem::destroy(ts_);
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  Fixture(const Fixture&) = delete;
  Fixture& operator=(const Fixture&) = delete;

  // Every request through OIIO; RGBA floats 0..1, four per request.
  std::vector<float> oiio_run(Mode mode, const std::vector<OiioRequest>& rs) {
    std::vector<float> out(4 * rs.size());
    for (size_t i = 0; i < rs.size(); ++i) {
      if (!lookup(mode, rs[i], &out[4 * i])) {
        throw std::runtime_error(path_ + ": OpenImageIO lookup failed: " + ts_->geterror());
      }
    }
    return out;
  }
  // One lookup (texture() takes its options by non-const reference: one set per mode).
  bool lookup(Mode mode, const OiioRequest& r, float* rgba) {
    OIIO::TextureOpt& o = mode == Mode::kAniso ? aniso_opt_ : trilinear_opt_;
    return ts_->texture(handle_, perthread_, o, r.s, r.t, r.dsdx, r.dtdx, r.dsdy, r.dtdy, 4, rgba);
  }

  const texram::TexramTexture& texture() const { return texture_; }
  const texram::SamplerConfig& sampler() const { return sampler_; }
  const footprint::Config& footprint_config() const { return footprint_; }
  const texram::FastTrilinear& fast_trilinear() const { return *fast_trilinear_; }
  const footprint::FastFootprint& fast_footprint() const { return *fast_footprint_; }
  const std::vector<texram::Request>& trilinear_requests() const { return trilinear_; }
  const std::vector<OiioRequest>& trilinear_oiio() const { return trilinear_oiio_; }
  const std::vector<footprint::Request>& footprint_requests() const { return footprint_requests_; }
  const std::vector<OiioRequest>& footprint_oiio() const { return footprint_oiio_; }
  Difference trilinear_diff() const { return trilinear_diff_; }
  Difference aniso_diff() const { return aniso_diff_; }
  double golden_probes() const { return golden_probes_; }
  double oiio_probes() const { return oiio_probes_; }

 private:
  void make_trilinear_requests() {
    const int top = texture_.geometry.levels() - 1;
    std::mt19937_64 rng(1);
    std::uniform_int_distribution<int32_t> coord(-kSide / 2 * 256, 3 * kSide / 2 * 256 - 1);
    std::uniform_int_distribution<int32_t> lod(0, top * 256 - 1);
    for (size_t i = 0; i < kRequests; ++i) {
      texram::Request r;
      r.u = coord(rng);
      r.v = coord(rng);
      r.lambda = lod(rng);
      trilinear_.push_back(r);
      const float d = texram::oiio_trilinear_derivative(r.lambda / 256.0, top, kSide);
      trilinear_oiio_.push_back({static_cast<float>(r.u / 256.0 / kSide),
                                 static_cast<float>(r.v / 256.0 / kSide), d, 0.0f, 0.0f, d});
    }
  }

  void make_footprint_requests() {
    std::mt19937_64 rng(2);
    std::uniform_int_distribution<int32_t> coord(0, kSide * 256 - 1);
    std::uniform_real_distribution<double> log_major(-1.0, 7.0), ratio(1.0, 8.0),
        angle(0.0, 2 * std::numbers::pi);
    std::bernoulli_distribution swap(0.5);
    const auto port = [](double texels) { return static_cast<int32_t>(std::lround(texels * 256)); };
    const auto norm = [](int32_t raw) { return static_cast<float>(raw / 256.0 / kSide); };
    for (size_t i = 0; i < kRequests; ++i) {
      const double major = std::exp2(log_major(rng)), minor = major / ratio(rng), a = angle(rng);
      footprint::Request r;
      r.u = coord(rng);
      r.v = coord(rng);
      r.r1u = port(major * std::cos(a));
      r.r1v = port(major * std::sin(a));
      r.r2u = port(-minor * std::sin(a));
      r.r2v = port(minor * std::cos(a));
      if (swap(rng)) {
        std::swap(r.r1u, r.r2u);
        std::swap(r.r1v, r.r2v);
      }
      footprint_requests_.push_back(r);
      footprint_oiio_.push_back(
          {norm(r.u), norm(r.v), norm(r.r1u), norm(r.r1v), norm(r.r2u), norm(r.r2v)});
    }
  }

  std::filesystem::path dir_;
  std::string path_;
  texram::TexramTexture texture_;
  texram::SamplerConfig sampler_;
  footprint::Config footprint_;
  std::optional<texram::FastTrilinear> fast_trilinear_;  // prepared once, outside the timing
  std::optional<footprint::FastFootprint> fast_footprint_;
  OIIO::TextureSystem* ts_ = nullptr;
  OIIO::TextureSystem::TextureHandle* handle_ = nullptr;
  OIIO::TextureSystem::Perthread* perthread_ = nullptr;
  OIIO::TextureOpt trilinear_opt_, aniso_opt_;
  std::vector<texram::Request> trilinear_;
  std::vector<OiioRequest> trilinear_oiio_;
  std::vector<footprint::Request> footprint_requests_;
  std::vector<OiioRequest> footprint_oiio_;
  Difference trilinear_diff_, aniso_diff_;
  double golden_probes_ = 0, oiio_probes_ = 0;
};

Fixture* fixture = nullptr;  // built in main, before the benchmarks run

void set_rate(benchmark::State& state, size_t per_iteration) {
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(per_iteration));
}

void BM_TrilinearGolden(benchmark::State& state) {
  const Fixture& f = *fixture;
  for (auto _ : state) {
    uint32_t acc = 0;
    for (const texram::Request& r : f.trilinear_requests())
      acc ^= texram::sample(f.texture(), f.sampler(), r);
    benchmark::DoNotOptimize(acc);
  }
  set_rate(state, f.trilinear_requests().size());
}

void BM_TrilinearFast(benchmark::State& state) {
  const Fixture& f = *fixture;
  std::vector<uint32_t> out(f.trilinear_requests().size());
  for (auto _ : state) {
    f.fast_trilinear().sample_batch(f.trilinear_requests(), out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  set_rate(state, f.trilinear_requests().size());
}

void BM_TrilinearOiio(benchmark::State& state) {
  Fixture& f = *fixture;
  bool ok = true;
  for (auto _ : state) {
    float acc = 0;
    float rgba[4];
    for (const OiioRequest& r : f.trilinear_oiio()) {
      ok &= f.lookup(Mode::kTrilinear, r, rgba);
      acc += rgba[0];
    }
    benchmark::DoNotOptimize(acc);
  }
  if (!ok) state.SkipWithError("OIIO lookup failed");
  set_rate(state, f.trilinear_oiio().size());
  state.counters["diff_mean"] = f.trilinear_diff().mean;
  state.counters["diff_max"] = f.trilinear_diff().max;
}

void BM_FootprintGolden(benchmark::State& state) {
  const Fixture& f = *fixture;
  for (auto _ : state) {
    uint32_t acc = 0;
    for (const footprint::Request& r : f.footprint_requests())
      acc ^= footprint::sample(f.texture(), f.sampler(), f.footprint_config(), r);
    benchmark::DoNotOptimize(acc);
  }
  set_rate(state, f.footprint_requests().size());
  state.counters["probes"] = f.golden_probes();
}

void BM_FootprintFast(benchmark::State& state) {
  const Fixture& f = *fixture;
  std::vector<uint32_t> out(f.footprint_requests().size());
  for (auto _ : state) {
    f.fast_footprint().sample_batch(f.footprint_requests(), out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  set_rate(state, f.footprint_requests().size());
  state.counters["probes"] = f.golden_probes();
}

void BM_AnisoOiio(benchmark::State& state) {
  Fixture& f = *fixture;
  bool ok = true;
  for (auto _ : state) {
    float acc = 0;
    float rgba[4];
    for (const OiioRequest& r : f.footprint_oiio()) {
      ok &= f.lookup(Mode::kAniso, r, rgba);
      acc += rgba[0];
    }
    benchmark::DoNotOptimize(acc);
  }
  if (!ok) state.SkipWithError("OIIO lookup failed");
  set_rate(state, f.footprint_oiio().size());
  state.counters["probes"] = f.oiio_probes();
  state.counters["diff_mean"] = f.aniso_diff().mean;
  state.counters["diff_max"] = f.aniso_diff().max;
}

BENCHMARK(BM_TrilinearGolden)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TrilinearFast)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TrilinearOiio)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FootprintGolden)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FootprintFast)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AnisoOiio)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tmu::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  tmu::bench::Fixture f;
  tmu::bench::fixture = &f;
  tmu::bench::RatioReporter reporter({{"BM_TrilinearGolden", "BM_TrilinearOiio"},
                                      {"BM_TrilinearFast", "BM_TrilinearOiio"},
                                      {"BM_FootprintGolden", "BM_AnisoOiio"},
                                      {"BM_FootprintFast", "BM_AnisoOiio"}});
  benchmark::RunSpecifiedBenchmarks(&reporter);
  fmt::print(
      "\n{} requests, {}x{} true colour, wrap; |golden - OIIO| per channel (8-bit levels):\n"
      "  trilinear                  mean {:.4f}  max {:.3f}\n"
      "  footprint (N max {}) vs aniso {}: mean {:.4f}  max {:.3f}  (different filters)\n"
      "  probes per request: golden {:.3f}, OIIO {:.3f} (its own statistic)\n",
      tmu::bench::kRequests, tmu::bench::kSide, tmu::bench::kSide, f.trilinear_diff().mean,
      f.trilinear_diff().max, 1 << tmu::bench::kLog2MaxProbes, 1 << tmu::bench::kLog2MaxProbes,
      f.aniso_diff().mean, f.aniso_diff().max, f.golden_probes(), f.oiio_probes());
  benchmark::Shutdown();
}
