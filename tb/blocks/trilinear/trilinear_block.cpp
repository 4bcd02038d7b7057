#include "blocks/trilinear/trilinear_block.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "blocks/trilinear/texram_memory.hpp"
#include "blocks/trilinear/texram_sampler.hpp"
#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/texram/trilinear_sc.hpp"
#include "rtl_models_trilinear.hpp"
#include "texram/trilinear.hpp"
#include "texram/trilinear_ideal.hpp"

TMU_DESCRIBE_SC(trilinear)

namespace tmu::tb {
namespace fmts = tmu::formats;
using D = desc::trilinear;
using texram::Border;
using texram::Combine;
using texram::Filter;
using texram::TexelKind;

namespace {

constexpr int kFrac = fmts::kTexCoord.frac_bits;
constexpr int32_t kOne = int32_t{1} << kFrac;  // one texel (or one level) in raw .8
constexpr int32_t kCoordMin = static_cast<int32_t>(fmts::kTexCoord.min_raw());
constexpr int32_t kCoordMax = static_cast<int32_t>(fmts::kTexCoord.max_raw());
constexpr int32_t kLodMin = static_cast<int32_t>(fmts::kLod.min_raw());
constexpr int32_t kLodMax = static_cast<int32_t>(fmts::kLod.max_raw());
static_assert(fmts::kLod.frac_bits == kFrac);
// Sphere addressing: uN = 1 in raw UnitComp, and the bits of the coordinate port it reads.
constexpr int32_t kUnitOne = int32_t{1} << fmts::kUnitComp.frac_bits;
constexpr int64_t kUnitCompBits = fmts::kUnitComp.width();
// A random run draws a new environment after this many items.
constexpr size_t kBatch = 2500;

constexpr uint64_t low_bits(const fx::Format& f) { return (uint64_t{1} << f.width()) - 1; }

// Uniform in lo..hi (inclusive) from the generator's raw output (no std distributions, so
// the stimulus is the same on every standard library).
int64_t uniform(std::mt19937_64& rng, int64_t lo, int64_t hi) {
  return lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(hi - lo + 1));
}

int32_t clamp_coord(int64_t raw) {
  return static_cast<int32_t>(std::clamp<int64_t>(raw, kCoordMin, kCoordMax));
}
int32_t clamp_lod(int64_t raw) {
  return static_cast<int32_t>(std::clamp<int64_t>(raw, kLodMin, kLodMax));
}

// Level 0's size and the top level of a setup, in raw .8 units.
struct Extent {
  int64_t w, h, top;
};
Extent extent(const TexramSetup& s) {
  return {int64_t{kOne} << s.log2_w, int64_t{kOne} << s.log2_h,
          int64_t{std::max(s.log2_w, s.log2_h)} * kOne};
}

// The golden unit over a run: a configuration item names the environment (the CLUT and the
// pages stay, as in the RTL and the memory); every access is a memory request.
class Golden : public Model {
 public:
  explicit Golden(std::shared_ptr<const TrilinearBlock> block)
      : widths_(block->first().config.widths), unit_("trilinear", block->textures()) {}
  void configure(const Txn& cfg) override { unit_.configure(trilinear_setup_of(cfg, widths_)); }
  void step(const Txn& item, Sink& sink) override {
    if (item.f[0] == D::op_clut) {
      unit_.write_clut(static_cast<uint8_t>(item.f[D::clut_addr]),
                       static_cast<uint32_t>(item.f[D::clut_rgba]));
      return;
    }
    Txn out;
    out.f[D::out_rgba] = unit_.sample(trilinear_request(item), sink);
    sink.output(out);
  }
  Counters counters() const override { return unit_.counters(); }

