// Rendering scenes: only the units a scene calls for are built and clocked; traces replay bit
// for bit; bands merge into the whole frame; --check catches an altered result; bad materials
// name their field.
#include "render/render.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "blocks/specular_combine/specular_combine_block.hpp"
#include "common/error.hpp"
#include "common/image.hpp"
#include "render/bands.hpp"
#include "render/pipeline.hpp"
#include "render/tiles.hpp"
#include "render/unit_check.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::render {
namespace {

const std::string kScenes = std::string(TMU_SOURCE_DIR) + "/scenes/";
constexpr double kProceduralIdealBound = 47.0;  // measured 49.9 dB

RenderOptions options(Level level, const std::string& out) {
  RenderOptions o;
  o.level = level;
  o.out_dir = (tb::testing::temp_dir("tmu_render_test") / out).string();
  o.progress = false;
  return o;
}

RenderReport render(const std::string& scene, const RenderOptions& o, int expect_exit = 0) {
  std::stringstream log;
  RenderReport rep;
  EXPECT_EQ(render_scene(kScenes + scene, o, log, &rep), expect_exit) << log.str();
  return rep;
}

ImageRgb8 picture(const RenderOptions& o) { return read_image(o.out_dir + "/render.png"); }

bool has_kind(const RenderReport& r, const std::string& kind) {
  for (const UnitReport& u : r.units) {
    if (u.kind == kind) return true;
  }
  return false;
}

// The plain scene and the everything scene have the same frame and objects; the plain one
// uses plain textures only, so no mipmap generator, low-cost unit or footprint unit is built
// or clocked, and it takes fewer simulated cycles. (Cycles, not wall time: tests never time
// themselves.)
TEST(RenderTest, PlainSceneBuildsAndClocksOnlyTheTrilinearUnits) {
  reset_census();
  const RenderReport plain = render("plain.json", options(Level::kRtl, "plain"));
  EXPECT_EQ(census("mipgen").built, 0u);
  EXPECT_EQ(census("mipgen").cycles, 0u);
  EXPECT_EQ(census("ccc_cache_bilinear").built, 0u);
  EXPECT_EQ(census("ccc_cache_bilinear").cycles, 0u);
  EXPECT_EQ(census("footprint").built, 0u);
  EXPECT_EQ(census("footprint").cycles, 0u);
  for (const char* kind :
       {"normal_encoder", "deflect", "coord_gen", "cube_address", "specular_combine", "material"}) {
    EXPECT_EQ(census(kind).built, 0u) << kind;
  }
  EXPECT_GT(census("trilinear").built, 0u);
  for (const UnitReport& u : plain.units) EXPECT_EQ(u.kind, "trilinear") << u.name;

  reset_census();
  const RenderReport all = render("everything.json", options(Level::kRtl, "everything"));
  EXPECT_GT(census("mipgen").cycles, 0u);
  EXPECT_GT(census("ccc_cache_bilinear").cycles, 0u);
  EXPECT_GT(census("footprint").cycles, 0u);
  EXPECT_TRUE(has_kind(all, "mipgen") && has_kind(all, "ccc_cache_bilinear") &&
              has_kind(all, "footprint"));
  EXPECT_EQ(plain.pixels, all.pixels);
  EXPECT_LT(plain.unit_cycles(), all.unit_cycles());
  std::cout << "plain scene: " << plain.unit_cycles()
            << " cycles; everything: " << all.unit_cycles() << " cycles\n";
}

// A unit whose material has no fragment in the band is not built: in each band of
// scenes/everything.json the floor's mipmap generator is built exactly when the floor's
// footprint unit is (the floor has fragments there), and some band has no floor at all.
TEST(RenderTest, MipmapGeneratorIsBuiltOnlyForABandThatShowsItsMaterial) {
  constexpr int kBands = 8;
  int without = 0, with = 0;
  for (int band = 0; band < kBands; ++band) {
    reset_census();
    RenderOptions o = options(Level::kGolden, "everything_band" + std::to_string(band));
    o.tile = band;
    o.tiles = kBands;
    const RenderReport r = render("everything.json", o);
    const bool floor_shown = has_kind(r, "footprint");
    EXPECT_EQ(census("mipgen").built > 0, floor_shown) << "band " << band;
    EXPECT_EQ(has_kind(r, "mipgen"), floor_shown) << "band " << band;
    (floor_shown ? with : without) += 1;
  }
  EXPECT_GT(without, 0);
  EXPECT_GT(with, 0);
}

// --- Every effect is simulated only where a scene calls for it ------------------------------

// One effect of the documents' pipelines: a bundled scene that has it, how to take it out of a
// material, and the census keys of the units only it builds (render/units.hpp).
struct Effect {
  const char* name;
  const char* scene;
  std::function<void(nlohmann::json& material)> remove;
  std::vector<std::string> units;
};

void erase(nlohmann::json& m, std::initializer_list<const char*> keys) {
  for (const char* k : keys) m.erase(k);
}

// Takes an environment map of `map` ("sphere", "cube") out, with the reflectance that needs it.
std::function<void(nlohmann::json&)> without_environment(const std::string& map) {
  return [map](nlohmann::json& m) {
    if (m.contains("environment") && m["environment"].value("map", "") == map)
      erase(m, {"environment", "reflectance"});
  };
}

const std::vector<std::string> kCubeFaces = {"cube_address",
                                             "trilinear.environment+X",
                                             "trilinear.environment-X",
                                             "trilinear.environment+Y",
                                             "trilinear.environment-Y",
                                             "trilinear.environment+Z",
                                             "trilinear.environment-Z"};

const std::vector<Effect>& effects() {
  static const std::vector<Effect> e = {
      {"real-time mipmaps", "everything.json", [](auto& m) { erase(m, {"mipmaps"}); }, {"mipgen"}},
      {"low-cost unit",
       "everything.json",
       [](auto& m) { erase(m, {"unit"}); },
       {"ccc_cache_bilinear"}},
      {"footprint assembly",
       "everything.json",
       [](auto& m) { erase(m, {"footprint"}); },
       {"footprint"}},
      {"bump map",
       "bumps.json",
       [](auto& m) { erase(m, {"bump"}); },
       {"deflect", "trilinear.bump"}},
      {"shading maps",
       "bumps.json",  // a bump or a specular term implies them
       [](auto& m) {
         erase(m, {"shading", "bump", "specular", "reflectance"});
       },
       {"trilinear.diffuse"}},
      {"specular map",
       "bumps.json",
       [](auto& m) {
         erase(m, {"specular", "reflectance"});
       },
       {"trilinear.specular", "specular_combine"}},
      {"sphere environment map",
       "reflect.json",
       without_environment("sphere"),
       {"trilinear.environment"}},
      {"cube environment map", "reflect.json", without_environment("cube"), kCubeFaces},
      {"reflectance map",
       "reflect.json",
       [](auto& m) {
         if (m.contains("reflectance") && m["reflectance"].is_object())
           m["reflectance"] = {0.5, 0.5, 0.5};
       },
       {"trilinear.reflectance"}},
      {"normal-based shading",
       "reflect.json",
       [](auto& m) {
         erase(m, {"shading", "bump", "specular", "environment", "reflectance"});
       },
       {"normal_encoder", "coord_gen", "specular_combine"}},
      {"procedural materials",
       "procedural.json",
       [](auto& m) {
         if (m.contains("procedural")) {
           erase(m, {"procedural", "combine"});
           m["texture"] = {{"pattern", "smooth"}, {"size", {64, 64}}};
         }
       },
       {"material", "specular_combine"}},
  };
  return e;
}

// `scene` with `remove` applied to every material, written beside the test's outputs; the
// files it names are made absolute so that it loads from there.
std::string scene_without(const std::string& scene, const Effect& effect, const std::string& out) {
  nlohmann::json j = nlohmann::json::parse(std::ifstream(kScenes + scene));
  for (auto& [name, material] : j["materials"].items()) effect.remove(material);
  const std::function<void(nlohmann::json&)> absolute = [&](nlohmann::json& node) {
    for (auto& [key, value] : node.items()) {
      if (value.is_string() && (key == "image" || key == "ccc" || key == "file")) {
        value = kScenes + value.get<std::string>();
      } else if (value.is_structured()) {
        absolute(value);
      }
    }
  };
  absolute(j);
  const std::filesystem::path path = tb::testing::temp_dir("tmu_render_test") / (out + ".json");
  std::ofstream(path) << j.dump(2);
  return path.string();
}

// For every effect: the bundled scene that has it constructs each of its units (so the check
// can fail), and the same scene without it constructs none of them, at golden (the census
// counts engine constructions at any level).
TEST(RenderTest, AnEffectNoMaterialNamesBuildsNoUnit) {
  for (const Effect& e : effects()) {
    reset_census();
    render(e.scene, options(Level::kGolden, std::string("with_") + e.name));
    for (const std::string& unit : e.units)
      EXPECT_GT(census(unit).built, 0u) << e.name << ": " << e.scene << " builds no " << unit;
    const std::string edited = scene_without(e.scene, e, std::string("without_") + e.name);
    reset_census();
    std::stringstream log;
    ASSERT_EQ(render_scene(edited, options(Level::kGolden, std::string("without_") + e.name), log),
              0)
        << e.name << ": " << log.str();
    for (const std::string& unit : e.units) {
      EXPECT_EQ(census(unit).built, 0u) << "without " << e.name << ", " << unit << " was built";
      EXPECT_EQ(census(unit).cycles, 0u) << "without " << e.name << ", " << unit << " ran";
    }
  }
}

// What a render leaves on the host is named in its report, only for the materials that need it.
TEST(RenderTest, TheReportNamesTheHostWork) {
  const auto stages = [](const RenderReport& r) {
    std::vector<std::string> s;
    for (const HostWork& w : r.host_work) s.push_back(w.stage.substr(0, w.stage.find(' ')));
    return s;
  };
  EXPECT_TRUE(render("plain.json", options(Level::kRtl, "plain_host")).host_work.empty());
  const RenderReport reflect = render("reflect.json", options(Level::kGolden, "reflect_host"));
  using V = std::vector<std::string>;
  // chrome: sphere map (RTL), k_s; gold: cube, k_s; varnish: bump and shading maps (RTL),
  // cube, map R. Bump texels and sphere-map coordinates are RTL: tmu_deflect unpacks the
  // texel, tmu_trilinear's sphere addressing reads (uN, vN).
  EXPECT_EQ(stages(reflect), (V{"reflectance", "cube-face"})) << reflect.text();
}

// --- render --check, unit by unit -----------------------------------------------------------

UnitRun combine_unit(const std::string& material) {
  UnitRun u;
  u.kind = "specular_combine";
  u.material = material;
  const auto block = std::make_shared<tb::SpecularCombineBlock>();
  attach(u, block);
  std::mt19937_64 rng(3);
  u.items = block->random_items(rng, 40);
  run_unit(u, Level::kGolden, {});
  return u;
}

// The check compares each unit's outputs field by field and its counters, so a wrong bit in a
// unit's output or a wrong count is named although a later unit could mask it in the pixels;
// two renders that built different units differ at the first.
TEST(RenderTest, UnitCheckNamesTheUnitWhoseOutputOrCounterDiffers) {
  const std::vector<UnitRun> reference = {combine_unit("a"), combine_unit("b")};
  EXPECT_TRUE(check_units(reference, reference).match());
  EXPECT_EQ(check_units(reference, reference).compared, 2u);

  std::vector<UnitRun> got = reference;
  got[1].result.outputs[7].f[tb::desc::specular_combine::out_colour] ^= 1;
  UnitCheck c = check_units(got, reference);
  ASSERT_EQ(c.differences.size(), 1u);
  EXPECT_NE(c.differences[0].find("specular_combine[b]: 1 of 40 outputs differ, first output 7 "
                                  "(colour)"),
            std::string::npos)
      << c.differences[0];
  EXPECT_EQ(c.first_unit, 1u);
  EXPECT_EQ(c.first_cycle, got[1].result.output_cycles[7]);

  got = reference;
  std::vector<UnitRun> counted = reference;
  counted[0].result.counters.push_back({"hits", 3});
  got[0].result.counters.push_back({"hits", 4});
  c = check_units(got, counted);
  ASSERT_EQ(c.differences.size(), 1u);
  EXPECT_NE(c.differences[0].find("specular_combine[a]: counter hits"), std::string::npos)
      << c.differences[0];

  got = reference;
  got[0].material = "c";
  c = check_units(got, reference);
  ASSERT_EQ(c.differences.size(), 1u);
  EXPECT_NE(c.differences[0].find("this render built specular_combine[c], the reference "
                                  "specular_combine[a]"),
            std::string::npos)
      << c.differences[0];
}

// The units of each material of scenes/reflect.json, in the order the chain runs them
// (render/effect_chain.hpp): what the material names is built, nothing else.
TEST(RenderTest, DeflectionChainBuildsWhatEachMaterialNames) {
  const RenderReport r = render("reflect.json", options(Level::kGolden, "reflect_units"));
  std::map<std::string, std::vector<std::string>> units;
  for (const UnitReport& u : r.units) {
    const std::string material = u.name.substr(u.name.find('[') + 1);
    units[material.substr(0, material.find_first_of(".]"))].push_back(u.name);
  }
  using V = std::vector<std::string>;
  EXPECT_EQ(units["floor"], V{"trilinear[floor]"});
  // A sphere map without shading maps or bump: the vertex shade, no deflection.
  EXPECT_EQ(units["chrome"], (V{"normal_encoder[chrome]", "coord_gen[chrome]", "trilinear[chrome]",
                                "trilinear[chrome.environment]", "specular_combine[chrome]"}));
  // The cube: its addressing unit, then one map per face a fragment sees.
  const V& gold = units["gold"];
  ASSERT_GE(gold.size(), 6u);
  EXPECT_EQ(V(gold.begin(), gold.begin() + 4), (V{"normal_encoder[gold]", "coord_gen[gold]",
                                                  "trilinear[gold]", "cube_address[gold]"}));
  EXPECT_EQ(gold.back(), "specular_combine[gold]");
  for (size_t i = 4; i + 1 < gold.size(); ++i)
    EXPECT_EQ(gold[i].rfind("trilinear[gold.environment", 0), 0u) << gold[i];
  // Everything: bump, deflection, diffuse map, cube, reflectance map.
  const V& varnish = units["varnish"];
  ASSERT_GE(varnish.size(), 9u);
  EXPECT_EQ(V(varnish.begin(), varnish.begin() + 7),
            (V{"normal_encoder[varnish]", "trilinear[varnish.bump]", "deflect[varnish]",
               "coord_gen[varnish]", "trilinear[varnish.diffuse]", "trilinear[varnish]",
               "cube_address[varnish]"}));
  EXPECT_EQ(varnish[varnish.size() - 2], "trilinear[varnish.reflectance]");
  EXPECT_EQ(varnish.back(), "specular_combine[varnish]");
}

// Bit for bit on rtl, with the deflection cache's counts in the report: every look-up is a
// hit, a miss or a bypass, and each miss waits for its block.
TEST(RenderTest, DeflectionScenesMatchGoldenOnRtlAndReportTheCache) {
  for (const char* scene : {"bumps.json", "reflect.json"}) {
    RenderOptions o = options(Level::kRtl, std::string("rtl_") + scene);
    o.check = Level::kGolden;
    const RenderReport r = render(scene, o);
    ASSERT_TRUE(r.check.has_value());
    EXPECT_EQ(r.check->differing, 0u) << scene;
    EXPECT_GT(r.check->compared, 10000u);
    uint64_t transactions = 0, hits = 0, misses = 0, bypasses = 0, stalls = 0;
    for (const UnitReport& u : r.units) {
      if (u.kind != "deflect") continue;
      transactions += u.transactions;
      hits += tb::counter_value(u.counters, "hits").value_or(0);
      misses += tb::counter_value(u.counters, "misses").value_or(0);
      bypasses += tb::counter_value(u.counters, "bypasses").value_or(0);
      stalls += tb::counter_value(u.counters, "stall_cycles").value_or(0);
    }
    EXPECT_GT(transactions, 0u) << scene;
    EXPECT_EQ(hits + misses + bypasses, transactions) << scene;
    EXPECT_GT(hits, 0u);
    EXPECT_GE(stalls, misses) << scene;  // a block takes at least a cycle to arrive
    EXPECT_NE(r.text().find("deflection cache (MBR)"), std::string::npos);
  }
}

// Golden against the ideal chain (exact normals, rotation, coordinates and reflection): the
// deflected normal is within one grid step (0.70 degrees, tests/deflect_test.cpp) of the exact
// one, which moves a sharp edge of a shading map by a fraction of a texel but a reflected
// edge of the environment by several (a reflection turns twice as fast as the normal, and the
// room has sharp edges): 001 §7.2 finds 512 x 256 enough for bumps, visible on reflections.
// Measured 51.9 dB (bumps) and 32.1 dB (reflect); the bounds leave 2 dB.
TEST(RenderTest, DeflectionScenesStayNearTheIdeal) {
  for (const auto& [scene, bound] : {std::pair{"bumps.json", 50.0}, {"reflect.json", 30.0}}) {
    RenderOptions o = options(Level::kGolden, std::string("ideal_") + scene);
    o.compare_ideal = true;
    const RenderReport r = render(scene, o);
    ASSERT_TRUE(r.compare.has_value());
    EXPECT_GT(r.compare->psnr, bound) << scene;
    std::cout << scene << ": golden against ideal " << r.compare->psnr << " dB\n";
  }
}

// scenes/detail.json on chips against the ideal renderer (texram/detail_ideal's exact detail
// sample). The cloth alone (the sphere given the cloth's material) is a luminance texture with a
// modulating detail map under eq. 5's shade: every channel within the detail sample's bound,
// 3.5 for modulate + 0.5 for eq. 5 (docs/detail.md "Accuracy"; measured 2.86). The whole scene
// adds the sphere's environment chain, whose quantised map coordinates miss at the silhouette as
// in reflect.json: a PSNR bound only (measured 40.10 dB).
TEST(RenderTest, DetailSceneStaysNearTheIdeal) {
  RenderOptions o = options(Level::kGolden, "detail_ideal");
  o.chips = 4;
  o.compare_ideal = true;
  const RenderReport whole = render("detail.json", o);
  ASSERT_TRUE(whole.compare.has_value());
  EXPECT_GT(whole.compare->psnr, 38.0);
  std::ifstream in(kScenes + "detail.json");
  std::stringstream text;
  text << in.rdbuf();
  std::string cloth = text.str();
  const std::string sphere = "\"material\": \"lacquer\"";
  ASSERT_NE(cloth.find(sphere), std::string::npos);
  cloth.replace(cloth.find(sphere), sphere.size(), "\"material\": \"cloth\"");
  const std::string path = o.out_dir + "_cloth.json";
  std::ofstream(path) << cloth;
  o.out_dir += "_cloth";
  std::stringstream log;
  RenderReport alone;
  ASSERT_EQ(render_scene(path, o, log, &alone), 0) << log.str();
  ASSERT_TRUE(alone.compare.has_value());
  EXPECT_LE(alone.compare->max_error, 4.0);
  std::cout << "detail.json: golden against ideal " << whole.compare->psnr
            << " dB; the cloth alone " << alone.compare->psnr << " dB, max "
            << alone.compare->max_error << "\n";
}

// A detail map under footprint assembly (000 §9 with §10): the chip samples each probe through
// the detail path, and so does the ideal footprint marcher (footprint::ideal_march with
// texram/detail_ideal's exact sample). scenes/detail.json's cloth alone, with a footprint of up
// to 8 probes, on chips against the ideal renderer: the average of N probes is within the largest
// probe's error, the detail sample's bound of 4 (3.5 for modulate + 0.5 for eq. 5, as above),
// plus the footprint's own: golden's probe positions, lambda and average against the exact ones
// (docs/footprint.md "Accuracy": 1.38 at most on a smooth texture). The bound is their sum, 5.5
// (measured 5.36, 49.7 dB).
TEST(RenderTest, DetailUnderFootprintAssemblyStaysNearTheIdeal) {
  std::ifstream in(kScenes + "detail.json");
  std::stringstream text;
  text << in.rdbuf();
  std::string scene = text.str();
  const std::string sphere = "\"material\": \"lacquer\"";
  const std::string detail = "\"combine\": \"modulate\"}},";
  ASSERT_NE(scene.find(sphere), std::string::npos);
  ASSERT_NE(scene.find(detail), std::string::npos);
  scene.replace(scene.find(sphere), sphere.size(), "\"material\": \"cloth\"");
  scene.replace(scene.find(detail), detail.size(),
                "\"combine\": \"modulate\"}, \"footprint\": {\"max_probes\": 8}},");
  // A grazing view: the far cloth's footprints take several probes (about 700 more probes than
  // the same view without footprint assembly, by the chip's accesses).
  const std::string camera = "\"position\": [0, 0.55, 1.6], \"target\": [0, 0.25, 0]";
  ASSERT_NE(scene.find(camera), std::string::npos);
  scene.replace(scene.find(camera), camera.size(),
                "\"position\": [0, 0.12, 1.2], \"target\": [0, 0, -0.6]");
  RenderOptions o = options(Level::kGolden, "detail_footprint_ideal");
  o.chips = 4;  // every material compiles, the unused lacquer too
  o.compare_ideal = true;
  const std::string path = o.out_dir + ".json";
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path) << scene;
  std::stringstream log;
  RenderReport r;
  ASSERT_EQ(render_scene(path, o, log, &r), 0) << log.str();
  ASSERT_TRUE(r.compare.has_value());
  EXPECT_LE(r.compare->max_error, 5.5);
  std::cout << "detail.json's cloth with a footprint: golden against ideal " << r.compare->psnr
            << " dB, max " << r.compare->max_error << "\n";
}

