#include "render/drf_compile.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <stdexcept>

#include "common/error.hpp"
#include "texram/chip/chip_memory.hpp"
#include "texram/detail.hpp"
#include "texram/page_model.hpp"
#include "texram/video/video_map.hpp"

namespace tmu::render {
namespace {

using texram::chip::DrfOp;
using texram::chip::kCubeDrf;
using texram::chip::kDrfs;

// One DRF of a material's chain before placement.
struct Step {
  std::string role;  // "" for the texture, else the map's role
  std::shared_ptr<const texram::TexramTexture> texture;
  texram::SamplerConfig sampler;
  DrfOp op = DrfOp::kTexture;
  bool takes_coords = false;
  std::string parameter;  // what its parameter transaction carries (takes_coords or the lead)
  std::array<std::shared_ptr<const texram::TexramTexture>, 6> faces{};  // a cube map
  std::optional<footprint::Config> footprint;                           // the texture's
  // A texture or reflectance step with a detail map: its offsets and detail steps follow it.
  std::shared_ptr<const texram::DetailMap> detail;
  bool modulate = false;
  std::shared_ptr<const texram::TexramTexture> offset_v;  // an offsets step's v map
  // A video map's two buffers (render/video_feed): both placed, the DRF's base the front one.
  std::shared_ptr<const VideoBuffers> video;
};

bool needs_clut(const texram::TexramTexture& t) {
  return t.kind == texram::TexelKind::kIndex || t.kind == texram::TexelKind::kCcc;
}

using texram::page_up;

// `s`, and when it has a detail map its offsets step (both offset maps) and detail step, which
// the chip visits within s's sample (000 §9: "linked to the u, v-offset map finally pointing to
// the texture detail map").
void push_with_detail(std::vector<Step>& steps, const Step& s) {
  steps.push_back(s);
  if (!s.detail) return;
  const texram::DetailMap& d = *s.detail;
  const std::string role = s.role.empty() ? "" : s.role + ".";
  Step offsets{role + "detail-offsets",
               std::make_shared<const texram::TexramTexture>(d.offset_u),
               texram::offset_sampler(s.sampler),
               DrfOp::kOffsets,
               false,
               "",
               {},
               std::nullopt,
               {},
               false,
               std::make_shared<const texram::TexramTexture>(d.offset_v),
               {}};
  Step detail{role + "detail",
              std::make_shared<const texram::TexramTexture>(d.detail),
              texram::detail_sampler(d, s.sampler),
              DrfOp::kDetail,
              false,
              "",
              {},
              std::nullopt,
              {},
              false,
              {},
              {}};
  steps.push_back(offsets);
  steps.push_back(detail);
}

// The chain of `mat` in effect_chain's order, or the reason it has none.
std::vector<Step> steps_of(const host::Material& mat, const MaterialTexture& tex,
                           std::string& why) {
  if (mat.procedural) {
    why = "procedural: the material unit (002), no TEXRAM map";
    return {};
  }
  if (mat.unit == host::Material::Unit::kLowcost) {
    why = "the CCC low-cost unit (000 §4): its own memory and block cache, not the TEXRAM";
    return {};
  }
  const EffectMaps& maps = tex.effects;
  std::vector<Step> steps;
  const auto map_step = [](const std::string& role, const MapTexture& m, DrfOp op, bool takes,
                           const std::string& parameter, texram::Addressing addressing) {
    Step s{role, m.texture, m.sampler, op, takes, parameter, {}, std::nullopt, {}, false, {}, {}};
    s.sampler.addressing = addressing;
    return s;
  };
  if (maps.bump) {
    steps.push_back(map_step("bump", maps.bump, DrfOp::kEmit, false, "(u, v), lambda 0",
                             texram::Addressing::kTexel));
  }
  if (maps.diffuse) {
    steps.push_back(map_step("diffuse", maps.diffuse, DrfOp::kShading, true, "(uN, vN)",
                             texram::Addressing::kSphere));
  }
  const std::string coords = mat.footprint ? "(u, v, r1, r2), I_d" : "(u, v, lambda), I_d";
  Step texture{"",     tex.texram, mat.sampler,   DrfOp::kTexture, !steps.empty(),
               coords, {},         mat.footprint, tex.detail,      false,
               {},     {}};
  texture.modulate = mat.detail && mat.detail->modulate;
  texture.video = tex.video;
  push_with_detail(steps, texture);
  if (maps.reflectance) {
    Step r = map_step("reflectance", maps.reflectance, DrfOp::kReflectance, false, "",
                      texram::Addressing::kTexel);
    r.detail = tex.reflectance_detail;
    r.modulate = mat.reflectance.detail && mat.reflectance.detail->modulate;
    push_with_detail(steps, r);
  }
  const uint32_t k_s = reflectance_register(mat.reflectance.constant);  // without a map
  if (maps.specular || maps.sphere) {
    steps.push_back(map_step(maps.specular ? "specular" : "environment",
                             maps.specular ? maps.specular : maps.sphere, DrfOp::kEnvironment, true,
                             "(uN, vN)", texram::Addressing::kSphere));
    steps.back().sampler.constant_rgba = k_s;
  } else if (maps.cube[0]) {
    Step cube = map_step("environment", maps.cube[0], DrfOp::kEnvironment, true,
                         "face, (u, v) on it", texram::Addressing::kTexel);
    for (size_t f = 0; f < 6; ++f) cube.faces[f] = maps.cube[f].texture;
    cube.sampler.constant_rgba = k_s;
    steps.push_back(cube);
  }
  return steps;
}

uint32_t cells_of(const Step& s) {
  if (s.video) return 2 * page_up(s.texture->geometry.bank_cells());
  if (s.offset_v) {
    return page_up(s.texture->geometry.bank_cells()) + page_up(s.offset_v->geometry.bank_cells());
  }
  if (!s.faces[0]) return page_up(s.texture->geometry.bank_cells());
  uint32_t n = 0;
  for (const auto& f : s.faces) n += page_up(f->geometry.bank_cells());
  return n;
}

// Why `chip` cannot take `steps`, or "".
std::string no_room(const ChipProgram& chip, const std::vector<Step>& steps,
                    const texram::Clut32* clut) {
  bool cube = false;
  uint64_t cells = 0;
  for (const Step& s : steps) {
    cube = cube || s.faces[0] != nullptr;
    cells += cells_of(s);
  }
  // A cube map takes DRF 7; the rest of the chain the DRFs from used_drfs + 1 up.
  if (cube && (chip.cube_used || chip.used_drfs >= kCubeDrf)) return "DRF 7 is taken";
  const int plain = static_cast<int>(steps.size()) - (cube ? 1 : 0);
  const int limit = chip.cube_used || cube ? kCubeDrf - 1 : kDrfs;
  const int free_plain = std::max(0, limit - chip.used_drfs);
  if (plain > free_plain) return fmt::format("{} DRFs left, {} needed", free_plain, plain);
  if (chip.used_cells + cells > texram::chip::kBankCells) {
    return fmt::format("{} cells a bank left, {} needed",
                       texram::chip::kBankCells - chip.used_cells, cells);
  }
  if (clut && chip.clut && *chip.clut != *clut) return "its CLUT holds another palette";
  return "";
}

}  // namespace

ScenePrograms compile_drfs(const host::Scene& scene, const std::vector<MaterialTexture>& textures,
                           int chips) {
  ScenePrograms out;
  out.chips.resize(static_cast<size_t>(chips));
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    const host::Material& mat = scene.materials[m];
    MaterialProgram prog;
    prog.material = static_cast<int>(m);
    const std::vector<Step> steps = steps_of(mat, textures[m], prog.why);
    if (steps.empty()) {
      out.materials.push_back(prog);
      continue;
    }
    if (steps.size() > static_cast<size_t>(texram::chip::kMaxSteps)) {
      throw InputError(scene.path, "materials." + mat.name,
                       fmt::format("a chain of {} maps: the TEXRAM links at most {}", steps.size(),
                                   texram::chip::kMaxSteps));
    }
    if (mat.footprint && !(mat.footprint->widths == footprint::Widths{})) {
      throw InputError(scene.path, "materials." + mat.name + ".footprint",
                       "the chip's footprint marcher has the default widths only");
    }
    const texram::Clut32* clut = nullptr;
    for (const Step& s : steps) {
      if (needs_clut(*s.texture)) {
        if (clut && *clut != s.texture->clut) {
          throw InputError(scene.path, "materials." + mat.name,
                           "two maps with different palettes: a chip has one CLUT");
        }
        clut = &s.texture->clut;
      }
    }
    std::string reasons;
    for (int c = 0; c < chips && prog.chip < 0; ++c) {
      const std::string why = no_room(out.chips[static_cast<size_t>(c)], steps, clut);
      if (why.empty()) {
        prog.chip = c;
      } else {
        reasons += fmt::format("; chip {}: {}", c, why);
      }
    }
    if (prog.chip < 0) {
      throw InputError(scene.path, "materials." + mat.name,
                       fmt::format("does not fit in the {} chip{} given{} (texsim: --chips)", chips,
                                   chips == 1 ? "" : "s", reasons));
    }
    ChipProgram& chip = out.chips[static_cast<size_t>(prog.chip)];
    if (clut) chip.clut = *clut;
    // DRF numbers first, so each can name the next.
    for (const Step& s : steps) {
      if (s.faces[0]) {
        prog.drfs.push_back(kCubeDrf);
        chip.cube_used = true;
      } else {
        prog.drfs.push_back(++chip.used_drfs);
      }
    }
    for (size_t k = 0; k < steps.size(); ++k) {
      const Step& s = steps[k];
      texram::chip::Drf& d = chip.drfs[static_cast<size_t>(prog.drfs[k] - 1)];
      d.sampler = s.sampler;
      d.log2_w = s.texture->geometry.log2_width();
      d.log2_h = s.texture->geometry.log2_height();
      d.op = s.op;
      d.takes_coords = s.takes_coords;
      // An emit DRF ends its pass: its texel leaves the chip for the deflection unit, whose
      // coordinates the next pass brings (the units run one after the other over all pixels,
      // so a pixel cannot wait inside the chip for them).
      const bool ends_pass = s.op == DrfOp::kEmit;
      d.link = k + 1 < steps.size() && !ends_pass ? prog.drfs[k + 1] : 0;
      if (k == 0 || steps[k - 1].op == DrfOp::kEmit) prog.passes.push_back(prog.drfs[k]);
      if (s.detail) {
        d.detail = true;
        d.detail_combine =
            s.modulate ? texram::DetailCombine::kModulate : texram::DetailCombine::kReplace;
      }
      if (s.footprint) {
        d.footprint = true;
        d.log2_max_probes = s.footprint->log2_max_probes;
        d.q_rule = s.footprint->q_rule;
      }
      const std::string label = mat.name + (s.role.empty() ? "" : "." + s.role);
      const auto place = [&](const std::shared_ptr<const texram::TexramTexture>& t,
                             const std::string& name, int face) {
        const uint32_t base = chip.used_cells;
        chip.used_cells += page_up(t->geometry.bank_cells());
        chip.maps.push_back(
            {name, s.role, prog.material, prog.drfs[k], face, base, t->geometry.bank_cells(), t});
        return base;
      };
      if (s.faces[0]) {
        d.cube = true;
        for (size_t f = 0; f < 6; ++f)
          d.face_base[f] = place(s.faces[f], label + kCubeFaceNames[f], static_cast<int>(f));
        d.base = d.face_base[0];
      } else if (s.offset_v) {  // the v map right after the u map, where the chip reads it
        d.base = place(s.texture, label + ".u", -1);
        if (place(s.offset_v, label + ".v", -1) != texram::chip::offsets_v_base(d))
          throw std::logic_error("drf_compile: the v-offset map is not where the chip reads it");
      } else if (s.video) {
        // Buffer 1 one page-rounded buffer after buffer 0, where VideoMap::buffer_base puts it.
        const std::array<uint32_t, 2> at = {place(s.video->buffers[0], label + ".video[0]", -1),
                                            place(s.video->buffers[1], label + ".video[1]", -1)};
        if (at[1] - at[0] != texram::video::VideoMap::buffer_stride(s.texture->geometry))
          throw std::logic_error("drf_compile: a video's buffer 1 is not where the swap puts it");
        d.base = at[static_cast<size_t>(s.video->front)];
      } else {
        d.base = place(s.texture, label, -1);
      }
      if (k == 0 || s.takes_coords) prog.parameters.push_back(s.parameter);
    }
    texram::chip::check_program(chip.drfs, prog.passes);
    out.materials.push_back(prog);
  }
  return out;
}

}  // namespace tmu::render
