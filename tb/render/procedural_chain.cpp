#include "render/procedural_chain.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "blocks/material/material_block.hpp"
#include "blocks/specular_combine/specular_combine_block.hpp"
#include "perlin/materials_ideal.hpp"
#include "render/material_config.hpp"
#include "texram/sampler_config.hpp"

namespace tmu::render {
namespace {

constexpr uint32_t kOpaqueBlack = 0x000000FF;  // C_d = 0 with alpha 255

}  // namespace

std::vector<uint32_t> run_procedural(const ChainInput& in, std::vector<UnitRun>& units,
                                     std::vector<std::vector<size_t>>& outputs_of) {
  const host::Material& mat = in.material;
  const host::Procedural& p = *mat.procedural;
  UnitRun unit;
  unit.kind = "material";
  unit.material = mat.name;
  tb::BlockOptions options;
  attach(unit, std::make_shared<tb::MaterialBlock>(options));
  unit.items = tb::material_load_items(material_registers(p), material_tables(p));
  for (size_t i : in.frags) {
    const auto& s = in.records[i].solid;
    unit.items.push_back(tb::material_sample_item(s[0], s[1], s[2]));
  }
  std::vector<uint32_t> rgba;
  for (const tb::Txn& t : run_and_keep(std::move(unit), in.level, in.frags, units, outputs_of))
    rgba.push_back((static_cast<uint32_t>(t.f[tb::desc::material::out_rgb]) << 8) | 0xFF);
  if (mat.sampler.combine != texram::Combine::kShade) return rgba;

  UnitRun shade;
  shade.kind = "specular_combine";
  shade.material = mat.name;
  attach(shade, std::make_shared<tb::SpecularCombineBlock>());
  for (size_t k = 0; k < in.frags.size(); ++k) {
    shade.items.push_back(
        tb::specular_combine_item(kOpaqueBlack, rgba[k], in.records[in.frags[k]].shade));
  }
  std::vector<uint32_t> out;
  for (const tb::Txn& t : run_and_keep(std::move(shade), in.level, in.frags, units, outputs_of))
    out.push_back(static_cast<uint32_t>(t.f[tb::desc::specular_combine::out_colour]));
  return out;
}

std::vector<glm::dvec4> ideal_procedural(const ChainInput& in,
                                         const std::vector<host::Fragment>& fragments) {
  const host::Material& mat = in.material;
  const perlin::MaterialRegs regs = material_registers(*mat.procedural);
  const perlin::ColourTables tables = material_tables(*mat.procedural);
  std::vector<glm::dvec4> out;
  for (size_t i : in.frags) {
    const host::Fragment& f = fragments[i];
    const uint32_t rgb =
        perlin::ideal::shade_material(regs, tables, f.solid.x, f.solid.y, f.solid.z);
    glm::dvec4 c((rgb >> 16) & 0xFF, (rgb >> 8) & 0xFF, rgb & 0xFF, 255.0);
    if (mat.sampler.combine == texram::Combine::kShade) c *= glm::dvec4(f.shade, 1.0);
    out.push_back(c);
  }
  return out;
}

}  // namespace tmu::render