// scenes/procedural.json: a procedural material builds its material unit, and the specular
// combine for eq. 5's product with the vertex shade only when it combines with the shade;
// no texture unit (the floor is an ordinary texture).
TEST(RenderTest, ProceduralMaterialsBuildTheMaterialUnitOnly) {
  const RenderReport r = render("procedural.json", options(Level::kGolden, "procedural_units"));
  std::vector<std::string> names;
  for (const UnitReport& u : r.units) names.push_back(u.name);
  using V = std::vector<std::string>;
  EXPECT_EQ(names,
            (V{"trilinear[floor]", "material[wall]", "specular_combine[wall]", "material[marble]",
               "specular_combine[marble]", "material[wood]", "specular_combine[wood]",
               "material[fog]", "material[cloud]", "material[fire]"}));
}

// Golden against the ideal materials (exact noise, sums and index): a colour index moves to
// its neighbouring entry where the ideal index lies within the sums' error (0.089 x g_t
// entries, tests/perlin_materials_test.cpp) of an entry boundary, and the gases' levels by
// the sums' error times their gain: measured 49.9 dB, the bound leaves 2.9 dB.
TEST(RenderTest, ProceduralSceneStaysNearTheIdeal) {
  RenderOptions o = options(Level::kGolden, "procedural_ideal");
  o.compare_ideal = true;
  const RenderReport r = render("procedural.json", o);
  ASSERT_TRUE(r.compare.has_value());
  std::cout << "procedural.json: golden against ideal " << r.compare->psnr << " dB\n";
  EXPECT_GT(r.compare->psnr, kProceduralIdealBound);
}

