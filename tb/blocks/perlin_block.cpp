#include "blocks/perlin_block.hpp"

#include <Vtmu_fractal_pipelined.h>
#include <Vtmu_fractal_pipelined_threads.h>
#include <Vtmu_fractal_shared.h>
#include <Vtmu_noise.h>
#include <Vtmu_noise_threads.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "formats/formats.hpp"
#include "harness/hls_runner.hpp"
#include "hls/perlin/fractal_sc.hpp"
#include "hls/perlin/noise_sc.hpp"
#include "icarus/icarus_engine.hpp"
#include "perlin/noise_ideal.hpp"

namespace tmu::tb {
namespace fmts = tmu::formats;
using perlin::NoiseConfig;

namespace {

const Schema kInputs({{"u", fmts::kSolidCoord},
                      {"v", fmts::kSolidCoord},
                      {"w", fmts::kSolidCoord}});
const Schema kPerlinOutputs({{"p", fmts::kNoiseValue}});
const Schema kTurbulenceOutputs({{"fractal_sum", fmts::kFractalValue},
                                 {"turbulence", fmts::kFractalValue}});

constexpr int kCoordW = fmts::kSolidCoord.width();      // 24
constexpr int32_t kUnit = 1 << perlin::kCoordFracBits;  // 1.0, raw SQ12.12
constexpr int32_t kCoordMin = -(1 << (kCoordW - 1));
constexpr int32_t kCoordMax = (1 << (kCoordW - 1)) - 1;
constexpr uint32_t kLatticeMask = (1u << perlin::kLatticeBits) - 1;
constexpr int32_t kNoiseOne = perlin::noise_one(NoiseConfig{});  // 1.0 of P, raw
constexpr int32_t kSumOne = perlin::sum_one(NoiseConfig{});      // 1.0 of the sums, raw

constexpr uint64_t mask(int width) { return (uint64_t{1} << width) - 1; }
bool in_range(int64_t x) { return x >= kCoordMin && x <= kCoordMax; }
// x as a 24-bit two's complement value (the coordinate an octave shift wraps to).
int32_t wrap24(int64_t x) {
  const auto low = static_cast<uint32_t>(static_cast<uint64_t>(x) & mask(kCoordW));
  return static_cast<int32_t>(low << (32 - kCoordW)) >> (32 - kCoordW);
}

int32_t lattice_value_at(int32_t i, int32_t j, int32_t k) {
  return perlin::lattice_value(static_cast<uint32_t>(i) & kLatticeMask,
                               static_cast<uint32_t>(j) & kLatticeMask,
                               static_cast<uint32_t>(k) & kLatticeMask);
}

using Lattice = std::array<int32_t, 3>;
constexpr int32_t kSearch = 16;  // directed searches look at the lattice points [-16, 16)^3

// The first n lattice points of the search cube that satisfy `want` (in a fixed order).
std::vector<Lattice> lattice_points_where(const std::function<bool(const Lattice&)>& want,
                                          size_t n) {
  std::vector<Lattice> found;
  for (int32_t i = -kSearch; i < kSearch && found.size() < n; ++i) {
    for (int32_t j = -kSearch; j < kSearch && found.size() < n; ++j) {
      for (int32_t k = -kSearch; k < kSearch && found.size() < n; ++k) {
        if (want({i, j, k})) found.push_back({i, j, k});
      }
    }
  }
  return found;
}

// Adds an item when all three coordinates are SolidCoord values.
void add_item(std::vector<Txn>& items, int64_t u, int64_t v, int64_t w) {
  if (in_range(u) && in_range(v) && in_range(w)) {
    items.push_back(
        solid_item(static_cast<int32_t>(u), static_cast<int32_t>(v), static_cast<int32_t>(w)));
  }
}

// --- engines -----------------------------------------------------------------------------

class PerlinGoldenEngine : public Engine {
 public:
  std::string name() const override { return "golden"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions&) override {
    RunResult r;
    r.outputs.reserve(items.size());
    const auto start = std::chrono::steady_clock::now();
    for (const Txn& t : items) {
      const auto [u, v, w] = solid_coords(t);
      Txn out;
      out.f[kPerlinP] = static_cast<uint64_t>(perlin::noise(NoiseConfig{}, u, v, w)) &
                        mask(fmts::kNoiseValue.width());
      r.outputs.push_back(out);
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.output_cycles.assign(r.outputs.size(), 0);
    return r;
  }
};

class TurbulenceGoldenEngine : public Engine {
 public:
  std::string name() const override { return "golden"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions&) override {
    RunResult r;
    r.outputs.reserve(items.size());
    const auto start = std::chrono::steady_clock::now();
    const uint64_t m = mask(fmts::kFractalValue.width());
    for (const Txn& t : items) {
      const auto [u, v, w] = solid_coords(t);
      const perlin::FractalSums s = perlin::fractal_sums(NoiseConfig{}, u, v, w);
      Txn out;
      out.f[kTurbSum] = static_cast<uint64_t>(s.fractal_sum) & m;
      out.f[kTurbTurbulence] = static_cast<uint64_t>(s.turbulence) & m;
      r.outputs.push_back(out);
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.output_cycles.assign(r.outputs.size(), 0);
    return r;
  }
};

// The ideal (double precision) noise and fractal sums of the same coordinates, rounded to the
// output formats only so that the run has outputs: `texsim levels` times it, nothing compares it.
class NoiseIdealEngine : public Engine {
 public:
  explicit NoiseIdealEngine(bool fractal) : fractal_(fractal) {}
  std::string name() const override { return "ideal"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions&) override {
    RunResult r;
    r.outputs.reserve(items.size());
    const double unit = std::ldexp(1.0, fmts::kSolidCoord.frac_bits);
    const auto start = std::chrono::steady_clock::now();
    for (const Txn& t : items) {
      const auto [u, v, w] = solid_coords(t);
      Txn out;
      if (fractal_) {
        const auto s = perlin::ideal::fractal_sums(u / unit, v / unit, w / unit);
        out.f[kTurbSum] = raw_of(s.fractal_sum, fmts::kFractalValue);
        out.f[kTurbTurbulence] = raw_of(s.turbulence, fmts::kFractalValue);
      } else {
        out.f[kPerlinP] =
            raw_of(perlin::ideal::noise(u / unit, v / unit, w / unit), fmts::kNoiseValue);
      }
      r.outputs.push_back(out);
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.output_cycles.assign(r.outputs.size(), 0);
    return r;
  }

 private:
  static uint64_t raw_of(double value, const fx::Format& format) {
    return static_cast<uint64_t>(std::llround(std::ldexp(value, format.frac_bits))) &
           mask(format.width());
  }
  bool fractal_;
};

// The hls modules with their signals, driven by the harness's ScDriver.
template <class Sc>
class CoordBench : public sc_core::sc_module, public ScAdapter {
 public:
  template <class... Args>
  CoordBench(sc_core::sc_module_name name, sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n,
             Args&&... args)
      : sc_module(name), dut_("dut", std::forward<Args>(args)...) {
    dut_.clk_i(clk);
    dut_.rst_ni(rst_n);
    dut_.in_valid_i(in_valid_);
    dut_.in_ready_o(in_ready_);
    dut_.in_u_i(in_u_);
    dut_.in_v_i(in_v_);
    dut_.in_w_i(in_w_);
    dut_.out_valid_o(out_valid_);
    dut_.out_ready_i(out_ready_);
  }
  void drive(const Txn* item) override {
    in_valid_.write(item != nullptr);
    const std::array<int32_t, 3> c = item ? solid_coords(*item) : std::array<int32_t, 3>{};
    in_u_.write(c[0]);
    in_v_.write(c[1]);
    in_w_.write(c[2]);
  }
  bool accepts(const Txn&) const override { return in_ready_.read(); }
  void set_out_ready(bool ready) override { out_ready_.write(ready); }
  bool out_valid() const override { return out_valid_.read(); }

