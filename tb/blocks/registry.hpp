// Every co-simulation block by name: what `texsim cosim BLOCK` and the tests instantiate.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "deflect/coord_tables.hpp"
#include "deflect/normal_encoder.hpp"
#include "footprint/footprint.hpp"
#include "harness/block.hpp"
#include "texram/sampler_config.hpp"

namespace tmu::tb {

struct BlockOptions {
  uint64_t seed = 1;
  std::string texture;            // ccc_cache_bilinear: a .ccc file instead of a random texture
  std::optional<bool> lookahead;  // ccc_cache_bilinear: neighbour prefetch (unset: drawn)
  // mipgen: parts of every frame format; -1 draws them from the seed.
  int mip_log2_w = -1;      // log2 of the width, 0..10
  int mip_log2_h = -1;      // log2 of the height, 0..10
  int mip_interlaced = -1;  // 0 or 1
  // trilinear: the environment is drawn from the seed; each field that is set overrides its
  // draw (the configuration, the texture's size and content, the unit's widths).
  std::optional<texram::TexelKind> tri_kind;
  std::optional<int> tri_single_channel;  // 0 R .. 3 A
  std::optional<texram::Filter> tri_filter;
  std::optional<texram::Border> tri_border_u, tri_border_v;
  std::optional<uint32_t> tri_border_rgba;  // RGBA8888
  std::optional<texram::Combine> tri_combine;
  std::optional<uint32_t> tri_constant_rgba;  // k_T, RGBA8888
  std::optional<int> tri_log2_w, tri_log2_h;  // 0..10
  // The content: a pattern (gradient, checker, noise, smooth, random bytes), or an image file
  // (its size; sides powers of two up to 1024).
  std::string tri_pattern;
  std::string tri_image;
  // The unit's widths; the rtl engine is verilated at a few (rtl/blocks.cmake).
  texram::Widths tri_widths;
  // footprint: the trilinear unit's environment as above (tri_*), and (footprint_setup too) the
  // setup's configuration: each field that is set overrides its draw from the seed.
  std::optional<int> fp_log2_max_probes;  // 0..4: at most 2^this probes
  std::optional<footprint::QRule> fp_q_rule;
  // The setup's widths D, T, F; the rtl engine is verilated at a few (rtl/blocks.cmake).
  footprint::Widths fp_widths;
  // deflect: the map memory answers a block request after this many cycles (1..1000), plus
  // 0..dfl_map_jitter cycles drawn from the seed per request.
  int dfl_map_latency = 4;
  int dfl_map_jitter = 0;
  // normal_encoder: the encoder's seed and angle-table widths (grid A = 9, the ports'); the
  // rtl level is verilated at the variants of rtl/blocks.cmake.
  deflect::EncoderConfig encoder;
  // coord_gen: the tables' grid (A 6..9) and entry width (W 8..10); the rtl level is verilated
  // at the variants of rtl/blocks.cmake.
  deflect::TableConfig coord_tables;
  // fractal, material: the fractal sums on one noise unit shared by the four octaves (one
  // sample per 4 clocks, the thesis's design) instead of four pipelined units (one per clock).
  bool fractal_shared = false;
  // texram_chip: the random items are scan lines of one named program ("texture", "detail",
  // "extreme": docs/texram_chip.md's cycle figures) instead of random programs; "" random.
  std::string chip_workload;
  // volume: the mode of every volume drawn (0 value, 1 raw; unset: drawn), and a figure's ray
  // set (z, x or oblique through a 64 x 128 x 128 volume, docs/volume.md; empty: the directed
  // and random rays).
  std::optional<int> vol_mode;
  std::string vol_rays;
  // video_unit: the cells of a row buffer, 8 (the block) or 512 (a page, the chip's rows; the
  // rtl variant "page"), and a figure's workload ("1p", "4p", "1i", "4i": two frames of a 512 x
  // 512 video of one or four planes, progressive or interlaced, at 30 frames per second under a
  // sampler that wants every cycle, docs/video.md; empty: the directed and random items).
  uint32_t video_cells = 8;
  std::string video_workload;
};

struct BlockInfo {
  std::string name;
  std::string summary;               // one line, with its source section
  std::vector<std::string> aliases;  // names it had before
};

std::vector<BlockInfo> block_list();
// The block of a name or alias (a hyphen stands for an underscore: cube-address); throws
// std::invalid_argument naming the known blocks when `name` is not one of them.
std::unique_ptr<Block> make_block(const std::string& name, const BlockOptions& options);
// The name of the block `name` or alias names, or "" when none does.
std::string block_name(const std::string& name);

// Every variant of every block (rtl/blocks.cmake): the block, its variant key ("" the
// default), its RTL top and the `texsim cosim` options that select it.
struct BlockVariant {
  std::string block, key, top, options;
};
std::vector<BlockVariant> block_variants();

}  // namespace tmu::tb

// At the end of a block's .cpp: registers Class under the block's name (rtl/blocks.cmake lists the
// blocks) with the one-line summary and old names of its description (TMU_BLOCK_INFO_<block>,
// generated from tb/blocks/<block>/<block>.json).
#define TMU_REGISTER_BLOCK(block, Class)                             \
  namespace tmu::tb {                                                \
  BlockInfo block_info_##block() { return TMU_BLOCK_INFO_##block; }  \
  std::unique_ptr<Block> make_block_##block(const BlockOptions& o) { \
    return std::make_unique<Class>(o);                               \
  }                                                                  \
  }

namespace tmu::tb {}  // namespace tmu::tb
