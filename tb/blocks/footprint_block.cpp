#include "blocks/footprint_block.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <footprint_variants.hpp>
#include <numbers>
#include <stdexcept>
#include <string_view>
#include <tuple>

#include "blocks/footprint_hls.hpp"
#include "formats/formats.hpp"
#include "texram/trilinear.hpp"

namespace tmu::tb {
namespace fmts = tmu::formats;

namespace {

const Schema kInputs({{"op", fx::UQ(1, 0)},
                      {"u", fmts::kTexCoord},
                      {"v", fmts::kTexCoord},
                      {"r1u", fmts::kTexDeriv},
                      {"r1v", fmts::kTexDeriv},
                      {"r2u", fmts::kTexDeriv},
                      {"r2v", fmts::kTexDeriv},
                      {"shade", fmts::kRgba8888},
                      {"clut_addr", fmts::kClutIndex},
                      {"clut_rgba", fmts::kRgba8888}});
const Schema kOutputs({{"rgba", fmts::kRgba8888}});

constexpr int kFrac = fmts::kTexCoord.frac_bits;
constexpr int32_t kOne = int32_t{1} << kFrac;  // one texel in raw .8
constexpr int32_t kCoordMin = static_cast<int32_t>(fmts::kTexCoord.min_raw());
constexpr int32_t kCoordMax = static_cast<int32_t>(fmts::kTexCoord.max_raw());
constexpr int32_t kDerivMin = static_cast<int32_t>(fmts::kTexDeriv.min_raw());
constexpr int32_t kDerivMax = static_cast<int32_t>(fmts::kTexDeriv.max_raw());
static_assert(fmts::kTexDeriv.frac_bits == kFrac);
constexpr uint32_t kWhite = 0xFFFF'FFFFu;
// Appended to the content of a texture painted by paint_white_quarter.
constexpr std::string_view kWhiteContent = ", level 0's top-left quarter white";

constexpr uint64_t low_bits(const fx::Format& f) { return (uint64_t{1} << f.width()) - 1; }

int32_t clamp_coord(int64_t raw) {
  return static_cast<int32_t>(std::clamp<int64_t>(raw, kCoordMin, kCoordMax));
}
int32_t clamp_deriv(int64_t raw) {
  return static_cast<int32_t>(std::clamp<int64_t>(raw, kDerivMin, kDerivMax));
}
int32_t deriv_field(uint64_t field) {
  return static_cast<int32_t>(fx::fit(static_cast<int64_t>(field & low_bits(fmts::kTexDeriv)),
                                      fmts::kTexDeriv, fx::Overflow::kWrap));
}

size_t count_samples(const std::vector<Txn>& items) {
  size_t n = 0;
  for (const Txn& t : items) n += t.f[kFpOp] == kFpOpSample;
  return n;
}

// Random draws from the generator's raw output (no std distributions: the integer stimulus is
// the same on every standard library; the few draws through exp2, cos and sin are rounded to
// raw port values).
int64_t draw(std::mt19937_64& rng, int64_t lo, int64_t hi) {
  return lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(hi - lo + 1));
}
double draw_unit(std::mt19937_64& rng) {  // [0, 1)
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}
// A length in raw units, log-uniform between 2^lo and 2^hi texels.
double draw_length(std::mt19937_64& rng, double lo, double hi) {
  return std::exp2(lo + (hi - lo) * draw_unit(rng)) * kOne;
}

// The top-left quarter of level 0 white (every byte 0xFF, the CLUT's last entry white): a
// region whose probes are all 255 at lambda <= 0, so the average's sums reach 16 x 255. The
// other levels keep their content (a level 0 too small for a quarter has its first cell
// white, and that cell's replicas).
void paint_white_quarter(TrilinearEnv& env) {
  texram::TexramTexture t = *env.texture;
  const texram::Geometry& g = t.geometry;
  const uint32_t rw = std::max(1u, g.grid_width(0) / 4), rh = std::max(1u, g.grid_height(0) / 4);
  for (uint32_t y = 0; y < g.stored_height(0); ++y) {
    for (uint32_t x = 0; x < g.stored_width(0); ++x) {
      if (x % g.grid_width(0) >= rw || y % g.grid_height(0) >= rh) continue;
      for (int p = 0; p < g.planes(); ++p) {
        const texram::BankCell c = g.cell(0, x, y, p);
        t.banks[c.bank][c.address] = 0xFF;
      }
    }
  }
  t.clut[0xFF] = kWhite;  // index and CCC textures: the bytes 0xFF are index 255
  env.texture = std::make_shared<const texram::TexramTexture>(std::move(t));
  env.content += kWhiteContent;
}

// ---- Engines -------------------------------------------------------------------------------

class GoldenEngine : public Engine {
 public:
  explicit GoldenEngine(FootprintEnv env) : env_(std::move(env)) {}
  std::string name() const override { return "golden"; }
  RunResult run(const std::vector<Txn>& items, const RunOptions&) override {
    RunResult r;
    r.outputs.reserve(count_samples(items));
    texram::TexramTexture texture = *env_.trilinear.texture;  // CLUT writes change its CLUT
    TexramAccessLog log;
    uint64_t probes = 0;
    std::vector<texram::SamplePlan> plans;
    const auto start = std::chrono::steady_clock::now();
    try {
      for (const Txn& t : items) {
        if (t.f[kFpOp] == kFpOpClutWrite) {
          texture.clut[static_cast<uint8_t>(t.f[kFpClutAddr])] =
              static_cast<uint32_t>(t.f[kFpClutRgba]);
          continue;
        }
        plans.clear();
        Txn out;
        out.f[0] = footprint::sample(texture, env_.trilinear.config, env_.config,
                                     footprint_request(t), &plans);
        r.outputs.push_back(out);
        for (const texram::SamplePlan& p : plans) log.sample(p.bank_address, p.planes);
        probes += plans.size();
      }
    } catch (const std::exception& e) {
      r.error = e.what();
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.output_cycles.assign(r.outputs.size(), 0);
    r.counters = log.counters();
    r.counters.emplace_back("probes", probes);
    return r;
  }

 private:
  FootprintEnv env_;
};

}  // namespace

// ---- Environment and items -------------------------------------------------------------------

FootprintEnv make_footprint_env(const BlockOptions& o) {
  // Every draw is made whether or not it is overridden, so an override changes nothing else.
  std::mt19937_64 rng(o.seed ^ 0xF007'9817'0000'0001ull);
  constexpr int kMaxDraws[8] = {0, 1, 2, 3, 3, 4, 4, 4};
  const int max_probes = kMaxDraws[rng() % 8];
  const footprint::QRule q_rule =
      rng() % 2 == 0 ? footprint::QRule::kHeights : footprint::QRule::kSides;

  FootprintEnv env;
  env.trilinear = make_trilinear_env(o);
  if (o.tri_image.empty()) paint_white_quarter(env.trilinear);
  env.config.log2_max_probes = o.fp_log2_max_probes.value_or(max_probes);
  env.config.q_rule = o.fp_q_rule.value_or(q_rule);
  env.config.widths = o.fp_widths;
  const footprint::Widths& w = env.config.widths;
  if (w.deriv_bits < 6 || w.deriv_bits > 24 || w.table_bits < 1 || w.table_bits > 10 ||
      w.log_frac < 1 || w.log_frac > 12) {
    throw std::invalid_argument(
        "footprint: widths D,T,F must be deriv 6..24, table 1..10, log fraction 1..12");
  }
  if (env.config.log2_max_probes < 0 || env.config.log2_max_probes > fmts::kMaxProbeLog2) {
    throw std::invalid_argument("footprint: at most 1, 2, 4, 8 or 16 probes");
  }
  return env;
}

footprint::Request footprint_request(const Txn& t) {
  footprint::Request r;
  r.u = trilinear_coord(t.f[kFpU]);
  r.v = trilinear_coord(t.f[kFpV]);
  r.r1u = deriv_field(t.f[kFpR1u]);
  r.r1v = deriv_field(t.f[kFpR1v]);
  r.r2u = deriv_field(t.f[kFpR2u]);
  r.r2v = deriv_field(t.f[kFpR2v]);
  r.shade = static_cast<uint32_t>(t.f[kFpShade]);
  return r;
}

Txn footprint_sample_item(int32_t u, int32_t v, int32_t r1u, int32_t r1v, int32_t r2u, int32_t r2v,
                          uint32_t shade) {
  Txn t;
  t.f[kFpOp] = kFpOpSample;
  t.f[kFpU] = static_cast<uint32_t>(u);
  t.f[kFpV] = static_cast<uint32_t>(v);
  t.f[kFpR1u] = static_cast<uint32_t>(r1u);
  t.f[kFpR1v] = static_cast<uint32_t>(r1v);
  t.f[kFpR2u] = static_cast<uint32_t>(r2u);
  t.f[kFpR2v] = static_cast<uint32_t>(r2v);
  t.f[kFpShade] = shade;
  return kInputs.masked(t);
}

Txn footprint_clut_item(uint8_t index, uint32_t rgba) {
  Txn t;
  t.f[kFpOp] = kFpOpClutWrite;
  t.f[kFpClutAddr] = index;
  t.f[kFpClutRgba] = rgba;
  return t;
}

// ---- The block ---------------------------------------------------------------------------

FootprintBlock::FootprintBlock(const BlockOptions& options)
    : FootprintBlock(options, make_footprint_env(options)) {}

FootprintBlock::FootprintBlock(const BlockOptions& options, FootprintEnv env)
    : options_(options), env_(std::move(env)), trilinear_(options, env_.trilinear) {}

const Schema& FootprintBlock::inputs() const { return kInputs; }
const Schema& FootprintBlock::outputs() const { return kOutputs; }

std::string FootprintBlock::describe() const {
  const footprint::Config& c = env_.config;
  return fmt::format("{}; at most {} probes, q rule {}, setup widths {},{},{}",
                     trilinear_.describe(), 1 << c.log2_max_probes, footprint::name(c.q_rule),
                     c.widths.deriv_bits, c.widths.table_bits, c.widths.log_frac);
}

std::string FootprintBlock::repro_options() const {
  const BlockOptions& o = options_;
  std::string out = trilinear_.repro_options();
  auto add = [&out](const std::string& p) { out += (out.empty() ? "" : " ") + p; };
  if (o.fp_log2_max_probes) add(fmt::format("--max-probes {}", 1 << *o.fp_log2_max_probes));
  if (o.fp_q_rule) add(fmt::format("--q-rule {}", footprint::name(*o.fp_q_rule)));
  if (!(o.fp_widths == footprint::Widths{})) {
    add(fmt::format("--fp-widths {},{},{}", o.fp_widths.deriv_bits, o.fp_widths.table_bits,
                    o.fp_widths.log_frac));
  }
  return out;
}

std::vector<Txn> FootprintBlock::setup_items() const {
  std::vector<Txn> items;
  const texram::TexramTexture& t = *env_.trilinear.texture;
  for (size_t i = 0; i < t.clut.size(); ++i) {
    items.push_back(footprint_clut_item(static_cast<uint8_t>(i), t.clut[i]));
  }
  return items;
}

std::vector<Txn> FootprintBlock::directed_items() const {
  const texram::Geometry& g = env_.trilinear.texture->geometry;
  const int64_t w = int64_t{g.texel_width(0)} * kOne, h = int64_t{g.texel_height(0)} * kOne;
  std::vector<Txn> items;
  uint32_t shade = 0x80FF'40C0u;
  auto frag = [&](int64_t u, int64_t v, int64_t r1u, int64_t r1v, int64_t r2u, int64_t r2v) {
    items.push_back(footprint_sample_item(clamp_coord(u), clamp_coord(v), clamp_deriv(r1u),
                                          clamp_deriv(r1v), clamp_deriv(r2u), clamp_deriv(r2v),
                                          shade));
    shade = shade * 0x9E37'79B1u + 0x7F4A'7C15u;  // a different I_d each time
  };
  // An interior centre, off the texel grid.
  const int64_t cu = w / 2 + 77, cv = h / 3 + 41;

  // r1 zero: a line along r2 (area 0: rho is infinite): k = kmax, marching along r2
  // (s2 > s1), capped by the length (probes a quarter texel apart at least: |r2| ~ 3 texels
  // allows 8 probes, 5 texels 16), lambda = log2 |r2| - k. Heights and sides agree (smin = 0).
  frag(cu, cv, 0, 0, 3 * kOne, kOne / 2);
  frag(cu, cv, 0, 0, -kOne / 3, 5 * kOne);
  // r2 zero: the same along r1 (caps 8 and 16).
  frag(cu, cv, 3 * kOne, -kOne / 2, 0, 0);
  frag(cu, cv, -7 * kOne, 0, 0, 0);
  // Both zero: a point: k = 0, the smallest lambda (the finest level), one probe at the centre
  // (also on a texel edge and at the port's corner).
  frag(cu, cv, 0, 0, 0, 0);
  frag(kOne, kOne, 0, 0, 0, 0);
  frag(kCoordMin, kCoordMax, 0, 0, 0, 0);

  // r1 parallel to r2 (r2 = 2 r1): area 0: kmax probes along r2, the longer (|r2| ~ 4.5
  // texels: 16 at most).
  frag(cu, cv, 2 * kOne, kOne, 4 * kOne, 2 * kOne);
  // Antiparallel and equally long (r2 = -r1): area 0, s1 = s2: along r1 (r2 only when
  // strictly longer), kmax probes (|r1| ~ 2.2 texels: 8 at most).
  frag(cu, cv, 2 * kOne, kOne, -2 * kOne, -kOne);
  // Not parallel, but the cross product (-1 LSB^2) vanishes after the block-floating shift
  // (sh = 12 at D = 12): a line to the setup, kmax probes, lambda ~ log2 |r| - kmax.
  frag(cu, cv, 0x40'0000, 0x40'0001, 0x40'0001, 0x40'0002);

  // Isotropic (|r1| = |r2|, orthogonal): rho = 0: one probe, lambda = log2 |r| (2 texels:
  // ~1.0; rotated by 45 degrees: the same).
  frag(cu, cv, 2 * kOne, 0, 0, 2 * kOne);
  frag(cu, cv, 362, 362, -362, 362);
  // Equal lengths, 60 degrees apart: sides rho = 0 (k = 0); heights q = |r| sin 60, rho =
  // 2 log2(1 / sin 60) ~ 0.42: k = 0.
  frag(cu, cv, 4 * kOne, 0, 2 * kOne, 887);
  // Equal lengths, 10 degrees apart: sides k = 0; heights q = |r| sin 10, rho ~ 2.5: the
  // rounding threshold between 4 and 8 probes.
  frag(cu, cv, 4 * kOne, 0, 1008, 178);

  // The ratio |r1| / |r2| at the rounding thresholds 2^(j + 1/2) (orthogonal: heights and
  // sides agree), and a few LSB either side: k = j below, j + 1 above (clamped to kmax), up to
  // the table's error (the threshold is where it shows). Along u and v, r1 or r2 longer.
  for (int j = 0; j < fmts::kMaxProbeLog2; ++j) {
    const int64_t major = 16 * kOne;
    const auto minor = static_cast<int64_t>(std::lround(major / std::exp2(j + 0.5)));
    for (int64_t d = -2; d <= 2; ++d) {
      frag(cu, cv, major, 0, 0, minor + d);
      frag(cu, cv, minor + d, 0, 0, -major);  // r2 longer, along v
    }
  }
  // Exact powers of two: ratio 1, 2, 4, 8, 16 at a 2-texel minor side: k = 0 .. 4 (clamped).
  for (int j = 0; j <= fmts::kMaxProbeLog2; ++j) frag(cu, cv, (2 * kOne) << j, 0, 0, 2 * kOne);

  // Ratios far beyond the maximum N (64, 1000, 2^15 with a 1-LSB minor side): k = kmax
  // (clamped), lambda = max(log2 q, log2 |r_max| - kmax): fewer probes grow to cover the length.
  frag(cu, cv, 64 * kOne, 0, 0, kOne);
  frag(cu, cv, 0, 1000 * kOne, kOne, 0);
  frag(cu, cv, 128 * kOne, 128 * kOne, 1, -1);
  frag(cu, cv, kDerivMax, 0, 0, 1);

  // Magnification (|r_max| <= 1 texel): probes at least a quarter texel apart leave one
  // under half a texel, two under a texel, whatever the ratio; lambda < 0.
  frag(cu, cv, kOne / 2, 0, 0, kOne / 4);
  frag(cu, cv, kOne / 2, kOne / 3, 0, kOne / 64);
  frag(cu, cv, 1, 0, 0, 1);  // one LSB each
  frag(cu, cv, 1, 1, -1, 1);
  // The cap k <= floor(log2 |r_max|) + 2 at its steps, |r_max| = 1/4, 1/2, 1, 2, 4, 8 texels
  // and one LSB below (ratio 16: k would be 4 without it): one probe under 1/2 texel, then up
  // to 2, 4, 8, 16 probes from 1/2, 1, 2, 4 texels (clamped by kmax). Exact on the square's
  // leading one, also after a block-floating shift (at D = 8 a 1-texel component is shifted,
  // sh = 1).
  for (int64_t len = kOne / 4; len <= 8 * kOne; len *= 2) {
    for (int64_t d = -1; d <= 0; ++d) {
      frag(cu, cv, len + d, 0, 0, len / 16);
      frag(cu, cv, 0, len / 16, 0, -(len + d));  // r2 the longer
    }
  }

  // Huge derivatives (components at +-2^15 texels, beyond every level): lambda ~ 15 (the
  // trilinear unit clamps it to the top level), probes up to 15/32 of 2^15 texels from the
  // centre: beyond the port's range, they wrap (wrap, mirror) or saturate (clamp, border).
  frag(cu, cv, kDerivMax, 0, 0, kDerivMax);
  frag(cu, cv, kDerivMin, kDerivMin, kDerivMax, kDerivMin);
  frag(cu, cv, kDerivMin, kDerivMax, kDerivMax, kDerivMin);  // nearly antiparallel
  frag(cu, cv, kDerivMin, 0, 0, kOne);
  frag(kCoordMax, kCoordMin, kDerivMax, kDerivMax, kDerivMin, kDerivMax);
  // Every component at the largest magnitude 2^23 - 1 (all ones, 2^D - 1 after the shift,
  // where a power of two leaves 2^(D-1)): the squared lengths and the area, 2 (2^D - 1)^2,
  // reach the top bit of the logarithms' 2D + 1-bit operands (docs/coverage.md).
  frag(cu, cv, kDerivMax, kDerivMax, -kDerivMax, kDerivMax);
  // The largest ratio at D = 16 (no shift): (a, a - 1) and (a - 1, a - 2), a = 2^16 - 1,
  // nearly parallel, cross product -1 LSB^2: heights rho = log2(s_max / area) ~ 33.
  frag(cu, cv, 0xFFFF, 0xFFFE, 0xFFFE, 0xFFFD);

  // Probes crossing the texture's edges: centres a quarter texel inside u = 0, u = size, v = 0,
  // v = size and at the corners, 8-texel footprints across the edge: probes on both sides
  // (the border modes differ there).
  for (const auto& [u, v] :
       std::initializer_list<std::pair<int64_t, int64_t>>{{kOne / 4, h / 2},
                                                          {w - kOne / 4, h / 2},
                                                          {w / 2, kOne / 4},
                                                          {w / 2, h - kOne / 4},
                                                          {0, 0},
                                                          {w, h}}) {
    frag(u, v, 8 * kOne, 0, 0, kOne / 2);
    frag(u, v, kOne / 2, 0, 0, 8 * kOne);
    frag(u, v, 6 * kOne, 6 * kOne, -kOne / 2, kOne / 2);
  }
  // Near the port's range (+-2^15 texels): probes beyond it wrap modulo 2^16 texels (wrap,
  // mirror) or saturate (clamp, border).
  for (int64_t c : {int64_t{kCoordMax} - kOne, int64_t{kCoordMin} + kOne, int64_t{kCoordMax},
                    int64_t{kCoordMin}}) {
    frag(c, h / 2, 16 * kOne, 0, 0, kOne);
    frag(w / 2, c, kOne, 0, 0, -16 * kOne);
    frag(c, c, 8 * kOne, 8 * kOne, -kOne, kOne);
  }
  frag(kCoordMax, kCoordMax, kDerivMax, kDerivMax, 1, -1);  // far beyond, both axes

  // The white quarter (every channel 255; kWhite shade): 16 probes of a line inside it (k =
  // kmax; 8 texels long, 16 probes half a texel apart, lambda < 0: level 0): every probe 255
  // with combine one or shade, the sums at their largest, 16 x 255 = 4080 (needs a texture at
  // least 64 texels wide and high: the probes reach 4 texels from the centre, w / 8).
  for (const auto& [r1u, r1v] : std::initializer_list<std::pair<int64_t, int64_t>>{
           {8 * kOne, 0}, {0, 8 * kOne}, {6 * kOne, 6 * kOne}}) {
    items.push_back(footprint_sample_item(clamp_coord(w / 8), clamp_coord(h / 8), clamp_deriv(r1u),
                                          clamp_deriv(r1v), 0, 0, kWhite));
  }

  // A CLUT write between fragments (index and CCC textures change colour), and back to back.
  const texram::TexramTexture& tex = *env_.trilinear.texture;
  for (uint8_t i : {uint8_t{0}, tex.banks[0].empty() ? uint8_t{0} : tex.banks[0][0]}) {
    frag(kOne / 2, kOne / 2, 2 * kOne, 0, 0, kOne / 2);
    items.push_back(footprint_clut_item(i, ~tex.clut[i]));
    frag(kOne / 2, kOne / 2, 2 * kOne, 0, 0, kOne / 2);
    items.push_back(footprint_clut_item(i, tex.clut[i]));
    items.push_back(footprint_clut_item(i, tex.clut[i]));
    frag(kOne / 2, kOne / 2, kOne / 2, 0, 0, 2 * kOne);
  }
  return items;
}

std::vector<Txn> FootprintBlock::random_items(std::mt19937_64& rng, size_t count) const {
  const texram::Geometry& g = env_.trilinear.texture->geometry;
  const int64_t w = int64_t{g.texel_width(0)} * kOne, h = int64_t{g.texel_height(0)} * kOne;
  std::vector<Txn> items;
  items.reserve(count);
  // A vector of length `len` (raw) at angle `a`.
  auto polar = [](double len, double a) {
    return std::pair<int64_t, int64_t>{std::llround(len * std::cos(a)),
                                       std::llround(len * std::sin(a))};
  };
  while (items.size() < count) {
    const uint64_t r = rng() % 1000;
    if (r == 0) {  // rarely, a CLUT rewrite
      const uint64_t x = rng();
      items.push_back(footprint_clut_item(static_cast<uint8_t>(x), static_cast<uint32_t>(x >> 8)));
      continue;
    }
    // The centre: mostly over the texture and around it, sometimes far, now and then anywhere
    // in the port's range.
    int64_t u, v;
    const uint64_t where = rng() % 100;
    if (where < 85) {
      u = draw(rng, -w / 4, w + w / 4);
      v = draw(rng, -h / 4, h + h / 4);
    } else if (where < 95) {
      u = draw(rng, -2 * w, 3 * w);
      v = draw(rng, -2 * h, 3 * h);
    } else {
      u = draw(rng, kCoordMin, kCoordMax);
      v = draw(rng, kCoordMin, kCoordMax);
    }
    const double angle = 2.0 * std::numbers::pi * draw_unit(rng);
    std::pair<int64_t, int64_t> r1, r2;
    const uint64_t kind = rng() % 100;
    if (kind < 25) {  // isotropic: equal and orthogonal, 1/4 to 64 texels
      const double len = draw_length(rng, -2, 6);
      r1 = polar(len, angle);
      r2 = polar(len, angle + std::numbers::pi / 2);
    } else if (kind < 70) {
      // Anisotropic: ratio 1 .. 64, the major side 1/2 .. 256 texels, the minor one mostly
      // orthogonal, sometimes skewed; r1 or r2 the longer.
      const double major = draw_length(rng, -1, 8);
      const double ratio = std::exp2(6.0 * draw_unit(rng));
      const double skew = rng() % 4 == 0 ? (draw_unit(rng) - 0.5) * std::numbers::pi / 2 : 0.0;
      r1 = polar(major, angle);
      r2 = polar(major / ratio, angle + std::numbers::pi / 2 + skew);
      if (rng() % 2 == 0) std::swap(r1, r2);
    } else if (kind < 82) {  // magnified: both shorter than a texel
      r1 = polar(draw_length(rng, -7, 0), angle);
      r2 = polar(draw_length(rng, -7, 0), angle + 2.0 * std::numbers::pi * draw_unit(rng));
    } else if (kind < 94) {  // degenerate
      const double len = draw_length(rng, -3, 9);
      switch (rng() % 5) {
        case 0:  // one vector zero
          r1 = polar(len, angle);
          r2 = {0, 0};
          if (rng() % 2 == 0) std::swap(r1, r2);
          break;
        case 1:  // both zero
          r1 = r2 = {0, 0};
          break;
        case 2: {  // parallel or antiparallel: r2 = t r1, |t| <= 2
          r1 = polar(len, angle);
          const int64_t t = draw(rng, -8, 8);
          r2 = {r1.first * t / 4, r1.second * t / 4};
          break;
        }
        case 3:  // a few LSB
          r1 = {draw(rng, -3, 3), draw(rng, -3, 3)};
          r2 = {draw(rng, -3, 3), draw(rng, -3, 3)};
          break;
        default:  // equal lengths, random angle between them
          r1 = polar(len, angle);
          r2 = polar(len, angle + 2.0 * std::numbers::pi * draw_unit(rng));
          break;
      }
    } else {  // components anywhere in the port's range, of random magnitudes
      auto component = [&rng] {
        const int bits = static_cast<int>(draw(rng, 0, 23));
        return draw(rng, -(int64_t{1} << bits), (int64_t{1} << bits) - 1);
      };
      r1 = {component(), component()};
      r2 = {component(), component()};
    }
    items.push_back(footprint_sample_item(clamp_coord(u), clamp_coord(v), clamp_deriv(r1.first),
                                          clamp_deriv(r1.second), clamp_deriv(r2.first),
                                          clamp_deriv(r2.second), static_cast<uint32_t>(rng())));
  }
  return items;
}

std::unique_ptr<Engine> FootprintBlock::engine(const std::string& level) const {
  if (level == "golden") return std::make_unique<GoldenEngine>(env_);
  if (level == "hls") return make_footprint_hls_engine(env_);
  if (level == "rtl") {
    if (!(env_.trilinear.config.widths == texram::Widths{})) {
      throw std::invalid_argument(
          "footprint: the rtl model's trilinear unit is verilated at widths 8,8,8 only");
    }
    // The Verilated model of these setup widths (rtl/CMakeLists.txt: TMU_FOOTPRINT_VARIANTS).
#define TMU_VARIANT(D, T, F, MODEL)                     \
  if (env_.config.widths == footprint::Widths{D, T, F}) \
    return make_footprint_rtl_engine<MODEL>("rtl", env_);
    TMU_FOOTPRINT_VARIANTS(TMU_VARIANT)
#undef TMU_VARIANT
    std::string built;
#define TMU_VARIANT(D, T, F, MODEL) \
  built += (built.empty() ? "" : "; ") + std::string(#D "," #T "," #F);
    TMU_FOOTPRINT_VARIANTS(TMU_VARIANT)
#undef TMU_VARIANT
    throw std::invalid_argument(
        "footprint: no rtl model was verilated at these setup widths (built: " + built +
        "; add them to TMU_FOOTPRINT_VARIANTS in rtl/CMakeLists.txt)");
  }
  throw std::invalid_argument("footprint: no engine '" + level + "' (golden, hls, rtl)");
}

// ---- Coverage ----------------------------------------------------------------------------

namespace {

constexpr const char* kCaseClamped = "k clamped (ratio beyond the maximum N)";
constexpr const char* kCaseLine = "line footprint (area 0, vectors not 0)";
constexpr const char* kCaseOneZero = "one vector zero";
constexpr const char* kCasePoint = "point (both vectors zero)";
constexpr const char* kCaseMagnified = "magnification (|r_max| < 1 texel)";
constexpr const char* kCaseCapped = "k capped by the length (probes >= 1/4 texel apart)";
constexpr const char* kCaseR2Longer = "r2 longer (marching along r2)";
constexpr const char* kCaseEqual = "equal lengths (|r1| = |r2|, not 0)";
constexpr const char* kCaseHuge = "huge derivative (a component >= 2^14 texels)";
constexpr const char* kCaseOutside = "probe outside the texture";
constexpr const char* kCaseWrapped = "probe wrapped beyond the port (wrap, mirror)";
constexpr const char* kCaseSaturated = "probe saturated beyond the port (clamp, border)";
constexpr const char* kCaseLambdaNeg = "lambda < 0 (probes magnified)";
constexpr const char* kCaseLambdaTop = "lambda beyond the top level";
constexpr const char* kCaseFull = "every probe 255 in R, G or B (sum 16 x 255)";
constexpr const char* kCaseAfterClut = "fragment right after a CLUT write";

bool saturates(texram::Border b) {
  return b == texram::Border::kClamp || b == texram::Border::kBorder;
}

std::string k_case(int k) { return fmt::format("k = {} ({} probes)", k, 1 << k); }

// The white quarter holds a 16-probe line (8 texels) with its taps when the texture was
// painted (make_footprint_env: not an image file) and is at least 64 texels wide and high;
// the probes' colours stay 255 unless eq. 5 multiplies by a constant (and a single-component
// texture of alpha has no colour).
bool white_line_fits(const FootprintEnv& env) {
  const texram::Geometry& g = env.trilinear.texture->geometry;
  const texram::SamplerConfig& s = env.trilinear.config;
  return env.trilinear.content.ends_with(kWhiteContent) && g.texel_width(0) >= 64 &&
         g.texel_height(0) >= 64 && s.combine != texram::Combine::kConstant &&
         !(s.kind == texram::TexelKind::kSingle && s.single_channel == 3);
}

}  // namespace

std::vector<std::string> FootprintBlock::coverage_cases() const {
  const footprint::Config& c = env_.config;
  const texram::SamplerConfig& s = env_.trilinear.config;
  std::vector<std::string> cases = {fmt::format("q rule {}", footprint::name(c.q_rule)),
                                    fmt::format("at most {} probes", 1 << c.log2_max_probes)};
  for (int k = 0; k <= c.log2_max_probes; ++k) cases.push_back(k_case(k));
  cases.insert(cases.end(),
               {kCaseClamped, kCaseLine, kCaseOneZero, kCasePoint, kCaseMagnified, kCaseR2Longer,
                kCaseEqual, kCaseHuge, kCaseOutside, kCaseLambdaNeg, kCaseLambdaTop});
  if (c.log2_max_probes > 0) cases.push_back(kCaseCapped);
  // One probe is the centre itself: only N > 1 reaches beyond the port.
  if (c.log2_max_probes > 0 && (!saturates(s.border_u) || !saturates(s.border_v))) {
    cases.push_back(kCaseWrapped);
  }
  if (c.log2_max_probes > 0 && (saturates(s.border_u) || saturates(s.border_v))) {
    cases.push_back(kCaseSaturated);
  }
  if (c.log2_max_probes == fmts::kMaxProbeLog2 && white_line_fits(env_)) {
    cases.push_back(kCaseFull);
  }
  if (s.kind == texram::TexelKind::kIndex || s.kind == texram::TexelKind::kCcc) {
    cases.push_back(kCaseAfterClut);
  }
  return cases;
}

void FootprintBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                           Coverage& cov) const {
  const footprint::Config& c = env_.config;
  const texram::SamplerConfig& s = env_.trilinear.config;
  const texram::Geometry& g = env_.trilinear.texture->geometry;
  ++cov[fmt::format("q rule {}", footprint::name(c.q_rule))];
  ++cov[fmt::format("at most {} probes", 1 << c.log2_max_probes)];
  const footprint::Request req = footprint_request(items[index]);
  footprint::Plan p;
  try {
    p = footprint::plan(req, c);
  } catch (const std::exception&) {
    return;  // golden reports it
  }
  ++cov[k_case(p.log2_n)];

  // The footprint's shape, in doubles (a classification, not the setup's arithmetic).
  const int64_t r1u = req.r1u, r1v = req.r1v, r2u = req.r2u, r2v = req.r2v;
  const bool zero1 = r1u == 0 && r1v == 0, zero2 = r2u == 0 && r2v == 0;
  const int64_t s1 = r1u * r1u + r1v * r1v, s2 = r2u * r2u + r2v * r2v;
  const int64_t cross = r1u * r2v - r1v * r2u;
  const double l1 = std::sqrt(static_cast<double>(s1)) / kOne;
  const double l2 = std::sqrt(static_cast<double>(s2)) / kOne;
  const double lmax = std::max(l1, l2);
  const double area = std::abs(static_cast<double>(cross)) / (double{kOne} * kOne);
  if (zero1 && zero2) {
    ++cov[kCasePoint];
  } else if (zero1 || zero2) {
    ++cov[kCaseOneZero];
  } else if (cross == 0) {
    ++cov[kCaseLine];
  }
  if (!(zero1 && zero2) && lmax < 1.0) ++cov[kCaseMagnified];
  if (p.r2_longer) ++cov[kCaseR2Longer];
  if (s1 == s2 && s1 != 0) ++cov[kCaseEqual];
  if (std::max({std::abs(r1u), std::abs(r1v), std::abs(r2u), std::abs(r2v)}) >=
      (int64_t{1} << 14) * kOne) {
    ++cov[kCaseHuge];
  }
  const double q = c.q_rule == footprint::QRule::kHeights ? area / lmax : std::min(l1, l2);
  if (q > 0.0 && lmax >= 1.0 && std::log2(lmax / q) > c.log2_max_probes + 0.5) {
    ++cov[kCaseClamped];
  }
  // The ratio asks for more probes than the length allows (floor(log2 |r_max|) + 2: probes a
  // quarter texel apart at least).
  if (lmax > 0.0) {
    const double k_ratio =
        q > 0.0 ? std::min<double>(c.log2_max_probes, std::floor(std::log2(lmax / q) + 0.5))
                : c.log2_max_probes;
    if (std::max(0.0, std::floor(std::log2(lmax)) + 2.0) < k_ratio) ++cov[kCaseCapped];
  }
  if (p.lambda < 0) ++cov[kCaseLambdaNeg];
  if (p.lambda > (g.levels() - 1) * kOne) ++cov[kCaseLambdaTop];

  // The probes: outside the texture; beyond the port's range (the exact position, as golden's
  // probe() computes it before wrapping or saturating).
  const int k = p.log2_n;
  const int64_t du = p.r2_longer ? r2u : r1u, dv = p.r2_longer ? r2v : r1v;
  const int64_t w = int64_t{g.texel_width(0)} * kOne, h = int64_t{g.texel_height(0)} * kOne;
  for (int i = 0; i < (1 << k); ++i) {
    const texram::Request pr = footprint::probe(req, p, i, s);
    if (pr.u < 0 || pr.v < 0 || pr.u >= w || pr.v >= h) ++cov[kCaseOutside];
    const int64_t n = 2 * int64_t{i} - ((int64_t{1} << k) - 1);
    for (const auto& [centre, d, border] :
         {std::tuple{int64_t{req.u}, du, s.border_u}, std::tuple{int64_t{req.v}, dv, s.border_v}}) {
      const int64_t exact = ((centre << (k + 1)) + n * d + (int64_t{1} << k)) >> (k + 1);
      if (exact >= kCoordMin && exact <= kCoordMax) continue;
      ++cov[saturates(border) ? kCaseSaturated : kCaseWrapped];
    }
  }

  // The CLUT as the fragment sees it (the writes before it replayed), for the probes' colours.
  CoverState& st = cover_state_;
  if (st.items != &items || index < st.next || !st.texture) {
    st = CoverState{&items, 0, std::make_shared<texram::TexramTexture>(*env_.trilinear.texture)};
  }
  for (; st.next < index; ++st.next) {
    const Txn& t = items[st.next];
    if (t.f[kFpOp] == kFpOpClutWrite) {
      st.texture->clut[static_cast<uint8_t>(t.f[kFpClutAddr])] =
          static_cast<uint32_t>(t.f[kFpClutRgba]);
    }
  }
  if (k == fmts::kMaxProbeLog2) {
    std::array<uint32_t, 3> sums{};  // R, G, B (alpha is 255 in many kinds)
    try {
      for (int i = 0; i < (1 << k); ++i) {
        const uint32_t rgba = texram::sample(*st.texture, s, footprint::probe(req, p, i, s));
        for (int ch = 0; ch < 3; ++ch) sums[static_cast<size_t>(ch)] += texram::channel(rgba, ch);
      }
    } catch (const std::exception&) {
      sums = {};
    }
    if (std::find(sums.begin(), sums.end(), 16u * 255u) != sums.end()) ++cov[kCaseFull];
  }
  if (index > 0 && items[index - 1].f[kFpOp] == kFpOpClutWrite) ++cov[kCaseAfterClut];
}

std::vector<Port> FootprintBlock::ports() const {
  constexpr int kAddrBus = fmts::kBanks * fmts::kBankAddr.width();
  return {{"clk_i"},
          {"rst_ni"},
          {"cfg_log2_w_i", fmts::kMipLog2.width()},
          {"cfg_log2_h_i", fmts::kMipLog2.width()},
          {"cfg_kind_i", fmts::kTexKind.width()},
          {"cfg_single_channel_i", fmts::kBytePlane.width()},
          {"cfg_filter_i", fmts::kTexFilter.width()},
          {"cfg_border_u_i", fmts::kTexBorder.width()},
          {"cfg_border_v_i", fmts::kTexBorder.width()},
          {"cfg_border_rgba_i", fmts::kRgba8888.width()},
          {"cfg_combine_i", fmts::kTexCombine.width()},
          {"cfg_constant_rgba_i", fmts::kRgba8888.width()},
          {"cfg_log2_max_probes_i", fmts::kProbeLog2.width()},
          {"cfg_q_rule_i", fmts::kQRule.width()},
          {"clut_valid_i"},
          {"clut_ready_o"},
          {"clut_addr_i", fmts::kClutIndex.width()},
          {"clut_rgba_i", fmts::kRgba8888.width()},
          {"req_valid_i"},
          {"req_ready_o"},
          {"req_u_i", fmts::kTexCoord.width(), true},
          {"req_v_i", fmts::kTexCoord.width(), true},
          {"req_r1u_i", fmts::kTexDeriv.width(), true},
          {"req_r1v_i", fmts::kTexDeriv.width(), true},
          {"req_r2u_i", fmts::kTexDeriv.width(), true},
          {"req_r2v_i", fmts::kTexDeriv.width(), true},
          {"req_shade_i", fmts::kRgba8888.width()},
          {"mem_req_valid_o"},
          {"mem_req_ready_i"},
          {"mem_req_en_o", fmts::kBanks},
          {"mem_req_addr_o", kAddrBus},
          {"mem_resp_valid_i"},
          {"mem_resp_data_i", fmts::kBanks * 8},
          {"out_valid_o"},
          {"out_ready_i"},
          {"out_rgba_o", fmts::kRgba8888.width()},
          {"stat_probes_o", fmts::kStatCount.width()}};
}

}  // namespace tmu::tb
