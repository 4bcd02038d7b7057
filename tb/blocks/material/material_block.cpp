#include "blocks/material/material_block.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <stdexcept>

#include "blocks/noise/solid_stimulus.hpp"
#include "harness/described_engines.hpp"
#include "harness/described_hls.hpp"
#include "hls/perlin/material_sc.hpp"
#include "perlin/noise.hpp"
#include "rtl_models_material.hpp"

TMU_DESCRIBE_SC(material)

namespace tmu::tb {
using perlin::ColourTables;
using perlin::MaterialKind;
using perlin::MaterialReg;
using perlin::MaterialRegs;
using perlin::NoiseConfig;
using D = desc::material;

namespace {

constexpr int32_t kOne = solid::kUnit;  // 1.0, raw SQ12.12
using solid::kCoordMax;
using solid::kCoordMin;
constexpr int64_t kIndexLimit = int64_t{1} << perlin::kIndexBits;                // 2^15
constexpr int kFireShift = perlin::kCoordFracBits - perlin::kFireTableFracBits;  // v >> 7
// Random items: a new register set in the middle of every this many items, new tables too.
constexpr size_t kRegsPeriod = 2048;
constexpr size_t kTablesPeriod = 16384;

uint32_t u16(int64_t x) { return static_cast<uint32_t>(x) & 0xFFFFu; }

void append(std::vector<Txn>& to, const std::vector<Txn>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

bool is_sample(const Txn& t) { return t.f[0] == D::op_in; }
bool is_table_write(const Txn& t) { return t.f[0] == D::op_wr && t.f[D::wr_op] != 0; }

// Applies a write item to the golden unit.
void apply_write(perlin::MaterialUnit& unit, const Txn& t) {
  if (t.f[D::wr_op] == 0) {
    unit.write_reg(static_cast<MaterialReg>(t.f[D::wr_reg]),
                   static_cast<uint32_t>(t.f[D::wr_value]));
  } else {
    unit.write_table(static_cast<uint32_t>(t.f[D::wr_table]),
                     static_cast<uint32_t>(t.f[D::wr_index]),
                     static_cast<uint32_t>(t.f[D::wr_rgb]));
  }
}

// Every register of `r` as write items (pw and ph before the mortars).
std::vector<Txn> reg_items(const MaterialRegs& r) {
  return {material_reg_item(MaterialReg::kKind, static_cast<uint32_t>(r.kind)),
          material_reg_item(MaterialReg::kGt, r.g_t),
          material_reg_item(MaterialReg::kGv, r.g_v),
          material_reg_item(MaterialReg::kGr, r.g_r),
          material_reg_item(MaterialReg::kGw, u16(r.g_w)),
          material_reg_item(MaterialReg::kOffset, u16(r.offset)),
          material_reg_item(MaterialReg::kGl, r.g_l),
          material_reg_item(MaterialReg::kCutoff, u16(r.cutoff)),
          material_reg_item(MaterialReg::kPw, static_cast<uint32_t>(r.pw)),
          material_reg_item(MaterialReg::kPh, static_cast<uint32_t>(r.ph)),
          material_reg_item(MaterialReg::kMortarW, static_cast<uint32_t>(r.mortar_w)),
          material_reg_item(MaterialReg::kMortarH, static_cast<uint32_t>(r.mortar_h))};
}

std::vector<Txn> table_items(const ColourTables& tables) {
  std::vector<Txn> items;
  for (uint32_t i = 0; i < perlin::kColourEntries; ++i) {
    items.push_back(material_table_item(0, i, tables.main[i]));
  }
  for (uint32_t i = 0; i < perlin::kColourEntries; ++i) {
    items.push_back(material_table_item(1, i, tables.mortar[i]));
  }
  return items;
}

// The golden unit over a run: writes change its registers and tables, a sample is shaded on
// what was written before it.
class GoldenMaterial : public Model {
 public:
  void step(const Txn& item, Sink& sink) override {
    if (!is_sample(item)) {
      apply_write(unit_, item);
      return;
    }
    const auto [u, v, w] = solid::coords(item, D::in_u);
    Txn out;
    out.f[D::out_rgb] = unit_.sample(u, v, w);
    sink.output(out);
  }

 private:
  perlin::MaterialUnit unit_;
};

// --- what the golden model computes, for the directed search and coverage ------------------

struct SampleTrace {
  MaterialKind kind = MaterialKind::kMarble;
  perlin::FractalSums sums;  // of the shaped coordinates
  int64_t unwrapped = 0;     // marble, wood, brick: the index value before mod 2^15; fire:
                             // before the clamp
  uint32_t entry = 0;        // the table entry read (marble, wood, brick, fire)
  bool table_reader = false;
  bool mortar = false;  // brick: the mortar table
  int64_t rings = 0;    // wood: (u^2 + v^2) g_r >> 24
  int64_t level = 0;    // gases: F g_l >> 22 (fog: |F|) before the clamp
  // brick geometry
  bool even_row = false, negative_row = false;
  int64_t ur = 0, vr = 0;
};

SampleTrace trace_sample(const MaterialRegs& r, int32_t u, int32_t v, int32_t w) {
  SampleTrace t;
  t.kind = r.kind;
  const perlin::Shaped s = perlin::shape(r, u, v, w);
  t.sums = perlin::fractal_sums(NoiseConfig{}, s.u, s.v, s.w);
  const int64_t tt = t.sums.turbulence, f = t.sums.fractal_sum;
  const int64_t tg = (tt * r.g_t) >> 14;
  switch (r.kind) {
    case MaterialKind::kMarble:
      t.unwrapped = tg + ((int64_t{v} * r.g_v) >> 12);
      break;
    case MaterialKind::kWood:
      t.rings = static_cast<int64_t>(
          (static_cast<uint64_t>(int64_t{u} * u + int64_t{v} * v) * r.g_r) >> 24);
      t.unwrapped = t.rings + ((int64_t{w} * r.g_w) >> 12) + tg;
      break;
    case MaterialKind::kBrick: {
      t.unwrapped = tg;
      const int64_t pw = int64_t{1} << r.pw, ph = int64_t{1} << r.ph;
      t.even_row = ((int64_t{v} >> r.ph) & 1) == 0;
      t.negative_row = v < 0;
      t.ur = (u + (t.even_row ? pw / 2 : 0)) & (pw - 1);
      t.vr = v & (ph - 1);
      t.mortar = !perlin::in_brick(r, u, v);
      break;
    }
    case MaterialKind::kFire:
      t.unwrapped = ((f * r.g_t) >> 14) + r.offset;
      break;
    case MaterialKind::kFog:
      t.level = ((f < 0 ? -f : f) * r.g_l) >> 22;
      break;
    case MaterialKind::kCloud:
      t.level = (f * r.g_l) >> 22;
      break;
  }
  t.table_reader = r.kind != MaterialKind::kFog && r.kind != MaterialKind::kCloud;
  if (t.table_reader) {
    t.entry = perlin::index_value(NoiseConfig{}, r, u, v, w) >> 8;
  }
  return t;
}

// --- directed items ------------------------------------------------------------------------

// Coordinates every material is shaded at: the origin, fractions, negative ones, the
// SolidCoord extremes, lattice points, and a few fixed pseudo-random ones.
std::vector<std::array<int32_t, 3>> probe_coords() {
  std::vector<std::array<int32_t, 3>> c = {{0, 0, 0},
                                           {kOne / 2, kOne / 4, 3 * kOne / 4},
                                           {-kOne / 2, -3, -5 * kOne - 7},
                                           {-1, -1, -1},
                                           {kCoordMin, kCoordMin, kCoordMin},
                                           {kCoordMax, kCoordMax, kCoordMax},
                                           {kCoordMin, kCoordMax, 0},
                                           {kCoordMax, kCoordMin, -1},
                                           {12345, -6789, 424242},
                                           {3 * kOne, 5 * kOne, 7 * kOne},
                                           {-11 * kOne, 2 * kOne + 1, -kOne / 3}};
  std::mt19937_64 rng(0x3A7E);
  for (int i = 0; i < 16; ++i) {
    const auto draw = [&rng] { return static_cast<int32_t>(rng() % (64 * kOne)) - 32 * kOne; };
    c.push_back({draw(), draw(), draw()});
  }
  return c;
}

// The first coordinate that satisfies `want`: lattice points (u on half units, so that cloud's
// 2u is one too: there every octave reads a lattice value, and the sums reach beyond +-1),
// then points inside the cells, in a fixed order.
std::array<int32_t, 3> find_coord(const std::function<bool(const std::array<int32_t, 3>&)>& want) {
  for (const int32_t inside : {0, 1}) {
    for (int32_t i = -16; i < 16; ++i) {
      for (int32_t j = -16; j < 16; ++j) {
        for (int32_t k = -16; k < 16; ++k) {
          const std::array<int32_t, 3> c = {i * kOne / 2 + inside * kOne / 8,
                                            j * kOne + inside * kOne / 4,
                                            k * kOne + inside * kOne / 16};
          if (want(c)) return c;
        }
      }
    }
  }
  throw std::logic_error("material: no directed coordinate found");
}

}  // namespace

Txn material_reg_item(MaterialReg reg, uint32_t value) {
  return channel_item(D::table(), "wr", {0, static_cast<uint32_t>(reg), value});
}

Txn material_table_item(uint32_t table, uint32_t index, uint32_t rgb) {
  // An index beyond 255 stays beyond 127 (ignored) rather than wrapping into the table.
  return channel_item(D::table(), "wr", {1, 0, 0, table, std::min<uint32_t>(index, 0xFF), rgb});
}

Txn material_sample_item(int32_t u, int32_t v, int32_t w) {
  return channel_item(
      D::table(), "in",
      {static_cast<uint32_t>(u), static_cast<uint32_t>(v), static_cast<uint32_t>(w)});
}

std::vector<Txn> material_load_items(const MaterialRegs& regs, const ColourTables& tables) {
  std::vector<Txn> items = reg_items(regs);
  append(items, table_items(tables));
  return items;
}

MaterialRegs random_material_regs(std::mt19937_64& rng) {
  MaterialRegs r;
  r.kind = static_cast<MaterialKind>(rng() % 6);
  r.g_t = static_cast<uint32_t>(rng() % 0x10000);
  r.g_v = static_cast<uint32_t>(rng() % 0x4000);  // up to 64 entries per unit of v
  r.g_r = static_cast<uint32_t>(rng() % 0x10000);
  r.g_w = static_cast<int32_t>(rng() % 0x10000) - 0x8000;
  r.offset = static_cast<int32_t>(rng() % 0x10000) - 0x8000;
  r.g_l = static_cast<uint32_t>(rng() % 0x10000);
  r.cutoff = static_cast<int32_t>(rng() % 0x8000) - 0x4000;  // within the sums' +-1
  r.pw = 1 + static_cast<int>(rng() % 20);
  r.ph = 1 + static_cast<int>(rng() % 20);
  r.mortar_w = static_cast<int32_t>(rng() % std::min<uint64_t>(1u << (r.pw - 1), 0x10000));
  r.mortar_h = static_cast<int32_t>(rng() % std::min<uint64_t>(1u << (r.ph - 1), 0x10000));
  perlin::check(r);
  return r;
}

ColourTables random_colour_tables(std::mt19937_64& rng) {
  ColourTables t;
  for (auto& e : t.main) e = static_cast<uint32_t>(rng()) & 0xFFFFFFu;
  for (auto& e : t.mortar) e = static_cast<uint32_t>(rng()) & 0xFFFFFFu;
  return t;
}

MaterialBlock::MaterialBlock(const BlockOptions& options)
    : DescribedBlockOf(D::table()), seed_(options.seed), shared_(options.fractal_shared) {
  add_level("hls", hls_level<desc::material_sc, hls::MaterialSc>(shared_));
  TMU_ADD_RTL_LEVELS(material, variant());
}

std::string MaterialBlock::variant() const { return shared_ ? "shared" : ""; }

std::unique_ptr<Model> MaterialBlock::golden() const { return std::make_unique<GoldenMaterial>(); }

std::vector<Txn> MaterialBlock::setup_items() const {
  // Every register and every entry (the tables have no reset), from the seed.
  std::mt19937_64 rng(seed_ ^ 0x3A7E121Au);
  const MaterialRegs regs = random_material_regs(rng);
  return material_load_items(regs, random_colour_tables(rng));
}

std::vector<Txn> MaterialBlock::directed_items() const {
  std::vector<Txn> items;
  const auto reg = [&items](MaterialReg r, int64_t value) {
    items.push_back(material_reg_item(r, static_cast<uint32_t>(value)));
  };
  const auto kind = [&reg](MaterialKind k) { reg(MaterialReg::kKind, static_cast<int64_t>(k)); };
  const auto sample = [&items](int64_t u, int64_t v, int64_t w) {
    items.push_back(material_sample_item(static_cast<int32_t>(u), static_cast<int32_t>(v),
                                         static_cast<int32_t>(w)));
  };
  const auto entry = [&items](uint32_t table, uint32_t index, uint32_t rgb) {
    items.push_back(material_table_item(table, index, rgb));
  };
  const auto regs = [&items](const MaterialRegs& r) { append(items, reg_items(r)); };
  const auto probes = probe_coords();
  const auto sample_probes = [&] {
    for (const auto& c : probes) sample(c[0], c[1], c[2]);
  };
  constexpr std::array<MaterialKind, 6> kKinds = {MaterialKind::kMarble, MaterialKind::kWood,
                                                  MaterialKind::kBrick,  MaterialKind::kFog,
                                                  MaterialKind::kCloud,  MaterialKind::kFire};

  // Every material on the probes, with the seed's registers (from the setup) and with golden's
  // defaults; then the kind switched before every sample.
  for (const MaterialKind k : kKinds) {
    kind(k);
    sample_probes();
  }
  regs(MaterialRegs{});
  for (const MaterialKind k : kKinds) {
    kind(k);
    sample_probes();
  }
  for (size_t i = 0; i < 12; ++i) {
    for (const MaterialKind k : kKinds) {
      kind(k);
      sample(probes[i][0], probes[i][1], probes[i][2]);
    }
  }

  // The colour index wraps mod 128 entries: marble with g_t = 0 and one entry per unit of v
  // reads entry floor(v) mod 128 (127 just below v = 128 and v = 0, 0 at them).
  entry(0, 0, 0x0000F0);
  entry(0, 1, 0x0010E0);
  entry(0, 126, 0xE01000);
  entry(0, 127, 0xF00000);
  MaterialRegs marble;
  marble.g_t = 0;
  marble.g_v = 1 << 8;
  regs(marble);
  for (const int64_t v :
       {int64_t{128} * kOne - 1, int64_t{128} * kOne, int64_t{-1}, int64_t{0}, int64_t{-128} * kOne,
        int64_t{127} * kOne + kOne / 2, int64_t{256} * kOne - 1, int64_t{256} * kOne,
        int64_t{-129} * kOne, int64_t{1} * kOne, int64_t{126} * kOne}) {
    sample(0, v, 0);
    sample(-3 * kOne + 5, v, 77 * kOne);
  }
  // ... and with the turbulence added (32 entries per unit): the sum itself wraps.
  reg(MaterialReg::kGt, 32 << 8);
  for (int64_t v = 120 * kOne; v <= 129 * kOne; v += kOne / 4) sample(kOne / 3, v, -kOne / 5);
  reg(MaterialReg::kGv, 0xFFFF);
  sample_probes();

  // Fire: the shaping at v <= 0 (e^0), at the table's last entry and beyond it, at every
  // entry k (v in [k/32, (k+1)/32)); the index clamped at 0 and at 2^15 - 1.
  MaterialRegs fire;
  fire.kind = MaterialKind::kFire;
  fire.g_t = 64 << 8;
  fire.offset = 64 << 8;
  regs(fire);
  for (const int64_t v : {int64_t{0}, int64_t{-1}, int64_t{-kOne}, int64_t{kCoordMin}, int64_t{1},
                          int64_t{127}, int64_t{128}, int64_t{65535}, int64_t{65536},
                          int64_t{65537}, int64_t{16} * kOne + 5, int64_t{kCoordMax}}) {
    sample(1234, v, 5678);
    sample(-3 * kOne, v, 7 * kOne / 2);
  }
  for (int64_t k = 0; k < perlin::kFireTableEntries; ++k) {
    sample(k * 91 - 20000, (k << kFireShift) + (k * 37) % (1 << kFireShift), 3000 - k * 57);
  }
  reg(MaterialReg::kOffset, 0x7FFF);  // every F >= 0 clamps at 2^15 - 1
  sample_probes();
  reg(MaterialReg::kOffset, 0x8000);  // -2^15: every F <= 0 clamps at 0
  sample_probes();
  reg(MaterialReg::kOffset, 0);
  reg(MaterialReg::kGt, 0xFFFF);  // |F| > 1/2 leaves 0..2^15 - 1 on either side
  sample_probes();

  // Brick: periods of one unit by half a unit, joints 205 wide; index 0 (g_t = 0) of the
  // brick table or the mortar table. u_r and v_r on the joints' strict bounds and just
  // inside, in even (shifted) and odd rows, positive and negative.
  entry(0, 0, 0xB22222);
  entry(1, 0, 0xC0C0C0);
  MaterialRegs brick;
  brick.kind = MaterialKind::kBrick;
  brick.g_t = 0;
  regs(brick);
  {
    const int64_t pw = int64_t{1} << brick.pw, ph = int64_t{1} << brick.ph;
    const int64_t mw = brick.mortar_w, mh = brick.mortar_h;
    for (const int64_t row : {int64_t{0}, int64_t{1}, int64_t{-1}, int64_t{-2}, int64_t{7}}) {
      const bool even = (row & 1) == 0;
      for (const int64_t vr : {mh, mh + 1, ph / 2, ph - mh - 1, ph - mh}) {
        for (const int64_t ur : {int64_t{0}, mw, mw + 1, pw / 2, pw - mw - 1, pw - mw, pw - 1}) {
          const int64_t u = ur - (even ? pw / 2 : 0) + (row - 2) * pw;
          sample(u, row * ph + vr, 3 * kOne);
        }
      }
    }
  }
  // The same geometry with the seed's turbulence gain, and the periods' extremes: 2 x 2 raw
  // units (mortars 0), 2^20 x 2^20 with the widest and no mortar.
  reg(MaterialReg::kGt, 40 << 8);
  sample_probes();
  reg(MaterialReg::kPw, 1);
  reg(MaterialReg::kPh, 1);
  for (int64_t u = -2; u < 4; ++u) {
    for (int64_t v = -2; v < 4; ++v) sample(u, v, u - v);
  }
  reg(MaterialReg::kPw, 20);
  reg(MaterialReg::kPh, 20);
  reg(MaterialReg::kMortarW, 0xFFFF);  // 2^19 - 1 allows 65535
  reg(MaterialReg::kMortarH, 0);
  for (const int64_t ur :
       {int64_t{65535}, int64_t{65536}, int64_t{(1 << 20) - 65536}, int64_t{(1 << 20) - 65535}}) {
    for (const int64_t v :
         {int64_t{0}, int64_t{1}, int64_t{(1 << 20) - 1}, int64_t{1 << 20}, int64_t{-1}}) {
      const bool even = ((v >> 20) & 1) == 0;
      sample(ur - (even ? 1 << 19 : 0), v, 0);
    }
  }

  // Register writes that saturate: the kind at 5 (fire), pw and ph at 1..20, a mortar at half
  // its period minus one, also when the period shrinks (and it stays clamped when the period
  // grows again); unknown registers change nothing.
  regs(brick);
  reg(MaterialReg::kKind, 6);
  sample_probes();
  reg(MaterialReg::kKind, 0xFFFF);
  sample(kOne, 2 * kOne, 3 * kOne);
  kind(MaterialKind::kBrick);
  reg(MaterialReg::kGt, 0);
  reg(MaterialReg::kMortarW, 0xFFFF);  // pw = 12: 2047
  for (const int64_t ur : {int64_t{100}, int64_t{2047}, int64_t{2048}, int64_t{2049}}) {
    sample(ur - 2048, 1000, 0);
  }
  reg(MaterialReg::kPw, 3);  // the mortar clamps to 3
  for (const int64_t ur : {int64_t{2}, int64_t{3}, int64_t{4}, int64_t{5}}) sample(ur - 4, 1000, 0);
  reg(MaterialReg::kPw, 12);  // ... and stays 3
  for (const int64_t ur : {int64_t{3}, int64_t{4}, int64_t{100}, int64_t{4092}, int64_t{4093}}) {
    sample(ur - 2048, 1000, 0);
  }
  reg(MaterialReg::kPw, 0);  // 1
  sample(0, 1000, 0);
  sample(1, 1000, 0);
  reg(MaterialReg::kPw, 21);          // 20
  reg(MaterialReg::kMortarW, 70000);  // the low 16 bits: 4464
  sample(4464 - (1 << 19), 1000, 0);
  sample(4465 - (1 << 19), 1000, 0);
  reg(MaterialReg::kPh, 0xFFFF);  // 20
  reg(MaterialReg::kMortarH, 3);
  sample(5000 - (1 << 19), 3, 0);
  sample(5000 - (1 << 19), 4, 0);
  reg(MaterialReg::kPh, 0);  // 1: the mortar clamps to 0
  sample(5000 - (1 << 19), 4, 0);
  for (uint32_t id = 12; id < 16; ++id) {
    items.push_back(material_reg_item(static_cast<MaterialReg>(id), 0x1234));
  }
  sample_probes();

  // Cloud at, just below and just above its cut-off (F of the shaped (2u, v, w)); the gases'
  // levels saturated; fog of a negative F.
  const auto sums_of = [](MaterialKind k, const std::array<int32_t, 3>& c) {
    MaterialRegs r;
    r.kind = k;
    const perlin::Shaped s = perlin::shape(r, c[0], c[1], c[2]);
    return perlin::fractal_sums(NoiseConfig{}, s.u, s.v, s.w);
  };
  const int32_t one = perlin::sum_one(NoiseConfig{});
  MaterialRegs cloud;
  cloud.kind = MaterialKind::kCloud;
  cloud.g_l = 0xFFFF;
  regs(cloud);
  for (const auto& want : std::vector<std::function<bool(int32_t)>>{
           [one](int32_t f) { return f > one; },  // saturates at g_l = 0xFFFF
           [one](int32_t f) { return f > one / 8 && f < one / 4; },
           [](int32_t f) { return f < 0; }}) {
    const auto c = find_coord([&](const std::array<int32_t, 3>& p) {
      return want(sums_of(MaterialKind::kCloud, p).fractal_sum);
    });
    const int32_t f = sums_of(MaterialKind::kCloud, c).fractal_sum;
    for (const int32_t cutoff : {f, f - 1, f + 1}) {
      reg(MaterialReg::kCutoff, u16(cutoff));
      sample(c[0], c[1], c[2]);
    }
    reg(MaterialReg::kGl, 255 << 8);
    sample(c[0], c[1], c[2]);
    reg(MaterialReg::kGl, 0xFFFF);
  }
  for (const int32_t cutoff : {-0x8000, 0x7FFF, 0}) {
    reg(MaterialReg::kCutoff, u16(cutoff));
    sample_probes();
  }
  MaterialRegs fog;
  fog.kind = MaterialKind::kFog;
  fog.g_l = 0xFFFF;
  regs(fog);
  for (const auto& want : std::vector<std::function<bool(int32_t)>>{
           [one](int32_t f) { return f < -one; }, [](int32_t f) { return f < 0; },
           [one](int32_t f) { return f > one; }}) {
    const auto c = find_coord([&](const std::array<int32_t, 3>& p) {
      return want(sums_of(MaterialKind::kFog, p).fractal_sum);
    });
    sample(c[0], c[1], c[2]);
  }
  sample_probes();
  reg(MaterialReg::kGl, 1);
  sample_probes();
  // g_l = 0 (-g_l's sign clear): every level 0; then back.
  reg(MaterialReg::kGl, 0);
  sample_probes();
  reg(MaterialReg::kGl, 0xFFFF);
  sample(probes[0][0], probes[0][1], probes[0][2]);

  // Brick at every period, pw 1 .. 20 then 1 again, ph the reverse, one sample each: every
  // bit of 2^pw and 2^ph rises and falls (docs/coverage.md).
  regs(brick);
  for (int64_t i = 0; i <= 20; ++i) {
    const int64_t p = i % 20 + 1;  // 1 .. 20, then 1 again
    reg(MaterialReg::kPw, p);
    reg(MaterialReg::kPh, 21 - p);
    sample(p * 12345, (21 - p) * 54321, p);
  }

  // Wood at the largest gains: the rings' wide product at the SolidCoord extremes.
  MaterialRegs wood;
  wood.kind = MaterialKind::kWood;
  wood.g_r = 0xFFFF;
  wood.g_w = -0x8000;
  regs(wood);
  sample_probes();
  reg(MaterialReg::kGw, 0x7FFF);
  sample_probes();

  // A table write followed at once by a sample reading that entry (marble, g_t = 0, one entry
  // per unit of v; brick's two tables); writes beyond 127 change nothing (128 + k is not k).
  regs(marble);
  for (const uint32_t k : {0u, 5u, 64u, 127u}) {
    entry(0, k, 0x102030 + k);
    sample(kOne, int64_t{k} * kOne + 100, -kOne);
  }
  for (const uint32_t k : {3u, 126u}) {  // ... and rewritten right after a sample read it
    sample(kOne, int64_t{k} * kOne + 100, -kOne);
    entry(0, k, 0x302010 + k);
    sample(kOne, int64_t{k} * kOne + 100, -kOne);
  }
  for (const uint32_t k : {200u, 255u, 128u, 1000u}) {
    entry(0, k, 0xABCDEF);
    sample(0, int64_t{k % 128} * kOne, 0);
  }
  regs(brick);
  entry(1, 0, 0x404040);
  sample(-2048, 0, 0);  // u_r = 0: a joint
  entry(0, 0, 0x800000);
  sample(0, 1000, 0);  // u_r = 2048, v_r = 1000: a brick

  // The seed's registers and tables again for the random items.
  append(items, setup_items());
  return items;
}

std::vector<Txn> MaterialBlock::random_items(std::mt19937_64& rng, size_t count) const {
  std::vector<Txn> items;
  items.reserve(count);
  const std::vector<Txn> coords = solid::random_items(rng, count);
  size_t next_coord = 0;
  size_t next_regs = kRegsPeriod / 2, next_tables = kTablesPeriod / 2;
  while (items.size() < count) {
    if (items.size() >= next_tables) {  // new tables
      next_tables += kTablesPeriod;
      if (items.size() + 2 * perlin::kColourEntries <= count) {
        append(items, table_items(random_colour_tables(rng)));
        continue;
      }
    }
    if (items.size() >= next_regs) {  // a new material
      next_regs += kRegsPeriod;
      if (items.size() + static_cast<size_t>(MaterialReg::kCount) <= count) {
        append(items, reg_items(random_material_regs(rng)));
        continue;
      }
    }
    const uint64_t r = rng();
    if ((r & 31) == 0) {  // one register write (ids 12..15 ignored), values often saturating
      const auto id = static_cast<uint32_t>(r >> 8) & 0xF;
      uint32_t value = static_cast<uint32_t>(r >> 16) & 0xFFFF;
      if (id == static_cast<uint32_t>(MaterialReg::kKind)) value %= 8;
      if (id == static_cast<uint32_t>(MaterialReg::kPw) ||
          id == static_cast<uint32_t>(MaterialReg::kPh))
        value %= 24;
      if ((r >> 40) % 4 == 0 && (id == static_cast<uint32_t>(MaterialReg::kMortarW) ||
                                 id == static_cast<uint32_t>(MaterialReg::kMortarH)))
        value %= 64;
      items.push_back(material_reg_item(static_cast<MaterialReg>(id), value));
    } else if ((r & 63) == 1) {  // one table entry (an index beyond 127 is ignored)
      items.push_back(material_table_item(static_cast<uint32_t>(r >> 8) & 1,
                                          static_cast<uint32_t>(r >> 9) & 0xFF,
                                          static_cast<uint32_t>(r >> 17)));
    } else {
      std::array<int32_t, 3> c = solid::coords(coords[next_coord++ % coords.size()]);
      switch ((r >> 8) % 8) {
        case 0:  // fire's range of v: -2 .. 18 units
          c[1] = static_cast<int32_t>((r >> 16) % (20 * kOne)) - 2 * kOne;
          break;
        case 1:  // near the origin: +-4 units
          for (size_t a = 0; a < 3; ++a) {
            c[a] = static_cast<int32_t>((r >> (16 + 12 * a)) % (8 * kOne)) - 4 * kOne;
          }
          break;
        default:
          break;
      }
      items.push_back(material_sample_item(c[0], c[1], c[2]));
    }
  }
  return items;
}

namespace {
constexpr const char* kMarble = "marble";
constexpr const char* kWood = "wood";
constexpr const char* kBrickIn = "brick: in a brick (brick table)";
constexpr const char* kBrickJoint = "brick: in a joint (mortar table)";
constexpr const char* kFog = "fog";
constexpr const char* kCloudAbove = "cloud: F > cutoff";
constexpr const char* kCloudBelow = "cloud: F <= cutoff (r = g = 0)";
constexpr const char* kFire = "fire";
constexpr const char* kWrapHigh = "index >= 2^15 before mod (wraps)";
constexpr const char* kWrapLow = "index < 0 before mod (wraps)";
constexpr const char* kWrap127To0 = "entry 127, next sample entry 0";
constexpr const char* kEntry0 = "entry 0 read";
constexpr const char* kEntry127 = "entry 127 read";
constexpr const char* kWoodRingsWrap = "wood: rings term >= 2^15";
constexpr const char* kWoodGwNegative = "wood: g_w < 0";
constexpr const char* kBrickEven = "brick: even row (half-brick shift)";
constexpr const char* kBrickOdd = "brick: odd row";
constexpr const char* kBrickNegRow = "brick: negative row";
constexpr const char* kBrickUrBound = "brick: u_r on a joint bound";
constexpr const char* kBrickVrBound = "brick: v_r on a joint bound";
constexpr const char* kBrickUrInside = "brick: u_r one inside a bound";
constexpr const char* kBrickVrInside = "brick: v_r one inside a bound";
constexpr const char* kBrickMortar0 = "brick: a mortar of 0";
constexpr const char* kBrickPeriodExtreme = "brick: pw or ph at 1 or 20";
constexpr const char* kFireBase = "fire: v <= 0 (e^0)";
constexpr const char* kFireBeyond = "fire: v >= 16 (beyond the table)";
constexpr const char* kFireEvery = "fire: every table entry k";
constexpr const char* kFireClampLow = "fire: index clamped at 0";
constexpr const char* kFireClampHigh = "fire: index clamped at 2^15 - 1";
constexpr const char* kFogNegative = "fog: F < 0";
constexpr const char* kGasSaturated = "gas level saturated at 255";
constexpr const char* kGasMid = "gas level 0 < l < 255";
constexpr const char* kCloudAt = "cloud: F = cutoff";
constexpr const char* kNegative = "negative coordinate";
constexpr const char* kMinCoord = "coordinate -2^23";
constexpr const char* kMaxCoord = "coordinate 2^23 - 1";
constexpr const char* kAfterReg = "sample right after a register write";
constexpr const char* kAfterKind = "sample right after a kind change";
constexpr const char* kAfterEntry = "sample reads the entry just written";
constexpr const char* kEntryRewritten = "entry rewritten after its read";
constexpr const char* kSaturated = "register value saturated";
constexpr const char* kMortarClamped = "mortar clamped by a smaller period";
constexpr const char* kUnknownReg = "unknown register written (ignored)";
constexpr const char* kIgnoredEntry = "table write beyond 127 (ignored)";
}  // namespace

std::vector<std::string> MaterialBlock::coverage_cases() const {
  return {kMarble,        kWood,          kBrickIn,      kBrickJoint,         kFog,
          kCloudAbove,    kCloudBelow,    kFire,         kWrapHigh,           kWrapLow,
          kWrap127To0,    kEntry0,        kEntry127,     kWoodRingsWrap,      kWoodGwNegative,
          kBrickEven,     kBrickOdd,      kBrickNegRow,  kBrickUrBound,       kBrickVrBound,
          kBrickUrInside, kBrickVrInside, kBrickMortar0, kBrickPeriodExtreme, kFireBase,
          kFireBeyond,    kFireEvery,     kFireClampLow, kFireClampHigh,      kFogNegative,
          kGasSaturated,  kGasMid,        kCloudAt,      kNegative,           kMinCoord,
          kMaxCoord,      kAfterReg,      kAfterKind,    kAfterEntry,         kEntryRewritten,
          kSaturated,     kMortarClamped, kUnknownReg,   kIgnoredEntry};
}

void MaterialBlock::cover(const std::vector<Txn>& items, size_t index, const Txn&,
                          Coverage& cov) const {
  CoverState& st = cover_state_;
  if (st.items != &items || index < st.next) {
    st = CoverState{};
    st.items = &items;
  }
  for (; st.next < index; ++st.next) {
    const Txn& t = items[st.next];
    if (is_sample(t)) {
      st.reg_write = st.kind_change = st.saturated = st.mortar_clamped = false;
      st.unknown_reg = st.ignored_entry = false;
      continue;
    }
    if (is_table_write(t)) {
      if (t.f[D::wr_index] >= perlin::kColourEntries) st.ignored_entry = true;
      apply_write(st.unit, t);
      continue;
    }
    const MaterialRegs before = st.unit.regs();
    const auto id = static_cast<uint32_t>(t.f[D::wr_reg]);
    const auto value = static_cast<uint32_t>(t.f[D::wr_value]);
    apply_write(st.unit, t);
    const MaterialRegs& after = st.unit.regs();
    st.reg_write = true;
    if (after.kind != before.kind) st.kind_change = true;
    if (id >= static_cast<uint32_t>(MaterialReg::kCount)) st.unknown_reg = true;
    const auto stored = [&](MaterialReg r) -> int64_t {
      switch (r) {
        case MaterialReg::kKind:
          return static_cast<int64_t>(after.kind);
        case MaterialReg::kPw:
          return after.pw;
        case MaterialReg::kPh:
          return after.ph;
        case MaterialReg::kMortarW:
          return after.mortar_w;
        case MaterialReg::kMortarH:
          return after.mortar_h;
        default:
          return value;
      }
    };
    if (id < static_cast<uint32_t>(MaterialReg::kCount) &&
        stored(static_cast<MaterialReg>(id)) != value)
      st.saturated = true;
    if ((id == static_cast<uint32_t>(MaterialReg::kPw) && after.mortar_w < before.mortar_w) ||
        (id == static_cast<uint32_t>(MaterialReg::kPh) && after.mortar_h < before.mortar_h))
      st.mortar_clamped = true;
  }

  const MaterialRegs& r = st.unit.regs();
  const auto [u, v, w] = solid::coords(items[index], D::in_u);
  const SampleTrace t = trace_sample(r, u, v, w);
  for (const int32_t x : {u, v, w}) {
    if (x == kCoordMin) ++cov[kMinCoord];
    if (x == kCoordMax) ++cov[kMaxCoord];
  }
  if (u < 0 || v < 0 || w < 0) ++cov[kNegative];
  if (st.reg_write) ++cov[kAfterReg];
  if (st.kind_change) ++cov[kAfterKind];
  if (st.saturated) ++cov[kSaturated];
  if (st.mortar_clamped) ++cov[kMortarClamped];
  if (st.unknown_reg) ++cov[kUnknownReg];
  if (st.ignored_entry) ++cov[kIgnoredEntry];

  const int64_t f = t.sums.fractal_sum;
  switch (r.kind) {
    case MaterialKind::kMarble:
      ++cov[kMarble];
      break;
    case MaterialKind::kWood:
      ++cov[kWood];
      if (t.rings >= kIndexLimit) ++cov[kWoodRingsWrap];
      if (r.g_w < 0) ++cov[kWoodGwNegative];
      break;
    case MaterialKind::kBrick: {
      ++cov[t.mortar ? kBrickJoint : kBrickIn];
      ++cov[t.even_row ? kBrickEven : kBrickOdd];
      if (t.negative_row) ++cov[kBrickNegRow];
      const int64_t pw = int64_t{1} << r.pw, ph = int64_t{1} << r.ph;
      if (t.ur == r.mortar_w || t.ur == pw - r.mortar_w) ++cov[kBrickUrBound];
      if (t.vr == r.mortar_h || t.vr == ph - r.mortar_h) ++cov[kBrickVrBound];
      if (t.ur == r.mortar_w + 1 || t.ur == pw - r.mortar_w - 1) ++cov[kBrickUrInside];
      if (t.vr == r.mortar_h + 1 || t.vr == ph - r.mortar_h - 1) ++cov[kBrickVrInside];
      if (r.mortar_w == 0 || r.mortar_h == 0) ++cov[kBrickMortar0];
      if (r.pw == 1 || r.pw == 20 || r.ph == 1 || r.ph == 20) ++cov[kBrickPeriodExtreme];
      break;
    }
    case MaterialKind::kFog:
      ++cov[kFog];
      if (f < 0) ++cov[kFogNegative];
      break;
    case MaterialKind::kCloud:
      ++cov[f > r.cutoff ? kCloudAbove : kCloudBelow];
      if (f == r.cutoff) ++cov[kCloudAt];
      break;
    case MaterialKind::kFire: {
      ++cov[kFire];
      if (v <= 0) ++cov[kFireBase];
      if (v >= 16 * kOne) ++cov[kFireBeyond];
      const int64_t k = std::clamp<int64_t>(v >> kFireShift, 0, perlin::kFireTableEntries - 1);
      if (!st.fire_k.test(static_cast<size_t>(k))) {
        st.fire_k.set(static_cast<size_t>(k));
        if (st.fire_k.all()) ++cov[kFireEvery];
      }
      if (t.unwrapped < 0) ++cov[kFireClampLow];
      if (t.unwrapped >= kIndexLimit) ++cov[kFireClampHigh];
      break;
    }
  }
  const bool wraps = r.kind == MaterialKind::kMarble || r.kind == MaterialKind::kWood ||
                     r.kind == MaterialKind::kBrick;
  if (wraps && t.unwrapped >= kIndexLimit) ++cov[kWrapHigh];
  if (wraps && t.unwrapped < 0) ++cov[kWrapLow];
  const bool gas = r.kind == MaterialKind::kFog || (r.kind == MaterialKind::kCloud && f > r.cutoff);
  if (gas && t.level >= 255) ++cov[kGasSaturated];
  if (gas && t.level > 0 && t.level < 255) ++cov[kGasMid];
  if (t.table_reader) {
    if (t.entry == 0) ++cov[kEntry0];
    if (t.entry == 127) ++cov[kEntry127];
    if (t.entry == 0 && st.last_entry == 127) ++cov[kWrap127To0];
    if (index > 0 && is_table_write(items[index - 1])) {
      const Txn& wr = items[index - 1];
      const bool mortar_table = wr.f[D::wr_table] != 0;
      if (wr.f[D::wr_index] == t.entry && mortar_table == t.mortar) ++cov[kAfterEntry];
    }
    if (index + 1 < items.size() && is_table_write(items[index + 1])) {
      const Txn& wr = items[index + 1];
      const bool mortar_table = wr.f[D::wr_table] != 0;
      if (wr.f[D::wr_index] == t.entry && mortar_table == t.mortar) ++cov[kEntryRewritten];
    }
    st.last_entry = t.entry;
  } else {
    st.last_entry = -1;
  }
}

}  // namespace tmu::tb

TMU_REGISTER_BLOCK(material, MaterialBlock)
