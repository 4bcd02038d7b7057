// The TEXRAM chip's golden sequencer (golden/texram/chip/texram_chip.hpp) against today's chains
// of separate units: every bundled scene compiled to DRF programs (render/drf_compile.hpp), its
// maps placed in each chip's one memory, the DRFs loaded through the write port, and each
// fragment of a material the chip samples run through its chain with the parameters the chain's
// units were given (the texture's (u, v, lambda) and I_d, a bump map's (u, v), the (uN, vN) or
// cube face the deflection units computed): the chip's colour equals the chain's, and an emit
// DRF's sample equals the bump unit's texel, for every fragment. And the renderer through the
// chips gives the same colours (check_renderer).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "blocks/footprint/footprint_block.hpp"
#include "blocks/mipgen/mipgen_frames.hpp"
#include "blocks/trilinear/trilinear_block.hpp"
#include "render/chip_stage.hpp"
#include "render/drf_compile.hpp"
#include "texram/chip/texram_chip.hpp"

namespace tmu::render {
namespace {

namespace fs = std::filesystem;
using texram::chip::ChipOutput;
using texram::chip::PixelParameter;

// The requests each trilinear unit of a material was given, by role and fragment; cube faces
// by fragment.
struct UnitRequests {
  std::map<std::string, std::map<size_t, PixelParameter>> by_role;
  std::map<size_t, int> face;
  std::map<size_t, uint32_t> bump_texel;
};

UnitRequests requests_of(const Pipeline& pipe, const std::string& material) {
  static const std::string kEnv = "environment";
  const auto& table = tb::desc::trilinear::table();
  const auto& footprint_table = tb::desc::footprint::table();
  const int req = table.channel_index("req");
  const int footprint_req = footprint_table.channel_index("req");
  UnitRequests out;
  for (size_t u = 0; u < pipe.units().size(); ++u) {
    const UnitRun& run = pipe.units()[u];
    if (run.material != material || (run.kind != "trilinear" && run.kind != "footprint")) continue;
    const bool marcher = run.kind == "footprint";
    std::string role = run.role;
    int face = -1;
    if (role.size() == kEnv.size() + 2 && role.compare(0, kEnv.size(), kEnv) == 0) {
      static const std::vector<std::string> kFaces = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
      face = static_cast<int>(std::find(kFaces.begin(), kFaces.end(), role.substr(kEnv.size())) -
                              kFaces.begin());
      role = kEnv;
    }
    const std::vector<size_t>& frags = pipe.fragments_of_outputs()[u];
    size_t i = 0;
    for (const tb::Txn& t : run.items) {
      if (marcher ? footprint_table.channel_of(t) != footprint_req : table.channel_of(t) != req)
        continue;
      const size_t f = frags.at(i);
      PixelParameter& p = out.by_role[role][f];
      if (marcher) {
        const footprint::Request r = tb::footprint_request(t);
        p.request = {r.u, r.v, 0, r.shade};
        p.r1u = r.r1u;
        p.r1v = r.r1v;
        p.r2u = r.r2u;
        p.r2v = r.r2v;
      } else {
        p.request = tb::trilinear_request(t);
      }
      if (face >= 0) out.face[f] = face;
      if (role == "bump") out.bump_texel[f] = static_cast<uint32_t>(run.result.outputs.at(i).f[0]);
      ++i;
    }
  }
  return out;
}

// The page model's time per pixel (000 §5: 30 ns an access, a page fault 30 ns more), for the
// reader: what the chain costs on one chip, beside the patent's figures (docs/texram_chip.md).
void print_timing(const std::string& material, size_t maps, const texram::chip::ChipStats& s) {
  if (s.pixels == 0) return;
  const double ns = static_cast<double>(s.pages.accesses + s.pages.slow_accesses) *
                    texram::kAccessNs / static_cast<double>(s.pixels);
  fmt::print(
      "  {}: {} map{}, {} pixels, {:.2f} accesses and {:.2f} page-faulting accesses a "
      "pixel: {:.0f} ns a pixel, {:.1f} M pixels/s\n",
      material, maps, maps == 1 ? "" : "s", s.pixels,
      static_cast<double>(s.pages.accesses) / static_cast<double>(s.pixels),
      static_cast<double>(s.pages.slow_accesses) / static_cast<double>(s.pixels), ns, 1e3 / ns);
}

// The renderer through the chips (render/chip_stage.hpp, texsim render --chips): the same
// colours `rgba` as through the separate units, and on the chips the materials compile_drfs
// placed, less those chip_stage names a reason for; their map units and specular combine did
// not run. Adds the materials on the chips to `on_chip`.
void check_renderer(const host::Scene& scene, const std::vector<host::FragmentRecord>& records,
                    const std::vector<host::Fragment>& frags, const std::vector<uint32_t>& rgba,
                    size_t& on_chip) {
  Pipeline pipe(scene, Level::kGolden, 4);
  if (samples_at_vertices_anywhere(scene)) front_end(scene, pipe, 0, -1, nullptr);
  EXPECT_EQ(pipe.shade(records, &frags, nullptr), rgba);
  const ChipStage& chips = *pipe.chips();
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    EXPECT_TRUE(chips.programs().materials[m].chip >= 0 || !chips.samples(m));
    EXPECT_EQ(chips.samples(m), chips.why_not(m).empty());
    on_chip += chips.samples(m);
  }
  for (const UnitRun& u : pipe.units()) {
    const auto mat = std::find_if(scene.materials.begin(), scene.materials.end(),
                                  [&](const host::Material& m) { return m.name == u.material; });
    if (mat == scene.materials.end() ||
        !chips.samples(static_cast<size_t>(mat - scene.materials.begin())))
      continue;
    EXPECT_TRUE(u.kind != "trilinear" && u.kind != "specular_combine") << u.name();
  }
}

// Runs every chip-sampled material of `scene` through the chip; returns the fragments checked.
size_t check_scene(const host::Scene& scene, size_t& on_chip) {
  Pipeline pipe(scene, Level::kGolden);
  const std::vector<host::Fragment> frags = front_end(scene, pipe, 0, -1, nullptr);
  std::vector<host::FragmentRecord> records;
  for (const host::Fragment& f : frags) records.push_back(host::quantize(f));
  const std::vector<uint32_t> rgba = pipe.shade(records, &frags, nullptr);
  const ScenePrograms programs = compile_drfs(scene, pipe.textures(), 4);
  check_renderer(scene, records, frags, rgba, on_chip);

  size_t checked = 0;
  for (size_t c = 0; c < programs.chips.size(); ++c) {
    const ChipProgram& prog = programs.chips[c];
    if (prog.maps.empty()) continue;
    texram::chip::ChipMemory memory;
    for (const ChipMap& m : prog.maps) memory.place(*m.texture, m.base);
    const texram::Clut32 clut = prog.clut.value_or(texram::Clut32{});
    for (const MaterialProgram& mp : programs.materials) {
      const host::Material& mat = scene.materials[static_cast<size_t>(mp.material)];
      // The tau unit (004) stays in front of the chip: its outputs are the texture unit's
      // requests, so they are the chip's parameters. Orders texture and composed sample at the
      // vertices: their pixels are the interpolated colours.
      if (mp.chip != static_cast<int>(c) || samples_at_vertices(mat)) continue;
      SCOPED_TRACE(mat.name);
      // A chip per material, so that its page model counts this material's pixels alone.
      texram::chip::TexramChip chip(memory, clut);
      for (int n = 1; n <= texram::chip::kDrfs; ++n) {
        for (const auto& w : texram::chip::drf_writes(n, prog.drfs[static_cast<size_t>(n - 1)]))
          chip.write(w);
      }
      EXPECT_EQ(chip.drfs(), prog.drfs);
      const UnitRequests units = requests_of(pipe, mat.name);
      std::map<int, std::string> role_of;  // DRF -> role
      for (const ChipMap& m : prog.maps) {
        if (m.material == mp.material) role_of[m.drf] = m.role;
      }
      // A pixel per pass (a bump map's emit DRF ends the first): the lead's parameter and one
      // per DRF of the pass that takes coordinates.
      const auto pass_parameters = [&](int lead, size_t f) {
        std::vector<PixelParameter> params;
        for (int n : texram::chip::chain(prog.drfs, lead)) {
          if (n != lead && !prog.drfs[static_cast<size_t>(n - 1)].takes_coords) continue;
          PixelParameter p = units.by_role.at(role_of.at(n)).at(f);
          p.lead = lead;
          if (const auto face = units.face.find(f); face != units.face.end()) p.face = face->second;
          params.push_back(p);
        }
        return params;
      };
      for (size_t f = 0; f < records.size(); ++f) {
        if (records[f].material != mp.material) continue;
        const auto bump = units.bump_texel.find(f);
        if (mp.passes.size() != (bump != units.bump_texel.end() ? 2u : 1u)) {
          ADD_FAILURE() << mp.passes.size() << " passes, with a bump map 2, else 1";
          return checked;
        }
        for (size_t pass = 0; pass < mp.passes.size(); ++pass) {
          const std::vector<PixelParameter> params = pass_parameters(mp.passes[pass], f);
          size_t next = 0;
          std::vector<ChipOutput> out;
          chip.pixel(params, next, out);
          EXPECT_EQ(next, params.size()) << "fragment " << f;
          // The emit pass gives the bump texel, then a colour nobody reads.
          const bool emit = pass + 1 < mp.passes.size();
          if (out.size() != (emit ? 2u : 1u)) {
            ADD_FAILURE() << "fragment " << f << " pass " << pass << ": " << out.size()
                          << " outputs";
            return checked;
          }
          if (emit) {
            EXPECT_EQ(out[0], (ChipOutput{bump->second, false})) << "fragment " << f;
          } else {
            EXPECT_EQ(out.back(), (ChipOutput{rgba[f], true})) << "fragment " << f;
          }
        }
        ++checked;
      }
      EXPECT_FALSE(chip.stats().step_limit);
      print_timing(mat.name, mp.drfs.size(), chip.stats());
    }
  }
  return checked;
}

TEST(RenderChipTest, EveryBundledChainGivesTheSameColoursOnTheChip) {
  size_t on_chip = 0;
  for (const auto& entry : fs::directory_iterator(std::string(TMU_SOURCE_DIR) + "/scenes")) {
    if (entry.path().extension() != ".json") continue;
    std::ifstream in(entry.path());
    const nlohmann::json j = nlohmann::json::parse(in);
    if (j.contains("flyover")) continue;  // a clip-map fly-over (003)
    if (j.contains("volume")) continue;   // a volume scene (000 §13): no maps, no DRFs
    SCOPED_TRACE(entry.path().filename().string());
    const host::Scene scene = host::load_scene(entry.path().string());
    // Detail and video maps: only the chip samples them, there are no separate units to compare
    // with (render_scene_detail and render_scene_video check those scenes rtl = golden on the
    // chips).
    if (std::any_of(scene.materials.begin(), scene.materials.end(),
                    [](const host::Material& m) { return m.has_detail() || m.video; }))
      continue;
    std::cout << entry.path().filename().string() << ":\n";
    const size_t checked = check_scene(scene, on_chip);
    std::cout << "  " << checked << " fragments through the chip\n";
  }
  std::cout << on_chip << " materials through the chips in the renderer\n";
  // 34 when written, 37 with the footprint materials, 38 with the mipmap generator's (the
  // floor of everything.json): fewer means a chain fell off the chips.
  EXPECT_GE(on_chip, 38u);
}

// A material whose mipmaps the real-time generator makes (000 §12) goes on a chip: the mipgen
// units run (one per byte plane) and the chip's map is the pyramid they wrote, cell by cell at the
// map's base, not the host's (whose cells are the same values: MipgenTest shows the stream equals
// the pyramid, so the colours alone cannot tell them apart); the chip samples it, no trilinear
// unit does.
TEST(RenderChipTest, TheMipmapGeneratorWritesItsMapInTheChip) {
  const host::Scene scene =
      host::load_scene(std::string(TMU_SOURCE_DIR) + "/scenes/everything.json");
  const auto floor = std::find_if(scene.materials.begin(), scene.materials.end(),
                                  [](const host::Material& m) { return m.name == "floor"; });
  ASSERT_NE(floor, scene.materials.end());
  ASSERT_EQ(floor->mipmaps, host::Material::Mipmaps::kMipgen);
  const auto m = static_cast<size_t>(floor - scene.materials.begin());
  Pipeline pipe(scene, Level::kGolden, 4);
  const std::vector<host::Fragment> frags = front_end(scene, pipe, 0, -1, nullptr);
  std::vector<host::FragmentRecord> records;
  for (const host::Fragment& f : frags) records.push_back(host::quantize(f));
  pipe.shade(records, &frags, nullptr);

  const ChipStage& chips = *pipe.chips();
  ASSERT_TRUE(chips.samples(m)) << chips.why_not(m);
  const MaterialProgram& prog = chips.programs().materials[m];
  const ChipProgram& chip = chips.programs().chips.at(static_cast<size_t>(prog.chip));
  const auto map = std::find_if(chip.maps.begin(), chip.maps.end(), [&](const ChipMap& c) {
    return c.material == static_cast<int>(m) && c.role.empty();
  });
  ASSERT_NE(map, chip.maps.end());
  EXPECT_EQ(map->texture, pipe.textures()[m].texram) << "the chip holds the host's pyramid";

  size_t mipgen_units = 0, writes = 0, chip_units = 0;
  for (const UnitRun& u : pipe.units()) {
    if (u.material.rfind("floor", 0) != 0) continue;
    EXPECT_NE(u.kind, "trilinear");
    EXPECT_NE(u.kind, "footprint");
    chip_units += u.kind == "texram_chip";
    if (u.kind != "mipgen") continue;
    ++mipgen_units;
    for (const tb::Txn& out : u.result.outputs) {
      const texram::CellWrite w = tb::mipgen_txn_write(out);
      ASSERT_EQ(map->texture->banks[w.cell.bank][w.cell.address], w.value)
          << "bank " << w.cell.bank << " cell " << w.cell.address;
      ++writes;
    }
  }
  const texram::Geometry& g = map->texture->geometry;
  size_t texels = 0;  // every texel of every level, the levels narrower than 2 replicated to 2
  for (int l = 0; l < g.levels(); ++l) texels += size_t{g.stored_width(l)} * g.stored_height(l);
  EXPECT_EQ(mipgen_units, static_cast<size_t>(g.planes()));
  EXPECT_EQ(writes, texels * static_cast<size_t>(g.planes()));
  EXPECT_EQ(chip_units, 1u);
}

}  // namespace
}  // namespace tmu::render
