// The footprint assembly unit's hls model (hls/footprint/footprint_sc.hpp through
// make_footprint_hls_engine) against a direct golden computation (footprint::sample over the
// same items, CLUT writes applied): every output bit for bit, the probes counter equal to the
// sum of 2^k, and the memory's counters (accesses, bank reads, page faults, the hash of every
// access's banks and addresses in order) equal to those of the golden probes' plans.
//
// Fragments: isotropic, anisotropic up to ratio 64 at random angles (either vector the longer,
// sheared), magnified, zero vectors, parallel vectors (area 0), huge derivatives (up to the
// port's extremes), anywhere in the port; positions over and around the texture and at the
// port's extremes (probes beyond the port wrap or saturate). Every border mode x max probes
// 1, 4, 16, with the texel kind, filter, q rule and setup widths varying from run to run.
#include "blocks/footprint_hls.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "blocks/footprint_env.hpp"
#include "blocks/trilinear_block.hpp"
#include "footprint/footprint.hpp"
#include "formats/formats.hpp"

namespace tmu::tb {
namespace {

namespace fmts = tmu::formats;
using texram::Border;
using texram::Filter;
using texram::TexelKind;

constexpr int kW = fmts::kTexCoord.width();  // 24: coordinates and derivatives
static_assert(fmts::kTexDeriv.width() == kW);
constexpr int64_t kOne = int64_t{1} << fmts::kTexCoord.frac_bits;
constexpr int64_t kPortMin = fmts::kTexCoord.min_raw(), kPortMax = fmts::kTexCoord.max_raw();
constexpr int64_t kDerivMin = fmts::kTexDeriv.min_raw(), kDerivMax = fmts::kTexDeriv.max_raw();

constexpr std::array<Border, 4> kBorders = {Border::kWrap, Border::kClamp, Border::kBorder,
                                            Border::kMirror};
constexpr std::array<TexelKind, 5> kKinds = {TexelKind::kLuminance, TexelKind::kIndex,
                                             TexelKind::kTrueColour, TexelKind::kSingle,
                                             TexelKind::kCcc};

uint64_t port_bits(int64_t raw) { return static_cast<uint64_t>(raw) & ((uint64_t{1} << kW) - 1); }
int32_t from_bits(uint64_t field) {
  return static_cast<int32_t>(static_cast<int64_t>(field << (64 - kW)) >> (64 - kW));
}

Txn sample_item(const footprint::Request& r) {
  Txn t;
  t.f[kFpOp] = kFpOpSample;
  t.f[kFpU] = port_bits(r.u);
  t.f[kFpV] = port_bits(r.v);
  t.f[kFpR1u] = port_bits(r.r1u);
  t.f[kFpR1v] = port_bits(r.r1v);
  t.f[kFpR2u] = port_bits(r.r2u);
  t.f[kFpR2v] = port_bits(r.r2v);
  t.f[kFpShade] = r.shade;
  return t;
}

Txn clut_item(uint8_t index, uint32_t rgba) {
  Txn t;
  t.f[kFpOp] = kFpOpClutWrite;
  t.f[kFpClutAddr] = index;
  t.f[kFpClutRgba] = rgba;
  return t;
}

// The 256 writes that load a texture's CLUT.
std::vector<Txn> clut_load(const texram::TexramTexture& texture) {
  std::vector<Txn> items;
  for (size_t i = 0; i < texture.clut.size(); ++i) {
    items.push_back(clut_item(static_cast<uint8_t>(i), texture.clut[i]));
  }
  return items;
}

footprint::Request request_of(const Txn& t) {
  return {from_bits(t.f[kFpU]),
          from_bits(t.f[kFpV]),
          from_bits(t.f[kFpR1u]),
          from_bits(t.f[kFpR1v]),
          from_bits(t.f[kFpR2u]),
          from_bits(t.f[kFpR2v]),
          static_cast<uint32_t>(t.f[kFpShade])};
}

// ---- stimulus ----------------------------------------------------------------------------

enum Shape { kIsotropic, kAnisotropic, kMagnified, kZero, kParallel, kHuge, kAnyRaw, kShapes };
constexpr std::array<const char*, kShapes> kShapeNames = {
    "isotropic", "anisotropic", "magnified", "zero vectors", "parallel", "huge", "any raw"};

struct Stimulus {
  std::vector<Txn> items;
  std::array<int, kShapes> shapes{};
};

class Generator {
 public:
  Generator(uint64_t seed, const texram::Geometry& g)
      : rng_(seed), w_(int64_t{g.texel_width(0)} * kOne), h_(int64_t{g.texel_height(0)} * kOne) {}