 private:
  texram::Widths widths_;
  TexramSampler unit_;
};

// The ideal (double precision) sampler on the same requests, rounded to RGBA8888 only so that
// the run has outputs: `texsim levels` times it, nothing compares it.
class Ideal : public Model {
 public:
  explicit Ideal(std::shared_ptr<const TrilinearBlock> block) : block_(std::move(block)) {}
  void configure(const Txn& cfg) override {
    setup_ = trilinear_setup_of(cfg, block_->first().config.widths);
    texture_ = texram::ideal_texture(block_->textures()->texture_of(setup_)->source);
    texture_.clut = clut_;
  }
  void step(const Txn& item, Sink& sink) override {
    if (item.f[0] == D::op_clut) {
      const auto i = static_cast<uint8_t>(item.f[D::clut_addr]);
      clut_[i] = texture_.clut[i] = static_cast<uint32_t>(item.f[D::clut_rgba]);
      return;
    }
    const double unit = std::ldexp(1.0, kFrac);
    const texram::Request q = trilinear_request(item);
    double u = q.u / unit, v = q.v / unit;
    if (setup_.config.addressing ==
        texram::Addressing::kSphere) {  // (uN + 1) / 2 W, (1 - vN) / 2 H
      const auto unit_comp = [](int32_t port) {
        return static_cast<double>(static_cast<int16_t>(port)) / (1 << 14);  // the low 16 bits
      };
      u = (unit_comp(q.u) + 1) / 2 * std::ldexp(1.0, setup_.log2_w);
      v = (1 - unit_comp(q.v)) / 2 * std::ldexp(1.0, setup_.log2_h);
    }
    const auto c = texram::ideal_sample(texture_, setup_.config, u, v, q.lambda / unit, q.shade);
    uint64_t rgba = 0;
    for (double channel : c) rgba = rgba << 8 | static_cast<uint64_t>(std::lround(channel));
    Txn out;
    out.f[D::out_rgba] = rgba;
    sink.output(out);
  }

 private:
  std::shared_ptr<const TrilinearBlock> block_;
  TexramSetup setup_;
  texram::IdealTexture texture_;  // the setup's source, with the CLUT as written
  texram::Clut32 clut_{};
};

}  // namespace

// ---- Items -------------------------------------------------------------------------------

int32_t trilinear_coord(uint64_t field) {
  return static_cast<int32_t>(fx::fit(static_cast<int64_t>(field & low_bits(fmts::kTexCoord)),
                                      fmts::kTexCoord, fx::Overflow::kWrap));
}

int32_t trilinear_lambda(uint64_t field) {
  return static_cast<int32_t>(
      fx::fit(static_cast<int64_t>(field & low_bits(fmts::kLod)), fmts::kLod, fx::Overflow::kWrap));
}

texram::Request trilinear_request(const Txn& t) {
  return {trilinear_coord(t.f[D::req_u]), trilinear_coord(t.f[D::req_v]),
          trilinear_lambda(t.f[D::req_lambda]), static_cast<uint32_t>(t.f[D::req_shade])};
}

Txn trilinear_sample_item(int32_t u_raw, int32_t v_raw, int32_t lambda_raw, uint32_t shade) {
  return channel_item(D::table(), "req",
                      {static_cast<uint32_t>(u_raw), static_cast<uint32_t>(v_raw),
                       static_cast<uint32_t>(lambda_raw), shade});
}

Txn trilinear_clut_item(uint8_t index, uint32_t rgba) {
  return channel_item(D::table(), "clut", {index, rgba});
}

std::vector<Txn> trilinear_clut_load(const texram::TexramTexture& texture) {
  std::vector<Txn> items;
  for (size_t i = 0; i < texture.clut.size(); ++i) {
    items.push_back(trilinear_clut_item(static_cast<uint8_t>(i), texture.clut[i]));
  }
  return items;
}

Txn texram_cfg_item(const TexramSetup& s) {
  const texram::SamplerConfig& c = s.config;
  return channel_item(
      D::table(), "cfg",
      {uint64_t(s.log2_w), uint64_t(s.log2_h), uint64_t(c.kind), uint64_t(c.single_channel),
       uint64_t(c.filter), uint64_t(c.border_u), uint64_t(c.border_v), c.border_rgba,
       uint64_t(c.combine), c.constant_rgba, uint64_t(s.pattern), s.content});
}

Txn trilinear_cfg_item(const TexramSetup& s) {
  Txn item = texram_cfg_item(s);
  item.f[D::cfg_addressing] = uint64_t(s.config.addressing);
  return item;
}

TexramSetup trilinear_setup_of(const Txn& t, const texram::Widths& widths) {
  TexramSetup s = texram_setup_of(t, widths);
  if (t.f[D::cfg_addressing] > uint64_t(texram::Addressing::kSphere)) {
    throw std::invalid_argument("trilinear: a configuration item outside the encodings: " +
                                D::table().inputs().describe(t));
  }
  s.config.addressing = static_cast<texram::Addressing>(t.f[D::cfg_addressing]);
  return s;
}