TEST(RenderTest, RtlMatchesGoldenOnTheDefaultScene) {
  RenderOptions o = options(Level::kRtl, "default_rtl");
  o.check = Level::kGolden;
  const RenderReport r = render("default.json", o);
  ASSERT_TRUE(r.check.has_value());
  EXPECT_EQ(r.check->differing, 0u);
  EXPECT_GT(r.check->compared, 10000u);
}

TEST(RenderTest, TraceReplaysBitForBit) {
  RenderOptions save = options(Level::kGolden, "trace_save");
  save.save_trace = save.out_dir + "/default.trace.csv";
  render("default.json", save);
  RenderOptions replay = options(Level::kRtl, "trace_replay");
  replay.replay_trace = save.save_trace;
  replay.check = Level::kGolden;
  const RenderReport r = render("default.json", replay);
  EXPECT_EQ(r.check->differing, 0u);
  EXPECT_EQ(picture(replay), picture(save));
}

TEST(RenderTest, BandsMergeIntoTheWholeFrame) {
  const RenderOptions whole = options(Level::kGolden, "whole");
  render("default.json", whole);
  std::vector<std::string> bands;
  for (int i = 2; i >= 0; --i) {  // any order
    RenderOptions o = options(Level::kGolden, "band");
    o.tile = i;
    o.tiles = 3;
    render("default.json", o);
    bands.push_back(o.out_dir + "/render.tile-" + std::to_string(i) + "-of-3.png");
  }
  EXPECT_EQ(merge_bands(bands), picture(whole));
  bands.pop_back();  // one band missing
  EXPECT_THROW(merge_bands(bands), InputError);
}