  // `fragments` fragments, with a CLUT write now and then between them.
  Stimulus make(size_t fragments) {
    Stimulus s;
    while (s.items.size() < fragments + writes_) {
      if (rng_() % 40 == 0) {
        const uint64_t x = rng_();
        s.items.push_back(clut_item(static_cast<uint8_t>(x), static_cast<uint32_t>(x >> 8)));
        ++writes_;
        continue;
      }
      const auto shape = static_cast<Shape>(rng_() % kShapes);
      ++s.shapes[shape];
      s.items.push_back(sample_item(fragment(shape)));
    }
    return s;
  }

 private:
  int64_t uniform(int64_t lo, int64_t hi) {
    return lo + static_cast<int64_t>(rng_() % static_cast<uint64_t>(hi - lo + 1));
  }
  double real(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(rng_() >> 11) * 0x1p-53;
  }
  static int32_t deriv(double texels) {
    return static_cast<int32_t>(
        std::clamp<int64_t>(std::llround(texels * kOne), kDerivMin, kDerivMax));
  }

  footprint::Request fragment(Shape shape) {
    footprint::Request r;
    // Position: over the texture and around it mostly; anywhere; the port's extremes.
    const uint64_t where = rng_() % 10;
    const auto coord = [&](int64_t side) -> int32_t {
      if (where < 7) return static_cast<int32_t>(uniform(-side / 2, side + side / 2));
      if (where < 9) return static_cast<int32_t>(uniform(kPortMin, kPortMax));
      return static_cast<int32_t>(rng_() % 2 ? kPortMin + uniform(0, 64 * kOne)
                                             : kPortMax - uniform(0, 64 * kOne));
    };
    r.u = coord(w_);
    r.v = coord(h_);
    r.shade = static_cast<uint32_t>(rng_());

    const double angle = real(0, 2 * std::numbers::pi);
    const double c = std::cos(angle), s = std::sin(angle);
    const auto set = [&r](double ax, double ay, double bx, double by) {
      r.r1u = deriv(ax);
      r.r1v = deriv(ay);
      r.r2u = deriv(bx);
      r.r2v = deriv(by);
    };
    switch (shape) {
      case kIsotropic: {
        const double len = std::exp2(real(-4, 9));
        const double flip = rng_() % 2 ? 1.0 : -1.0;  // either orientation of the pair
        set(len * c, len * s, -flip * len * s, flip * len * c);
        break;
      }
      case kAnisotropic: {
        const double major = std::exp2(real(-1, 10));
        const double minor = major / std::exp2(real(0, 6));  // ratio 1 .. 64
        const double shear = real(-0.5, 0.5) * minor;        // not always a rectangle
        const double ax = major * c, ay = major * s;
        const double bx = -minor * s + shear * c, by = minor * c + shear * s;
        if (rng_() % 2) {
          set(ax, ay, bx, by);
        } else {
          set(bx, by, ax, ay);
        }
        break;
      }
      case kMagnified: {
        const double len = std::exp2(real(-9, 0));
        const double minor = len / std::exp2(real(0, 6));
        set(len * c, len * s, -minor * s, minor * c);
        if (rng_() % 2) {
          std::swap(r.r1u, r.r2u);
          std::swap(r.r1v, r.r2v);
        }
        break;
      }
      case kZero: {
        const double len = std::exp2(real(-4, 8));
        const uint64_t which = rng_() % 3;
        set(which == 1 ? 0 : len * c, which == 1 ? 0 : len * s, which == 2 ? 0 : -len * s,
            which == 2 ? 0 : len * c);
        if (which == 0) r.r1u = r.r1v = r.r2u = r.r2v = 0;
        break;
      }
      case kParallel: {
        // r2 = t r1 exactly in raw units: a zero cross product.
        const int64_t pu = uniform(-2000, 2000), pv = uniform(-2000, 2000);
        const int64_t a = uniform(-64, 64), b = uniform(-64, 64);
        r.r1u = static_cast<int32_t>(std::clamp(a * pu, kDerivMin, kDerivMax));
        r.r1v = static_cast<int32_t>(std::clamp(a * pv, kDerivMin, kDerivMax));
        r.r2u = static_cast<int32_t>(std::clamp(b * pu, kDerivMin, kDerivMax));
        r.r2v = static_cast<int32_t>(std::clamp(b * pv, kDerivMin, kDerivMax));
        break;
      }
      case kHuge: {
        const auto big = [&]() -> int32_t {
          switch (rng_() % 4) {
            case 0:
              return static_cast<int32_t>(kDerivMin);
            case 1:
              return static_cast<int32_t>(kDerivMax);
            case 2:
              return static_cast<int32_t>(uniform(kDerivMin, kDerivMin + kDerivMax / 8));
            default:
              return static_cast<int32_t>(uniform(kDerivMax - kDerivMax / 8, kDerivMax));
          }
        };
        r.r1u = big();
        r.r1v = rng_() % 2 ? big() : static_cast<int32_t>(uniform(-kOne, kOne));
        r.r2u = rng_() % 2 ? big() : static_cast<int32_t>(uniform(-kOne, kOne));
        r.r2v = big();
        break;
      }
      default:
        r.r1u = static_cast<int32_t>(uniform(kDerivMin, kDerivMax));
        r.r1v = static_cast<int32_t>(uniform(kDerivMin, kDerivMax));
        r.r2u = static_cast<int32_t>(uniform(kDerivMin, kDerivMax));
        r.r2v = static_cast<int32_t>(uniform(kDerivMin, kDerivMax));
        break;
    }
    return r;
  }

