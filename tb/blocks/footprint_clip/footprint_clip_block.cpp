#include "blocks/footprint_clip/footprint_clip_block.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "blocks/clipmap/clipmap_block.hpp"
#include "blocks/footprint/footprint_block.hpp"
#include "blocks/footprint/fragments.hpp"
#include "clipmap/clip_footprint.hpp"
#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/footprint/footprint_clip_sc.hpp"
#include "rtl_models_footprint_clip.hpp"

TMU_DESCRIBE_SC(footprint_clip)

namespace tmu::tb {
namespace fmts = tmu::formats;
using D = desc::footprint_clip;
using F = desc::footprint;
using clipmap::Substitution;
using texram::Border;

// The fragment in the footprint block's slots (footprint_request reads both); the clip-map's
// memory port in the clip-map block's (clip_access_request and ClipMemory serve both).
static_assert(D::req_u == F::req_u && D::req_shade == F::req_shade && D::op_req == F::op_req);
static_assert(D::mem_req_en == desc::clipmap::mem_req_en &&
              D::mem_req_we == desc::clipmap::mem_req_we &&
              D::mem_req_wdata == desc::clipmap::mem_req_wdata &&
              D::mem_resp_data == desc::clipmap::mem_resp_data &&
              D::cfg_substitution == desc::clipmap::cfg_substitution);

namespace {

constexpr int64_t kOne = int64_t{1} << fmts::kTexCoord.frac_bits;  // one texel in raw .8
// A random run draws a new environment after this many items.
constexpr size_t kBatch = 2500;

footprint::Config setup_of(const Txn& cfg, const footprint::Widths& widths) {
  footprint::Config c;
  c.log2_max_probes =
      std::min(static_cast<int>(cfg.f[D::cfg_log2_max_probes]), fmts::kMaxProbeLog2);
  c.q_rule = static_cast<footprint::QRule>(cfg.f[D::cfg_q_rule]);
  c.widths = widths;
  return c;
}

// The golden unit: a fragment is planned, each probe a clip-map sample (its reads and the
// clip-map's counters), the colours averaged.
class Golden : public ClipGolden<D> {
 public:
  explicit Golden(const footprint::Widths& widths) : widths_(widths) {}
  void configure(const Txn& cfg) override {
    ClipGolden<D>::configure(cfg);
    setup_ = setup_of(cfg, widths_);
  }
  Counters counters() const override {
    Counters c = {{"probes", probes_ & 0xFFFF'FFFFu}};
    for (const auto& x : ClipGolden<D>::counters()) c.push_back(x);
    return c;
  }

 private:
  void serve(const Txn& item, Sink& sink) override {
    std::vector<clipmap::ClipPlan> plans;
    const uint32_t rgba = clipmap::footprint_sample(memory(), config(), regions(), setup_,
                                                    footprint_request(item), &plans);
    for (const clipmap::ClipPlan& p : plans) read(p, sink);
    probes_ += plans.size();
    Txn out;
    out.f[D::out_rgba] = rgba;
    sink.output(out);
  }
  footprint::Widths widths_;
  footprint::Config setup_;
  uint64_t probes_ = 0;
};

// A fragment centred within two tiles of the eye (footprint shapes as fragments::random).
footprint::Request near_eye(std::mt19937_64& rng, const ClipSetup& s) {
  const int64_t reach = int64_t{4} << s.config.log2_tile;
  footprint::Request r = fragments::random(rng, reach * kOne, reach * kOne);
  const auto shift = [&](int32_t c, double eye) {
    return fragments::clamp_coord(c +
                                  std::llround((eye - static_cast<double>(reach) / 2.0) * kOne));
  };
  r.u = shift(r.u, s.eye_u);
  r.v = shift(r.v, s.eye_v);
  return r;
}

}  // namespace

// ---- Items -------------------------------------------------------------------------------

Txn footprint_clip_cfg_item(const clipmap::Config& clip, const footprint::Config& setup) {
  return clip_cfg_item<D>(clip, setup.log2_max_probes, setup.q_rule);
}

Txn footprint_clip_item(const footprint::Request& r) {
  return channel_item(D::table(), "req",
                      {static_cast<uint32_t>(r.u), static_cast<uint32_t>(r.v),
                       static_cast<uint32_t>(r.r1u), static_cast<uint32_t>(r.r1v),
                       static_cast<uint32_t>(r.r2u), static_cast<uint32_t>(r.r2v), r.shade});
}

// ---- The block ---------------------------------------------------------------------------

FootprintClipBlock::FootprintClipBlock(const BlockOptions& options)
    : DescribedBlockOf(D::table()), options_(options) {
  std::mt19937_64 rng(options.seed);
  first_ = draw(rng);
  add_level("hls", hls_level<desc::footprint_clip_sc, hls::FootprintClipSc>(options_.fp_widths));
  TMU_ADD_RTL_LEVELS(footprint_clip, variant());
}

FootprintClipBlock::FootprintClipBlock(const clipmap::Config& clip, const footprint::Config& setup,
                                       const texram::Clut32& clut)
    : DescribedBlockOf(D::table()), given_(true), clut_(clut) {
  clipmap::check(clip);
  options_.fp_widths = setup.widths;
  first_.clip.config = clip;
  first_.setup = setup;
  add_level("hls", hls_level<desc::footprint_clip_sc, hls::FootprintClipSc>(options_.fp_widths));
  TMU_ADD_RTL_LEVELS(footprint_clip, variant());
}

FootprintClipSetup FootprintClipBlock::draw(std::mt19937_64& rng) const {
  return {draw_clip_setup(rng), fragments::draw_setup(rng, options_)};
}

std::string FootprintClipBlock::variant() const {
  return fragments::setup_variant(options_.fp_widths);
}

std::string FootprintClipBlock::repro_options() const {
  return fragments::setup_repro_options(options_);
}

std::vector<Txn> FootprintClipBlock::environment_items(const FootprintClipSetup& s) const {
  std::vector<Txn> items = {footprint_clip_cfg_item(s.clip.config, s.setup)};
  if (s.clip.config.sampler.kind == texram::TexelKind::kIndex) {
    for (uint32_t i = 0; i < 256; ++i) {
      items.push_back(
          clip_clut_item<D>(static_cast<uint8_t>(i), clipmap_texel(s.clip.content, 99, i, 0)));
    }
  }
  for (const Txn& t : clip_fill_items<D>(s.clip, clipmap_texel)) items.push_back(t);
  return items;
}

std::vector<Txn> FootprintClipBlock::setup_items() const {
  if (!given_) return environment_items(first_);
  std::vector<Txn> items = {footprint_clip_cfg_item(first_.clip.config, first_.setup)};
  if (first_.clip.config.sampler.kind == texram::TexelKind::kIndex) {
    for (uint32_t i = 0; i < 256; ++i)
      items.push_back(clip_clut_item<D>(static_cast<uint8_t>(i), clut_[i]));
  }
  return items;
}

std::vector<Txn> FootprintClipBlock::directed_fragments(const FootprintClipSetup& s) const {
  const clipmap::Config& c = s.clip.config;
  const int64_t side = int64_t{1} << c.log2_virtual;
  std::vector<Txn> items;
  for (const footprint::Request& r : fragments::directed(side * kOne, side * kOne))
    items.push_back(footprint_clip_item(r));
  // Long footprints from the eye outward across each clipped level's tile edges: along u, v
  // and the diagonal, each direction both ways, the minor side a texel or a tenth of the major
  // (some probes held by the finest tile, the far ones wayward), centred at the eye and at the
  // tile's edge.
  uint32_t shade = 0x8040'20FFu;
  for (int l = 0; l <= c.clipped_levels(); ++l) {
    const double major = std::ldexp(1.0, c.log2_tile + l);  // a tile of level l, in level 0
    const clipmap::Region r = clipmap::centred_region(
        c, std::min(l, std::max(0, c.clipped_levels() - 1)), s.clip.eye_u, s.clip.eye_v);
    const double edge_u = r.x1 * std::ldexp(1.0, l);
    for (const auto& [du, dv] : {std::pair{1.0, 0.0}, {0.0, 1.0}, {0.7071, 0.7071}, {-1.0, 0.0}}) {
      for (const double minor : {1.0, major / 10}) {
        for (const double cu : {s.clip.eye_u, edge_u}) {
          const auto raw = [](double x) { return std::llround(x * kOne); };
          items.push_back(footprint_clip_item(
              fragments::fragment(raw(cu), raw(s.clip.eye_v), raw(major * du), raw(major * dv),
                                  raw(-minor * dv), raw(minor * du), shade)));
          shade = shade * 0x9E37'79B9u + 1;
        }
      }
    }
  }
  return items;
}

std::vector<Txn> FootprintClipBlock::directed_items() const {
  std::mt19937_64 rng(first_.clip.content);
  std::vector<Txn> items = directed_fragments(first_);
  // Writes right after fragments, a fragment right after each: loads of texels the tiles hold
  // (a load that overtook the fragment before it would change what its probes read), a region
  // write.
  const clipmap::Region r0 =
      clipmap::centred_region(first_.clip.config, 0, first_.clip.eye_u, first_.clip.eye_v);
  for (uint32_t i = 0; i < 8; ++i) {
    items.push_back(footprint_clip_item(near_eye(rng, first_.clip)));
    items.push_back(clip_load_item<D>({0, r0.x0 + i, r0.y0 + i, static_cast<uint32_t>(rng())}));
  }
  items.push_back(footprint_clip_item(near_eye(rng, first_.clip)));
  items.push_back(clip_region_item<D>(0, r0));
  items.push_back(footprint_clip_item(near_eye(rng, first_.clip)));
  // A tour: both substitution rules under every border mode with the eye at the virtual
  // texture's corners (probes beyond its edges), at most 16 probes, every texel kind; the 32k
  // virtual texture.
  struct Tour {
    int v, t;
    Border border;
    Substitution sub;
    double eye_u, eye_v;  // in units of the virtual side
  };
  constexpr Tour kTours[] = {{7, 4, Border::kWrap, Substitution::kPerSample, 0.0, 0.0},
                             {7, 4, Border::kClamp, Substitution::kPerTap, 1.0, 1.0},
                             {6, 3, Border::kMirror, Substitution::kPerTap, 0.0, 1.0},
                             {6, 3, Border::kBorder, Substitution::kPerSample, 1.0, 0.0},
                             {15, 2, Border::kWrap, Substitution::kPerSample, 0.999, 0.5},
                             {15, 2, Border::kClamp, Substitution::kPerTap, 0.5, 0.999}};
  constexpr texram::TexelKind kTourKinds[] = {
      texram::TexelKind::kLuminance, texram::TexelKind::kIndex, texram::TexelKind::kTrueColour,
      texram::TexelKind::kSingle};
  size_t n = 0;
  for (const Tour& t : kTours) {
    FootprintClipSetup s = first_;
    s.clip.config.sampler.kind = kTourKinds[n++ % 4];
    s.clip.config.log2_virtual = t.v;
    s.clip.config.log2_tile = t.t;
    s.clip.config.sampler.filter = texram::Filter::kTrilinear;
    s.clip.config.sampler.border_u = s.clip.config.sampler.border_v = t.border;
    s.clip.config.substitution = t.sub;
    s.clip.eye_u = t.eye_u * std::ldexp(1.0, t.v) + 0.3;
    s.clip.eye_v = t.eye_v * std::ldexp(1.0, t.v) + 0.7;
    s.setup.log2_max_probes = options_.fp_log2_max_probes.value_or(fmts::kMaxProbeLog2);
    for (const Txn& x : environment_items(s)) items.push_back(x);
    for (const Txn& x : directed_fragments(s)) items.push_back(x);
  }
  for (const Txn& x : environment_items(first_)) items.push_back(x);  // where the random ones start
  return items;
}

std::vector<Txn> FootprintClipBlock::random_items(std::mt19937_64& rng, size_t count) const {
  std::vector<Txn> items;
  items.reserve(count);
  FootprintClipSetup s = first_;
  size_t next_batch = kBatch;
  while (items.size() < count) {
    if (items.size() >= next_batch) {  // a new environment, as a driver between batches
      next_batch += kBatch;
      s = draw(rng);
      for (const Txn& t : environment_items(s)) items.push_back(t);
      continue;
    }
    const uint64_t r = rng() % 1000;
    const int64_t side = int64_t{1} << s.clip.config.log2_virtual;
    if (r < 3) {  // the eye moves: the tiles follow (the regions and every texel, again)
      s.clip.eye_u += static_cast<double>(static_cast<int64_t>(rng() % 81) - 40) / 4;
      s.clip.eye_v += static_cast<double>(static_cast<int64_t>(rng() % 81) - 40) / 4;
      for (const Txn& t : clip_fill_items<D>(s.clip, clipmap_texel)) items.push_back(t);
    } else if (r < 6) {  // a load between fragments
      items.push_back(
          clip_load_item<D>({static_cast<int>(rng() % 4), static_cast<uint32_t>(rng() % 300),
                             static_cast<uint32_t>(rng() % 300), static_cast<uint32_t>(rng())}));
    } else if (r < 400) {  // anywhere over the virtual texture and around it
      items.push_back(footprint_clip_item(fragments::random(rng, side * kOne, side * kOne)));
    } else {
      items.push_back(footprint_clip_item(near_eye(rng, s.clip)));
    }
  }
  items.resize(std::min(items.size(), count));
  return items;
}

std::unique_ptr<Model> FootprintClipBlock::golden() const {
  return std::make_unique<Golden>(options_.fp_widths);
}

std::unique_ptr<Environment> FootprintClipBlock::environment(uint64_t seed) const {
  return std::make_unique<ClipMemory>(seed);
}

// ---- Coverage ----------------------------------------------------------------------------

namespace {

constexpr const char* kKinds[] = {"kind luminance", "kind index", "kind true colour",
                                  "kind single"};
constexpr const char* kMixed = "a fragment with held and wayward probes";
constexpr const char* kAllWayward = "every probe wayward";
constexpr const char* kAllHeld = "every probe held";
constexpr const char* kPerTap = "per tap substitution";
constexpr const char* kPerSample = "per sample substitution";
constexpr const char* kSixteen = "16 probes";
constexpr const char* kAfterWrite = "fragment right after a write";
constexpr const char* kLargest = "virtual texture of 32k";

}  // namespace

std::vector<std::string> FootprintClipBlock::coverage_cases() const {
  std::vector<std::string> cases(std::begin(kKinds), std::end(kKinds));
  cases.insert(cases.end(), {kMixed, kAllWayward, kAllHeld, kPerTap, kPerSample, kSixteen,
                             kAfterWrite, kLargest});
  return cases;
}

void FootprintClipBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                               Coverage& cov) const {
  if (index < cover_next_) {
    cover_next_ = 0;
    cover_regions_ = {};
  }
  for (; cover_next_ < index; ++cover_next_) {
    const Txn& t = items[cover_next_];
    if (D::table().is_cfg(t)) {
      cover_setup_.clip.config = clip_config_of<D>(t);
      cover_setup_.setup = setup_of(t, options_.fp_widths);
    } else if (t.f[0] == D::op_region && t.f[D::region_level] < cover_regions_.size()) {
      cover_regions_[t.f[D::region_level]] = {
          static_cast<uint32_t>(t.f[D::region_x0]), static_cast<uint32_t>(t.f[D::region_y0]),
          static_cast<uint32_t>(t.f[D::region_x1]), static_cast<uint32_t>(t.f[D::region_y1])};
    }
  }
  cover_next_ = index;
  const Txn& item = items[index];
  if (item.f[0] != D::op_req) return;
  const clipmap::Config& c = cover_setup_.clip.config;
  ++cov[kKinds[static_cast<size_t>(c.sampler.kind)]];
  ++cov[c.substitution == Substitution::kPerTap ? kPerTap : kPerSample];
  if (c.log2_virtual == 15) ++cov[kLargest];
  if (index > 0 && items[index - 1].f[0] != D::op_req && !D::table().is_cfg(items[index - 1]))
    ++cov[kAfterWrite];
  const footprint::Request req = footprint_request(item);
  const footprint::Plan plan = footprint::plan(req, cover_setup_.setup);
  if (plan.log2_n == fmts::kMaxProbeLog2) ++cov[kSixteen];
  int wayward = 0;
  const int n = 1 << plan.log2_n;
  try {
    for (int i = 0; i < n; ++i) {
      wayward += clipmap::plan_clip_sample(c.geometry(), c, cover_regions_,
                                           footprint::probe(req, plan, i, c.sampler))
                     .wayward;
    }
  } catch (const std::exception&) {
    return;  // golden reports it
  }
  ++cov[wayward == 0 ? kAllHeld : wayward == n ? kAllWayward : kMixed];
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(footprint_clip, FootprintClipBlock)