TEST(RenderTest, CheckCatchesAnAlteredResult) {
  RenderOptions o = options(Level::kHls, "altered");
  o.check = Level::kGolden;
  o.inject_fault = 1234;
  const RenderReport r = render("plain.json", o, 1);
  ASSERT_TRUE(r.check.has_value());
  EXPECT_EQ(r.check->differing, 1u);
  EXPECT_TRUE(std::filesystem::exists(o.out_dir + "/render.check-diff.png"));
  EXPECT_NE(r.text().find("MISMATCH: 1 of"), std::string::npos);
}

TEST(RenderTest, CompareIdealReportsPsnr) {
  RenderOptions o = options(Level::kGolden, "compare");
  o.compare_ideal = true;
  const RenderReport r = render("plain.json", o);
  ASSERT_TRUE(r.compare.has_value());
  EXPECT_GT(r.compare->psnr, 40.0);  // golden within about a level of the ideal engine
  EXPECT_TRUE(std::filesystem::exists(o.out_dir + "/render.compare-error.png"));
}

TEST(RenderTest, MaterialTextureErrorsNameTheField) {
  const auto dir = tb::testing::temp_dir("tmu_render_bad");
  write_image((dir / "odd.png").string(), ImageRgb8(37, 21));
  std::ofstream(dir / "bad.json")
      << R"({"camera": {"position": [0, 1, 3], "target": [0, 0, 0], "up": [0, 1, 0],
    "fov": 50, "resolution": [32, 24]}, "materials": {"m": {"texture": {"image": "odd.png"}}},
    "objects": [{"type": "plane", "material": "m"}]})";
  std::stringstream log;
  try {
    render_scene((dir / "bad.json").string(), options(Level::kGolden, "bad"), log);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "materials.m.texture.image");
    EXPECT_NE(std::string(e.what()).find("powers of two"), std::string::npos) << e.what();
  }
}