  std::mt19937_64 rng_;
  int64_t w_, h_;
  size_t writes_ = 0;
};

// ---- golden ------------------------------------------------------------------------------

struct Golden {
  std::vector<uint32_t> outputs;
  Counters memory;
  uint64_t probes = 0;
  std::map<int, int> k_histogram;  // log2 N -> fragments
  int beyond_port = 0;             // fragments with a probe whose position left the port
};

Golden golden(const FootprintEnv& env, const std::vector<Txn>& items) {
  Golden g;
  texram::TexramTexture texture = *env.trilinear.texture;  // CLUT writes change its CLUT
  TexramAccessLog log;
  for (const Txn& t : items) {
    if (t.f[kFpOp] == kFpOpClutWrite) {
      texture.clut[static_cast<uint8_t>(t.f[kFpClutAddr])] =
          static_cast<uint32_t>(t.f[kFpClutRgba]);
      continue;
    }
    const footprint::Request r = request_of(t);
    std::vector<texram::SamplePlan> plans;
    g.outputs.push_back(footprint::sample(texture, env.trilinear.config, env.config, r, &plans));
    for (const texram::SamplePlan& p : plans) log.sample(p.bank_address, p.planes);
    const footprint::Plan plan = footprint::plan(r, env.config);
    const int n = 1 << plan.log2_n;
    EXPECT_EQ(plans.size(), static_cast<size_t>(n));
    g.probes += static_cast<uint64_t>(n);
    ++g.k_histogram[plan.log2_n];
    // The outermost probes, exactly: p +- (N - 1) r / (2N).
    const int64_t du = plan.r2_longer ? r.r2u : r.r1u, dv = plan.r2_longer ? r.r2v : r.r1v;
    for (int64_t sign : {-1, 1}) {
      const int64_t u = r.u + sign * (n - 1) * du / (2 * n),
                    v = r.v + sign * (n - 1) * dv / (2 * n);
      if (u < kPortMin || u > kPortMax || v < kPortMin || v > kPortMax) {
        ++g.beyond_port;
        break;
      }
    }
  }
  g.memory = log.counters();
  return g;
}

uint64_t counter(const RunResult& r, const std::string& name) {
  const auto v = counter_value(r.counters, name);
  if (!v) ADD_FAILURE() << "no counter " << name;
  return v.value_or(0);
}

struct Totals {
  uint64_t fragments = 0, probes = 0, cycles = 0;
  double seconds = 0;
};

// Runs the hls engine on the items and compares with golden; returns the run.
RunResult check(const FootprintEnv& env, const std::vector<Txn>& items, const RunOptions& options,
                Totals* totals = nullptr) {
  const Golden g = golden(env, items);
  const RunResult r = make_footprint_hls_engine(env)->run(items, options);
  EXPECT_EQ(r.error, "");
  EXPECT_EQ(r.outputs.size(), g.outputs.size());
  size_t mismatches = 0;
  for (size_t i = 0, o = 0; i < items.size() && o < std::min(r.outputs.size(), g.outputs.size());
       ++i) {
    if (items[i].f[kFpOp] != kFpOpSample) continue;
    if (r.outputs[o].f[0] != g.outputs[o] && ++mismatches <= 5) {
      const footprint::Request q = request_of(items[i]);
      ADD_FAILURE() << "output " << o << " (item " << i << "): hls 0x" << std::hex
                    << r.outputs[o].f[0] << ", golden 0x" << g.outputs[o] << std::dec << "; u "
                    << q.u << " v " << q.v << " r1 (" << q.r1u << ", " << q.r1v << ") r2 (" << q.r2u
                    << ", " << q.r2v << ")";
    }
    ++o;
  }
  EXPECT_EQ(mismatches, 0u);
  EXPECT_EQ(counter(r, "probes"), g.probes);
  for (const auto& [name, value] : g.memory) {
    EXPECT_EQ(counter(r, name), value) << "memory counter " << name;
  }
  if (totals) {
    totals->fragments += r.outputs.size();
    totals->probes += counter(r, "probes");
    totals->cycles += r.cycles;
    totals->seconds += r.seconds;
  }
  return r;
}

RunOptions stalls(uint64_t seed, double in_idle, double out_stall) {
  RunOptions o;
  o.stalls = {seed, in_idle, out_stall};
  return o;
}

// ---- tests -------------------------------------------------------------------------------

// Every border mode (u, and v the same or another) x max probes 1, 4, 16: a few hundred
// random fragments of every shape, back-pressure on in half of the runs.
TEST(FootprintHlsTest, RandomFragmentsEveryBorderAndMaxProbes) {
  Totals totals;
  std::array<int, kShapes> shapes{};
  int beyond_port = 0;
  uint64_t seed = 500;
  for (size_t b = 0; b < kBorders.size(); ++b) {
    for (int log2_max : {0, 2, 4}) {
      ++seed;
      BlockOptions o;
      o.seed = seed;
      o.tri_kind = kKinds[seed % kKinds.size()];
      o.tri_filter = seed % 3 == 0 ? Filter::kBilinear : Filter::kTrilinear;
      o.tri_border_u = kBorders[b];
      o.tri_border_v = kBorders[(b + static_cast<size_t>(log2_max) / 2) % kBorders.size()];
      o.tri_log2_w = static_cast<int>(3 + seed % 6);  // 8 .. 256 texels
      o.tri_log2_h = static_cast<int>(3 + (seed / 3) % 6);
      FootprintEnv env;
      env.trilinear = make_trilinear_env(o);
      env.config.log2_max_probes = log2_max;
      env.config.q_rule = seed % 2 ? footprint::QRule::kHeights : footprint::QRule::kSides;
      if (seed % 4 == 0) env.config.widths = {8, 5, 6};
      SCOPED_TRACE("border u " + std::string(texram::name(*o.tri_border_u)) + " v " +
                   std::string(texram::name(*o.tri_border_v)) + ", max probes " +
                   std::to_string(1 << log2_max) + ", kind " +
                   std::string(texram::name(*o.tri_kind)) + ", q rule " +
                   std::string(footprint::name(env.config.q_rule)) + ", seed " +
                   std::to_string(seed));

      Generator gen(seed, env.trilinear.texture->geometry);
      Stimulus s = gen.make(300);
      std::vector<Txn> items = clut_load(*env.trilinear.texture);
      items.insert(items.end(), s.items.begin(), s.items.end());

      const bool back_pressure = seed % 2 == 1;
      check(env, items, back_pressure ? stalls(seed, 0.25, 0.25) : stalls(seed, 0, 0), &totals);

      // Every probe count up to the maximum was used.
      const Golden g = golden(env, items);
      for (int k = 0; k <= log2_max; ++k) EXPECT_GT(g.k_histogram.count(k), 0u) << "k = " << k;
      beyond_port += g.beyond_port;
      for (size_t i = 0; i < kShapes; ++i) shapes[i] += s.shapes[i];
    }
  }
  for (size_t i = 0; i < kShapes; ++i) {
    EXPECT_GT(shapes[i], 0) << kShapeNames[i];
    std::cout << "  " << kShapeNames[i] << ": " << shapes[i] << " fragments\n";
  }
  EXPECT_GT(beyond_port, 0);
  std::cout << "  fragments with a probe beyond the port: " << beyond_port << "\n";
  std::cout << "hls: " << totals.fragments << " fragments, " << totals.probes << " probes, "
            << totals.cycles << " cycles, " << totals.seconds
            << " s: " << static_cast<double>(totals.fragments) / totals.seconds << " fragments/s, "
            << static_cast<double>(totals.probes) / totals.seconds << " probes/s\n";
}

// A CLUT write after every fragment of an index texture, 16 probes each, under heavy
// back-pressure: a write must reach the trilinear unit after the previous fragment's probes and
// before the next one's, whatever is still in flight.
TEST(FootprintHlsTest, ClutWritesBetweenFragmentsInFlight) {
  BlockOptions o;
  o.seed = 77;
  o.tri_kind = TexelKind::kIndex;
  o.tri_filter = Filter::kTrilinear;
  o.tri_border_u = o.tri_border_v = Border::kWrap;
  o.tri_log2_w = o.tri_log2_h = 4;
  o.tri_pattern = "random";
  FootprintEnv env;
  env.trilinear = make_trilinear_env(o);
  env.config.log2_max_probes = 4;
  const texram::TexramTexture& tex = *env.trilinear.texture;
  std::vector<Txn> items = clut_load(tex);
  std::mt19937_64 rng(o.seed);
  for (int i = 0; i < 200; ++i) {
    // A long thin footprint across the texture: 16 probes over many texels.
    footprint::Request r;
    r.u = static_cast<int32_t>(rng() % (16 * kOne));
    r.v = static_cast<int32_t>(rng() % (16 * kOne));
    r.r1u = static_cast<int32_t>(12 * kOne);
    r.r1v = static_cast<int32_t>(rng() % (4 * kOne));
    r.r2u = 0;
    r.r2v = static_cast<int32_t>(kOne / 4);
    r.shade = static_cast<uint32_t>(rng());
    items.push_back(sample_item(r));
    // A texel index the next fragments read, to a new colour.
    const std::vector<uint8_t>& bank = tex.banks[rng() % 8];
    items.push_back(clut_item(bank.at(rng() % bank.size()), static_cast<uint32_t>(rng())));
  }
  const Golden g = golden(env, items);
  EXPECT_EQ(g.k_histogram.count(4), 1u);
  EXPECT_EQ(g.k_histogram.at(4), 200);
  for (double out_stall : {0.0, 0.7}) {
    for (double in_idle : {0.0, 0.5}) {
      SCOPED_TRACE("in idle " + std::to_string(in_idle) + ", out stall " +
                   std::to_string(out_stall));
      check(env, items, stalls(3, in_idle, out_stall));
    }
  }
}

// The comparison has teeth: the unit given an all-zero CLUT disagrees with golden given an
// all-ones one (an index texture read through the CLUT, T unmodified), and with a golden that
// plans at most one probe, on the probes counter.
TEST(FootprintHlsTest, WrongClutOrProbeCountIsCaught) {
  BlockOptions o;
  o.seed = 78;
  o.tri_kind = TexelKind::kIndex;
  o.tri_combine = texram::Combine::kOne;
  o.tri_border_u = o.tri_border_v = Border::kWrap;
  o.tri_log2_w = o.tri_log2_h = 3;
  FootprintEnv env;
  env.trilinear = make_trilinear_env(o);
  env.config.log2_max_probes = 4;
  std::vector<Txn> items, altered;
  for (size_t i = 0; i < 256; ++i) {
    items.push_back(clut_item(static_cast<uint8_t>(i), 0));
    altered.push_back(clut_item(static_cast<uint8_t>(i), 0xFFFF'FFFFu));
  }
  Generator gen(o.seed, env.trilinear.texture->geometry);
  const Stimulus s = gen.make(100);
  items.insert(items.end(), s.items.begin(), s.items.end());
  altered.insert(altered.end(), s.items.begin(), s.items.end());
  const RunResult r = make_footprint_hls_engine(env)->run(items, {});
  ASSERT_EQ(r.error, "");
  const Golden g = golden(env, altered);
  ASSERT_EQ(r.outputs.size(), g.outputs.size());
  size_t differ = 0;
  for (size_t i = 0; i < g.outputs.size(); ++i) differ += r.outputs[i].f[0] != g.outputs[i];
  EXPECT_GT(differ, g.outputs.size() / 2);

  FootprintEnv one = env;
  one.config.log2_max_probes = 0;
  EXPECT_LT(golden(one, items).probes, counter(r, "probes"));
}

}  // namespace
}  // namespace tmu::tb