TexramSetup texram_setup_of(const Txn& t, const texram::Widths& widths) {
  TexramSetup s;
  texram::SamplerConfig& c = s.config;
  s.log2_w = static_cast<int>(t.f[D::cfg_log2_w]);
  s.log2_h = static_cast<int>(t.f[D::cfg_log2_h]);
  c.kind = static_cast<TexelKind>(t.f[D::cfg_kind]);
  c.single_channel = static_cast<int>(t.f[D::cfg_single_channel]);
  c.filter = static_cast<Filter>(t.f[D::cfg_filter]);
  c.border_u = static_cast<Border>(t.f[D::cfg_border_u]);
  c.border_v = static_cast<Border>(t.f[D::cfg_border_v]);
  c.border_rgba = static_cast<uint32_t>(t.f[D::cfg_border_rgba]);
  c.combine = static_cast<Combine>(t.f[D::cfg_combine]);
  c.constant_rgba = static_cast<uint32_t>(t.f[D::cfg_constant_rgba]);
  c.widths = widths;
  s.pattern = static_cast<TexturePattern>(t.f[D::cfg_pattern]);
  s.content = static_cast<uint32_t>(t.f[D::cfg_content]);
  if (t.f[D::cfg_kind] > uint64_t(TexelKind::kCcc) ||
      t.f[D::cfg_filter] > uint64_t(Filter::kTrilinear) ||
      t.f[D::cfg_combine] > uint64_t(Combine::kShade) ||
      t.f[D::cfg_pattern] > uint64_t(TexturePattern::kGiven) || s.log2_w > fmts::kMaxMipLog2 ||
      s.log2_h > fmts::kMaxMipLog2) {
    throw std::invalid_argument("trilinear: a configuration item outside the encodings: " +
                                D::table().inputs().describe(t));
  }
  return s;
}

// ---- The block ---------------------------------------------------------------------------

TrilinearBlock::TrilinearBlock(const BlockOptions& options)
    : DescribedBlockOf(D::table()), options_(options) {
  auto textures = std::make_shared<TexramTextures>("trilinear");
  if (!options.tri_image.empty()) textures->give_image(options.tri_image);
  textures_ = textures;
  first_ = textures_->fit(first_texram_setup(options));
  add_level("hls", hls_level<desc::trilinear_sc, hls::TrilinearSc>(first_.config.widths));
  TMU_ADD_RTL_LEVELS(trilinear, variant());
}

TrilinearBlock::TrilinearBlock(const BlockOptions& options, TrilinearEnv env)
    : DescribedBlockOf(D::table()), options_(options) {
  options_.tri_widths = env.config.widths;
  auto textures = std::make_shared<TexramTextures>("trilinear");
  textures->give_texture(env.texture, env.content);
  textures_ = textures;
  TexramSetup s;
  s.config = env.config;
  first_ = textures_->fit(s);
  add_level("hls", hls_level<desc::trilinear_sc, hls::TrilinearSc>(first_.config.widths));
  TMU_ADD_RTL_LEVELS(trilinear, variant());
}

std::string TrilinearBlock::describe() const {
  return tb::describe(first_, textures_->content(first_));
}

std::string TrilinearBlock::variant() const {
  const texram::Widths& w = first_.config.widths;
  if (w == texram::Widths{}) return "";
  return fmt::format("s{}w{}l{}", w.sub_texel, w.weight, w.lod_frac);
}

std::string TrilinearBlock::repro_options() const { return texram_repro_options(options_); }

std::vector<Txn> TrilinearBlock::texture_load(const TexramSetup& setup) const {
  std::vector<Txn> items = {trilinear_cfg_item(setup)};
  if (uses_clut(setup.config.kind)) {
    for (const Txn& t : trilinear_clut_load(*textures_->texture_of(setup))) items.push_back(t);
  }
  return items;
}

std::vector<Txn> TrilinearBlock::setup_items() const { return texture_load(first_); }