// Materials on parallel threads (Pipeline::set_jobs, texsim render --jobs): at rtl, every
// fragment's colour and every unit (its name, outputs, output cycles, counters and memory
// requests, in the same order) equal the serial run's. reflect.json's and procedural.json's
// materials each build a chain of several units (procedural: seven materials).
TEST(RenderTest, MaterialsOnParallelThreadsGiveTheSerialRun) {
  for (const char* name : {"reflect.json", "procedural.json"}) {
    SCOPED_TRACE(name);
    const host::Scene scene = host::load_scene(kScenes + name);
    const auto run = [&](int jobs, std::vector<uint32_t>& rgba) {
      auto pipe = std::make_unique<Pipeline>(scene, Level::kRtl);
      pipe->set_jobs(jobs);
      const std::vector<host::Fragment> frags = front_end(scene, *pipe, 0, -1, nullptr);
      std::vector<host::FragmentRecord> records;
      for (const host::Fragment& f : frags) records.push_back(host::quantize(f));
      rgba = pipe->shade(records, &frags, nullptr);
      return pipe;
    };
    std::vector<uint32_t> serial_rgba, parallel_rgba;
    const auto serial = run(1, serial_rgba);
    const auto parallel = run(3, parallel_rgba);
    EXPECT_EQ(parallel_rgba, serial_rgba);
    ASSERT_EQ(parallel->units().size(), serial->units().size());
    for (size_t u = 0; u < serial->units().size(); ++u) {
      const UnitRun &a = serial->units()[u], &b = parallel->units()[u];
      EXPECT_EQ(b.name(), a.name());
      EXPECT_EQ(b.result.outputs, a.result.outputs) << a.name();
      EXPECT_EQ(b.result.output_cycles, a.result.output_cycles) << a.name();
      EXPECT_EQ(b.result.counters, a.result.counters) << a.name();
      EXPECT_EQ(b.result.requests, a.result.requests) << a.name();
    }
    EXPECT_EQ(parallel->host_work(), serial->host_work());
    EXPECT_EQ(parallel->fragments_of_outputs(), serial->fragments_of_outputs());
  }
}

