#include "blocks/clipmap/clipmap_block.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bitset>
#include <cmath>
#include <stdexcept>

#include "blocks/clipmap/clip_memory.hpp"
#include "blocks/trilinear/texram_memory.hpp"
#include "clipmap/tile_centre.hpp"
#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/texram/clipmap_sc.hpp"
#include "rtl_models_clipmap.hpp"
#include "texram/page_model.hpp"

TMU_DESCRIBE_SC(clipmap)

namespace tmu::tb {
namespace fmts = tmu::formats;
using D = desc::clipmap;
using clipmap::Substitution;
using texram::Border;
using texram::Filter;
using texram::TexelKind;

namespace {

constexpr int kFrac = fmts::kTexCoord.frac_bits;
constexpr int32_t kOne = int32_t{1} << kFrac;  // one texel (or one level) in raw .8
constexpr int32_t kCoordMin = static_cast<int32_t>(fmts::kTexCoord.min_raw());
constexpr int32_t kCoordMax = static_cast<int32_t>(fmts::kTexCoord.max_raw());
constexpr int32_t kLodMin = static_cast<int32_t>(fmts::kLod.min_raw());
constexpr int32_t kLodMax = static_cast<int32_t>(fmts::kLod.max_raw());
// A random run draws a new environment after this many items.
constexpr size_t kBatch = 2500;

int64_t uniform(std::mt19937_64& rng, int64_t lo, int64_t hi) {
  return lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(hi - lo + 1));
}
int32_t clamp_coord(int64_t raw) {
  return static_cast<int32_t>(std::clamp<int64_t>(raw, kCoordMin, kCoordMax));
}
int32_t clamp_lod(int64_t raw) {
  return static_cast<int32_t>(std::clamp<int64_t>(raw, kLodMin, kLodMax));
}
int32_t sign_extend(uint64_t field, const fx::Format& f) {
  return static_cast<int32_t>(fx::fit(
      static_cast<int64_t>(field & ((uint64_t{1} << f.width()) - 1)), f, fx::Overflow::kWrap));
}

texram::Request request_of(const Txn& t) {
  return {sign_extend(t.f[D::req_u], fmts::kTexCoord), sign_extend(t.f[D::req_v], fmts::kTexCoord),
          sign_extend(t.f[D::req_lambda], fmts::kLod), static_cast<uint32_t>(t.f[D::req_shade])};
}

// The golden unit: a request is one clip-map sample.
class Golden : public ClipGolden<D> {
  void serve(const Txn& item, Sink& sink) override {
    clipmap::ClipPlan plan;
    const uint32_t rgba = clipmap::sample(memory(), config(), regions(), request_of(item), &plan);
    read(plan, sink);
    Txn out;
    out.f[D::out_rgba] = rgba;
    sink.output(out);
  }
};

}  // namespace

ClipSetup draw_clip_setup(std::mt19937_64& rng) {
  ClipSetup s;
  clipmap::Config& c = s.config;
  c.log2_virtual = static_cast<int>(uniform(rng, 3, 8));
  c.log2_tile = static_cast<int>(uniform(rng, 2, std::min(c.log2_virtual - 1, 4)));
  constexpr TexelKind kKinds[] = {TexelKind::kLuminance, TexelKind::kIndex, TexelKind::kTrueColour,
                                  TexelKind::kSingle};
  c.sampler.kind = kKinds[rng() % 4];
  c.sampler.single_channel = static_cast<int>(rng() % 4);
  c.sampler.filter = static_cast<Filter>(rng() % 3);
  c.sampler.border_u = static_cast<Border>(rng() % 4);
  c.sampler.border_v = rng() % 2 ? c.sampler.border_u : static_cast<Border>(rng() % 4);
  c.sampler.border_rgba = static_cast<uint32_t>(rng());
  c.sampler.combine = static_cast<texram::Combine>(rng() % 3);
  c.sampler.constant_rgba = static_cast<uint32_t>(rng());
  c.substitution = rng() % 2 ? Substitution::kPerTap : Substitution::kPerSample;
  s.content = static_cast<uint32_t>(rng());
  const double side = std::ldexp(1.0, c.log2_virtual);
  s.eye_u = static_cast<double>(uniform(rng, -8, static_cast<int64_t>(side) + 8));
  s.eye_v = static_cast<double>(uniform(rng, -8, static_cast<int64_t>(side) + 8));
  return s;
}