std::vector<TexramSetup> TrilinearBlock::tour() const {
  // A given texture fixes the kind and size: the directed items stay in the first environment.
  std::vector<TexramSetup> out;
  if (!tours()) return out;
  // Sizes: one-texel sides, rows and columns, non-square, and the largest true-colour texture
  // (entry 2: addresses above 2^20).
  constexpr std::array<std::pair<int, int>, 15> kSizes = {{{3, 3},
                                                           {0, 0},
                                                           {10, 10},
                                                           {1, 6},
                                                           {4, 4},
                                                           {2, 0},
                                                           {6, 5},
                                                           {0, 3},
                                                           {4, 1},
                                                           {8, 8},
                                                           {2, 7},
                                                           {5, 5},
                                                           {3, 0},
                                                           {7, 2},
                                                           {1, 1}}};
  for (size_t i = 0; i < kSizes.size(); ++i) {
    out.push_back(textures_->fit(tour_setup(i, kSizes[i].first, kSizes[i].second, options_)));
  }
  // Sphere-map addressing: sides of 128 (no shift), more (shifted left), fewer (floored).
  constexpr std::array<std::pair<int, int>, 3> kSphereSizes = {{{7, 7}, {10, 8}, {3, 5}}};
  for (size_t i = 0; i < kSphereSizes.size(); ++i) {
    TexramSetup s = tour_setup(i, kSphereSizes[i].first, kSphereSizes[i].second, options_);
    s.config.addressing = texram::Addressing::kSphere;
    out.push_back(textures_->fit(s));
  }
  return out;
}

bool TrilinearBlock::tours() const {
  return first_.pattern != TexturePattern::kGiven || !options_.tri_image.empty();
}

std::vector<Txn> TrilinearBlock::directed_items() const {
  std::vector<Txn> items = directed_samples(first_);
  const std::vector<TexramSetup> setups = tour();
  for (const TexramSetup& s : setups) {
    for (const Txn& t : texture_load(s)) items.push_back(t);
    for (const Txn& t : directed_samples(s)) items.push_back(t);
  }
  // Back to the first environment, where the random items begin.
  if (!setups.empty()) {
    for (const Txn& t : texture_load(first_)) items.push_back(t);
  }
  return items;
}