 protected:
  Sc dut_;

 private:
  sc_core::sc_signal<bool> in_valid_{"in_valid"}, in_ready_{"in_ready"};
  sc_core::sc_signal<typename Sc::coord_t> in_u_{"in_u"}, in_v_{"in_v"}, in_w_{"in_w"};
  sc_core::sc_signal<bool> out_valid_{"out_valid"}, out_ready_{"out_ready"};
};

class PerlinHlsBench : public CoordBench<hls::NoiseSc> {
 public:
  PerlinHlsBench(sc_core::sc_module_name name, sc_core::sc_clock& clk,
                 sc_core::sc_signal<bool>& rst_n)
      : CoordBench(name, clk, rst_n) {
    dut_.out_p_o(out_p_);
  }
  Txn out() const override {
    Txn t;
    t.f[kPerlinP] = out_p_.read();
    return t;
  }

 private:
  sc_core::sc_signal<hls::NoiseSc::noise_t> out_p_{"out_p"};
};

class TurbulenceHlsBench : public CoordBench<hls::FractalSc> {
 public:
  TurbulenceHlsBench(sc_core::sc_module_name name, sc_core::sc_clock& clk,
                     sc_core::sc_signal<bool>& rst_n, bool shared)
      : CoordBench(name, clk, rst_n, shared) {
    dut_.out_sum_o(out_sum_);
    dut_.out_turbulence_o(out_turbulence_);
  }
  Txn out() const override {
    Txn t;
    t.f[kTurbSum] = out_sum_.read();
    t.f[kTurbTurbulence] = out_turbulence_.read();
    return t;
  }

