#include "blocks/registry.hpp"

#include <block_list.hpp>
#include <stdexcept>

#include "blocks/ccc_decoder_block.hpp"
#include "blocks/coord_gen_block.hpp"
#include "blocks/cube_map_block.hpp"
#include "blocks/deflect_block.hpp"
#include "blocks/footprint_block.hpp"
#include "blocks/material_block.hpp"
#include "blocks/mipgen_block.hpp"
#include "blocks/normal_encoder_block.hpp"
#include "blocks/specular_combine_block.hpp"
#include "blocks/trilinear_block.hpp"

namespace tmu::tb {

#define TMU_DECLARE_BLOCK(block)  \
  BlockInfo block_info_##block(); \
  std::unique_ptr<Block> make_block_##block(const BlockOptions& o);
TMU_BLOCKS(TMU_DECLARE_BLOCK)
#undef TMU_DECLARE_BLOCK

namespace {

struct Entry {
  BlockInfo (*info)();
  std::unique_ptr<Block> (*make)(const BlockOptions&);
};
#define TMU_BLOCK_ENTRY(block) {block_info_##block, make_block_##block},
const Entry kEntries[] = {TMU_BLOCKS(TMU_BLOCK_ENTRY)};
#undef TMU_BLOCK_ENTRY

std::string underscores(std::string s) {
  for (char& c : s) c = c == '-' ? '_' : c;
  return s;
}

}  // namespace

std::vector<BlockVariant> block_variants() {
#define TMU_VARIANT_ROW(block, key, top, options) {#block, key, top, options},
  return {TMU_BLOCK_VARIANTS(TMU_VARIANT_ROW)};
#undef TMU_VARIANT_ROW
}

std::vector<BlockInfo> block_list() {
  std::vector<BlockInfo> out;
  for (const Entry& e : kEntries) out.push_back(e.info());
  std::vector<BlockInfo> old = {
      {"ccc", "CCC decoder (000 §3, Fig. 5): block word + texel address -> RGB888", {}},
      {"mipgen",
       "TEXRAM mipmap generator (000 §12, Fig. 14): 2x2 box levels from a texel stream, bank "
       "writes",
       {}},
      {"trilinear",
       "TEXRAM trilinear unit (000 §2, §5, §6): 8-bank mipmap, border modes, texel "
       "configurations, eq. 5",
       {}},
      {"footprint",
       "Footprint assembly (000 §10): N trilinear probes along the longer derivative, "
       "averaged",
       {}},
      {"coord-gen",
       "Shading/environment-map coordinates (001 §5, eq. 17-22): seven tables -> uN, vN, "
       "uR, vR, wR",
       {}},
      {"cube-map",
       "Cube environment map addressing (000 §7): reflection vector -> face and texel "
       "coordinate, dividing by the largest component (the normal encoder's divider)",
       {}},
      {"deflect",
       "Bump deflection unit (001 §4.4, §6.2): phi_D - theta_N, first-octant s2s map "
       "through a one-block MBR, + phi_N",
       {}},
      {"normal-encoder",
       "Normal encoder (001 §4.1, eq. 12-16): (x, y, z) -> (phi, theta) by two seeded "
       "Newton-Raphson dividers and angle tables",
       {}},
      {"specular-combine",
       "Specular combine (000 §7 eq. 6, §8 eq. 7): per channel min(255, D + E R / 255), "
       "alpha from D",
       {}},
      {"material",
       "Material unit (002 §4.2): registers and colour tables behind a write port; (u, v, "
       "w) -> shape -> fractal sums -> marble, wood, brick, fog, cloud, fire RGB888",
       {}}};
  for (BlockInfo& b : old) out.push_back(std::move(b));
  return out;
}

std::string block_name(const std::string& name) {
  const std::string n = underscores(name);
  for (const BlockInfo& b : block_list()) {
    if (b.name == n || underscores(b.name) == n) return b.name;
    for (const std::string& a : b.aliases) {
      if (a == name) return b.name;
    }
  }
  return "";
}

std::unique_ptr<Block> make_block(const std::string& name_or_alias, const BlockOptions& options) {
  const std::string name = block_name(name_or_alias);
  for (const Entry& e : kEntries) {
    if (e.info().name == name) return e.make(options);
  }
  if (name == "ccc") return std::make_unique<CccDecoderBlock>(options.seed);
  if (name == "mipgen") return std::make_unique<MipgenBlock>(options);
  if (name == "trilinear") return std::make_unique<TrilinearBlock>(options);
  if (name == "footprint") return std::make_unique<FootprintBlock>(options);
  if (name == "coord-gen") return std::make_unique<CoordGenBlock>(options.seed);
  if (name == "cube-map") return std::make_unique<CubeMapBlock>(options);
  if (name == "deflect") return std::make_unique<DeflectBlock>(options);
  if (name == "normal-encoder") return std::make_unique<NormalEncoderBlock>(options);
  if (name == "specular-combine") return std::make_unique<SpecularCombineBlock>();
  if (name == "material") return std::make_unique<MaterialBlock>(options);
  std::string known;
  for (const BlockInfo& b : block_list()) known += (known.empty() ? "" : ", ") + b.name;
  throw std::invalid_argument("unknown block '" + name_or_alias + "' (blocks: " + known + ")");
}

}  // namespace tmu::tb
