#include "blocks/footprint/footprint_block.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <span>
#include <stdexcept>
#include <tuple>

#include "blocks/footprint/fragments.hpp"
#include "blocks/trilinear/texram_memory.hpp"
#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/footprint/footprint_sc.hpp"
#include "rtl_models_footprint.hpp"
#include "texram/trilinear.hpp"

TMU_DESCRIBE_SC(footprint)

namespace tmu::tb {
namespace fmts = tmu::formats;
using D = desc::footprint;
using T = desc::trilinear;

// The trilinear unit's configuration and memory in the trilinear block's slots: one
// environment (TexramMemory), one golden sampler and one configuration item for both.
static_assert(uint64_t{D::op_clut} == uint64_t{T::op_clut} &&
              uint64_t{D::op_cfg} == uint64_t{T::op_cfg});
static_assert(D::cfg_log2_w == T::cfg_log2_w && D::cfg_constant_rgba == T::cfg_constant_rgba &&
              D::cfg_pattern == T::cfg_pattern && D::cfg_content == T::cfg_content);
static_assert(D::mem_req_en == T::mem_req_en && D::mem_req_addr == T::mem_req_addr &&
              D::mem_resp_data == T::mem_resp_data);

namespace {

constexpr int kFrac = fmts::kTexCoord.frac_bits;
constexpr int32_t kOne = int32_t{1} << kFrac;  // one texel in raw .8
constexpr int32_t kCoordMin = static_cast<int32_t>(fmts::kTexCoord.min_raw());
constexpr int32_t kCoordMax = static_cast<int32_t>(fmts::kTexCoord.max_raw());
constexpr uint32_t kWhite = 0xFFFF'FFFFu;
// What content() adds for a texture paint_white_quarter painted.
constexpr const char* kWhiteContent = ", level 0's top-left quarter white";
// A random run draws a new environment after this many items.
constexpr size_t kBatch = 2500;

constexpr uint64_t low_bits(const fx::Format& f) { return (uint64_t{1} << f.width()) - 1; }

int32_t deriv_field(uint64_t field) {
  return static_cast<int32_t>(fx::fit(static_cast<int64_t>(field & low_bits(fmts::kTexDeriv)),
                                      fmts::kTexDeriv, fx::Overflow::kWrap));
}

// The top-left quarter of level 0 white (every byte 0xFF, the CLUT's last entry white): a
// region whose probes are all 255 at lambda <= 0, so the average's sums reach 16 x 255. The
// other levels keep their content (a level 0 too small for a quarter has its first cell
// white, and that cell's replicas).
void paint_white_quarter(texram::TexramTexture& t) {
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
}

std::shared_ptr<TexramTextures> painted_textures() {
  return std::make_shared<TexramTextures>("footprint", paint_white_quarter, kWhiteContent);
}

// The golden unit over a run: the setup plans each fragment, each probe is a golden trilinear
// sample (its accesses the memory requests), the average is the output.
class Golden : public Model {
 public:
  explicit Golden(std::shared_ptr<const FootprintBlock> block)
      : block_(std::move(block)), unit_("footprint", block_->textures()) {}
  void configure(const Txn& cfg) override {
    cfg_ = block_->cfg_of(cfg);
    unit_.configure(cfg_.texram);
  }
  void step(const Txn& item, Sink& sink) override {
    if (item.f[0] == D::op_clut) {
      unit_.write_clut(static_cast<uint8_t>(item.f[D::clut_addr]),
                       static_cast<uint32_t>(item.f[D::clut_rgba]));
      return;
    }
    const footprint::Request r = footprint_request(item);
    const footprint::Plan p = footprint::plan(r, cfg_.setup);
    std::array<uint32_t, size_t{1} << fmts::kMaxProbeLog2> colours{};
    const int n = 1 << p.log2_n;
    for (int i = 0; i < n; ++i) {
      colours[static_cast<size_t>(i)] =
          unit_.sample(footprint::probe(r, p, i, unit_.config()), sink);
    }
    probes_ += static_cast<uint64_t>(n);
    Txn out;
    out.f[D::out_rgba] =
        footprint::average(std::span(colours.data(), static_cast<size_t>(n)), p.log2_n);
    sink.output(out);
  }
  Counters counters() const override {
    Counters c = {{"probes", probes_ & 0xFFFF'FFFFu}};  // the RTL's counter is 32 bits
    for (auto& m : unit_.counters()) c.push_back(std::move(m));
    return c;
  }

 private:
  std::shared_ptr<const FootprintBlock> block_;
  TexramSampler unit_;
  FootprintCfg cfg_;
  uint64_t probes_ = 0;
};

}  // namespace

// ---- Items -------------------------------------------------------------------------------

footprint::Request footprint_request(const Txn& t) {
  footprint::Request r;
  r.u = trilinear_coord(t.f[D::req_u]);
  r.v = trilinear_coord(t.f[D::req_v]);
  r.r1u = deriv_field(t.f[D::req_r1u]);
  r.r1v = deriv_field(t.f[D::req_r1v]);
  r.r2u = deriv_field(t.f[D::req_r2u]);
  r.r2v = deriv_field(t.f[D::req_r2v]);
  r.shade = static_cast<uint32_t>(t.f[D::req_shade]);
  return r;
}

Txn footprint_sample_item(int32_t u, int32_t v, int32_t r1u, int32_t r1v, int32_t r2u, int32_t r2v,
                          uint32_t shade) {
  return channel_item(
      D::table(), "req",
      {static_cast<uint32_t>(u), static_cast<uint32_t>(v), static_cast<uint32_t>(r1u),
       static_cast<uint32_t>(r1v), static_cast<uint32_t>(r2u), static_cast<uint32_t>(r2v), shade});
}

Txn footprint_item(const footprint::Request& r) {
  return footprint_sample_item(r.u, r.v, r.r1u, r.r1v, r.r2u, r.r2v, r.shade);
}

Txn footprint_clut_item(uint8_t index, uint32_t rgba) {
  return channel_item(D::table(), "clut", {index, rgba});
}

// ---- The block ---------------------------------------------------------------------------

FootprintBlock::FootprintBlock(const BlockOptions& options)
    : DescribedBlockOf(D::table()), options_(options) {
  auto textures = painted_textures();
  if (!options.tri_image.empty()) textures->give_image(options.tri_image);
  textures_ = textures;
  first_.texram = textures_->fit(first_texram_setup(options));
  first_.setup = fragments::first_setup(options);
  add_level("hls", hls_level<desc::footprint_sc, hls::FootprintSc>(first_.setup.widths,
                                                                   first_.texram.config.widths));
  TMU_ADD_RTL_LEVELS(footprint, variant());
}

FootprintBlock::FootprintBlock(const BlockOptions& options, FootprintEnv env)
    : DescribedBlockOf(D::table()), options_(options) {
  options_.tri_widths = env.trilinear.config.widths;
  options_.fp_widths = env.config.widths;
  auto textures = painted_textures();
  textures->give_texture(env.trilinear.texture, env.trilinear.content);
  textures_ = textures;
  first_.texram.config = env.trilinear.config;
  first_.texram = textures_->fit(first_.texram);
  first_.setup = env.config;
  add_level("hls", hls_level<desc::footprint_sc, hls::FootprintSc>(first_.setup.widths,
                                                                   first_.texram.config.widths));
  TMU_ADD_RTL_LEVELS(footprint, variant());
}

std::string FootprintBlock::describe() const {
  const footprint::Config& c = first_.setup;
  return fmt::format("{}; at most {} probes, q rule {}, setup widths {},{},{}",
                     tb::describe(first_.texram, textures_->content(first_.texram)),
                     1 << c.log2_max_probes, footprint::name(c.q_rule), c.widths.deriv_bits,
                     c.widths.table_bits, c.widths.log_frac);
}

std::string FootprintBlock::variant() const {
  const texram::Widths& t = first_.texram.config.widths;
  const footprint::Widths& f = first_.setup.widths;
  std::string key =
      t == texram::Widths{} ? "" : fmt::format("s{}w{}l{}", t.sub_texel, t.weight, t.lod_frac);
  const std::string setup = fragments::setup_variant(f);
  return key + (key.empty() || setup.empty() ? "" : "_") + setup;
}

std::string FootprintBlock::repro_options() const {
  const BlockOptions& o = options_;
  std::string out = texram_repro_options(o);
  const std::string setup = fragments::setup_repro_options(o);
  return out + (out.empty() || setup.empty() ? "" : " ") + setup;
}

FootprintCfg FootprintBlock::cfg_of(const Txn& cfg) const {
  FootprintCfg c;
  c.texram = texram_setup_of(cfg, first_.texram.config.widths);
  c.setup.log2_max_probes = static_cast<int>(cfg.f[D::cfg_log2_max_probes]);
  c.setup.q_rule = static_cast<footprint::QRule>(cfg.f[D::cfg_q_rule]);
  c.setup.widths = first_.setup.widths;
  return c;
}

std::vector<Txn> FootprintBlock::texture_load(const FootprintCfg& cfg) const {
  Txn item = texram_cfg_item(cfg.texram);
  item.f[D::cfg_log2_max_probes] = static_cast<uint64_t>(cfg.setup.log2_max_probes);
  item.f[D::cfg_q_rule] = static_cast<uint64_t>(cfg.setup.q_rule);
  std::vector<Txn> items = {D::table().inputs().masked(item)};
  if (uses_clut(cfg.texram.config.kind)) {
    const texram::TexramTexture& t = *textures_->texture_of(cfg.texram);
    for (size_t i = 0; i < t.clut.size(); ++i) {
      items.push_back(footprint_clut_item(static_cast<uint8_t>(i), t.clut[i]));
    }
  }
  return items;
}

FootprintCfg FootprintBlock::draw(std::mt19937_64& rng) const {
  FootprintCfg c;
  c.texram = textures_->fit(draw_texram_setup(rng, options_));
  c.setup = fragments::draw_setup(rng, options_);
  return c;
}

std::vector<Txn> FootprintBlock::setup_items() const { return texture_load(first_); }

std::vector<FootprintCfg> FootprintBlock::tour() const {
  std::vector<FootprintCfg> out;
  if (first_.texram.pattern == TexturePattern::kGiven && options_.tri_image.empty()) return out;
  // Every maximum probe count with both q rules, the trilinear configurations varying with
  // them; entry 8 (16 probes, a single-component texture of 64 x 64, combine one) holds the
  // white line whose sums reach 16 x 255.
  constexpr std::array<std::pair<int, int>, 10> kSizes = {
      {{6, 6}, {3, 2}, {7, 5}, {0, 4}, {6, 7}, {5, 5}, {8, 8}, {2, 0}, {6, 6}, {4, 7}}};
  for (size_t i = 0; i < kSizes.size(); ++i) {
    FootprintCfg c;
    c.texram = textures_->fit(tour_setup(i, kSizes[i].first, kSizes[i].second, options_));
    c.setup.log2_max_probes = options_.fp_log2_max_probes.value_or(static_cast<int>(i / 2));
    c.setup.q_rule =
        options_.fp_q_rule.value_or(i % 2 ? footprint::QRule::kSides : footprint::QRule::kHeights);
    c.setup.widths = first_.setup.widths;
    out.push_back(c);
  }
  return out;
}

std::vector<Txn> FootprintBlock::directed_items() const {
  std::vector<Txn> items = directed_fragments(first_);
  const std::vector<FootprintCfg> cfgs = tour();
  for (const FootprintCfg& c : cfgs) {
    for (const Txn& t : texture_load(c)) items.push_back(t);
    for (const Txn& t : directed_fragments(c)) items.push_back(t);
  }
  // Back to the first environment, where the random items begin.
  if (!cfgs.empty()) {
    for (const Txn& t : texture_load(first_)) items.push_back(t);
  }
  return items;
}

std::vector<Txn> FootprintBlock::directed_fragments(const FootprintCfg& cfg) const {
  const int64_t w = int64_t{kOne} << cfg.texram.log2_w, h = int64_t{kOne} << cfg.texram.log2_h;
  std::vector<Txn> items;
  for (const footprint::Request& r : fragments::directed(w, h)) items.push_back(footprint_item(r));
  // The white quarter (every channel 255; kWhite shade): 16 probes of a line inside it (k =
  // kmax; 8 texels long, 16 probes half a texel apart, lambda < 0: level 0): every probe 255
  // with combine one or shade, the sums at their largest, 16 x 255 = 4080 (needs a texture at
  // least 64 texels wide and high: the probes reach 4 texels from the centre, w / 8).
  for (const auto& [r1u, r1v] : std::initializer_list<std::pair<int64_t, int64_t>>{
           {8 * kOne, 0}, {0, 8 * kOne}, {6 * kOne, 6 * kOne}}) {
    items.push_back(footprint_item(fragments::fragment(w / 8, h / 8, r1u, r1v, 0, 0, kWhite)));
  }
  // A CLUT write between fragments (index and CCC textures change colour), and back to back.
  const texram::TexramTexture& tex = *textures_->texture_of(cfg.texram);
  for (uint8_t i : {uint8_t{0}, tex.banks[0].empty() ? uint8_t{0} : tex.banks[0][0]}) {
    items.push_back(footprint_sample_item(kOne / 2, kOne / 2, 2 * kOne, 0, 0, kOne / 2));
    items.push_back(footprint_clut_item(i, ~tex.clut[i]));
    items.push_back(footprint_sample_item(kOne / 2, kOne / 2, 2 * kOne, 0, 0, kOne / 2));
    items.push_back(footprint_clut_item(i, tex.clut[i]));
    items.push_back(footprint_clut_item(i, tex.clut[i]));
    items.push_back(footprint_sample_item(kOne / 2, kOne / 2, kOne / 2, 0, 0, 2 * kOne));
  }
  return items;
}

std::vector<Txn> FootprintBlock::random_items(std::mt19937_64& rng, size_t count) const {
  int64_t w = int64_t{kOne} << first_.texram.log2_w, h = int64_t{kOne} << first_.texram.log2_h;
  std::vector<Txn> items;
  items.reserve(count);
  size_t next_batch = kBatch;
  while (items.size() < count) {
    if (items.size() >= next_batch) {  // a new environment, as a driver between batches
      next_batch += kBatch;
      const FootprintCfg c = draw(rng);
      for (const Txn& t : texture_load(c)) items.push_back(t);
      w = int64_t{kOne} << c.texram.log2_w;
      h = int64_t{kOne} << c.texram.log2_h;
      continue;
    }
    if (rng() % 1000 == 0) {  // rarely, a CLUT rewrite
      const uint64_t x = rng();
      items.push_back(footprint_clut_item(static_cast<uint8_t>(x), static_cast<uint32_t>(x >> 8)));
      continue;
    }
    items.push_back(footprint_item(fragments::random(rng, w, h)));
  }
  return items;
}

std::unique_ptr<Model> FootprintBlock::golden() const {
  return std::make_unique<Golden>(std::static_pointer_cast<const FootprintBlock>(share()));
}

std::unique_ptr<Environment> FootprintBlock::environment(uint64_t seed) const {
  const std::shared_ptr<const TexramTextures> textures = textures_;
  const texram::Widths widths = first_.texram.config.widths;
  return std::make_unique<TexramMemory>(
      [textures, widths](const Txn& cfg) {
        return textures->texture_of(texram_setup_of(cfg, widths));
      },
      seed);
}

// ---- Coverage ----------------------------------------------------------------------------

namespace {

constexpr const char* kOutside = "probe outside the texture";
constexpr const char* kWrapped = "probe wrapped beyond the port (wrap, mirror)";
constexpr const char* kSaturated = "probe saturated beyond the port (clamp, border)";
constexpr const char* kLambdaTop = "lambda beyond the top level";
constexpr const char* kFull = "every probe 255 in R, G or B (sum 16 x 255)";
constexpr const char* kAfterClut = "fragment right after a CLUT write";
constexpr const char* kAfterCfg = "fragment right after a configuration";

bool saturates(texram::Border b) {
  return b == texram::Border::kClamp || b == texram::Border::kBorder;
}

}  // namespace

bool FootprintBlock::white_line_fits(const FootprintCfg& cfg) const {
  const texram::SamplerConfig& s = cfg.texram.config;
  return cfg.texram.pattern != TexturePattern::kGiven && cfg.texram.log2_w >= 6 &&
         cfg.texram.log2_h >= 6 && s.combine != texram::Combine::kConstant &&
         !(s.kind == texram::TexelKind::kSingle && s.single_channel == 3);
}

std::vector<std::string> FootprintBlock::coverage_cases() const {
  const TexramChoices c = texram_choices(options_, first_.texram);
  std::vector<std::string> cases = config_cases(c);
  std::vector<footprint::QRule> q_rules = {footprint::QRule::kHeights, footprint::QRule::kSides};
  if (options_.fp_q_rule) q_rules = {*options_.fp_q_rule};
  std::vector<int> maxes = {0, 1, 2, 3, 4};
  if (options_.fp_log2_max_probes) maxes = {*options_.fp_log2_max_probes};
  for (const std::string& s : fragments::shape_cases(q_rules, maxes)) cases.push_back(s);
  cases.insert(cases.end(), {kOutside, kLambdaTop, kAfterCfg});
  // One probe is the centre itself: only N > 1 reaches beyond the port.
  const bool several = *std::max_element(maxes.begin(), maxes.end()) > 0;
  if (several && (c.any(texram::Border::kWrap) || c.any(texram::Border::kMirror))) {
    cases.push_back(kWrapped);
  }
  if (several && (c.any(texram::Border::kClamp) || c.any(texram::Border::kBorder))) {
    cases.push_back(kSaturated);
  }
  if (std::find(maxes.begin(), maxes.end(), fmts::kMaxProbeLog2) != maxes.end() && c.painted &&
      c.side_64 && (c.any(texram::Combine::kOne) || c.any(texram::Combine::kShade))) {
    cases.push_back(kFull);
  }
  if (c.any(texram::TexelKind::kIndex) || c.any(texram::TexelKind::kCcc)) {
    cases.push_back(kAfterClut);
  }
  return cases;
}

void FootprintBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                           Coverage& cov) const {
  // The environment in effect, and a trilinear unit configured and written as the items did.
  if (index < cover_next_ || !cover_unit_) {
    cover_next_ = 0;
    cover_cfg_ = first_;
    cover_unit_.emplace("footprint", textures_);
  }
  for (; cover_next_ < index; ++cover_next_) {
    const Txn& t = items[cover_next_];
    if (D::table().is_cfg(t)) {
      cover_cfg_ = cfg_of(t);
      cover_unit_->configure(cover_cfg_.texram);
    } else if (t.f[0] == D::op_clut) {
      cover_unit_->write_clut(static_cast<uint8_t>(t.f[D::clut_addr]),
                              static_cast<uint32_t>(t.f[D::clut_rgba]));
    }
  }
  cover_next_ = index;
  const FootprintCfg& c = cover_cfg_;
  const texram::SamplerConfig& s = c.texram.config;
  cover_config(c.texram, cov);
  if (index > 0 && items[index - 1].f[0] == D::op_clut) ++cov[kAfterClut];
  if (index > 0 && D::table().is_cfg(items[index - 1])) ++cov[kAfterCfg];
  const footprint::Request req = footprint_request(items[index]);
  footprint::Plan p;
  try {
    p = footprint::plan(req, c.setup);
  } catch (const std::exception&) {
    return;  // golden reports it
  }
  fragments::cover_shape(req, c.setup, p, cov);
  const int levels = std::max(c.texram.log2_w, c.texram.log2_h) + 1;
  if (p.lambda > (levels - 1) * kOne) ++cov[kLambdaTop];

  // The probes: outside the texture; beyond the port's range (the exact position, as golden's
  // probe() computes it before wrapping or saturating).
  const int k = p.log2_n;
  const int64_t du = p.r2_longer ? req.r2u : req.r1u, dv = p.r2_longer ? req.r2v : req.r1v;
  const int64_t w = int64_t{kOne} << c.texram.log2_w, h = int64_t{kOne} << c.texram.log2_h;
  for (int i = 0; i < (1 << k); ++i) {
    const texram::Request pr = footprint::probe(req, p, i, s);
    if (pr.u < 0 || pr.v < 0 || pr.u >= w || pr.v >= h) ++cov[kOutside];
    const int64_t n = 2 * int64_t{i} - ((int64_t{1} << k) - 1);
    for (const auto& [centre, d, border] :
         {std::tuple{int64_t{req.u}, du, s.border_u}, std::tuple{int64_t{req.v}, dv, s.border_v}}) {
      const int64_t exact = ((centre << (k + 1)) + n * d + (int64_t{1} << k)) >> (k + 1);
      if (exact >= kCoordMin && exact <= kCoordMax) continue;
      ++cov[saturates(border) ? kSaturated : kWrapped];
    }
  }
  // The probes' colours: their R, G, B sums at 16 x 255.
  if (k == fmts::kMaxProbeLog2 && white_line_fits(c)) {
    std::array<uint32_t, 3> sums{};  // R, G, B (alpha is 255 in many kinds)
    try {
      RunResult scratch;
      Sink sink(scratch);
      for (int i = 0; i < (1 << k); ++i) {
        const uint32_t rgba = cover_unit_->sample(footprint::probe(req, p, i, s), sink);
        for (int ch = 0; ch < 3; ++ch) sums[static_cast<size_t>(ch)] += texram::channel(rgba, ch);
      }
    } catch (const std::exception&) {
      sums = {};
    }
    if (std::find(sums.begin(), sums.end(), 16u * 255u) != sums.end()) ++cov[kFull];
  }
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(footprint, FootprintBlock)