 private:
  sc_core::sc_signal<hls::FractalSc::sum_t> out_sum_{"out_sum"}, out_turbulence_{"out_turbulence"};
};

class PerlinHlsEngine : public Engine {
 public:
  std::string name() const override { return "hls"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    return run_hls<PerlinHlsBench>(
        [](sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n) {
          return std::make_unique<PerlinHlsBench>("bench", clk, rst_n);
        },
        items, items.size(), options);
  }
};

class TurbulenceHlsEngine : public Engine {
 public:
  explicit TurbulenceHlsEngine(bool shared) : shared_(shared) {}
  std::string name() const override { return "hls"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions& options) override {
    return run_hls<TurbulenceHlsBench>(
        [this](sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst_n) {
          return std::make_unique<TurbulenceHlsBench>("bench", clk, rst_n, shared_);
        },
        items, items.size(), options);
  }

 private:
  bool shared_;
};

// --- random coordinates --------------------------------------------------------------------

enum class AxisKind { kUniform, kSmall, kLattice, kBoundary, kLarge, kLowBits, kCount };

// Raw fractions at and next to a cell boundary and the fade index's edges.
constexpr std::array<int32_t, 8> kBoundaryFractions = {0, 1, 15, 16, 0x7FF, 0x800, 0xFF0, 0xFFF};

int32_t random_axis(std::mt19937_64& rng, AxisKind kind) {
  const auto index = [&rng] { return static_cast<int32_t>(rng() % 4096) - 2048; };
  switch (kind) {
    case AxisKind::kSmall:  // within 8 units of the origin
      return static_cast<int32_t>(rng() % (16 * kUnit)) - 8 * kUnit;
    case AxisKind::kLattice:
      return index() * kUnit;
    case AxisKind::kBoundary:  // always in range: at most 2047 units + 0xFFF
      return index() * kUnit + kBoundaryFractions[rng() % kBoundaryFractions.size()];
    case AxisKind::kLarge: {  // |x| >= 2^20: octave 3 (and for 2^22, octave 1) wraps
      const auto mag = static_cast<int32_t>(0x100000 + rng() % (kCoordMax - 0x100000 + 1));
      return rng() % 2 ? mag : -mag;
    }
    case AxisKind::kLowBits: {  // the bits below the fade index all zero or all one
      const int32_t x = wrap24(static_cast<int64_t>(rng()));
      return rng() % 2 ? (x & ~0xF) : (x | 0xF);
    }
    default:
      return wrap24(static_cast<int64_t>(rng()));
  }
}

AxisKind random_kind(std::mt19937_64& rng) {
  return static_cast<AxisKind>(rng() % static_cast<uint64_t>(AxisKind::kCount));
}

}  // namespace

Txn solid_item(int32_t u, int32_t v, int32_t w) {
  Txn t;
  t.f[kSolidU] = static_cast<uint32_t>(u) & mask(kCoordW);
  t.f[kSolidV] = static_cast<uint32_t>(v) & mask(kCoordW);
  t.f[kSolidW] = static_cast<uint32_t>(w) & mask(kCoordW);
  return t;
}

std::array<int32_t, 3> solid_coords(const Txn& item) {
  return {wrap24(static_cast<int64_t>(item.f[kSolidU])),
          wrap24(static_cast<int64_t>(item.f[kSolidV])),
          wrap24(static_cast<int64_t>(item.f[kSolidW]))};
}

NoiseTrace trace_noise(int64_t u, int64_t v, int64_t w) {
  const NoiseConfig c;
  NoiseTrace t;
  const std::array<int64_t, 3> coords = {u, v, w};
  for (size_t a = 0; a < 3; ++a) {
    t.index[a] = static_cast<uint32_t>(coords[a] >> perlin::kCoordFracBits) & kLatticeMask;
    t.frac[a] = static_cast<uint32_t>(coords[a]) & static_cast<uint32_t>(kUnit - 1);
    t.fade_index[a] = t.frac[a] >> (perlin::kCoordFracBits - c.fade_index_bits);
    t.fade[a] = perlin::fade_entry(c, t.fade_index[a]);
  }
  for (uint32_t n = 0; n < 8; ++n) {
    t.corner[n] = perlin::lattice_value(t.index[0] + (n & 1), t.index[1] + ((n >> 1) & 1),
                                        t.index[2] + (n >> 2)) *
                  (1 << c.lerp_extra_bits);
  }
  const int b = c.fade_bits;
  const auto lerp = [&t, b](int32_t lo, int32_t hi, uint32_t weight) {
    const int64_t product = static_cast<int64_t>(weight) * (int64_t{hi} - lo);
    if ((product & ((int64_t{1} << b) - 1)) == (int64_t{1} << (b - 1))) t.tie = true;
    if (weight > 0 && hi < lo) t.step_down = true;
    return perlin::lerp(lo, hi, weight, b);
  };
  for (size_t n = 0; n < 4; ++n) t.x[n] = lerp(t.corner[2 * n], t.corner[2 * n + 1], t.fade[0]);
  for (size_t n = 0; n < 2; ++n) t.y[n] = lerp(t.x[2 * n], t.x[2 * n + 1], t.fade[1]);
  t.p = lerp(t.y[0], t.y[1], t.fade[2]);
  return t;
}

std::vector<Txn> noise_directed_items() {
  std::vector<Txn> items;
  const auto add = [&items](int64_t u, int64_t v, int64_t w) { add_item(items, u, v, w); };
  // Lattice points around the origin (every fade weight 0: P is a corner's value).
  for (int32_t i = -2; i <= 2; ++i) {
    for (int32_t j = -2; j <= 2; ++j) {
      for (int32_t k = -2; k <= 2; ++k) add(i * kUnit, j * kUnit, k * kUnit);
    }
  }
  // Lattice points whose value is -1.0 (P = -1.0, |P| one bit wider than P) or 127/128, and
  // one LSB to either side of them (the cell below on every axis; a fraction of 1/4096).
  for (const int32_t value : {-128, 127}) {
    const auto points = lattice_points_where(
        [value](const Lattice& l) { return lattice_value_at(l[0], l[1], l[2]) == value; }, 4);
    for (const Lattice& l : points) {
      const int64_t u = int64_t{l[0]} * kUnit, v = int64_t{l[1]} * kUnit, w = int64_t{l[2]} * kUnit;
      add(u, v, w);
      add(u - 1, v - 1, w - 1);
      add(u + 1, v + 1, w + 1);
      add(u + 16, v, w - 16);
    }
  }
  // Cell boundaries: raw fractions ..FFF, ..000, ..001, the fade index's edges (15 | 16:
  // index 0 | 1; 0xFEF | 0xFF0: index 254 | 255), the middle, on each axis and on all three;
  // at the origin, next to it, and at the ends of the range.
  for (const int32_t base : {0, 1, -1, 5, -7, 2047, -2048}) {
    for (const int32_t d : {-1, 0, 1, 15, 16, 0x7FF, 0x800, 0xFEF, 0xFF0, 0xFFF}) {
      const int64_t x = int64_t{base} * kUnit + d;
      add(x, 3 * kUnit + 0x5A0, -2 * kUnit + 0x3C0);
      add(9 * kUnit + 0x1F0, x, 0x777);
      add(-0x2345, 0x6789, x);
      add(x, x, x);
    }
  }
  // Every fade index on every axis (u k, v k, w 255 - k), with the bits below it varying.
  for (int32_t k = 0; k < 256; ++k) {
    add(k * 16 + k % 16, 3 * kUnit + k * 16, -5 * kUnit + (255 - k) * 16 + 15);
  }
  // Negative coordinates: -1 LSB, -1, -1 - 1 LSB, -1/2, -3/2, -1/256 (fade index 255), -17 LSB.
  for (const int32_t x : {-1, -kUnit, -kUnit - 1, -kUnit / 2, -3 * kUnit / 2, -16, -17}) {
    add(x, 0, 0);
    add(0, x, 0);
    add(0, 0, x);
    add(x, 2 * x, 3 * x);
  }
  // The SolidCoord extremes -2^23, 2^23 - 1 against each other, -1 LSB and 0.
  for (const int32_t a : {kCoordMin, kCoordMax, -1, 0}) {
    for (const int32_t b : {kCoordMin, kCoordMax, -1, 0}) {
      for (const int32_t c : {kCoordMin, kCoordMax, -1, 0}) add(a, b, c);
    }
  }
  // u = v = w.
  for (const int32_t x : {1, 0x800, 7 * kUnit + 0x9A0, 0x123456, -0x123456, -kUnit - 0x10}) {
    add(x, x, x);
  }
  // Coordinates whose octave shifts leave 24 bits (|x| >= 2^20, 2^21, 2^22).
  for (const int32_t x : {0x0FFFFF, 0x100000, 0x1FFFFF, 0x200000, 0x3FFFFF, 0x400000, -0x400000,
                          -0x400001, 0x555555, -0x2AAAAB, 0x7FF800, -0x7FF800}) {
    add(x, 0x12345, -x / 3);
    add(-0x54321, x, x / 5);
    add(x / 7, -0x3210, x);
    add(x, x, x);
  }
  return items;
}

std::vector<Txn> noise_random_items(std::mt19937_64& rng, size_t count) {
  std::vector<Txn> items;
  items.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    const uint64_t kind = rng() % 16;
    std::array<int32_t, 3> c{};
    if (kind < 6) {
      for (auto& x : c) x = random_axis(rng, AxisKind::kUniform);
    } else if (kind < 8) {
      for (auto& x : c) x = random_axis(rng, AxisKind::kSmall);
    } else if (kind < 10) {
      for (auto& x : c) x = random_axis(rng, AxisKind::kLattice);
    } else if (kind < 12) {
      for (auto& x : c) x = random_axis(rng, AxisKind::kBoundary);
    } else if (kind < 13) {
      c[0] = c[1] = c[2] = random_axis(rng, random_kind(rng));
    } else if (kind < 14) {
      for (auto& x : c) x = random_axis(rng, AxisKind::kLarge);
    } else {
      for (auto& x : c) x = random_axis(rng, random_kind(rng));
    }
    items.push_back(solid_item(c[0], c[1], c[2]));
  }
  return items;
}

// --- perlin ------------------------------------------------------------------------------------

const Schema& PerlinBlock::inputs() const { return kInputs; }
const Schema& PerlinBlock::outputs() const { return kPerlinOutputs; }

std::vector<Txn> PerlinBlock::directed_items() const { return noise_directed_items(); }

std::vector<Txn> PerlinBlock::random_items(std::mt19937_64& rng, size_t count) const {
  return noise_random_items(rng, count);
}

std::unique_ptr<Engine> PerlinBlock::engine(const std::string& level) const {
  if (level == "golden") return std::make_unique<PerlinGoldenEngine>();
  if (level == "hls") return std::make_unique<PerlinHlsEngine>();
  if (level == "rtl") return make_perlin_rtl_engine<Vtmu_noise>("rtl");
  if (level == "icarus")
    return make_icarus_engine("icarus", {"noise_tb", "tmu_noise"}, kInputs, kPerlinOutputs);
  if (level == "ideal") return std::make_unique<NoiseIdealEngine>(false);
  if (level == "rtl-threads") return make_perlin_rtl_engine<Vtmu_noise_threads>("rtl-threads");
  throw std::invalid_argument("perlin: no engine '" + level +
                              "' (golden, hls, rtl, icarus; ideal, rtl-threads)");
}

namespace {
constexpr const char* kLatticePoint = "lattice point (every fraction zero)";
constexpr const char* kOneFracZero = "one fraction zero, another not";
constexpr const char* kFracFFF = "raw fraction 0xFFF (below boundary)";
constexpr const char* kFrac001 = "raw fraction 0x001 (above boundary)";
constexpr const char* kLowBits = "fraction bits below fade index set";
constexpr const char* kFade0Nonzero = "fade index 0, fraction not zero";
constexpr const char* kFade255 = "fade index 255 (weight 2^B)";
constexpr const char* kFade128 = "fade index 128 (weight 1/2)";
constexpr std::array<const char*, 3> kEveryFade = {"every fade index on u", "every fade index on v",
                                                   "every fade index on w"};
constexpr const char* kNegative = "negative coordinate";
constexpr const char* kAllNegative = "every coordinate negative";
constexpr const char* kIndexWrap = "lattice index 4095 (+1 wraps to 0)";
constexpr const char* kMinCoord = "coordinate -2^23";
constexpr const char* kMaxCoord = "coordinate 2^23 - 1";
constexpr const char* kEqual = "u = v = w";
constexpr const char* kLarge = "|coord| >= 2^20 (octave 3 wraps)";
constexpr const char* kCornerMin = "a corner's lattice value -1.0";
constexpr const char* kCornerMax = "a corner's lattice value 127/128";
constexpr const char* kPMinusOne = "P = -1.0";
constexpr const char* kPZero = "P = 0";
constexpr const char* kPPositive = "P > 0";
constexpr const char* kPNegative = "P < 0";
constexpr const char* kPLarge = "|P| >= 1/2";
constexpr const char* kTie = "lerp tie: c (b-a) = 2^(B-1) mod 2^B";
constexpr const char* kStepDown = "a lerp steps down (b < a, c > 0)";

// Cases of the coordinates alone, shared by both blocks.
void cover_coords(const std::array<int32_t, 3>& c, Coverage& cov) {
  int negative = 0;
  for (const int32_t x : c) {
    if (x < 0) ++negative;
    if (x == kCoordMin) ++cov[kMinCoord];
    if (x == kCoordMax) ++cov[kMaxCoord];
  }
  if (negative > 0) ++cov[kNegative];
  if (negative == 3) ++cov[kAllNegative];
  if (c[0] == c[1] && c[1] == c[2]) ++cov[kEqual];
}
}  // namespace

std::vector<std::string> PerlinBlock::coverage_cases() const {
  std::vector<std::string> cases = {kLatticePoint, kOneFracZero,  kFracFFF, kFrac001,
                                    kLowBits,      kFade0Nonzero, kFade255, kFade128};
  cases.insert(cases.end(), kEveryFade.begin(), kEveryFade.end());
  cases.insert(cases.end(), {kNegative, kAllNegative, kIndexWrap, kMinCoord, kMaxCoord, kEqual,
                             kLarge, kCornerMin, kCornerMax, kPMinusOne, kPZero, kPPositive,
                             kPNegative, kPLarge, kTie, kStepDown});
  return cases;
}

void PerlinBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                        Coverage& cov) const {
  if (index == 0 || index != cover_next_) {
    for (auto& s : seen_fade_) s.reset();
  }
  cover_next_ = index + 1;
  const std::array<int32_t, 3> c = solid_coords(items[index]);
  const NoiseTrace t = trace_noise(c[0], c[1], c[2]);
  cover_coords(c, cov);
  int zero_fracs = 0;
  for (size_t a = 0; a < 3; ++a) {
    const uint32_t f = t.frac[a];
    if (f == 0) ++zero_fracs;
    if (f == 0xFFF) ++cov[kFracFFF];
    if (f == 0x001) ++cov[kFrac001];
    if ((f & 0xF) != 0) ++cov[kLowBits];
    if (t.fade_index[a] == 0 && f != 0) ++cov[kFade0Nonzero];
    if (t.fade_index[a] == 255) ++cov[kFade255];
    if (t.fade_index[a] == 128) ++cov[kFade128];
    if (t.index[a] == kLatticeMask) ++cov[kIndexWrap];
    if (std::abs(c[a]) >= 0x100000) ++cov[kLarge];
    if (!seen_fade_[a].test(t.fade_index[a])) {
      seen_fade_[a].set(t.fade_index[a]);
      if (seen_fade_[a].all()) ++cov[kEveryFade[a]];
    }
  }
  if (zero_fracs == 3) ++cov[kLatticePoint];
  if (zero_fracs > 0 && zero_fracs < 3) ++cov[kOneFracZero];
  const int32_t one16 = 1 << NoiseConfig{}.lerp_extra_bits;  // a lattice value's LSB in P
  if (std::find(t.corner.begin(), t.corner.end(), -128 * one16) != t.corner.end())
    ++cov[kCornerMin];
  if (std::find(t.corner.begin(), t.corner.end(), 127 * one16) != t.corner.end()) ++cov[kCornerMax];
  if (t.p == -kNoiseOne) ++cov[kPMinusOne];
  if (t.p == 0) ++cov[kPZero];
  if (t.p > 0) ++cov[kPPositive];
  if (t.p < 0) ++cov[kPNegative];
  if (std::abs(t.p) >= kNoiseOne / 2) ++cov[kPLarge];
  if (t.tie) ++cov[kTie];
  if (t.step_down) ++cov[kStepDown];
}

std::vector<Port> PerlinBlock::ports() const {
  const int cw = fmts::kSolidCoord.width();
  return {{"clk_i"},
          {"rst_ni"},
          {"in_valid_i"},
          {"in_ready_o"},
          {"in_u_i", cw, true},
          {"in_v_i", cw, true},
          {"in_w_i", cw, true},
          {"out_valid_o"},
          {"out_ready_i"},
          {"out_p_o", fmts::kNoiseValue.width(), true}};
}

// --- turbulence --------------------------------------------------------------------------------

TurbulenceBlock::TurbulenceBlock(const BlockOptions& options) : shared_(options.fractal_shared) {}

const Schema& TurbulenceBlock::inputs() const { return kInputs; }
const Schema& TurbulenceBlock::outputs() const { return kTurbulenceOutputs; }

std::vector<Txn> TurbulenceBlock::directed_items() const {
  std::vector<Txn> items = noise_directed_items();
  const auto add = [&items](int64_t u, int64_t v, int64_t w) { add_item(items, u, v, w); };
  // Octave i = 1..3 on a lattice point of value -1.0: the coordinates L 2^-i (exact: 4096 /
  // 8 is an integer), so that the shifted ones are L.
  const auto minus_one = lattice_points_where(
      [](const Lattice& l) { return lattice_value_at(l[0], l[1], l[2]) == -128; }, 2);
  for (const Lattice& l : minus_one) {
    for (int i = 1; i < perlin::kOctaves; ++i) {
      add(l[0] * (kUnit >> i), l[1] * (kUnit >> i), l[2] * (kUnit >> i));
    }
  }
  // Lattice points (every octave on one) whose sums are extreme: turbulence above 1 and 3/2,
  // the fractal sum above 1 and below -1, every octave's P >= 0 or <= 0.
  const auto sums_at = [](const Lattice& l) {
    return perlin::fractal_sums(NoiseConfig{}, int64_t{l[0]} * kUnit, int64_t{l[1]} * kUnit,
                                int64_t{l[2]} * kUnit);
  };
  const std::vector<std::function<bool(const perlin::FractalSums&)>> wants = {
      [](const perlin::FractalSums& s) { return s.turbulence > kSumOne; },
      [](const perlin::FractalSums& s) { return s.turbulence > kSumOne * 3 / 2; },
      [](const perlin::FractalSums& s) { return s.fractal_sum > kSumOne; },
      [](const perlin::FractalSums& s) { return s.fractal_sum < -kSumOne; },
      [](const perlin::FractalSums& s) { return s.fractal_sum == s.turbulence && s.turbulence; },
      [](const perlin::FractalSums& s) { return s.fractal_sum == -s.turbulence && s.turbulence; }};
  for (const auto& want : wants) {
    for (const Lattice& l :
         lattice_points_where([&](const Lattice& p) { return want(sums_at(p)); }, 2)) {
      add(int64_t{l[0]} * kUnit, int64_t{l[1]} * kUnit, int64_t{l[2]} * kUnit);
    }
  }
  return items;
}

std::vector<Txn> TurbulenceBlock::random_items(std::mt19937_64& rng, size_t count) const {
  return noise_random_items(rng, count);
}

std::unique_ptr<Engine> TurbulenceBlock::engine(const std::string& level) const {
  if (level == "golden") return std::make_unique<TurbulenceGoldenEngine>();
  if (level == "hls") return std::make_unique<TurbulenceHlsEngine>(shared_);
  if (level == "rtl") {
    if (shared_) return make_turbulence_rtl_engine<Vtmu_fractal_shared>("rtl");
    return make_turbulence_rtl_engine<Vtmu_fractal_pipelined>("rtl");
  }
  if (level == "icarus") {
    return make_icarus_engine(
        "icarus", {"fractal_tb", shared_ ? "tmu_fractal_shared" : "tmu_fractal_pipelined"}, kInputs,
        kTurbulenceOutputs);
  }
  if (level == "ideal") return std::make_unique<NoiseIdealEngine>(true);
  if (level == "rtl-threads" && !shared_) {
    return make_turbulence_rtl_engine<Vtmu_fractal_pipelined_threads>("rtl-threads");
  }
  throw std::invalid_argument("turbulence: no engine '" + level +
                              "' (golden, hls, rtl, icarus; ideal; rtl-threads when pipelined)");
}

namespace {
constexpr std::array<const char*, 4> kOctaveNegative = {"octave 0: P < 0", "octave 1: P < 0",
                                                        "octave 2: P < 0", "octave 3: P < 0"};
constexpr std::array<const char*, 4> kOctavePositive = {"octave 0: P > 0", "octave 1: P > 0",
                                                        "octave 2: P > 0", "octave 3: P > 0"};
constexpr std::array<const char*, 4> kOctaveMinusOne = {"octave 0: P = -1.0", "octave 1: P = -1.0",
                                                        "octave 2: P = -1.0", "octave 3: P = -1.0"};
constexpr const char* kOctave1Wraps = "octave 1 wraps (|2x| >= 2^23)";
constexpr const char* kOctave3Wraps = "octave 3 wraps (|8x| >= 2^23)";
constexpr const char* kAllLattice = "every octave at a lattice point";
constexpr const char* kTurbAbove1 = "turbulence > 1";
constexpr const char* kTurbAbove15 = "turbulence > 3/2";
constexpr const char* kSumAbove1 = "fractal sum > 1";
constexpr const char* kSumBelowMinus1 = "fractal sum < -1";
constexpr const char* kAllNonNegative = "sum = turbulence > 0 (all P >= 0)";
constexpr const char* kAllNonPositive = "sum = -turbulence < 0 (all P <= 0)";
constexpr const char* kBothZero = "fractal sum = turbulence = 0";
}  // namespace

std::vector<std::string> TurbulenceBlock::coverage_cases() const {
  std::vector<std::string> cases;
  for (int i = 0; i < perlin::kOctaves; ++i) {
    const auto k = static_cast<size_t>(i);
    cases.insert(cases.end(), {kOctaveNegative[k], kOctavePositive[k], kOctaveMinusOne[k]});
  }
  cases.insert(cases.end(), {kOctave1Wraps, kOctave3Wraps, kAllLattice, kTurbAbove1, kTurbAbove15,
                             kSumAbove1, kSumBelowMinus1, kAllNonNegative, kAllNonPositive,
                             kBothZero, kNegative, kAllNegative, kMinCoord, kMaxCoord, kEqual});
  return cases;
}

void TurbulenceBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                            Coverage& cov) const {
  const std::array<int32_t, 3> c = solid_coords(items[index]);
  cover_coords(c, cov);
  bool all_lattice = true;
  for (int i = 0; i < perlin::kOctaves; ++i) {
    const auto k = static_cast<size_t>(i);
    const int64_t scale = int64_t{1} << i;
    const int32_t p = perlin::noise(NoiseConfig{}, c[0] * scale, c[1] * scale, c[2] * scale);
    if (p < 0) ++cov[kOctaveNegative[k]];
    if (p > 0) ++cov[kOctavePositive[k]];
    if (p == -kNoiseOne) ++cov[kOctaveMinusOne[k]];
    for (const int32_t x : c) {
      if (((x * scale) & (kUnit - 1)) != 0) all_lattice = false;
    }
  }
  for (const int32_t x : c) {
    if (!in_range(int64_t{x} * 2)) ++cov[kOctave1Wraps];
    if (!in_range(int64_t{x} * 8)) ++cov[kOctave3Wraps];
  }
  if (all_lattice) ++cov[kAllLattice];
  const perlin::FractalSums s = perlin::fractal_sums(NoiseConfig{}, c[0], c[1], c[2]);
  if (s.turbulence > kSumOne) ++cov[kTurbAbove1];
  if (s.turbulence > kSumOne * 3 / 2) ++cov[kTurbAbove15];
  if (s.fractal_sum > kSumOne) ++cov[kSumAbove1];
  if (s.fractal_sum < -kSumOne) ++cov[kSumBelowMinus1];
  if (s.turbulence > 0 && s.fractal_sum == s.turbulence) ++cov[kAllNonNegative];
  if (s.turbulence > 0 && s.fractal_sum == -s.turbulence) ++cov[kAllNonPositive];
  if (s.turbulence == 0) ++cov[kBothZero];
}

std::vector<Port> TurbulenceBlock::ports() const {
  const int cw = fmts::kSolidCoord.width(), sw = fmts::kFractalValue.width();
  return {{"clk_i"},
          {"rst_ni"},
          {"in_valid_i"},
          {"in_ready_o"},
          {"in_u_i", cw, true},
          {"in_v_i", cw, true},
          {"in_w_i", cw, true},
          {"out_valid_o"},
          {"out_ready_i"},
          {"out_sum_o", sw, true},
          {"out_turbulence_o", sw, true}};
}

std::string TurbulenceBlock::repro_options() const { return shared_ ? "--fractal shared" : ""; }

}  // namespace tmu::tb
