#include "blocks/fractal/fractal_block.hpp"

#include <cmath>
#include <functional>

#include "blocks/noise/solid_stimulus.hpp"
#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/perlin/fractal_sc.hpp"
#include "perlin/noise_ideal.hpp"
#include "rtl_models_fractal.hpp"

TMU_DESCRIBE_SC(fractal)

namespace tmu::tb {
namespace fmts = tmu::formats;
using perlin::NoiseConfig;
using D = desc::fractal;
using solid::kUnit;
using solid::Lattice;

namespace {

constexpr int32_t kNoiseOne = perlin::noise_one(NoiseConfig{});  // 1.0 of P, raw
constexpr int32_t kSumOne = perlin::sum_one(NoiseConfig{});      // 1.0 of the sums, raw

uint64_t raw_bits(int64_t value) {
  return static_cast<uint64_t>(value) & ((uint64_t{1} << fmts::kFractalValue.width()) - 1);
}

Txn output_of(int64_t sum, int64_t turbulence) {
  Txn out;
  out.f[D::out_sum] = raw_bits(sum);
  out.f[D::out_turbulence] = raw_bits(turbulence);
  return out;
}

class GoldenFractal : public Model {
 public:
  void step(const Txn& item, Sink& sink) override {
    const auto [u, v, w] = solid::coords(item, D::in_u);
    const perlin::FractalSums s = perlin::fractal_sums(NoiseConfig{}, u, v, w);
    sink.output(output_of(s.fractal_sum, s.turbulence));
  }
};

// The ideal (double precision) sums, rounded to the output format only so that the run has
// outputs: `texsim levels` times it, nothing compares it.
class IdealFractal : public Model {
 public:
  void step(const Txn& item, Sink& sink) override {
    const double unit = std::ldexp(1.0, fmts::kSolidCoord.frac_bits);
    const auto [u, v, w] = solid::coords(item, D::in_u);
    const auto s = perlin::ideal::fractal_sums(u / unit, v / unit, w / unit);
    const auto raw = [](double x) {
      return std::llround(std::ldexp(x, fmts::kFractalValue.frac_bits));
    };
    sink.output(output_of(raw(s.fractal_sum), raw(s.turbulence)));
  }
};

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

FractalBlock::FractalBlock(const BlockOptions& options)
    : DescribedBlockOf(D::table()), shared_(options.fractal_shared) {
  add_level("hls", hls_level<desc::fractal_sc, hls::FractalSc>(shared_));
  TMU_ADD_RTL_LEVELS(fractal, variant());
}

std::vector<Txn> FractalBlock::directed_items() const {
  std::vector<Txn> items = solid::directed_items();
  const auto add = [&items](int64_t u, int64_t v, int64_t w) { solid::add(items, u, v, w); };
  // Octave i = 1..3 on a lattice point of value -1.0: the coordinates L 2^-i (exact: 4096 /
  // 8 is an integer), so that the shifted ones are L.
  const auto minus_one = solid::lattice_points_where(
      [](const Lattice& l) { return solid::lattice_value_at(l[0], l[1], l[2]) == -128; }, 2);
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
         solid::lattice_points_where([&](const Lattice& p) { return want(sums_at(p)); }, 2)) {
      add(int64_t{l[0]} * kUnit, int64_t{l[1]} * kUnit, int64_t{l[2]} * kUnit);
    }
  }
  return items;
}

std::vector<Txn> FractalBlock::random_items(std::mt19937_64& rng, size_t count) const {
  return solid::random_items(rng, count);
}

std::unique_ptr<Model> FractalBlock::golden() const { return std::make_unique<GoldenFractal>(); }
std::unique_ptr<Model> FractalBlock::ideal() const { return std::make_unique<IdealFractal>(); }

std::vector<std::string> FractalBlock::coverage_cases() const {
  std::vector<std::string> cases;
  for (int i = 0; i < perlin::kOctaves; ++i) {
    const auto k = static_cast<size_t>(i);
    cases.insert(cases.end(), {kOctaveNegative[k], kOctavePositive[k], kOctaveMinusOne[k]});
  }
  cases.insert(cases.end(),
               {kOctave1Wraps, kOctave3Wraps, kAllLattice, kTurbAbove1, kTurbAbove15, kSumAbove1,
                kSumBelowMinus1, kAllNonNegative, kAllNonPositive, kBothZero});
  for (const std::string& c : solid::coord_cases()) cases.push_back(c);
  return cases;
}

void FractalBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                         Coverage& cov) const {
  const std::array<int32_t, 3> c = solid::coords(items[index], D::in_u);
  solid::cover_coords(c, cov);
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
    if (!solid::in_range(int64_t{x} * 2)) ++cov[kOctave1Wraps];
    if (!solid::in_range(int64_t{x} * 8)) ++cov[kOctave3Wraps];
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

std::string FractalBlock::variant() const { return shared_ ? "shared" : ""; }

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(fractal, FractalBlock)
