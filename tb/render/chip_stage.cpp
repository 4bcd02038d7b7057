#include "render/chip_stage.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "common/error.hpp"
#include "texram/chip/drf.hpp"

namespace tmu::render {
namespace {

using D = tb::desc::texram_chip;

// Why the chips cannot sample material m yet, or "".
std::string why_not_on_chip(const host::Material& mat, const MaterialProgram& prog) {
  if (prog.chip < 0) return prog.why;
  if (samples_at_vertices(mat)) {
    return "orders texture and composed sample at the vertices (the material's texture unit)";
  }
  return "";
}

}  // namespace

ChipStage::ChipStage(const host::Scene& scene, const std::vector<MaterialTexture>& textures,
                     int chips)
    : scene_(scene), programs_(compile_drfs(scene, textures, chips)) {
  memories_.resize(programs_.chips.size());
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    const host::Material& mat = scene.materials[m];
    why_not_.push_back(why_not_on_chip(mat, programs_.materials[m]));
    if (mat.has_detail() && !why_not_.back().empty()) {  // no other unit has a detail path
      throw InputError(scene.path, "materials." + mat.name,
                       "has a detail map, which only the chip samples, but cannot go to a chip: " +
                           why_not_.back());
    }
    if (mat.video && !why_not_.back().empty()) {  // the video port writes a chip's memory
      throw InputError(scene.path, "materials." + mat.name + ".video",
                       "a video map is in a chip's memory, but the material cannot go to a chip: " +
                           why_not_.back());
    }
  }
}

void ChipStage::write_generated(size_t m, std::shared_ptr<const texram::TexramTexture> generated) {
  const MaterialProgram& prog = programs_.materials.at(m);
  if (prog.chip < 0) return;
  const auto chip = static_cast<size_t>(prog.chip);
  const std::lock_guard<std::mutex> lock(memories_mutex_);
  for (ChipMap& c : programs_.chips[chip].maps) {
    if (c.material != static_cast<int>(m) || !c.role.empty()) continue;  // the texture's map
    if (c.texture->geometry.bank_cells() != generated->geometry.bank_cells())
      throw std::logic_error("ChipStage: the generated pyramid has another layout: " + c.label);
    c.texture = generated;
  }
  // Passes that hold the old image keep it: they read none of m's cells (a chain reads its own
  // maps), so their samples are the same whichever image they read.
  memories_[chip].reset();
}

std::vector<uint32_t> ChipStage::run_pass(
    size_t m, size_t pass, std::vector<std::vector<texram::chip::PixelParameter>> params,
    const std::vector<size_t>& frags, Level level, std::vector<UnitRun>& units,
    std::vector<std::vector<size_t>>& outputs_of, std::vector<uint32_t>* emitted) {
  if (!samples(m)) throw std::logic_error("ChipStage: material not on a chip: " + why_not(m));
  const MaterialProgram& prog = programs_.materials[m];
  const auto chip = static_cast<size_t>(prog.chip);
  const ChipProgram& program = programs_.chips[chip];
  std::shared_ptr<const tb::ChipScene> memory;
  {
    const std::lock_guard<std::mutex> lock(memories_mutex_);
    if (!memories_[chip]) {
      std::vector<tb::ChipMapPlacement> maps;
      for (const ChipMap& c : program.maps) maps.push_back({{}, c.texture, c.base});
      memories_[chip] = std::make_shared<const tb::ChipScene>(
          tb::chip_scene_of(maps, program.clut.value_or(texram::Clut32{})));
    }
    memory = memories_[chip];
  }

  UnitRun unit;
  unit.kind = "texram_chip";
  unit.material = scene_.materials[m].name;
  unit.role = prog.passes.size() > 1 && pass == 0 ? "bump" : "";
  const auto block =
      std::make_shared<tb::TexramChipBlock>(tb::BlockOptions{}, memory, program.drfs);
  attach(unit, block);
  unit.items = block->setup_items();  // the CLUT and the chip's DRF program
  for (std::vector<texram::chip::PixelParameter>& pixel : params) {
    pixel.front().lead = prog.passes.at(pass);
    for (const texram::chip::PixelParameter& p : pixel)
      unit.items.push_back(tb::chip_param_item(p));
  }
  // Each output's fragment: a pixel gives its emitted samples, then its colour (last).
  run_unit(unit, level, {});
  std::vector<uint32_t> colour;
  std::vector<size_t> fragment_of_output;
  for (const tb::Txn& t : unit.result.outputs) {
    if (colour.size() >= frags.size())
      throw std::logic_error("texram_chip: more pixels than given");
    fragment_of_output.push_back(frags[colour.size()]);
    const auto rgba = static_cast<uint32_t>(t.f[D::out_rgba]);
    if (t.f[D::out_last]) {
      colour.push_back(rgba);
    } else if (emitted) {
      emitted->push_back(rgba);
    }
  }
  if (colour.size() != frags.size()) {
    throw std::runtime_error(
        "texram_chip[" + unit.material + "]: " + std::to_string(colour.size()) + " pixels out of " +
        std::to_string(frags.size()) + (unit.result.error.empty() ? "" : ": " + unit.result.error));
  }
  units.push_back(std::move(unit));
  outputs_of.push_back(std::move(fragment_of_output));
  return colour;
}

texram::chip::PixelParameter texture_parameter(const host::Material& mat,
                                               const host::FragmentRecord& at, uint32_t shade) {
  texram::chip::PixelParameter p{1, {at.u, at.v, at.lambda, shade}};
  if (mat.footprint) {
    p.r1u = at.r1[0];
    p.r1v = at.r1[1];
    p.r2u = at.r2[0];
    p.r2v = at.r2[1];
  }
  return p;
}

std::vector<std::string> chip_lines(const host::Scene& scene, const ChipStage& chips) {
  std::vector<std::string> lines;
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    const std::string& name = scene.materials[m].name;
    if (!chips.samples(m)) {
      lines.push_back(name + ": separate units: " + chips.why_not(m));
      continue;
    }
    const MaterialProgram& p = chips.programs().materials[m];
    const ChipProgram& c = chips.programs().chips[static_cast<size_t>(p.chip)];
    std::string passes;
    for (int lead : p.passes) {
      if (!passes.empty()) passes += " |";
      for (int n : texram::chip::chain(c.drfs, lead)) passes += fmt::format(" {}", n);
    }
    lines.push_back(fmt::format("{}: chip {}, DRF{}", name, p.chip, passes));
  }
  return lines;
}

}  // namespace tmu::render