namespace {

// A sample near the eye: within two tiles of it, lambda from magnification to beyond the
// clipped levels.
Txn near_eye_sample(std::mt19937_64& rng, const ClipSetup& s) {
  const int64_t reach = int64_t{2} << s.config.log2_tile;
  const auto at = [&](double eye) {
    return clamp_coord(static_cast<int64_t>(eye * kOne) +
                       uniform(rng, -reach * kOne, reach * kOne));
  };
  const int64_t top = int64_t{s.config.log2_virtual} * kOne;
  return clipmap_sample_item(at(s.eye_u), at(s.eye_v),
                             clamp_lod(uniform(rng, -2 * kOne, top + kOne)),
                             static_cast<uint32_t>(rng()));
}

}  // namespace

// ---- Items -------------------------------------------------------------------------------

Txn clipmap_sample_item(int32_t u_raw, int32_t v_raw, int32_t lambda_raw, uint32_t shade) {
  return channel_item(D::table(), "req",
                      {static_cast<uint32_t>(u_raw), static_cast<uint32_t>(v_raw),
                       static_cast<uint32_t>(lambda_raw), shade});
}

uint32_t clipmap_texel(uint32_t content, int level, uint32_t x, uint32_t y) {
  uint64_t z = (uint64_t{content} << 32) ^ (uint64_t(level) << 48) ^ (uint64_t{y} << 16) ^ x;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;  // splitmix64's finaliser
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
  return static_cast<uint32_t>(z ^ (z >> 31));
}

// ---- The block ---------------------------------------------------------------------------

ClipmapBlock::ClipmapBlock(const BlockOptions& options) : DescribedBlockOf(D::table()) {
  std::mt19937_64 rng(options.seed);
  first_ = draw_clip_setup(rng);
  add_level("hls", hls_level<desc::clipmap_sc, hls::ClipmapSc>());
  TMU_ADD_RTL_LEVELS(clipmap, variant());
}

ClipmapBlock::ClipmapBlock(const clipmap::Config& config, const texram::Clut32& clut)
    : DescribedBlockOf(D::table()), given_(true), clut_(clut) {
  clipmap::check(config);
  first_.config = config;
  add_level("hls", hls_level<desc::clipmap_sc, hls::ClipmapSc>());
  TMU_ADD_RTL_LEVELS(clipmap, variant());
}

std::vector<Txn> ClipmapBlock::environment_items(const ClipSetup& s) const {
  std::vector<Txn> items = {clipmap_cfg_item(s.config)};
  if (s.config.sampler.kind == TexelKind::kIndex) {
    for (uint32_t i = 0; i < 256; ++i)
      items.push_back(
          clipmap_clut_item(static_cast<uint8_t>(i), clipmap_texel(s.content, 99, i, 0)));
  }
  for (const Txn& t : clipmap_fill_items(s, clipmap_texel)) items.push_back(t);
  return items;
}

std::vector<Txn> ClipmapBlock::setup_items() const {
  if (!given_) return environment_items(first_);
  std::vector<Txn> items = {clipmap_cfg_item(first_.config)};
  if (first_.config.sampler.kind == TexelKind::kIndex) {
    for (uint32_t i = 0; i < 256; ++i)
      items.push_back(clipmap_clut_item(static_cast<uint8_t>(i), clut_[i]));
  }
  return items;
}

