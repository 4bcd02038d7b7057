#include "clipmap/clipmap.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

namespace tmu::clipmap {
namespace {

using texram::Border;
using texram::Filter;

constexpr int kLodFrac = formats::kLod.frac_bits;

// A tap of a level: its virtual texel after the border operator, or outside (border colour).
struct VirtualTap {
  bool outside = false;
  uint32_t x = 0, y = 0;
  int64_t raw_x = 0, raw_y = 0;  // before the border operator (a 1 x 1 level's replica)
};

VirtualTap virtual_tap(const ClipGeometry& g, const Config& c, int level, int64_t rx, int64_t ry) {
  const uint32_t n = g.virtual_side(level);
  const texram::Resolved x = texram::resolve_border(rx, n, c.sampler.border_u);
  const texram::Resolved y = texram::resolve_border(ry, n, c.sampler.border_v);
  return {x.outside || y.outside, x.x, y.x, rx, ry};
}

bool clipped(const Config& c, int level) { return level < c.clipped_levels(); }

// Whether a level's tile holds every tap the sample point has there (taps outside the virtual
// texture read nothing and need no tile).
bool holds_point(const ClipGeometry& g, const Config& c, const Regions& regions, int level,
                 const texram::Request& q) {
  if (!clipped(c, level)) return true;
  const bool nearest = c.sampler.filter == Filter::kNearest;
  const texram::Axis ax = texram::axis_taps(q.u, level, nearest, c.sampler.widths);
  const texram::Axis ay = texram::axis_taps(q.v, level, nearest, c.sampler.widths);
  const int taps = nearest ? 1 : 4;
  for (int k = 0; k < taps; ++k) {
    const VirtualTap t = virtual_tap(g, c, level, ax.t0 + (k & 1), ay.t0 + (k >> 1));
    if (!t.outside && !regions[static_cast<size_t>(level)].holds(t.x, t.y)) return false;
  }
  return true;
}

}  // namespace

void check(const Config& c) {
  (void)c.geometry();  // its own checks
  if (c.sampler.kind == texram::TexelKind::kCcc) {
    throw std::invalid_argument("clip-map kind: CCC textures are not clip-mapped");
  }
  if (c.sampler.addressing != texram::Addressing::kTexel) {
    throw std::invalid_argument("clip-map addressing: a clip-map takes texel coordinates");
  }
}

ClipPlan plan_clip_sample(const ClipGeometry& g, const Config& c, const Regions& regions,
                          const texram::Request& q) {
  ClipPlan out;
  texram::SamplePlan& plan = out.plan;
  const texram::Widths& widths = c.sampler.widths;
  const bool nearest = c.sampler.filter == Filter::kNearest;
  const int top = g.levels() - 1;
  static_cast<texram::LevelChoice&>(plan) = texram::choose_levels(top, c.sampler, q.lambda);
  if (c.substitution == Substitution::kPerSample) {
    // Held as it is when every level it reads holds the point; else raised to a whole level m
    // (weight 0 for the next: one level read) that does.
    const int first = plan.level[0];
    const bool held = holds_point(g, c, regions, first, q) &&
                      (plan.levels_read == 1 || holds_point(g, c, regions, plan.level[1], q));
    int m = held ? first : first + 1;
    while (m < c.clipped_levels() && !holds_point(g, c, regions, m, q)) ++m;
    if (m > first) {
      static_cast<texram::LevelChoice&>(plan) =
          texram::choose_levels(top, c.sampler, std::max(q.lambda, m << kLodFrac));
      out.wayward = true;
    }
  }
  plan.planes = g.planes();

  for (int j = 0; j < plan.levels_read; ++j) {
    const auto jj = static_cast<size_t>(j);
    const int l = plan.level[jj];
    const texram::Axis ax = texram::axis_taps(q.u, l, nearest, widths);
    const texram::Axis ay = texram::axis_taps(q.v, l, nearest, widths);
    plan.wx[jj] = ax.w;
    plan.wy[jj] = ay.w;
    for (int k = 0; k < plan.taps_per_level; ++k) {
      const auto kk = static_cast<size_t>(k);
      const VirtualTap v = virtual_tap(g, c, l, ax.t0 + (k & 1), ay.t0 + (k >> 1));
      texram::Tap& tap = plan.taps[jj][kk];
      tap.outside = v.outside;
      out.tap_level[jj][kk] = l;
      if (v.outside) continue;
      int level = l;
      uint32_t x = v.x, y = v.y;
      int64_t raw_x = v.raw_x, raw_y = v.raw_y;
      if (c.substitution == Substitution::kPerTap && clipped(c, level) &&
          !regions[static_cast<size_t>(level)].holds(x, y)) {
        do {  // the texel of the next coarser level that holds the location
          ++level;
          x >>= 1;
          y >>= 1;
        } while (clipped(c, level) && !regions[static_cast<size_t>(level)].holds(x, y));
        raw_x = x;
        raw_y = y;
        ++out.substituted_taps;
        out.wayward = true;
      }
      out.tap_level[jj][kk] = level;
      // Physical: modulo the stored side (toroidal); a 1 x 1 level's replica by the parity of
      // the unresolved coordinate, so that neighbouring taps use different banks.
      const uint32_t side = g.side(level);
      const auto stored = [side](uint32_t xy, int64_t raw) {
        return side > 1 ? xy & (side - 1) : static_cast<uint32_t>(raw & 1);
      };
      tap.x = x;
      tap.y = y;
      tap.cell = g.cell(level, stored(x, raw_x), stored(y, raw_y));
      auto& slot = plan.bank_address[tap.cell.bank];
      if (!slot) {
        slot = tap.cell.address;
      } else if (*slot != tap.cell.address) {
        ++out.conflicts;  // the lower tap's cell: this tap reads it
      }
    }
  }
  return out;
}

ClipMemory::ClipMemory(const ClipGeometry& g) : geometry(g) {
  for (auto& bank : banks) bank.assign(g.bank_cells(), 0);
}

std::vector<BankAccess> read_accesses(const ClipPlan& p) {
  BankAccess base;
  for (unsigned b = 0; b < 8; ++b) {
    if (!p.plan.bank_address[b]) continue;
    base.enable = static_cast<uint8_t>(base.enable | (1u << b));
    base.address[b] = *p.plan.bank_address[b];
  }
  std::vector<BankAccess> out;
  if (base.enable == 0) return out;
  for (int plane = 0; plane < p.plan.planes; ++plane) {
    BankAccess a = base;
    for (unsigned b = 0; b < 8; ++b) {
      if (a.enable & (1u << b)) a.address[b] += static_cast<uint32_t>(plane);
    }
    out.push_back(a);
  }
  return out;
}

std::vector<BankAccess> load_writes(const ClipGeometry& g, const Load& load) {
  std::vector<BankAccess> out;
  if (load.level < 0 || load.level >= g.levels()) return out;
  const uint32_t side = g.side(load.level);
  // Every stored position of the texel: itself, or the four replicas of a 1 x 1 level.
  std::vector<std::pair<uint32_t, uint32_t>> places;
  if (side > 1) {
    places.emplace_back(load.x & (side - 1), load.y & (side - 1));
  } else {
    places = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  }
  for (int plane = 0; plane < g.planes(); ++plane) {
    BankAccess a;
    for (const auto& [x, y] : places) {
      const texram::BankCell cell = g.cell(load.level, x, y, plane);
      a.enable = static_cast<uint8_t>(a.enable | (1u << cell.bank));
      a.address[cell.bank] = cell.address;
      a.data[cell.bank] = static_cast<uint8_t>(load.texel >> (24 - 8 * plane));
    }
    out.push_back(a);
  }
  return out;
}

void write(texram::BankImage& banks, const BankAccess& a) {
  for (unsigned b = 0; b < 8; ++b) {
    if (a.enable & (1u << b)) banks[b].at(a.address[b]) = a.data[b];
  }
}

uint32_t colour_of(const ClipPlan& p, const texram::AccessData& data, const Config& config,
                   const texram::Clut32& clut, uint32_t shade) {
  std::array<std::array<uint32_t, 4>, 2> colours{};
  for (size_t j = 0; j < static_cast<size_t>(p.plan.levels_read); ++j) {
    for (size_t k = 0; k < static_cast<size_t>(p.plan.taps_per_level); ++k) {
      colours[j][k] =
          texram::tap_colour(p.plan.taps[j][k], data, config.sampler.kind, config.sampler, clut);
    }
  }
  return texram::combine(texram::blend_taps(p.plan, colours, config.sampler.widths), config.sampler,
                         shade);
}

uint32_t sample(const ClipMemory& memory, const Config& config, const Regions& regions,
                const texram::Request& request, ClipPlan* plan_out) {
  const ClipPlan p = plan_clip_sample(memory.geometry, config, regions, request);
  texram::AccessData data{};
  const std::vector<BankAccess> accesses = read_accesses(p);
  for (size_t plane = 0; plane < accesses.size(); ++plane) {
    const BankAccess& a = accesses[plane];
    for (unsigned b = 0; b < 8; ++b) {
      if (a.enable & (1u << b)) data[b][plane] = memory.banks[b][a.address[b]];
    }
  }
  if (plan_out) *plan_out = p;
  return colour_of(p, data, config, memory.clut, request.shade);
}

}  // namespace tmu::clipmap