// A frame in bands on parallel threads (render_bands, texsim render --bands): at rtl with a
// check against golden, 3 bands on 3 threads give each band's units (outputs, cycles,
// counters) and image as 3 bands one after another, every band matches golden, and the joined
// frame is the whole frame's render.
TEST(RenderTest, BandsOnParallelThreadsGiveTheSerialRun) {
  const auto run = [&](int jobs, const std::string& out, std::vector<RenderReport>& reps) {
    RenderOptions o = options(Level::kRtl, out);
    o.check = Level::kGolden;
    o.jobs = jobs;
    std::stringstream log;
    EXPECT_EQ(render_bands(kScenes + "default.json", o, 3, log, &reps), 0) << log.str();
    return o;
  };
  std::vector<RenderReport> serial, parallel;
  const RenderOptions a = run(1, "bands_serial", serial), b = run(3, "bands_parallel", parallel);
  ASSERT_EQ(serial.size(), 3u);
  ASSERT_EQ(parallel.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    SCOPED_TRACE("band " + std::to_string(i));
    ASSERT_TRUE(parallel[i].check && parallel[i].check->match());
    EXPECT_GT(parallel[i].check->units_compared, 0u);
    ASSERT_EQ(parallel[i].units.size(), serial[i].units.size());
    for (size_t u = 0; u < serial[i].units.size(); ++u) {
      const UnitReport &x = serial[i].units[u], &y = parallel[i].units[u];
      EXPECT_EQ(y.name, x.name);
      EXPECT_EQ(y.transactions, x.transactions) << x.name;
      EXPECT_EQ(y.cycles, x.cycles) << x.name;
      EXPECT_EQ(y.counters, x.counters) << x.name;
    }
    const std::string band = "/" + band_stem(static_cast<int>(i), 3) + ".png";
    EXPECT_EQ(read_image(b.out_dir + band).pixels, read_image(a.out_dir + band).pixels);
  }
  const RenderOptions whole = options(Level::kGolden, "bands_whole");
  render("default.json", whole);
  EXPECT_EQ(picture(b).pixels, picture(whole).pixels);
  EXPECT_EQ(picture(a).pixels, picture(whole).pixels);
}

TEST(RenderTest, BandsAreForWholeSurfaceFrames) {
  RenderOptions o = options(Level::kGolden, "bands_bad");
  std::stringstream log;
  o.tile = 1;
  o.tiles = 2;
  EXPECT_THROW(render_bands(kScenes + "default.json", o, 2, log), InputError);
  o.tile = 0;
  o.tiles = 1;
  try {
    render_bands(kScenes + "default.json", o, 100000, log);
    ADD_FAILURE() << "more bands than rows accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--bands: 100000 bands for a frame of"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(o.out_dir)) << "nothing written for bad input";
}

}  // namespace
}  // namespace tmu::render