std::vector<Txn> ClipmapBlock::directed_samples(const ClipSetup& s, std::mt19937_64& rng) const {
  const clipmap::Config& c = s.config;
  std::vector<Txn> items;
  auto at = [&](double u, double v, double lambda) {
    items.push_back(clipmap_sample_item(
        clamp_coord(std::llround(u * kOne)), clamp_coord(std::llround(v * kOne)),
        clamp_lod(std::llround(lambda * kOne)), static_cast<uint32_t>(rng())));
  };
  // Taps straddling each clipped tile's edges (a texel either side at its own level and
  // between levels), lambda below 0 inside and outside the finest tile.
  for (int l = 0; l < c.clipped_levels(); ++l) {
    const clipmap::Region r = clipmap::centred_region(c, l, s.eye_u, s.eye_v);
    const double scale = std::ldexp(1.0, l);
    for (double edge : {double(r.x0), double(r.x1)}) {
      for (double d : {-1.0, -0.5, -0.25, 0.0, 0.25, 0.5, 1.0}) {
        for (double lambda : {-1.0, double(l), l + 0.5}) {
          at((edge + d) * scale, (r.y0 + r.y1) / 2.0 * scale, lambda);
          at((r.x0 + r.x1) / 2.0 * scale, (edge == r.x0 ? r.y0 : r.y1) * scale + d * scale, lambda);
        }
      }
    }
  }
  // The boundary between the last clipped level and the first whole one; the top.
  const double cl = c.clipped_levels();
  for (double lambda : {cl - 1, cl - 0.5, cl - 1.0 / 256, cl, cl + 0.5, double(c.log2_virtual),
                        double(c.log2_virtual) + 3}) {
    at(s.eye_u + 3.3, s.eye_v - 7.7, lambda);
    at(s.eye_u + std::ldexp(1.0, c.log2_tile + 1), s.eye_v, lambda);
  }
  // Far from the eye (every clipped level wayward), and beyond the virtual texture's edges.
  const double side = std::ldexp(1.0, c.log2_virtual);
  for (double lambda : {-2.0, 0.0, 1.5}) {
    at(side - s.eye_u, side - s.eye_v, lambda);
    at(-0.5, s.eye_v, lambda);
    at(side + 0.5, s.eye_v, lambda);
    at(s.eye_u, -3.25, lambda);
    at(side * 3 + 0.5, -side - 0.75, lambda);
  }
  return items;
}

std::vector<Txn> ClipmapBlock::directed_items() const {
  std::mt19937_64 rng(first_.content);
  std::vector<Txn> items = directed_samples(first_, rng);
  // Loads and region writes right after samples; a sample right after each.
  items.push_back(near_eye_sample(rng, first_));
  items.push_back(clipmap_load_item(
      {0, static_cast<uint32_t>(first_.eye_u), static_cast<uint32_t>(first_.eye_v), 0x12345678u}));
  items.push_back(near_eye_sample(rng, first_));
  items.push_back(clipmap_region_item(
      0, clipmap::centred_region(first_.config, 0, first_.eye_u, first_.eye_v)));
  items.push_back(near_eye_sample(rng, first_));
  // A tour of environments: each border mode with the eye at the virtual texture's corners;
  // both substitution rules; the toroidal wrap (an eye off the tile grid); an eye jumping
  // further than a tile (reloaded from scratch); non-nested regions; the largest virtual
  // texture (32k) with 4 x 4 tiles.
  struct Tour {
    int v, t;
    Border border;
    Substitution sub;
    double eye_u, eye_v;  // in units of the virtual side
  };
  constexpr Tour kTours[] = {
      {7, 4, Border::kWrap, Substitution::kPerSample, 0.0, 0.0},
      {7, 4, Border::kClamp, Substitution::kPerTap, 1.0, 1.0},
      {6, 3, Border::kMirror, Substitution::kPerSample, 0.0, 1.0},
      {6, 3, Border::kBorder, Substitution::kPerTap, 1.0, 0.0},
      {8, 4, Border::kWrap, Substitution::kPerTap, 0.37, 0.61},
      {8, 4, Border::kWrap, Substitution::kPerSample, 0.93, 0.12},  // the jump
      {15, 2, Border::kWrap, Substitution::kPerSample, 0.999, 0.5},
      {15, 2, Border::kClamp, Substitution::kPerTap, 0.5, 0.999}};
  constexpr TexelKind kTourKinds[] = {TexelKind::kLuminance, TexelKind::kIndex,
                                      TexelKind::kTrueColour, TexelKind::kSingle};
  size_t n = 0;
  for (const Tour& t : kTours) {
    ClipSetup s = first_;
    s.config.sampler.kind = kTourKinds[n++ % 4];
    s.config.log2_virtual = t.v;
    s.config.log2_tile = t.t;
    s.config.sampler.filter = Filter::kTrilinear;
    s.config.sampler.border_u = s.config.sampler.border_v = t.border;
    s.config.substitution = t.sub;
    s.eye_u = t.eye_u * std::ldexp(1.0, t.v) + 0.3;
    s.eye_v = t.eye_v * std::ldexp(1.0, t.v) + 0.7;
    for (const Txn& x : environment_items(s)) items.push_back(x);
    for (const Txn& x : directed_samples(s, rng)) items.push_back(x);
  }
  // Regions that are not nested: level 1's tile elsewhere than level 0's (per-tap substitution
  // can then want two cells of a bank: conflicts, resolved by the lowest tap).
  {
    ClipSetup s = first_;
    s.config.log2_virtual = 7;
    s.config.log2_tile = 3;
    s.config.sampler.filter = Filter::kTrilinear;
    s.config.substitution = Substitution::kPerTap;
    s.eye_u = s.eye_v = 40.2;
    for (const Txn& x : environment_items(s)) items.push_back(x);
    items.push_back(clipmap_region_item(1, {2, 2, 10, 10}));
    items.push_back(clipmap_region_item(2, {0, 0, 3, 3}));
    for (int i = 0; i < 200; ++i) items.push_back(near_eye_sample(rng, s));
  }
  for (const Txn& x : environment_items(first_)) items.push_back(x);  // where the random ones start
  return items;
}

