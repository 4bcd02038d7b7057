#include "blocks/texram_chip/texram_chip_block.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "blocks/trilinear/texram_memory.hpp"
#include "blocks/trilinear/texram_textures.hpp"
#include "formats/formats.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/texram/texram_chip_sc.hpp"
#include "rtl_models_texram_chip.hpp"
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

// The DRFs a pixel led by `lead` visits, as pixel() walks them (the step limit included), and
// which of them take a parameter (the first always).
struct Walk {
  std::vector<int> drfs;
  std::vector<bool> takes;
  bool limited = false;
};
Walk walk(const DrfFile& file, int lead) {
  Walk w;
  int number = lead & 7;
  for (int step = 0; number != 0; ++step) {
    if (step == kMaxSteps) {
      w.limited = true;
      break;
    }
    const Drf& d = file[static_cast<size_t>(number - 1)];
    w.drfs.push_back(number);
    w.takes.push_back(step == 0 || d.takes_coords);
    number = d.link;
  }
  return w;
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
  // chip's CLUT is its palette).
  const auto maps = static_cast<size_t>(uniform(rng, 4, 6));
  for (size_t i = 0; i < maps; ++i) {
    ChipMapPlacement m;
    m.setup = draw_texram_setup(rng, defaults);
    if (i == 0) m.setup.config.kind = texram::TexelKind::kTrueColour;
    if (i == 1) m.setup.config.kind = texram::TexelKind::kIndex;
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
  std::vector<ChipMapPlacement> all = s.maps;
  all.insert(all.end(), s.faces.begin(), s.faces.end());
  ChipScene placed = chip_scene_of(all, s.maps[1].texture->clut);
  placed.maps = s.maps;
  placed.faces = s.faces;
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
  return d;
}

// DRF 7 as the cube map: the faces' bases, their size and kind.
Drf cube_drf(std::mt19937_64& rng, const ChipScene& scene) {
  Drf d = draw_drf(rng, scene.faces[0]);
  d.cube = true;
  for (size_t f = 0; f < kCubeFaces; ++f) d.face_base[f] = scene.faces[f].base;
  return d;
}

// The coordinates of a parameter taken for DRF `d`: over its map and around it (a sphere
// map's (uN, vN) mostly on the disc's square), now and then anywhere in the formats.
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
  p.request.shade = static_cast<uint32_t>(rng());
  p.face = rng() % 16 == 0 ? static_cast<int>(uniform(rng, 6, 7)) : static_cast<int>(rng() % 6);
  return p;
}

}  // namespace

ChipProgram draw_chip_program(std::mt19937_64& rng, const ChipScene& scene) {
  ChipProgram p;
  std::array<int, kDrfs> order{};
  for (int i = 0; i < kDrfs; ++i) order[static_cast<size_t>(i)] = i + 1;
  for (size_t i = order.size() - 1; i > 0; --i) std::swap(order[i], order[rng() % (i + 1)]);
  const bool cube = rng() % 3 != 0;
  for (size_t i = 0; i < order.size();) {
    const size_t len = static_cast<size_t>(uniform(rng, 1, static_cast<int64_t>(order.size() - i)));
    for (size_t k = 0; k < len; ++k) {
      const int n = order[i + k];
      Drf d = cube && n == kCubeDrf ? cube_drf(rng, scene)
                                    : draw_drf(rng, scene.maps[rng() % scene.maps.size()]);
      d.link = k + 1 < len ? order[i + k + 1] : 0;
      p.file[static_cast<size_t>(n - 1)] = d;
      p.leads.push_back(n);
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
  return channel_item(D::table(), "param",
                      {static_cast<uint64_t>(p.lead) & 7,
                       static_cast<uint32_t>(p.request.u) & low_bits(fmts::kTexCoord),
                       static_cast<uint32_t>(p.request.v) & low_bits(fmts::kTexCoord),
                       static_cast<uint32_t>(p.request.lambda) & low_bits(fmts::kLod),
                       p.request.shade, static_cast<uint64_t>(p.face) & 7});
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
  return p;
}

// ---- The block -------------------------------------------------------------------------------

TexramChipBlock::TexramChipBlock(const BlockOptions& options)
    : TexramChipBlock(options, std::make_shared<const ChipScene>(draw_chip_scene(options.seed)),
                      {}) {
  std::mt19937_64 rng(options.seed ^ 0xC41F'0000'0000'0002ull);
  first_ = draw_chip_program(rng, *scene_);
  drawn_ = true;
}

TexramChipBlock::TexramChipBlock(const BlockOptions& /*nothing is drawn*/,
                                 std::shared_ptr<const ChipScene> scene,
                                 const texram::chip::DrfFile& program)
    : DescribedBlockOf(D::table()), scene_(std::move(scene)), first_{program, {}}, drawn_(false) {
  add_level("hls", hls_level<desc::texram_chip_sc, hls::TexramChipSc>());
  TMU_ADD_RTL_LEVELS(texram_chip, variant());
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

}  // namespace

std::vector<std::string> TexramChipBlock::coverage_cases() const {
  std::vector<std::string> cases(std::begin(kOpNames), std::end(kOpNames));
  cases.insert(cases.end(), std::begin(kFaces), std::end(kFaces));
  cases.insert(cases.end(), {kChain7, kStepLimit, kNewCoords, kLead0, kWriteBusy, kLambdaMin,
                             kLambdaMax, kFaceHigh, kSphere});
  return cases;
}

void TexramChipBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                            Coverage& cov) const {
  // Called once per item with outputs: a pixel's last parameter (its emits and colour).
  if (index < cover_next_) {
    cover_next_ = 0;
    cover_file_ = {};
    cover_pending_ = 0;
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
  }
  if (index + 1 < items.size() && items[index + 1].f[0] != D::op_param) ++cov[kWriteBusy];
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(texram_chip, TexramChipBlock)
