// What the two blocks on a clip-map (clipmap; footprint_clip, the footprint unit in front of
// it) share through clip.json's groups, for any description D that uses them: the items of the
// writes and of the clip-map's configuration, the loads that bring a clip-map to an eye, and
// the golden clip-map over a run (its writes, memory requests and counters), so that the
// second block adds only what its requests do.
#pragma once

#include <bitset>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "blocks/clipmap/clip_memory.hpp"
#include "blocks/trilinear/texram_memory.hpp"
#include "clipmap/clipmap.hpp"
#include "clipmap/tile_centre.hpp"
#include "harness/model.hpp"
#include "harness/ports.hpp"
#include "texram/page_model.hpp"

namespace tmu::tb {

// One environment: the configuration, the content seed and where the eye is (level-0 texels).
struct ClipSetup {
  clipmap::Config config;
  uint32_t content = 0;
  double eye_u = 0, eye_v = 0;
};

// The environment's texel: a hash of the seed, the level and the coordinates.
uint32_t clipmap_texel(uint32_t content, int level, uint32_t x, uint32_t y);
using TexelOf = uint32_t (*)(uint32_t content, int level, uint32_t x, uint32_t y);

// A cfg item: the clip_cfg group's fields of a configuration, then the block's own (`extra`).
template <class D, class... Extra>
Txn clip_cfg_item(const clipmap::Config& c, Extra... extra) {
  const texram::SamplerConfig& s = c.sampler;
  return channel_item(D::table(), "cfg",
                      {uint64_t(c.log2_virtual), uint64_t(c.log2_tile), uint64_t(s.kind),
                       uint64_t(s.single_channel), uint64_t(s.filter), uint64_t(s.border_u),
                       uint64_t(s.border_v), s.border_rgba, uint64_t(s.combine), s.constant_rgba,
                       uint64_t(c.substitution), uint64_t(extra)...});
}

template <class D>
Txn clip_clut_item(uint8_t index, uint32_t rgba) {
  return channel_item(D::table(), "clut", {index, rgba});
}
template <class D>
Txn clip_region_item(int level, const clipmap::Region& r) {
  return channel_item(D::table(), "region", {uint64_t(level), r.x0, r.y0, r.x1, r.y1});
}
template <class D>
Txn clip_load_item(const clipmap::Load& l) {
  return channel_item(D::table(), "load", {uint64_t(l.level), l.x, l.y, l.texel});
}

// The clip-map's configuration of a cfg item. Throws std::invalid_argument for an encoding
// outside the unit's or a size it does not take.
template <class D>
clipmap::Config clip_config_of(const Txn& t) {
  clipmap::Config c;
  c.log2_virtual = static_cast<int>(t.f[D::cfg_log2_virtual]);
  c.log2_tile = static_cast<int>(t.f[D::cfg_log2_tile]);
  texram::SamplerConfig& s = c.sampler;
  s.kind = static_cast<texram::TexelKind>(t.f[D::cfg_kind]);
  s.single_channel = static_cast<int>(t.f[D::cfg_single_channel]);
  s.filter = static_cast<texram::Filter>(t.f[D::cfg_filter]);
  s.border_u = static_cast<texram::Border>(t.f[D::cfg_border_u]);
  s.border_v = static_cast<texram::Border>(t.f[D::cfg_border_v]);
  s.border_rgba = static_cast<uint32_t>(t.f[D::cfg_border_rgba]);
  s.combine = static_cast<texram::Combine>(t.f[D::cfg_combine]);
  s.constant_rgba = static_cast<uint32_t>(t.f[D::cfg_constant_rgba]);
  c.substitution = static_cast<clipmap::Substitution>(t.f[D::cfg_substitution]);
  if (t.f[D::cfg_kind] > uint64_t(texram::TexelKind::kSingle) ||
      t.f[D::cfg_filter] > uint64_t(texram::Filter::kTrilinear) ||
      t.f[D::cfg_combine] > uint64_t(texram::Combine::kShade)) {
    throw std::invalid_argument(
        D::table().block() +
        ": a configuration item outside the encodings: " + D::table().inputs().describe(t));
  }
  clipmap::check(c);  // sizes: names what is wrong
  return c;
}

// The region writes and loads that bring a clip-map to the eye (every clipped level's centred
// tile, texel_of(level, x, y) for each of its texels and every whole level's): what the tile
// manager issues for a frame from scratch.
template <class D>
std::vector<Txn> clip_fill_items(const ClipSetup& s, TexelOf texel_of) {
  std::vector<Txn> items;
  const clipmap::Config& c = s.config;
  const clipmap::ClipGeometry g = c.geometry();
  for (int l = 0; l < g.levels(); ++l) {
    const bool clipped = l < c.clipped_levels();
    const clipmap::Region r = clipped ? clipmap::centred_region(c, l, s.eye_u, s.eye_v)
                                      : clipmap::Region{0, 0, g.virtual_side(l), g.virtual_side(l)};
    if (clipped) items.push_back(clip_region_item<D>(l, r));
    for (uint32_t y = r.y0; y < r.y1; ++y) {
      for (uint32_t x = r.x0; x < r.x1; ++x) {
        items.push_back(clip_load_item<D>({l, x, y, texel_of(s.content, l, x, y)}));
      }
    }
  }
  return items;
}

// The golden clip-map over a run: a configuration item clears the memory to the new clip-map
// (the CLUT, the regions and the pages stay, as in the RTL and the memory); the writes as the
// unit takes them; every read and write a request on the memory port, in order. A block's
// golden model derives from it and serves its requests with read().
template <class D>
class ClipGolden : public Model {
 public:
  void configure(const Txn& cfg) override {
    config_ = clip_config_of<D>(cfg);
    memory_.emplace(config_.geometry());
    memory_->clut = clut_;
  }
  void step(const Txn& item, Sink& sink) override {
    if (!memory_)
      throw std::runtime_error(D::table().block() + ": an item before the configuration");
    if (item.f[0] == D::op_clut) {
      const auto i = static_cast<uint8_t>(item.f[D::clut_addr]);
      clut_[i] = memory_->clut[i] = static_cast<uint32_t>(item.f[D::clut_rgba]);
      written_.set(i);
    } else if (item.f[0] == D::op_region) {
      const auto level = static_cast<size_t>(item.f[D::region_level]);
      if (level < regions_.size()) {
        regions_[level] = {static_cast<uint32_t>(item.f[D::region_x0]),
                           static_cast<uint32_t>(item.f[D::region_y0]),
                           static_cast<uint32_t>(item.f[D::region_x1]),
                           static_cast<uint32_t>(item.f[D::region_y1])};
      }
    } else if (item.f[0] == D::op_load) {
      const clipmap::Load load{
          static_cast<int>(item.f[D::load_level]), static_cast<uint32_t>(item.f[D::load_x]),
          static_cast<uint32_t>(item.f[D::load_y]), static_cast<uint32_t>(item.f[D::load_texel])};
      int plane = 0;
      for (const clipmap::BankAccess& a : clipmap::load_writes(memory_->geometry, load)) {
        sink.request(0, clip_access_request(a, true, plane++));
        pages_.access(cells_of(a));
        clipmap::write(memory_->banks, a);
      }
    } else {
      if (config_.sampler.kind == texram::TexelKind::kIndex && !written_.all()) {
        throw std::runtime_error(
            D::table().block() +
            ": a sample of an index texture before all 256 CLUT entries are written (the CLUT is "
            "a RAM without reset: load it first)");
      }
      serve(item, sink);
    }
  }
  Counters counters() const override {
    Counters c = {{"wayward_samples", wayward_ & 0xFFFF'FFFFu},
                  {"substituted_taps", substituted_ & 0xFFFF'FFFFu},
                  {"conflicts", conflicts_ & 0xFFFF'FFFFu}};
    for (const auto& p : page_counters(pages_.stats())) c.push_back(p);
    return c;
  }

 protected:
  // A request item (the op of neither write).
  virtual void serve(const Txn& item, Sink& sink) = 0;
  // One clip-map sample's memory requests and counters, as the unit makes them.
  void read(const clipmap::ClipPlan& plan, Sink& sink) {
    int plane = 0;
    for (const clipmap::BankAccess& a : clipmap::read_accesses(plan)) {
      sink.request(0, clip_access_request(a, false, plane++));
      pages_.access(cells_of(a));
    }
    wayward_ += plan.wayward;
    substituted_ += static_cast<uint64_t>(plan.substituted_taps);
    conflicts_ += static_cast<uint64_t>(plan.conflicts);
  }
  const clipmap::Config& config() const { return config_; }
  const clipmap::ClipMemory& memory() const { return *memory_; }
  const clipmap::Regions& regions() const { return regions_; }

 private:
  static BankCells cells_of(const clipmap::BankAccess& a) {
    BankCells cells;
    for (size_t b = 0; b < 8; ++b) {
      if ((a.enable >> b) & 1) cells[b] = a.address[b];
    }
    return cells;
  }
  clipmap::Config config_;
  std::optional<clipmap::ClipMemory> memory_;
  clipmap::Regions regions_{};  // empty after reset: everything from the whole levels
  texram::Clut32 clut_{};
  std::bitset<256> written_;
  texram::PageModel pages_;
  uint64_t wayward_ = 0, substituted_ = 0, conflicts_ = 0;
};

}  // namespace tmu::tb