std::vector<Txn> ClipmapBlock::random_items(std::mt19937_64& rng, size_t count) const {
  std::vector<Txn> items;
  items.reserve(count);
  ClipSetup s = first_;
  size_t next_batch = kBatch;
  while (items.size() < count) {
    if (items.size() >= next_batch) {  // a new environment, as a driver between batches
      next_batch += kBatch;
      s = draw_clip_setup(rng);
      for (const Txn& t : environment_items(s)) items.push_back(t);
      continue;
    }
    const uint64_t r = rng() % 1000;
    if (r < 3) {  // the eye moves: the tiles follow (the regions and every texel, again)
      s.eye_u += static_cast<double>(uniform(rng, -40, 40)) / 4;
      s.eye_v += static_cast<double>(uniform(rng, -40, 40)) / 4;
      for (const Txn& t : clipmap_fill_items(s, clipmap_texel)) items.push_back(t);
    } else if (r < 8) {  // a load or a region write between samples
      const int level = static_cast<int>(uniform(rng, 0, s.config.log2_virtual + 1));
      const auto x = static_cast<uint32_t>(rng() % 70000), y = static_cast<uint32_t>(rng() % 70000);
      if (rng() % 2) {
        items.push_back(clipmap_load_item({level, x, y, static_cast<uint32_t>(rng())}));
      } else {
        items.push_back(clipmap_region_item(
            level, {x % 300, y % 300, x % 300 + static_cast<uint32_t>(rng() % 40),
                    y % 300 + static_cast<uint32_t>(rng() % 40)}));
      }
    } else if (r < 30) {  // anywhere in the port formats
      items.push_back(clipmap_sample_item(static_cast<int32_t>(uniform(rng, kCoordMin, kCoordMax)),
                                          static_cast<int32_t>(uniform(rng, kCoordMin, kCoordMax)),
                                          static_cast<int32_t>(uniform(rng, kLodMin, kLodMax)),
                                          static_cast<uint32_t>(rng())));
    } else {
      items.push_back(near_eye_sample(rng, s));
    }
  }
  items.resize(std::min(items.size(), count));
  return items;
}

std::unique_ptr<Model> ClipmapBlock::golden() const { return std::make_unique<Golden>(); }

std::unique_ptr<Environment> ClipmapBlock::environment(uint64_t seed) const {
  return std::make_unique<ClipMemory>(seed);
}

// ---- Coverage ----------------------------------------------------------------------------

namespace {

constexpr const char* kKinds[] = {"kind luminance", "kind index", "kind true colour",
                                  "kind single"};
constexpr const char* kWayward = "wayward sample";
constexpr const char* kHeld = "sample held by its tiles";
constexpr const char* kPerTapSub = "per tap: a tap from a coarser level";
constexpr const char* kSkip = "per tap: a tap two or more levels coarser";
constexpr const char* kRaised = "per sample: lambda raised";
constexpr const char* kRaisedToWhole = "per sample: raised to the first whole level";
constexpr const char* kConflict = "per tap: two taps want one bank (not nested)";
constexpr const char* kToroidal =
    "a tap's tile position wraps (virtual x mod T < tile origin mod T)";
constexpr const char* kMagnified = "lambda < 0";
constexpr const char* kWholeOnly = "every level read is whole";
constexpr const char* kAfterLoad = "sample right after a load";
constexpr const char* kAfterRegion = "sample right after a region write";
constexpr const char* kLoadReplicas = "load of the 1 x 1 level (four replicas)";
constexpr const char* kLoadIgnored = "load beyond the top level (ignored)";
constexpr const char* kLargest = "virtual texture of 32k";

}  // namespace

