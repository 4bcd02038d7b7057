#include "blocks/texram_chip/texram_chip_block.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "blocks/trilinear/texram_memory.hpp"
#include "blocks/trilinear/texram_textures.hpp"
#include "footprint/footprint.hpp"
#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/texram/texram_chip_sc.hpp"
#include "rtl_models_texram_chip.hpp"
#include "texram/detail.hpp"
#include "texram/page_model.hpp"

TMU_DESCRIBE_SC(texram_chip)

namespace tmu::tb {
namespace fmts = tmu::formats;
using D = desc::texram_chip;
using texram::chip::Drf;
using texram::chip::DrfFile;
using texram::chip::DrfOp;
using texram::chip::DrfWrite;
using texram::chip::kBankCells;
using texram::chip::kCubeDrf;
using texram::chip::kCubeFaces;
using texram::chip::kDrfs;
using texram::chip::kMaxSteps;
using texram::chip::PixelParameter;

namespace {

constexpr int kFrac = fmts::kTexCoord.frac_bits;
constexpr int32_t kOne = int32_t{1} << kFrac;  // one texel (or one level) in raw .8
constexpr int32_t kCoordMin = static_cast<int32_t>(fmts::kTexCoord.min_raw());
constexpr int32_t kCoordMax = static_cast<int32_t>(fmts::kTexCoord.max_raw());
constexpr int32_t kLodMin = static_cast<int32_t>(fmts::kLod.min_raw());
constexpr int32_t kLodMax = static_cast<int32_t>(fmts::kLod.max_raw());
constexpr int32_t kUnitOne = int32_t{1} << fmts::kUnitComp.frac_bits;
constexpr uint32_t kPage = texram::kPageCells;
// A random run writes a new program after this many pixels.
constexpr int kPixelsPerProgram = 300;

constexpr uint64_t low_bits(const fx::Format& f) { return (uint64_t{1} << f.width()) - 1; }

// Uniform in lo..hi (inclusive) from the generator's raw output (no std distributions: the
// same stimulus on every standard library).
int64_t uniform(std::mt19937_64& rng, int64_t lo, int64_t hi) {
  return lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(hi - lo + 1));
}

int32_t sign_extend(uint64_t field, const fx::Format& f) {
  return static_cast<int32_t>(
      fx::fit(static_cast<int64_t>(field & low_bits(f)), f, fx::Overflow::kWrap));
}

int32_t clamp_coord(int64_t raw) {
  return static_cast<int32_t>(std::clamp<int64_t>(raw, kCoordMin, kCoordMax));
}
int32_t clamp_lod(int64_t raw) {
  return static_cast<int32_t>(std::clamp<int64_t>(raw, kLodMin, kLodMax));
}

// The DRFs a pixel led by `lead` visits, as pixel() walks them (past a detail map's offsets
// and detail DRFs, the step limit included), and which of them take a parameter (the first
// always).
struct Walk {
  std::vector<int> drfs;
  std::vector<bool> takes;
  bool limited = false;
};
Walk walk(const DrfFile& file, int lead) {
  Walk w;
  int number = lead & 7;
  for (int step = 0; number != 0; ++step) {
    if (step >= kMaxSteps) {
      w.limited = true;
      break;
    }
    const Drf& d = file[static_cast<size_t>(number - 1)];
    w.drfs.push_back(number);
    w.takes.push_back(step == 0 || d.takes_coords);
    int extra = 0;
    number = texram::chip::next_drf(file, d, &extra);
    step += extra;
  }
  return w;
}

// Whether DRF n's pixels stream in the rtl (tmu_texram_chip's rule): one texture or emit step
// (with footprint assembly or not) without a detail map, not DRF 7 (its cube faces' bases change
// with the pixel).
bool streams(const DrfFile& file, int n) {
  if (n < 1 || n >= texram::chip::kDrfs) return false;
  const Drf& d = file[static_cast<size_t>(n - 1)];
  return (d.op == DrfOp::kTexture || d.op == DrfOp::kEmit) && d.link == 0 && !d.detail;
}

// The golden chip over a run: DRF and CLUT writes as they come; a pixel's parameters are
// gathered until it has as many as its chain takes, then it runs, its outputs and its
// accesses (the requests) at its last parameter.
class Golden : public Model {
 public:
  explicit Golden(std::shared_ptr<const TexramChipBlock> block)
      : block_(std::move(block)), chip_(*block_->scene().memory, clut_) {}
  void step(const Txn& item, Sink& sink) override {
    if (item.f[0] == D::op_drf) {
      chip_.write({static_cast<uint8_t>(item.f[D::drf_drf]),
                   static_cast<uint8_t>(item.f[D::drf_field]),
                   static_cast<uint32_t>(item.f[D::drf_value])});
      return;
    }
    if (item.f[0] == D::op_clut) {
      clut_[static_cast<uint8_t>(item.f[D::clut_addr])] =
          static_cast<uint32_t>(item.f[D::clut_rgba]);
      return;
    }
    pending_.push_back(chip_parameter(item));
    if (pending_.size() == 1) {
      needed_ = static_cast<size_t>(texram::chip::pixel_parameters(chip_.drfs(), pending_[0].lead));
    }
    if (pending_.size() < needed_) return;
    size_t next = 0;
    std::vector<texram::chip::ChipOutput> out;
    chip_.pixel(pending_, next, out);
    pending_.clear();
    for (const auto& o : out) {
      Txn t;
      t.f[D::out_rgba] = o.rgba;
      t.f[D::out_last] = o.last;
      sink.output(t);
    }
    const auto& accesses = chip_.accesses();
    for (; reported_ < accesses.size(); ++reported_) {
      Txn t;
      for (size_t b = 0; b < 8; ++b) {
        const auto& a = accesses[reported_].address[b];
        t.f[D::mem_req_en + b] = a.has_value();
        t.f[D::mem_req_addr + b] = a.value_or(0);  // the RTL shows 0 where a bank is not read
      }
      sink.request(0, t);
    }
  }
  Counters counters() const override {
    const texram::chip::ChipStats& s = chip_.stats();
    constexpr uint64_t kWrap = 0xFFFF'FFFFu;  // StatCount
    Counters c = {{"pixels", s.pixels & kWrap},
                  {"parameters", s.parameters & kWrap},
                  {"steps", s.steps & kWrap},
                  {"step_limit", s.step_limit ? 1u : 0u}};
    for (auto& p : page_counters(s.pages)) c.push_back(std::move(p));
    return c;
  }