std::vector<Txn> TrilinearBlock::directed_samples(const TexramSetup& setup) const {
  if (setup.config.addressing == texram::Addressing::kSphere) return directed_sphere_samples(setup);
  const auto [w, h, top] = extent(setup);
  std::vector<Txn> items;
  uint32_t shade = 0x80FF'40C0u;
  auto at = [&](int64_t u, int64_t v, int64_t lambda) {
    items.push_back(
        trilinear_sample_item(clamp_coord(u), clamp_coord(v), clamp_lod(lambda), shade));
    shade = shade * 0x9E37'79B1u + 0x7F4A'7C15u;  // a different I_d each time
  };

  // lambda at and beyond both ends, on a texel centre and between texels.
  for (int64_t lambda : std::initializer_list<int64_t>{
           kLodMin, -16 * kOne, -kOne, -1, 0, 1, kOne / 2 - 1, kOne / 2, kOne - 1, kOne,
           top - kOne / 2 - 1, top - kOne / 2, top - 1, top, top + 1, top + kOne / 2, top + kOne,
           top + 5 * kOne, kLodMax}) {
    at(kOne / 2, kOne / 2, lambda);
    at(w / 2 + 77, h / 3 + 201, lambda);
  }
  // Level weights 0, half and max between every pair of levels, and the whole levels.
  for (int64_t l = 0; l <= top; l += kOne) {
    for (int64_t f : {0, 1, kOne / 2, kOne - 1}) at(w / 3 + 13, h / 2 + 99, l + f);
  }
  // Coordinates at the ends of the port format, alone and mixed.
  for (int64_t lambda : {int64_t{0}, int64_t{top / 2}, int64_t{top}}) {
    for (int64_t u : {int64_t{kCoordMin}, int64_t{kCoordMax}, int64_t{0}}) {
      for (int64_t v : {int64_t{kCoordMin}, int64_t{kCoordMax}, int64_t{0}}) at(u, v, lambda);
    }
    at(kCoordMin + 1, kCoordMax - 1, lambda);
    at(kCoordMin + 127, kCoordMin + 129, lambda);
  }
  // Far outside in every direction, and whole periods away (wrap and mirror repeat).
  for (int64_t lambda : {int64_t{-kOne}, int64_t{kOne + 64}}) {
    at(-1000 * kOne - 77, h / 2, lambda);
    at(w + 1000 * kOne + 177, h / 2, lambda);
    at(w / 2, -777 * kOne - 3, lambda);
    at(w / 2, h + 555 * kOne + 200, lambda);
    for (int64_t k : {-3, -2, -1, 1, 2, 3}) {
      at(k * w + kOne / 2 + 40, h / 2 + 30, lambda);
      at(w / 2 + 30, k * h + kOne / 2 + 40, lambda);
      at(k * w + w - kOne / 4, k * h + kOne / 4, lambda);
    }
  }
  // Texel centres at the corners, the edges and one LSB either side of them, at level 0.
  for (int64_t lambda : {int64_t{-kOne}, int64_t{0}}) {
    for (int64_t u : {int64_t{kOne / 2}, int64_t{w - kOne / 2}}) {
      for (int64_t v : {int64_t{kOne / 2}, int64_t{h - kOne / 2}}) at(u, v, lambda);
    }
    for (int64_t d : {-1, 0, 1}) {
      at(d, h / 2 + 5, lambda);
      at(w + d, h / 2 + 5, lambda);
      at(w / 2 + 5, d, lambda);
      at(w / 2 + 5, h + d, lambda);
      at(d, d, lambda);
      at(w + d, h + d, lambda);
    }
  }
  // Sub-texel fractions 0, 1 LSB, half and max after the half-texel offset, per axis and
  // together, at levels 0 and 1.
  for (int64_t level : {0, 1}) {
    const int64_t scale = int64_t{1} << level;
    for (int64_t fx : {0, 1, kOne / 2, kOne - 1}) {
      for (int64_t fy : {0, kOne - 1}) {
        at(scale * (kOne + kOne / 2 + fx), scale * (kOne + kOne / 2 + fy), level * kOne);
      }
    }
  }
  // A CLUT write between samples (index and CCC textures change colour), and back to back.
  const texram::TexramTexture& tex = *textures_->texture_of(setup);
  for (uint8_t i : {uint8_t{0}, tex.banks[0].empty() ? uint8_t{0} : tex.banks[0][0]}) {
    at(kOne / 2, kOne / 2, 0);
    items.push_back(trilinear_clut_item(i, ~tex.clut[i]));
    at(kOne / 2, kOne / 2, 0);
    at(kOne, kOne, kOne / 2);
    items.push_back(trilinear_clut_item(i, tex.clut[i]));
    items.push_back(trilinear_clut_item(i, tex.clut[i]));
    at(kOne / 2, kOne / 2, 0);
  }
  return items;
}