std::vector<std::string> ClipmapBlock::coverage_cases() const {
  std::vector<std::string> cases(std::begin(kKinds), std::end(kKinds));
  cases.insert(cases.end(), {kWayward, kHeld, kPerTapSub, kSkip, kRaised, kRaisedToWhole, kConflict,
                             kToroidal, kMagnified, kWholeOnly, kAfterLoad, kAfterRegion,
                             kLoadReplicas, kLoadIgnored, kLargest});
  return cases;
}

void ClipmapBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                         Coverage& cov) const {
  if (index < cover_next_) {
    cover_next_ = 0;
    cover_regions_ = {};
  }
  for (; cover_next_ < index; ++cover_next_) {
    const Txn& t = items[cover_next_];
    if (D::table().is_cfg(t)) {
      cover_config_ = clipmap_config_of(t);
    } else if (t.f[0] == D::op_region && t.f[D::region_level] < cover_regions_.size()) {
      cover_regions_[t.f[D::region_level]] = {
          static_cast<uint32_t>(t.f[D::region_x0]), static_cast<uint32_t>(t.f[D::region_y0]),
          static_cast<uint32_t>(t.f[D::region_x1]), static_cast<uint32_t>(t.f[D::region_y1])};
    } else if (t.f[0] == D::op_load) {
      const auto level = static_cast<int>(t.f[D::load_level]);
      if (level == cover_config_.log2_virtual) ++cov[kLoadReplicas];
      if (level > cover_config_.log2_virtual) ++cov[kLoadIgnored];
    }
  }
  cover_next_ = index;
  const Txn& item = items[index];
  if (item.f[0] != D::op_req) return;
  const clipmap::Config& c = cover_config_;
  ++cov[kKinds[static_cast<size_t>(c.sampler.kind)]];
  if (c.log2_virtual == 15) ++cov[kLargest];
  if (index > 0 && items[index - 1].f[0] == D::op_load) ++cov[kAfterLoad];
  if (index > 0 && items[index - 1].f[0] == D::op_region) ++cov[kAfterRegion];
  const texram::Request q = request_of(item);
  if (q.lambda < 0) ++cov[kMagnified];
  const clipmap::ClipGeometry g = c.geometry();
  clipmap::ClipPlan p;
  try {
    p = clipmap::plan_clip_sample(g, c, cover_regions_, q);
  } catch (const std::exception&) {
    return;  // golden reports it
  }
  ++cov[p.wayward ? kWayward : kHeld];
  if (p.conflicts > 0) ++cov[kConflict];
  if (c.substitution == Substitution::kPerSample && p.wayward) {
    ++cov[kRaised];
    if (p.plan.level[0] == c.clipped_levels()) ++cov[kRaisedToWhole];
  }
  bool whole = true;
  for (size_t j = 0; j < static_cast<size_t>(p.plan.levels_read); ++j) {
    whole = whole && p.plan.level[j] >= c.clipped_levels();
    for (size_t k = 0; k < static_cast<size_t>(p.plan.taps_per_level); ++k) {
      const texram::Tap& t = p.plan.taps[j][k];
      const int level = p.tap_level[j][k];
      if (t.outside) continue;
      if (level > p.plan.level[j]) ++cov[kPerTapSub];
      if (level > p.plan.level[j] + 1) ++cov[kSkip];
      if (level < c.clipped_levels()) {
        const uint32_t mask = g.side(level) - 1;
        const clipmap::Region& r = cover_regions_[static_cast<size_t>(level)];
        if ((t.x & mask) < (r.x0 & mask) || (t.y & mask) < (r.y0 & mask)) ++cov[kToroidal];
      }
    }
  }
  if (whole) ++cov[kWholeOnly];
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(clipmap, ClipmapBlock)