 private:
  std::shared_ptr<const TexramChipBlock> block_;
  texram::Clut32 clut_{};  // before chip_, which reads it
  texram::chip::TexramChip chip_;
  std::vector<PixelParameter> pending_;
  size_t needed_ = 0;
  size_t reported_ = 0;
};

// ---- The environment -------------------------------------------------------------------------

// A page-aligned base for `cells` that overlaps none of `used` ([begin, end) pairs).
uint32_t place_base(std::mt19937_64& rng, uint32_t cells,
                    std::vector<std::pair<uint32_t, uint32_t>>& used) {
  const uint32_t pages = std::max<uint32_t>(1, (cells + kPage - 1) / kPage);
  const uint32_t last_page = kBankCells / kPage - pages;
  for (;;) {
    const auto base = static_cast<uint32_t>(uniform(rng, 0, last_page)) * kPage;
    const uint32_t end = base + pages * kPage;
    if (std::none_of(used.begin(), used.end(),
                     [&](const auto& u) { return base < u.second && u.first < end; })) {
      used.emplace_back(base, end);
      return base;
    }
  }
}

}  // namespace

ChipScene draw_chip_scene(uint64_t seed) {
  std::mt19937_64 rng(seed ^ 0xC41F'7E1A'0000'0001ull);
  TexramTextures textures("texram_chip");
  const BlockOptions defaults;
  ChipScene s;
  std::vector<std::pair<uint32_t, uint32_t>> used;
  const auto place = [&](ChipMapPlacement& m) {
    m.texture = textures.texture_of(m.setup);
    m.base = place_base(rng, m.texture->geometry.bank_cells(), used);
  };
  // A few maps of random kinds and sizes; the first true colour, the second an index map (the
  // chip's CLUT is its palette), the third luminance: the second and the third 64..256 texels
  // a side, the one-plane maps of the workloads (a span of pixels crosses pages as on a real
  // texture).
  const auto maps = static_cast<size_t>(uniform(rng, 4, 6));
  for (size_t i = 0; i < maps; ++i) {
    ChipMapPlacement m;
    m.setup = draw_texram_setup(rng, defaults);
    if (i == 0) m.setup.config.kind = texram::TexelKind::kTrueColour;
    if (i == 1) m.setup.config.kind = texram::TexelKind::kIndex;
    if (i == 2) m.setup.config.kind = texram::TexelKind::kLuminance;
    if (i == 1 || i == 2) {
      m.setup.log2_w = static_cast<int>(uniform(rng, 6, 8));
      m.setup.log2_h = static_cast<int>(uniform(rng, 6, 8));
    }
    place(m);
    s.maps.push_back(m);
  }
  // The cube map: six square faces of one kind and size, each its own content.
  TexramSetup face = draw_texram_setup(rng, defaults);
  face.log2_w = face.log2_h = static_cast<int>(uniform(rng, 1, 6));
  for (ChipMapPlacement& f : s.faces) {
    f.setup = face;
    f.setup.content = static_cast<uint32_t>(rng());
    place(f);
  }
  // Detail mipmaps (000 §9): 16..256 texels a side, the first grey (luminance: one map for
  // modulating any texture), the second of a random kind.
  for (int i = 0; i < 2; ++i) {
    ChipMapPlacement m;
    m.setup = draw_texram_setup(rng, defaults);
    if (i == 0) m.setup.config.kind = texram::TexelKind::kLuminance;
    m.setup.log2_w = static_cast<int>(uniform(rng, 4, fmts::kMaxDetailLog2));
    m.setup.log2_h = static_cast<int>(uniform(rng, 4, fmts::kMaxDetailLog2));
    place(m);
    s.details.push_back(m);
  }
  // Offset map pairs at the first plain maps' sizes: offsets anywhere in 0..255, multiples of 16
  // (regions side by side), or 240..255 (regions that wrap at the detail map's side); the v map
  // right after the u map, page aligned (offsets_v_base).
  std::vector<ChipMapPlacement> offset_maps;
  for (size_t i = 0; i < std::min<size_t>(3, s.maps.size()); ++i) {
    ChipOffsetsPlacement o;
    o.map = i;
    o.log2_w = s.maps[i].setup.log2_w;
    o.log2_h = s.maps[i].setup.log2_h;
    texram::Level8 u(1u << o.log2_w, 1u << o.log2_h), v(u.width, u.height);
    const uint64_t mode = rng() % 3;
    for (texram::Level8* level : {&u, &v}) {
      for (uint8_t& t : level->texels) {
        const auto x = static_cast<uint8_t>(rng());
        t = mode == 0 ? x : mode == 1 ? static_cast<uint8_t>(x & 0xF0) : (x | 0xF0);
      }
    }
    const texram::DetailMap dm = texram::make_detail_map(*s.details[0].texture, u, v);
    const uint32_t u_cells = texram::page_up(dm.offset_u.geometry.bank_cells());
    o.base = place_base(rng, u_cells + dm.offset_v.geometry.bank_cells(), used);
    ChipMapPlacement pu, pv;
    pu.texture = std::make_shared<const texram::TexramTexture>(dm.offset_u);
    pu.base = o.base;
    pv.texture = std::make_shared<const texram::TexramTexture>(dm.offset_v);
    pv.base = o.base + u_cells;
    offset_maps.push_back(pu);
    offset_maps.push_back(pv);
    s.offsets.push_back(o);
  }
  std::vector<ChipMapPlacement> all = s.maps;
  all.insert(all.end(), s.faces.begin(), s.faces.end());
  all.insert(all.end(), s.details.begin(), s.details.end());
  all.insert(all.end(), offset_maps.begin(), offset_maps.end());
  ChipScene placed = chip_scene_of(all, s.maps[1].texture->clut);
  placed.maps = s.maps;
  placed.faces = s.faces;
  placed.offsets = s.offsets;
  placed.details = s.details;
  return placed;
}

ChipScene chip_scene_of(const std::vector<ChipMapPlacement>& maps, const texram::Clut32& clut) {
  ChipScene s;
  auto memory = std::make_shared<texram::chip::ChipMemory>();
  for (const ChipMapPlacement& m : maps) memory->place(*m.texture, m.base);
  s.clut = clut;
  s.memory = memory;
  auto image = std::make_shared<texram::TexramTexture>();
  image->banks = memory->banks();
  s.image = image;
  return s;
}

namespace {

// A DRF on `m` (its kind and size), the rest drawn: filter, borders, colours, combine, op.
Drf draw_drf(std::mt19937_64& rng, const ChipMapPlacement& m) {
  Drf d;
  d.base = m.base;
  d.log2_w = m.setup.log2_w;
  d.log2_h = m.setup.log2_h;
  d.sampler = m.setup.config;
  texram::SamplerConfig& c = d.sampler;
  c.single_channel = static_cast<int>(rng() % 4);
  c.filter = static_cast<texram::Filter>(rng() % 3);
  c.border_u = static_cast<texram::Border>(rng() % 4);
  c.border_v = rng() % 3 == 0 ? c.border_u : static_cast<texram::Border>(rng() % 4);
  c.border_rgba = static_cast<uint32_t>(rng());
  c.combine = static_cast<texram::Combine>(rng() % 3);
  c.constant_rgba = static_cast<uint32_t>(rng());
  c.addressing = rng() % 6 == 0 ? texram::Addressing::kSphere : texram::Addressing::kTexel;
  const uint64_t r = rng() % 10;
  d.op = r < 4    ? DrfOp::kTexture
         : r == 4 ? DrfOp::kShading
         : r == 5 ? DrfOp::kReflectance
         : r < 9  ? DrfOp::kEnvironment
                  : DrfOp::kEmit;
  d.takes_coords = rng() % 2 == 0;
  // Footprint assembly now and then, every probe limit (5..7 act as 4) and both q rules.
  d.footprint = rng() % 6 == 0;
  d.log2_max_probes = static_cast<int>(rng() % 8);
  d.q_rule = static_cast<footprint::QRule>(rng() % 2);
  return d;
}

// DRF 7 as the cube map: the faces' bases, their size and kind.
Drf cube_drf(std::mt19937_64& rng, const ChipScene& scene) {
  Drf d = draw_drf(rng, scene.faces[0]);
  d.cube = true;
  for (size_t f = 0; f < kCubeFaces; ++f) d.face_base[f] = scene.faces[f].base;
  return d;
}

// A derivative component of up to 2^(eighths / 8) texels, either sign (raw SQ16.8,
// saturated). Integers only: the same stimulus on every standard library.
int32_t deriv(std::mt19937_64& rng, int eighths) {
  constexpr std::array<int64_t, 8> kRoot = {256, 279, 304, 332, 362, 395, 431, 470};  // 2^(i/8)
  const int64_t whole = eighths >> 3;                                                 // floor
  const int64_t len = whole >= 0 ? kRoot[static_cast<size_t>(eighths & 7)] << whole
                                 : kRoot[static_cast<size_t>(eighths & 7)] >> -whole;
  const int64_t raw = len * static_cast<int64_t>(rng() % 1025) / 1024;
  constexpr int64_t kMax = (int64_t{1} << (fmts::kTexDeriv.width() - 1)) - 1;
  return static_cast<int32_t>(std::clamp<int64_t>(rng() % 2 ? raw : -raw, -kMax, kMax));
}

// r1 and r2 of a parameter: mostly an anisotropic footprint (r2 about r1 turned a quarter and
// shortened by up to 2^6, lengths from 1/32 texel, where the marcher's lambda is below -4, to
// 64 texels), now and then a point (both 0), a line (r2 0 or parallel to r1), or long vectors.
void draw_derivatives(std::mt19937_64& rng, PixelParameter& p) {
  const uint64_t r = rng() % 16;
  const auto eighths = static_cast<int>(uniform(rng, -5 * 8, 6 * 8));
  p.r1u = deriv(rng, eighths);
  p.r1v = deriv(rng, eighths);
  const int shrink = static_cast<int>(rng() % 7);
  p.r2u = -p.r1v / (1 << shrink) + deriv(rng, eighths - 32);
  p.r2v = p.r1u / (1 << shrink) + deriv(rng, eighths - 32);
  if (r == 0) p.r1u = p.r1v = p.r2u = p.r2v = 0;
  if (r == 1) p.r2u = p.r2v = 0;
  if (r == 2) {
    p.r2u = p.r1u / 2;
    p.r2v = p.r1v / 2;
  }
  if (r == 3) {
    p.r1u = deriv(rng, 14 * 8);
    p.r2v = deriv(rng, 14 * 8);
  }
}

// The coordinates of a parameter taken for DRF `d`: over its map and around it (a sphere
// map's (uN, vN) mostly on the disc's square), now and then anywhere in the formats; a DRF
// with a detail map gets the lambdas where detail's rules change (0, -1, -4, below -4, between
// -1 and 0) often.
PixelParameter draw_parameter(std::mt19937_64& rng, const Drf& d, int lead) {
  PixelParameter p;
  p.lead = lead;
  const int64_t w = int64_t{kOne} << d.log2_w, h = int64_t{kOne} << d.log2_h;
  const int64_t top = int64_t{std::max(d.log2_w, d.log2_h)} * kOne;
  const uint64_t r = rng() % 32;
  if (r == 0) {
    p.request.u = clamp_coord(uniform(rng, kCoordMin, kCoordMax));
    p.request.v = clamp_coord(uniform(rng, kCoordMin, kCoordMax));
  } else if (d.sampler.addressing == texram::Addressing::kSphere) {
    const int64_t reach = kUnitOne + kUnitOne / 32;
    p.request.u = clamp_coord(uniform(rng, -reach, reach));
    p.request.v = clamp_coord(uniform(rng, -reach, reach));
  } else {
    p.request.u = clamp_coord(uniform(rng, -w / 4, w + w / 4));
    p.request.v = clamp_coord(uniform(rng, -h / 4, h + h / 4));
  }
  const uint64_t l = rng() % 64;
  p.request.lambda = l == 0   ? kLodMin
                     : l == 1 ? kLodMax
                              : clamp_lod(uniform(rng, -2 * kOne, top + 2 * kOne));
  if (d.detail && rng() % 2 == 0) {
    constexpr std::array<int32_t, 10> kDetailLambdas = {
        0,       -kOne,     -4 * kOne, -4 * kOne - 1, -5 * kOne,
        kLodMin, -kOne / 2, -1,        -kOne + 1,     -kOne - 1};
    p.request.lambda = rng() % 2 ? kDetailLambdas[rng() % kDetailLambdas.size()]
                                 : clamp_lod(uniform(rng, -6 * kOne, kOne));
  }
  p.request.shade = static_cast<uint32_t>(rng());
  p.face = rng() % 16 == 0 ? static_cast<int>(uniform(rng, 6, 7)) : static_cast<int>(rng() % 6);
  draw_derivatives(rng, p);
  return p;
}

}  // namespace

ChipDetailDrfs chip_detail_drfs(std::mt19937_64& rng, const ChipScene& scene, size_t offsets,
                                size_t detail) {
  const ChipOffsetsPlacement& op = scene.offsets[offsets];
  const ChipMapPlacement& dm = scene.details[detail];
  ChipDetailDrfs c;
  c.t = draw_drf(rng, scene.maps[op.map]);
  c.t.op = rng() % 3 == 0 ? DrfOp::kReflectance : DrfOp::kTexture;
  if (rng() % 16 != 0) c.t.sampler.addressing = texram::Addressing::kTexel;
  c.t.detail = true;
  c.t.detail_combine = static_cast<texram::DetailCombine>(rng() % 2);
  // The offsets DRF as texram::offset_sampler sets it (luminance, nearest, the texture's border
  // modes), now and then another filter; the detail DRF as detail_sampler (trilinear, wrap),
  // now and then another filter, border or combine: the chip reads each map as its DRF says.
  c.o.op = DrfOp::kOffsets;
  c.o.base = op.base;
  c.o.log2_w = op.log2_w;
  c.o.log2_h = op.log2_h;
  c.o.sampler = texram::offset_sampler(c.t.sampler);
  if (rng() % 8 == 0) c.o.sampler.filter = static_cast<texram::Filter>(rng() % 3);
  c.o.takes_coords = rng() % 2 == 0;  // ignored: the offsets DRF is read within t's step
  c.d.op = DrfOp::kDetail;
  c.d.base = dm.base;
  c.d.log2_w = dm.setup.log2_w;
  c.d.log2_h = dm.setup.log2_h;
  c.d.sampler = dm.setup.config;
  c.d.sampler.single_channel = c.t.sampler.single_channel;
  c.d.sampler.filter = texram::Filter::kTrilinear;
  c.d.sampler.border_u = c.d.sampler.border_v = texram::Border::kWrap;
  c.d.sampler.combine = texram::Combine::kOne;
  c.d.sampler.addressing = texram::Addressing::kTexel;
  if (rng() % 8 == 0) {
    c.d.sampler.filter = static_cast<texram::Filter>(rng() % 3);
    c.d.sampler.border_u = static_cast<texram::Border>(rng() % 4);
    c.d.sampler.combine = static_cast<texram::Combine>(rng() % 3);
  }
  c.d.takes_coords = rng() % 2 == 0;
  return c;
}

ChipProgram draw_chip_program(std::mt19937_64& rng, const ChipScene& scene) {
  ChipProgram p;
  std::array<int, kDrfs> order{};
  for (int i = 0; i < kDrfs; ++i) order[static_cast<size_t>(i)] = i + 1;
  for (size_t i = order.size() - 1; i > 0; --i) std::swap(order[i], order[rng() % (i + 1)]);
  const bool cube = rng() % 3 != 0;
  const auto at = [&](int n) -> Drf& { return p.file[static_cast<size_t>(n - 1)]; };
  for (size_t i = 0; i < order.size();) {
    const size_t len = static_cast<size_t>(uniform(rng, 1, static_cast<int64_t>(order.size() - i)));
    for (size_t k = 0; k < len;) {
      const int n = order[i + k];
      const int next = k + 1 < len ? order[i + k + 1] : 0;
      // A texture or reflectance DRF with a detail map takes three DRFs of the chain (not the
      // cube map's): the pixel leads with it, never with its offsets or detail DRF.
      if (k + 3 <= len && rng() % 3 == 0 &&
          !(cube && (n == kCubeDrf || next == kCubeDrf || order[i + k + 2] == kCubeDrf))) {
        ChipDetailDrfs c = chip_detail_drfs(rng, scene, rng() % scene.offsets.size(),
                                            rng() % scene.details.size());
        const int o = next, d = order[i + k + 2];
        c.t.link = o;
        c.o.link = d;
        c.d.link = k + 3 < len ? order[i + k + 3] : 0;
        at(n) = c.t;
        at(o) = c.o;
        at(d) = c.d;
        p.leads.push_back(n);
        k += 3;
        continue;
      }
      Drf d = cube && n == kCubeDrf ? cube_drf(rng, scene)
                                    : draw_drf(rng, scene.maps[rng() % scene.maps.size()]);
      d.link = next;
      at(n) = d;
      p.leads.push_back(n);
      ++k;
    }
    i += len;
  }
  return p;
}

// ---- Items -----------------------------------------------------------------------------------

Txn chip_drf_item(const DrfWrite& w) {
  return channel_item(D::table(), "drf", {w.drf, w.field, w.value});
}

Txn chip_clut_item(uint8_t index, uint32_t rgba) {
  return channel_item(D::table(), "clut", {index, rgba});
}

Txn chip_param_item(const PixelParameter& p) {
  return channel_item(
      D::table(), "param",
      {static_cast<uint64_t>(p.lead) & 7,
       static_cast<uint32_t>(p.request.u) & low_bits(fmts::kTexCoord),
       static_cast<uint32_t>(p.request.v) & low_bits(fmts::kTexCoord),
       static_cast<uint32_t>(p.request.lambda) & low_bits(fmts::kLod), p.request.shade,
       static_cast<uint64_t>(p.face) & 7, static_cast<uint32_t>(p.r1u) & low_bits(fmts::kTexDeriv),
       static_cast<uint32_t>(p.r1v) & low_bits(fmts::kTexDeriv),
       static_cast<uint32_t>(p.r2u) & low_bits(fmts::kTexDeriv),
       static_cast<uint32_t>(p.r2v) & low_bits(fmts::kTexDeriv)});
}

std::vector<Txn> chip_program_items(const DrfFile& file) {
  std::vector<Txn> items;
  for (int n = 1; n <= kDrfs; ++n) {
    for (const DrfWrite& w : texram::chip::drf_writes(n, file[static_cast<size_t>(n - 1)])) {
      items.push_back(chip_drf_item(w));
    }
  }
  return items;
}

PixelParameter chip_parameter(const Txn& t) {
  PixelParameter p;
  p.lead = static_cast<int>(t.f[D::param_lead] & 7);
  p.request = {
      sign_extend(t.f[D::param_u], fmts::kTexCoord), sign_extend(t.f[D::param_v], fmts::kTexCoord),
      sign_extend(t.f[D::param_lambda], fmts::kLod), static_cast<uint32_t>(t.f[D::param_shade])};
  p.face = static_cast<int>(t.f[D::param_face] & 7);
  p.r1u = sign_extend(t.f[D::param_r1u], fmts::kTexDeriv);
  p.r1v = sign_extend(t.f[D::param_r1v], fmts::kTexDeriv);
  p.r2u = sign_extend(t.f[D::param_r2u], fmts::kTexDeriv);
  p.r2v = sign_extend(t.f[D::param_r2v], fmts::kTexDeriv);
  return p;
}

// ---- The block -------------------------------------------------------------------------------

TexramChipBlock::TexramChipBlock(const BlockOptions& options)
    : TexramChipBlock(options, std::make_shared<const ChipScene>(draw_chip_scene(options.seed)),
                      {}) {
  std::mt19937_64 rng(options.seed ^ 0xC41F'0000'0000'0002ull);
  first_ = draw_chip_program(rng, *scene_);
  drawn_ = true;
  workload_ = options.chip_workload;
  if (!workload_.empty() && workload_ != "texture" && workload_ != "detail" &&
      workload_ != "extreme") {
    throw std::invalid_argument("texram_chip: no workload '" + workload_ +
                                "' (texture, detail, extreme)");
  }
}

TexramChipBlock::TexramChipBlock(const BlockOptions& /*nothing is drawn*/,
                                 std::shared_ptr<const ChipScene> scene,
                                 const texram::chip::DrfFile& program)
    : DescribedBlockOf(D::table()), scene_(std::move(scene)), first_{program, {}}, drawn_(false) {
  add_level("hls", hls_level<desc::texram_chip_sc, hls::TexramChipSc>());
  TMU_ADD_RTL_LEVELS(texram_chip, variant());
}

std::string TexramChipBlock::repro_options() const {
  const std::string variant = DescribedBlock::repro_options();
  if (workload_.empty()) return variant;
  return (variant.empty() ? "" : variant + " ") + "--chip-workload " + workload_;
}

std::vector<Txn> TexramChipBlock::workload_items(size_t count) const {
  const ChipScene& s = *scene_;
  std::mt19937_64 rng(0xC41F'F16E);
  // A texture DRF as a renderer would set it: trilinear, wrap, the shade applied.
  const auto plain = [](Drf d) {
    d.sampler.filter = texram::Filter::kTrilinear;
    d.sampler.border_u = d.sampler.border_v = texram::Border::kWrap;
    d.sampler.addressing = texram::Addressing::kTexel;
    d.sampler.combine = texram::Combine::kShade;
    d.takes_coords = d.footprint = false;
    return d;
  };
  // A map with the grey detail map, modulated (the texture read too: 000 §9's four accesses).
  const auto with_detail = [&](size_t offsets, DrfOp op) {
    ChipDetailDrfs c = chip_detail_drfs(rng, s, offsets, 0);
    c.t = plain(c.t);
    c.t.op = op;
    c.t.detail_combine = texram::DetailCombine::kModulate;
    c.o.sampler = texram::offset_sampler(c.t.sampler);
    c.d.sampler.filter = texram::Filter::kTrilinear;
    c.d.sampler.border_u = c.d.sampler.border_v = texram::Border::kWrap;
    c.d.sampler.combine = texram::Combine::kOne;
    return c;
  };
  // One-plane maps, the larger first: the index map (1) and the luminance map (2), each with
  // its offset maps.
  const auto texels = [&](size_t m) { return s.maps[m].setup.log2_w + s.maps[m].setup.log2_h; };
  const size_t first = texels(1) >= texels(2) ? 1 : 2, second = 3 - first;
  ChipProgram program;
  int32_t lambda = 0, step = kOne;  // texture: a texel a pixel at level 0
  if (workload_ == "texture") {
    program.file[0] = plain(draw_drf(rng, s.maps[first]));
    program.file[0].op = DrfOp::kTexture;
  } else {
    // Magnified four times: lambda -2 (the detail map's level 2, the patent's level -2).
    lambda = -2 * kOne;
    step = kOne / 4;
    const ChipDetailDrfs a = with_detail(first, DrfOp::kTexture);
    program.file[0] = a.t;
    program.file[0].link = 2;
    program.file[1] = a.o;
    program.file[1].link = 3;
    program.file[2] = a.d;
    if (workload_ == "extreme") {
      const ChipDetailDrfs b = with_detail(second, DrfOp::kReflectance);
      program.file[2].link = 4;
      program.file[3] = b.t;
      program.file[3].link = 5;
      program.file[4] = b.o;
      program.file[4].link = 6;
      program.file[5] = b.d;
      program.file[5].link = 7;
      // A sphere environment map on a one-plane map, at the pixel's (uN, vN).
      program.file[6] = plain(draw_drf(rng, s.maps[first]));
      program.file[6].sampler.addressing = texram::Addressing::kSphere;
      program.file[6].op = DrfOp::kEnvironment;
      program.file[6].takes_coords = true;
    }
  }
  std::vector<Txn> items = chip_program_items(program.file);
  // Spans of 8 pixels (the patent's 8-pixel scan lines), each starting anywhere on the map, the
  // pixels stepping along u.
  const Drf& t = program.file[0];
  int32_t u0 = 0, v0 = 0;
  for (size_t i = 0; items.size() < count; ++i) {
    if (i % 8 == 0) {
      u0 = static_cast<int32_t>(uniform(rng, 0, (int64_t{kOne} << t.log2_w) - 1));
      v0 = static_cast<int32_t>(uniform(rng, 0, (int64_t{kOne} << t.log2_h) - 1));
    }
    PixelParameter p;
    p.lead = 1;
    p.request = {u0 + static_cast<int32_t>(i % 8) * step, v0, lambda, 0xFFC0'8040u};
    items.push_back(chip_param_item(p));
    if (workload_ == "extreme") {  // the environment's (uN, vN): a small arc along the span
      PixelParameter q;
      q.lead = 1;
      const int64_t n = i % 8 + static_cast<int64_t>(u0 & 0xFF) * 8;
      q.request = {static_cast<int32_t>(n * kUnitOne / 2048 - kUnitOne / 2),
                   static_cast<int32_t>((v0 & 0xFF) * kUnitOne / 512 - kUnitOne / 4), 0, 0};
      items.push_back(chip_param_item(q));
    }
  }
  return items;
}

std::vector<Txn> TexramChipBlock::setup_items() const {
  std::vector<Txn> items;
  for (size_t i = 0; i < scene_->clut.size(); ++i) {
    items.push_back(chip_clut_item(static_cast<uint8_t>(i), scene_->clut[i]));
  }
  if (drawn_) {
    // Pixels before any DRF is written: the DRFs as reset (golden's DrfFile{}: a 1 x 1
    // luminance map at base 0, trilinear, texture, link 0).
    for (int lead : {1, 7}) {
      PixelParameter p;
      p.lead = lead;
      p.request = {kOne / 2, kOne / 2, 0, 0x8040'20FFu};
      items.push_back(chip_param_item(p));
    }
  }
  for (const Txn& t : chip_program_items(first_.file)) items.push_back(t);
  return items;
}

std::vector<Txn> TexramChipBlock::pixel_items(std::mt19937_64& rng, const ChipProgram& program,
                                              int lead) const {
  std::vector<Txn> items;
  const Walk w = walk(program.file, lead);
  if (w.drfs.empty()) {  // lead 0: one parameter, no step
    items.push_back(chip_param_item(draw_parameter(rng, Drf{}, lead)));
    return items;
  }
  for (size_t k = 0; k < w.drfs.size(); ++k) {
    if (!w.takes[k]) continue;
    items.push_back(chip_param_item(
        draw_parameter(rng, program.file[static_cast<size_t>(w.drfs[k] - 1)], lead)));
  }
  return items;
}

std::vector<Txn> TexramChipBlock::directed_items() const {
  std::vector<Txn> items;
  std::mt19937_64 rng(0xC41F'D1EC);
  const ChipScene& s = *scene_;
  const auto add = [&items](const std::vector<Txn>& more) {
    items.insert(items.end(), more.begin(), more.end());
  };
  const auto pixels = [&](const ChipProgram& p, int lead, int n) {
    for (int i = 0; i < n; ++i) add(pixel_items(rng, p, lead));
  };

  // Every op in one chain: 1 emit -> 2 shading -> 3 texture [coords] -> 4 reflectance ->
  // 5 environment [coords]; 6 a texture alone; 7 the cube map's environment alone.
  ChipProgram ops;
  const std::array<DrfOp, 5> chain = {DrfOp::kEmit, DrfOp::kShading, DrfOp::kTexture,
                                      DrfOp::kReflectance, DrfOp::kEnvironment};
  for (size_t k = 0; k < chain.size(); ++k) {
    Drf d = draw_drf(rng, s.maps[k % s.maps.size()]);
    d.op = chain[k];
    d.takes_coords = k == 2 || k == 4;
    d.link = k + 1 < chain.size() ? static_cast<int>(k) + 2 : 0;
    ops.file[k] = d;
  }
  ops.file[5] = draw_drf(rng, s.maps[0]);
  ops.file[5].op = DrfOp::kTexture;
  ops.file[5].sampler.addressing = texram::Addressing::kSphere;
  ops.file[6] = cube_drf(rng, s);
  ops.file[6].op = DrfOp::kEnvironment;
  ops.leads = {1, 2, 3, 4, 5, 6, 7};
  add(chip_program_items(ops.file));
  for (int lead = 1; lead <= kDrfs; ++lead) pixels(ops, lead, 6);
  // Every cube face (and the face port's 6 and 7, taken modulo 6), at lambda's extremes too.
  for (int face = 0; face < 8; ++face) {
    for (int32_t lambda : {0, kLodMin, kLodMax, kOne}) {
      PixelParameter p = draw_parameter(rng, ops.file[6], 7);
      p.face = face;
      p.request.lambda = lambda;
      items.push_back(chip_param_item(p));
    }
  }
  // Lambda at its extremes on the chain.
  for (int32_t lambda : {kLodMin, kLodMax, kLodMin + 1, kLodMax - 1}) {
    for (Txn t : pixel_items(rng, ops, 1)) {
      t.f[D::param_lambda] = static_cast<uint32_t>(lambda) & low_bits(fmts::kLod);
      items.push_back(t);
    }
  }
  // Writes presented while a pixel is in flight (right after its last parameter): they wait
  // until its colour is out. DRF 1's base moved and back, a CLUT entry changed and back.
  for (int i = 0; i < 3; ++i) {
    pixels(ops, 1, 1);
    const uint32_t moved = ops.file[0].base >= kPage ? ops.file[0].base - kPage : kPage;
    items.push_back(chip_drf_item({1, 0, moved}));
    pixels(ops, 1, 1);
    items.push_back(chip_drf_item({1, 0, ops.file[0].base}));
    pixels(ops, 6, 1);
    items.push_back(chip_clut_item(static_cast<uint8_t>(i), ~s.clut[static_cast<size_t>(i)]));
    pixels(ops, 1, 1);
    items.push_back(chip_clut_item(static_cast<uint8_t>(i), s.clut[static_cast<size_t>(i)]));
  }
  // Writes that change nothing: DRF 0, field numbers 11..15, a face of a DRF other than 7.
  for (int field : {0, 4, 11, 15}) {
    items.push_back(chip_drf_item({0, static_cast<uint8_t>(field), 0xFFFF'FFFFu}));
  }
  for (int field = 11; field < 16; ++field) {
    items.push_back(chip_drf_item({3, static_cast<uint8_t>(field), 0x1234u}));
  }
  items.push_back(chip_drf_item({3, 5, 0x1F'FFFFu}));
  pixels(ops, 3, 4);
  // A lead of 0 (no DRF: the colour 0) and every DRF of the chain as a lead.
  pixels(ops, 0, 2);
  // A 7-step chain: 1 -> 2 -> ... -> 7 (the cube map last), random ops, coordinates taken.
  ChipProgram seven;
  for (int n = 1; n <= kDrfs; ++n) {
    Drf d = n == kCubeDrf ? cube_drf(rng, s) : draw_drf(rng, s.maps[rng() % s.maps.size()]);
    d.link = n < kDrfs ? n + 1 : 0;
    seven.file[static_cast<size_t>(n - 1)] = d;
  }
  seven.file[6].op = DrfOp::kEnvironment;
  seven.leads = {1};
  add(chip_program_items(seven.file));
  pixels(seven, 1, 24);
  // A few random programs, every lead.
  for (int i = 0; i < 4; ++i) {
    const ChipProgram p = draw_chip_program(rng, s);
    add(chip_program_items(p.file));
    for (int lead : p.leads) pixels(p, lead, 3);
  }
  // Footprint assembly (000 §10): DRF 1 a texture on a one-plane map, every probe limit 0..7
  // (5..7 act as 4) with both q rules, anisotropic footprints from a point to 64 texels; 16
  // probes along r1 = (16, 0) with r2 = (0, 1/2).
  size_t plain = 0;
  while (plain + 1 < s.maps.size() && four_planes(s.maps[plain].setup.config.kind)) ++plain;
  ChipProgram fp;
  fp.file[0] = draw_drf(rng, s.maps[plain]);
  fp.file[0].op = DrfOp::kTexture;
  fp.file[0].footprint = true;
  fp.file[0].link = 0;
  fp.leads = {1};
  add(chip_program_items(fp.file));
  for (int limit = 0; limit < 8; ++limit) {
    for (const auto rule : {footprint::QRule::kHeights, footprint::QRule::kSides}) {
      fp.file[0].log2_max_probes = limit;
      fp.file[0].q_rule = rule;
      items.push_back(chip_drf_item({1, 4, texram::chip::pack_control(fp.file[0])}));
      pixels(fp, 1, 3);
      PixelParameter p = draw_parameter(rng, fp.file[0], 1);
      p.r1u = 16 * kOne;
      p.r1v = p.r2u = 0;
      p.r2v = kOne / 2;
      items.push_back(chip_param_item(p));
    }
  }
  // Detail maps (000 §9): 1 a texture with a detail map -> 2 its offsets -> 3 its detail map,
  // each combine, at the lambdas where the rules change; then with footprint assembly, small
  // footprints (the marcher's lambda below 0); then border mode with the offsets' lookup
  // outside the texture (no region).
  constexpr std::array<int32_t, 12> kDetailLambdas = {0,
                                                      -1,
                                                      -kOne / 2,
                                                      -kOne + 1,
                                                      -kOne,
                                                      -kOne - 1,
                                                      -3 * kOne / 2,
                                                      -4 * kOne,
                                                      -4 * kOne - 1,
                                                      -5 * kOne,
                                                      kLodMin,
                                                      kOne};
  for (size_t k = 0; k < 2 * s.offsets.size(); ++k) {
    ChipDetailDrfs c = chip_detail_drfs(rng, s, k % s.offsets.size(), k % s.details.size());
    c.t.op = DrfOp::kTexture;
    c.t.footprint = false;
    c.t.detail_combine = static_cast<texram::DetailCombine>(k % 2);
    c.t.link = 2;
    c.o.link = 3;
    c.d.link = 0;
    ChipProgram dp;
    dp.file[0] = c.t;
    dp.file[1] = c.o;
    dp.file[2] = c.d;
    dp.leads = {1};
    add(chip_program_items(dp.file));
    for (const int32_t lambda : kDetailLambdas) {
      PixelParameter p = draw_parameter(rng, c.t, 1);
      p.request.lambda = lambda;
      items.push_back(chip_param_item(p));
    }
    dp.file[0].footprint = true;
    dp.file[0].log2_max_probes = static_cast<int>(k % 5);
    items.push_back(chip_drf_item({1, 4, texram::chip::pack_control(dp.file[0])}));
    for (int i = 0; i < 3; ++i) {  // 1/4 texel: 1 probe at lambda -2.7; 3/2, 2: 4 probes
      PixelParameter p = draw_parameter(rng, c.t, 1);
      p.r1u = i == 0 ? kOne / 4 : kOne + i * kOne / 2;
      p.r1v = kOne / 10;
      p.r2u = -kOne / 50;
      p.r2v = kOne / 10;
      items.push_back(chip_param_item(p));
    }
    pixels(dp, 1, 2);
  }
  {
    ChipDetailDrfs c = chip_detail_drfs(rng, s, 0, 0);
    c.t.op = DrfOp::kTexture;
    c.t.footprint = false;
    c.t.sampler.border_u = c.t.sampler.border_v = texram::Border::kBorder;
    c.o.sampler = texram::offset_sampler(c.t.sampler);
    c.t.link = 2;
    c.o.link = 3;
    c.d.link = 0;
    ChipProgram dp;
    dp.file[0] = c.t;
    dp.file[1] = c.o;
    dp.file[2] = c.d;
    add(chip_program_items(dp.file));
    for (const int32_t u : {-2 * kOne, -kOne / 4, kOne / 4}) {
      PixelParameter p = draw_parameter(rng, c.t, 1);
      p.request.u = u;
      p.request.lambda = -2 * kOne;
      items.push_back(chip_param_item(p));
    }
  }
  // The patent's extreme chain (000 §5): a texture and a reflectance map, each with a detail
  // map, then the cube environment map [new coordinates]: 1 -> 2 -> ... -> 7, seven steps;
  // then led by the offsets DRF 2 (read on its own: nothing more than a read).
  {
    ChipDetailDrfs a = chip_detail_drfs(rng, s, 0, 0);
    ChipDetailDrfs b = chip_detail_drfs(rng, s, 1 % s.offsets.size(), 1 % s.details.size());
    a.t.op = DrfOp::kTexture;
    b.t.op = DrfOp::kReflectance;
    a.t.takes_coords = b.t.takes_coords = false;
    a.t.link = 2;
    a.o.link = 3;
    a.d.link = 4;
    b.t.link = 5;
    b.o.link = 6;
    b.d.link = 7;
    ChipProgram ex;
    ex.file = {a.t, a.o, a.d, b.t, b.o, b.d, cube_drf(rng, s)};
    ex.file[6].op = DrfOp::kEnvironment;
    ex.file[6].takes_coords = true;
    ex.file[6].footprint = false;
    ex.file[6].link = 0;
    ex.leads = {1};
    add(chip_program_items(ex.file));
    pixels(ex, 1, 12);
    pixels(ex, 2, 2);
  }
  // Last (the flag is sticky): a link cycle, DRF 1 -> 1, ends after kMaxSteps accesses.
  ChipProgram cycle = seven;
  cycle.file[0].link = 1;
  cycle.file[0].takes_coords = false;
  cycle.file[0].op = DrfOp::kEmit;
  add(chip_program_items(cycle.file));
  pixels(cycle, 1, 2);
  cycle.file[0].op = DrfOp::kTexture;
  cycle.file[0].takes_coords = true;
  add(chip_program_items(cycle.file));
  pixels(cycle, 1, 2);
  return items;
}

std::vector<Txn> TexramChipBlock::random_items(std::mt19937_64& rng, size_t count) const {
  if (!workload_.empty()) return workload_items(count);
  std::vector<Txn> items;
  items.reserve(count + 16);
  ChipProgram program = first_;
  int pixels = 0;
  bool written = false;
  while (items.size() < count) {
    if (!written || pixels >= kPixelsPerProgram) {  // a new program, as a driver would
      program = draw_chip_program(rng, *scene_);
      for (const Txn& t : chip_program_items(program.file)) items.push_back(t);
      written = true;
      pixels = 0;
      continue;
    }
    if (rng() % 500 == 0) {  // now and then a CLUT entry rewritten between pixels
      const uint64_t x = rng();
      items.push_back(chip_clut_item(static_cast<uint8_t>(x), static_cast<uint32_t>(x >> 8)));
    }
    const int lead = program.leads[rng() % program.leads.size()];
    for (const Txn& t : pixel_items(rng, program, lead)) items.push_back(t);
    ++pixels;
  }
  return items;
}

std::unique_ptr<Model> TexramChipBlock::golden() const {
  return std::make_unique<Golden>(std::static_pointer_cast<const TexramChipBlock>(share()));
}

std::unique_ptr<Environment> TexramChipBlock::environment(uint64_t seed) const {
  const std::shared_ptr<const texram::TexramTexture> image = scene_->image;
  auto memory = std::make_unique<TexramMemory>([image](const Txn&) { return image; }, seed);
  memory->configure(Txn{});  // the chip's memory holds the scene from the start
  return memory;
}

// ---- Coverage --------------------------------------------------------------------------------

namespace {

constexpr const char* kOpNames[] = {"op texture", "op shading", "op reflectance", "op environment",
                                    "op emit"};
constexpr const char* kChain7 = "a chain of 7 DRFs";
constexpr const char* kStepLimit = "step limit (a link cycle)";
constexpr const char* kNewCoords = "a DRF takes the pixel's next parameter";
constexpr const char* kLead0 = "lead 0 (no DRF)";
constexpr const char* kWriteBusy = "a write presented while a pixel is in flight";
constexpr const char* kLambdaMin = "lambda at its minimum";
constexpr const char* kLambdaMax = "lambda at its maximum";
constexpr const char* kFaceHigh = "face 6 or 7 (taken modulo 6)";
constexpr const char* kSphere = "sphere addressing";
constexpr const char* kFaces[] = {"cube face +X", "cube face -X", "cube face +Y",
                                  "cube face -Y", "cube face +Z", "cube face -Z"};
constexpr const char* kFootprint = "footprint assembly";
constexpr const char* kFootprint16 = "footprint assembly, 16 probes";
constexpr const char* kFootprintSides = "footprint assembly, q rule sides";
constexpr const char* kFootprintBelow0 = "footprint assembly, the marcher's lambda below 0";
constexpr const char* kDetailReplace = "detail map, replace";
constexpr const char* kDetailModulate = "detail map, modulate";
constexpr const char* kDetailBlend = "detail map, -1 < lambda < 0";
constexpr const char* kDetailMinus1 = "detail map, lambda = -1";
constexpr const char* kDetailBelow4 = "detail map, lambda below -4";
constexpr const char* kDetailProbes = "detail map under footprint assembly";
constexpr const char* kExtreme = "texture and reflectance with detail maps, then environment";
// The rtl streams pixels whose chain is one texture or emit step without a detail map (StStream).
constexpr const char* kStreamed = "a one-step pixel right behind one of the same DRF";
constexpr const char* kStreamedFootprint =
    "a one-step footprint pixel right behind one of the same DRF";
constexpr const char* kStreamedEmit = "a one-step emit pixel right behind one of the same DRF";
constexpr const char* kStreamLeft = "another DRF's pixel right behind a one-step pixel";

}  // namespace

std::vector<std::string> TexramChipBlock::coverage_cases() const {
  std::vector<std::string> cases(std::begin(kOpNames), std::end(kOpNames));
  cases.insert(cases.end(), std::begin(kFaces), std::end(kFaces));
  cases.insert(cases.end(),
               {kChain7,      kStepLimit,         kNewCoords,       kLead0,         kWriteBusy,
                kLambdaMin,   kLambdaMax,         kFaceHigh,        kSphere,        kFootprint,
                kFootprint16, kFootprintSides,    kFootprintBelow0, kDetailReplace, kDetailModulate,
                kDetailBlend, kDetailMinus1,      kDetailBelow4,    kDetailProbes,  kExtreme,
                kStreamed,    kStreamedFootprint, kStreamedEmit,    kStreamLeft});
  return cases;
}

void TexramChipBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                            Coverage& cov) const {
  // Called once per item with outputs: a pixel's last parameter (its emits and colour).
  if (index < cover_next_) {
    cover_next_ = 0;
    cover_file_ = {};
    cover_pending_ = 0;
    cover_lead_ = 0;
  }
  for (; cover_next_ < index; ++cover_next_) {
    const Txn& t = items[cover_next_];
    if (t.f[0] == D::op_drf) {
      texram::chip::apply(cover_file_, {static_cast<uint8_t>(t.f[D::drf_drf]),
                                        static_cast<uint8_t>(t.f[D::drf_field]),
                                        static_cast<uint32_t>(t.f[D::drf_value])});
    } else if (t.f[0] == D::op_param) {
      ++cover_pending_;
    }
  }
  // This pixel's parameters: items index - pending .. index (no writes inside a pixel).
  const size_t first = index - static_cast<size_t>(cover_pending_);
  cover_pending_ = 0;
  cover_next_ = index + 1;
  const PixelParameter lead = chip_parameter(items[first]);
  const Walk w = walk(cover_file_, lead.lead);
  if (w.drfs.empty()) ++cov[kLead0];
  if (w.drfs.size() == static_cast<size_t>(kMaxSteps) && !w.limited) ++cov[kChain7];
  if (w.limited) ++cov[kStepLimit];
  size_t param = first;
  std::vector<DrfOp> details;  // the ops of the DRFs with a detail map, in chain order
  for (size_t k = 0; k < w.drfs.size(); ++k) {
    const Drf& d = cover_file_[static_cast<size_t>(w.drfs[k] - 1)];
    if (k > 0 && w.takes[k]) {
      ++param;
      ++cov[kNewCoords];
    }
    const PixelParameter p = chip_parameter(items[std::min(param, index)]);
    if (static_cast<size_t>(d.op) < std::size(kOpNames)) ++cov[kOpNames[static_cast<size_t>(d.op)]];
    if (d.cube) ++cov[kFaces[p.face % kCubeFaces]];
    if (d.cube && p.face >= kCubeFaces) ++cov[kFaceHigh];
    if (d.sampler.addressing == texram::Addressing::kSphere) ++cov[kSphere];
    if (p.request.lambda == kLodMin) ++cov[kLambdaMin];
    if (p.request.lambda == kLodMax) ++cov[kLambdaMax];
    // The probes' lambda: the marcher's with footprint assembly.
    int32_t lambda = p.request.lambda;
    if (d.footprint) {
      ++cov[kFootprint];
      footprint::Config config;
      config.log2_max_probes = std::min(d.log2_max_probes, fmts::kMaxProbeLog2);
      config.q_rule = d.q_rule;
      const footprint::Plan plan =
          footprint::plan({p.request.u, p.request.v, p.r1u, p.r1v, p.r2u, p.r2v, 0}, config);
      lambda = plan.lambda;
      if (plan.log2_n == fmts::kMaxProbeLog2) ++cov[kFootprint16];
      if (d.q_rule == footprint::QRule::kSides) ++cov[kFootprintSides];
      if (lambda < 0) ++cov[kFootprintBelow0];
    }
    int extra = 0;
    texram::chip::next_drf(cover_file_, d, &extra);
    if (extra != 0 && lambda < 0) {
      ++cov[d.detail_combine == texram::DetailCombine::kModulate ? kDetailModulate
                                                                 : kDetailReplace];
      if (lambda > -kOne) ++cov[kDetailBlend];
      if (lambda == -kOne) ++cov[kDetailMinus1];
      if (lambda < -4 * kOne) ++cov[kDetailBelow4];
      if (d.footprint) ++cov[kDetailProbes];
    }
    if (extra != 0) details.push_back(d.op);
  }
  if (details.size() >= 2 && details[0] == DrfOp::kTexture && details[1] == DrfOp::kReflectance &&
      cover_file_[static_cast<size_t>(w.drfs.back() - 1)].op == DrfOp::kEnvironment) {
    ++cov[kExtreme];
  }
  if (index + 1 < items.size() && items[index + 1].f[0] != D::op_param) ++cov[kWriteBusy];
  // The pixel before this one (its last parameter the item right before: no write between) was
  // led by cover_lead_; the lead field of a later parameter of a pixel means nothing.
  if (first > 0 && items[first - 1].f[0] == D::op_param && streams(cover_file_, cover_lead_)) {
    if (cover_lead_ != lead.lead) {
      ++cov[kStreamLeft];
    } else {
      ++cov[kStreamed];
      const Drf& d = cover_file_[static_cast<size_t>(cover_lead_ - 1)];
      if (d.footprint) ++cov[kStreamedFootprint];
      if (d.op == DrfOp::kEmit) ++cov[kStreamedEmit];
    }
  }
  cover_lead_ = lead.lead;
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(texram_chip, TexramChipBlock)