std::vector<Txn> TrilinearBlock::directed_sphere_samples(const TexramSetup& setup) const {
  const int64_t top = extent(setup).top;
  std::vector<Txn> items;
  auto at = [&](int64_t un, int64_t vn, int64_t lambda) {
    items.push_back(
        trilinear_sample_item(clamp_coord(un), clamp_coord(vn), clamp_lod(lambda), 0x40C0'80FFu));
  };
  // The disc's centre, edges and corners, one LSB either side, and half way.
  const std::initializer_list<int64_t> ends = {
      -kUnitOne - 1,    -kUnitOne,    -kUnitOne + 1, -kUnitOne / 2, -1, 0, 1,
      kUnitOne / 2 + 3, kUnitOne - 1, kUnitOne,      kUnitOne + 1};
  for (int64_t lambda : {int64_t{-kOne}, int64_t{0}, int64_t{kOne / 2}, top}) {
    for (int64_t un : ends) {
      for (int64_t vn : ends) at(un, vn, lambda);
    }
  }
  // UnitComp's whole range (|uN| up to 2), and port bits above its 16 (ignored).
  const int64_t lo = -(int64_t{1} << (kUnitCompBits - 1)), hi = -lo - 1;
  for (int64_t c : {lo, lo + 1, hi - 1, hi}) {
    at(c, 0, 0);
    at(0, c, 0);
    at(c, c, kOne);
  }
  for (int64_t high : {int64_t{1}, int64_t{-1}, int64_t{0x55}}) {
    const int64_t above = high << kUnitCompBits;
    at(above + 1234, above - 4321, 0);
    at(above - kUnitOne, above + kUnitOne / 3, kOne / 4);
  }
  return items;
}

std::vector<Txn> TrilinearBlock::random_items(std::mt19937_64& rng, size_t count) const {
  Extent e = extent(first_);
  bool sphere = first_.config.addressing == texram::Addressing::kSphere;
  std::vector<Txn> items;
  items.reserve(count);
  auto push = [&](int64_t u, int64_t v, int64_t lambda, uint32_t shade) {
    items.push_back(
        trilinear_sample_item(clamp_coord(u), clamp_coord(v), clamp_lod(lambda), shade));
  };
  size_t next_batch = kBatch;
  while (items.size() < count) {
    const int64_t w = e.w, h = e.h, top = e.top;
    if (items.size() >= next_batch) {  // a new environment, as a driver between batches
      next_batch += kBatch;
      TexramSetup setup = textures_->fit(draw_texram_setup(rng, options_));
      if (rng() % 4 == 0) setup.config.addressing = texram::Addressing::kSphere;
      for (const Txn& t : texture_load(setup)) items.push_back(t);
      e = extent(setup);
      sphere = setup.config.addressing == texram::Addressing::kSphere;
      continue;
    }
    if (sphere) {  // a sphere map's (uN, vN): mostly on the disc's square, now and then anywhere
      const int64_t reach = rng() % 8 == 0 ? kCoordMax : kUnitOne + kUnitOne / 32;
      push(uniform(rng, -reach, reach), uniform(rng, -reach, reach),
           uniform(rng, -kOne, top + kOne), static_cast<uint32_t>(rng()));
      continue;
    }
    const uint64_t r = rng() % 1000;
    if (r == 0) {  // rarely, a CLUT rewrite
      const uint64_t x = rng();
      items.push_back(trilinear_clut_item(static_cast<uint8_t>(x), static_cast<uint32_t>(x >> 8)));
    } else if (r < 20) {  // anywhere in the port formats
      push(uniform(rng, kCoordMin, kCoordMax), uniform(rng, kCoordMin, kCoordMax),
           uniform(rng, kLodMin, kLodMax), static_cast<uint32_t>(rng()));
    } else if (r < 400) {  // uniform over the texture and around it, lambda around the levels
      const bool near = rng() % 4 != 0;
      push(near ? uniform(rng, -w / 4, w + w / 4) : uniform(rng, -2 * w, 3 * w),
           near ? uniform(rng, -h / 4, h + h / 4) : uniform(rng, -2 * h, 3 * h),
           uniform(rng, -2 * kOne, top + 2 * kOne), static_cast<uint32_t>(rng()));
    } else {
      // A rasterized textured span: rows of steps in u (either direction) of about the
      // footprint 2^lambda, lambda changing slowly along the row, v stepping by about the
      // footprint from row to row, the shade changing slowly: mostly page hits. A row covers
      // about one and a half texture widths at most.
      int64_t lambda = uniform(rng, -kOne, top + kOne / 2);
      const int64_t dlambda = uniform(rng, -3, 3);
      const auto footprint = [&lambda] {  // 2^lambda texels, raw
        return std::max<int64_t>(
            1, static_cast<int64_t>(std::exp2(static_cast<double>(lambda) / kOne) * kOne));
      };
      const int64_t rows = uniform(rng, 1, 4);
      const int64_t per_row = std::clamp<int64_t>((3 * w / 2) / footprint(), 4, 64);
      const int64_t u0 = uniform(rng, 0, w);
      const int64_t sign = rng() % 4 == 0 ? -1 : 1;
      int64_t v = uniform(rng, 0, h);
      uint32_t shade = static_cast<uint32_t>(rng());
      for (int64_t row = 0; row < rows && items.size() < count; ++row) {
        int64_t u = u0 + uniform(rng, -kOne / 2, kOne / 2);
        for (int64_t i = 0; i < per_row && items.size() < count; ++i) {
          push(u, v, lambda, shade);
          u += sign * std::max<int64_t>(footprint() * uniform(rng, 128, 384) / kOne, 1);
          lambda = std::clamp<int64_t>(lambda + dlambda, kLodMin, kLodMax);
          shade += 0x0101'0101u;
        }
        v += footprint();
      }
    }
  }
  return items;
}

std::unique_ptr<Model> TrilinearBlock::golden() const {
  return std::make_unique<Golden>(std::static_pointer_cast<const TrilinearBlock>(share()));
}

std::unique_ptr<Model> TrilinearBlock::ideal() const {
  return std::make_unique<Ideal>(std::static_pointer_cast<const TrilinearBlock>(share()));
}

std::unique_ptr<Environment> TrilinearBlock::environment(uint64_t seed) const {
  const std::shared_ptr<const TexramTextures> textures = textures_;
  const texram::Widths widths = first_.config.widths;
  return std::make_unique<TexramMemory>(
      [textures, widths](const Txn& cfg) {
        return textures->texture_of(texram_setup_of(cfg, widths));
      },
      seed);
}

// ---- Coverage ----------------------------------------------------------------------------

namespace {

constexpr const char* kMagnified = "lambda < 0 (magnification)";
constexpr const char* kBeyondTop = "lambda beyond the top level";
constexpr const char* kOutside = "coordinate outside the texture";
constexpr const char* kFault = "access with a page fault";
constexpr const char* kHits = "accesses all page hits";
constexpr const char* kTwoLevels = "two levels read";
constexpr const char* kWeight0Between = "between levels, level weight 0";
constexpr const char* kTapWeight0 = "tap weight 0";
constexpr const char* kTapWeightMax = "tap weight max";
constexpr const char* kTapOutside = "tap outside (border colour)";
constexpr const char* kNoAccess = "every tap outside (no access)";
constexpr const char* kShareCell = "taps share a cell";
constexpr const char* kAfterClut = "sample right after a CLUT write";
constexpr const char* kAfterCfg = "sample right after a configuration";
constexpr const char* kOneTexelSide = "texture with a one-texel side";
constexpr const char* kNonSquare = "non-square texture";
constexpr const char* kHighAddress = "cell address >= 2^20 (true colour 1024 x 1024)";
constexpr const char* kSphereExact = "sphere addressing, side 128 (no shift)";
constexpr const char* kSphereLeft = "sphere addressing, side > 128 (shifted left)";
constexpr const char* kSphereRight = "sphere addressing, side < 128 (shifted right, floor)";
constexpr const char* kSphereBeyond = "sphere addressing, |uN| or |vN| > 1";
constexpr const char* kSphereHighBits = "sphere addressing, port bits above UnitComp set";

}  // namespace

std::vector<std::string> TrilinearBlock::coverage_cases() const {
  const TexramChoices c = texram_choices(options_, first_);
  std::vector<std::string> cases = config_cases(c);
  cases.insert(cases.end(), {kMagnified, kBeyondTop, kOutside, kFault, kHits, kAfterCfg});
  const bool filtered = c.any(Filter::kBilinear) || c.any(Filter::kTrilinear);
  if (c.any(Filter::kTrilinear)) {
    cases.push_back(kTwoLevels);
    cases.push_back(kWeight0Between);
  }
  if (filtered) {
    cases.push_back(kTapWeight0);
    cases.push_back(kTapWeightMax);
  }
  if (c.any(Border::kBorder)) {
    cases.push_back(kTapOutside);
    cases.push_back(kNoAccess);
  }
  // Taps share a cell at clamp and mirror edges, and in a CCC block.
  if (filtered && (c.any(Border::kClamp) || c.any(Border::kMirror) || c.any(TexelKind::kCcc))) {
    cases.push_back(kShareCell);
  }
  if (c.any(TexelKind::kIndex) || c.any(TexelKind::kCcc)) cases.push_back(kAfterClut);
  if (c.one_texel_side) cases.push_back(kOneTexelSide);
  if (c.non_square) cases.push_back(kNonSquare);
  if (c.largest_rgba) cases.push_back(kHighAddress);
  if (tours()) {
    cases.insert(cases.end(),
                 {kSphereExact, kSphereLeft, kSphereRight, kSphereBeyond, kSphereHighBits});
  }
  return cases;
}

void TrilinearBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                           Coverage& cov) const {
  const texram::Widths& widths = first_.config.widths;
  const auto plan_of = [this](const TexramSetup& s, const Txn& t) {
    return texram::plan_sample(textures_->texture_of(s)->geometry, s.config, trilinear_request(t));
  };
  // The setup in effect and the pages of every access before this item.
  if (index < cover_next_) {
    cover_next_ = 0;
    cover_setup_ = first_;
    cover_pages_ = texram::PageModel();
  }
  for (; cover_next_ < index; ++cover_next_) {
    const Txn& t = items[cover_next_];
    if (D::table().is_cfg(t)) {
      cover_setup_ = trilinear_setup_of(t, widths);
    } else if (t.f[0] == D::op_req) {
      try {
        for (const BankAccess& a : sample_accesses(plan_of(cover_setup_, t))) {
          cover_pages_.access(a.cells);
        }
      } catch (const std::exception&) {  // golden reports it
      }
    }
  }
  const TexramSetup& s = cover_setup_;
  const texram::SamplerConfig& c = s.config;
  const Txn& item = items[index];
  cover_config(s, cov);
  if (s.log2_w == 0 || s.log2_h == 0) ++cov[kOneTexelSide];
  if (s.log2_w != s.log2_h) ++cov[kNonSquare];
  const auto [w, h, top] = extent(s);
  const texram::Request req = trilinear_request(item);
  if (c.addressing == texram::Addressing::kSphere && item.f[0] == D::op_req) {
    for (const int log2 : {s.log2_w, s.log2_h}) {
      ++cov[log2 == 7 ? kSphereExact : log2 > 7 ? kSphereLeft : kSphereRight];
    }
    const auto unit_comp = [](int32_t port) {
      return fx::fit(port, fmts::kUnitComp, fx::Overflow::kWrap);
    };
    if (std::abs(unit_comp(req.u)) > kUnitOne || std::abs(unit_comp(req.v)) > kUnitOne)
      ++cov[kSphereBeyond];
    if (unit_comp(req.u) != req.u || unit_comp(req.v) != req.v) ++cov[kSphereHighBits];
  }
  if (req.lambda < 0) ++cov[kMagnified];
  if (req.lambda > top) ++cov[kBeyondTop];
  const texram::Request tex =
      texram::texel_request(textures_->texture_of(s)->geometry, c.addressing, req);
  if (tex.u < 0 || tex.v < 0 || tex.u >= w || tex.v >= h) ++cov[kOutside];
  if (index > 0 && items[index - 1].f[0] == D::op_clut) ++cov[kAfterClut];
  if (index > 0 && D::table().is_cfg(items[index - 1])) ++cov[kAfterCfg];

  texram::SamplePlan plan;
  try {
    plan = plan_of(s, item);
  } catch (const std::exception&) {
    return;  // golden reports it
  }
  const std::vector<BankAccess> accesses = sample_accesses(plan);
  const uint64_t faults = cover_pages_.stats().page_faults;
  for (const BankAccess& a : accesses) {
    cover_pages_.access(a.cells);
    for (const auto& cell : a.cells) {
      if (cell && *cell >= (1u << 20)) ++cov[kHighAddress];
    }
  }
  cover_next_ = index + 1;
  if (!accesses.empty()) ++cov[cover_pages_.stats().page_faults > faults ? kFault : kHits];

  const uint32_t wmax = (1u << c.widths.weight) - 1;
  if (plan.levels_read == 2) ++cov[kTwoLevels];
  if (plan.trilinear && plan.wl == 0 && req.lambda > 0 && int64_t{req.lambda} < top) {
    ++cov[kWeight0Between];
  }
  if (plan.taps_per_level == 4) {
    if (plan.wx[0] == 0 || plan.wy[0] == 0) ++cov[kTapWeight0];
    if (plan.wx[0] == wmax || plan.wy[0] == wmax) ++cov[kTapWeightMax];
  }
  int taps = 0, outside = 0;
  for (size_t j = 0; j < static_cast<size_t>(plan.levels_read); ++j) {
    for (size_t k = 0; k < static_cast<size_t>(plan.taps_per_level); ++k) {
      ++taps;
      outside += plan.taps[j][k].outside;
    }
  }
  if (outside > 0) ++cov[kTapOutside];
  if (accesses.empty()) ++cov[kNoAccess];
  const auto banks = std::count_if(plan.bank_address.begin(), plan.bank_address.end(),
                                   [](const auto& a) { return a.has_value(); });
  if (banks < taps - outside) ++cov[kShareCell];
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(trilinear, TrilinearBlock)
