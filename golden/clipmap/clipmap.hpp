// Golden model of the clip-map address unit (003: the SGI clip-map patent, §I and the summary;
// its §V-XIII are lost, so every rule below that the copy does not state is this project's
// choice, with its reason). It sits where the TEXRAM's trilinear unit computes addresses (000
// §2, §5, §6): the same levels, weights, blend and eq. 5, on a clip-map instead of a whole
// pyramid (clip_geometry.hpp says where each level lives).
//
// A request carries virtual texel coordinates (u, v: TexCoord, texels of the virtual level 0,
// so up to 32k) and lambda. The unit resolves every tap with the virtual texture's border
// operator (its level l is 2^(V-l) wide), then, for a clipped level, tests it against that
// level's valid region: the texels [x0, x1) x [y0, y1) the tile holds now (per-level registers
// the host writes; empty after reset). A tap outside its tile is "wayward" and is served from a
// coarser level, by one of two rules (the configuration field `substitution`):
//
// - per sample (the default): a sample whose levels' tiles all hold its taps (the sample
//   point's taps at each level it reads) is read as it is; otherwise its lambda is raised to
//   the first level m above the first it would read whose tile holds the point's taps (a whole
//   level always does): lambda' = m, read alone. Every tap then comes from its own level's
//   texels, filtered as usual, and a trilinear sample stays one access. Real clip-map hardware
//   clamped the LOD per pixel this way; it keeps the filter continuous inside a level and is
//   what the fly-over renders with. Both levels of a trilinear sample are tested because a tile
//   clamped at the virtual texture's edge holds the finer tile's area but not the taps that the
//   wrap border sends to the far edge.
// - per tap (as 003's summary describes it): each wayward tap takes "the texel of the next
//   coarser tile that holds it, the one closest to the location sought": the texel (x >> k,
//   y >> k) of the first coarser level l + k whose tile holds it (a whole level always does).
//   The weights stay the sample's.
//
// Neither rule reads outside the 8 banks of one access when the tiles are nested (each coarser
// tile holds the finer one's area and a texel more on every side: the host's centre rule keeps
// them so). If the registers break that, per-tap substitution can want two cells of one bank:
// the lowest-numbered tap (level group 0 before 1, taps x0y0, x1y0, x0y1, x1y1) then decides the
// bank's address and the others read that cell (counted as conflicts). Per-sample substitution
// never needs that; its taps at the raised level read what the tile holds there.
//
// The physical texel of virtual (x, y) at a level of stored side s is (x mod s, y mod s):
// toroidal inside a tile, the identity for a whole level. A load (the load port) writes the texel
// of a level at virtual (x, y) to that place, every replica of a 1 x 1 level included; a load to
// a level beyond the top is ignored. The rule for loads and register writes against samples that
// may be reading the same texels: each waits until every sample accepted before it has read its
// texels, and every sample after it sees it (the RTL holds the load and register ports' ready
// low while a sample is between the request port and its memory response; the ports are
// ordered with the samples, one stream). So a frame's updates can be issued between any two
// samples; the host issues them between frames (clipmap/tile_manager.hpp).
//
// Not supported: CCC textures (their 4 x 4 blocks would make a tile's edge a block's), sphere
// addressing. The virtual texture is square.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "clipmap/clip_geometry.hpp"
#include "texram/sampler_config.hpp"
#include "texram/texture.hpp"
#include "texram/trilinear.hpp"

namespace tmu::clipmap {

enum class Substitution : uint8_t {
  kPerSample,  // raise lambda to the first level whose tile holds the sample point's taps
  kPerTap,     // each wayward tap from the first coarser tile that holds its texel
};

struct Config {
  int log2_virtual = 8;           // V: the virtual level 0 is 2^V x 2^V texels
  int log2_tile = 5;              // t: a clipped level's tile is 2^t x 2^t
  texram::SamplerConfig sampler;  // kind (not CCC), filter, borders, combine, widths
  Substitution substitution = Substitution::kPerSample;
  int clipped_levels() const { return log2_virtual - log2_tile; }
  // Byte planes of a texel: 4 for true colour, else 1.
  int planes() const {
    return sampler.kind == texram::TexelKind::kTrueColour ? formats::kPlanes : 1;
  }
  ClipGeometry geometry() const { return ClipGeometry(log2_virtual, log2_tile, planes()); }
};

// The texels a clipped level's tile holds: [x0, x1) x [y0, y1), virtual coordinates of the level.
struct Region {
  uint32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool holds(uint32_t x, uint32_t y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
  friend bool operator==(const Region&, const Region&) = default;
};
// One register set per level that can be clipped (a write to a level beyond is ignored).
using Regions = std::array<Region, kMaxClippedLevels>;

// A sample's plan: the trilinear unit's (levels, weights, taps with their cells, the bank
// access) with the level each tap is read from, and what substitution did.
struct ClipPlan {
  texram::SamplePlan plan;
  std::array<std::array<int, 4>, 2> tap_level{};
  bool wayward = false;      // a substitution served the sample (raised lambda, or a tap)
  int substituted_taps = 0;  // per tap: taps read from a coarser level
  int conflicts = 0;         // taps that wanted another cell of a bank a lower tap took
};

ClipPlan plan_clip_sample(const ClipGeometry& geometry, const Config& config,
                          const Regions& regions, const texram::Request& request);

// The memory: the banks as geometry lays them out, and the CLUT.
struct ClipMemory {
  explicit ClipMemory(const ClipGeometry& g);
  ClipGeometry geometry;
  texram::BankImage banks;
  texram::Clut32 clut{};
};

// One access of the eight banks: which banks, at which cells (and, for a write, which bytes).
struct BankAccess {
  uint8_t enable = 0;  // bit b: bank b takes part
  std::array<uint32_t, 8> address{};
  std::array<uint8_t, 8> data{};  // writes only
  friend bool operator==(const BankAccess&, const BankAccess&) = default;
};

// The read accesses of a plan (one per byte plane; none when every tap is outside).
std::vector<BankAccess> read_accesses(const ClipPlan& plan);

// A load: texel (x, y) of a level, virtual coordinates, its bytes as RGBA8888 (plane p is
// byte 3 - p: R first; a one-plane texel is the top byte).
struct Load {
  int level = 0;
  uint32_t x = 0, y = 0;
  uint32_t texel = 0;
};
// Its writes, one access per byte plane (none for a level beyond the top).
std::vector<BankAccess> load_writes(const ClipGeometry& geometry, const Load& load);
void write(texram::BankImage& banks, const BankAccess& access);

// The colour of a planned sample from the bytes its accesses read (data[bank][plane]): the
// taps' texels, the blend and eq. 5. RGBA8888.
uint32_t colour_of(const ClipPlan& plan, const texram::AccessData& data, const Config& config,
                   const texram::Clut32& clut, uint32_t shade);

// The whole unit on one request: plan, read, convert, blend, combine. Returns RGBA8888.
uint32_t sample(const ClipMemory& memory, const Config& config, const Regions& regions,
                const texram::Request& request, ClipPlan* plan_out = nullptr);

// Throws std::invalid_argument, naming the field, for a configuration the unit does not take.
void check(const Config& config);

}  // namespace tmu::clipmap
