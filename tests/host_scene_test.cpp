// Scene files (scenes/README.md): every kind of mistake is an InputError naming the file, the
// exact field path and the reason; a valid scene gives back every field it sets; the
// transform order; the text pattern the scenes' text textures use.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "ccc/ccc_texture.hpp"
#include "common/error.hpp"
#include "common/image.hpp"
#include "common/test_patterns.hpp"
#include "scene/scene.hpp"

namespace tmu::host {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// A scene every test starts from: valid, without files.
Json base_scene() {
  return Json::parse(R"({
    "camera": {"position": [0, 2, 6], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 50,
               "resolution": [320, 240]},
    "lights": [{"type": "ambient", "colour": [0.25, 0.25, 0.25]}],
    "materials": {
      "floor": {"texture": {"pattern": "checker", "size": [256, 256], "cell": 32}},
      "label": {"texture": {"pattern": "text", "size": [128, 32], "text": "TEXRAM"}}
    },
    "objects": [
      {"type": "plane", "size": [8, 8], "uv_repeat": [4, 4], "material": "floor"},
      {"type": "sphere", "radius": 1, "segments": [16, 8], "material": "label",
       "transform": {"translate": [0, 1, 0]}},
      {"type": "torus", "radius": 1, "tube": 0.25, "segments": [24, 12], "material": "floor"}
    ]
  })");
}

Scene parse(const Json& j, const std::string& folder = ".") {
  return parse_scene(j.dump(2), "test.json", folder);
}

// Parses `j` expecting an InputError at `field` whose reason contains `reason`.
void expect_error(const Json& j, const std::string& field, const std::string& reason,
                  const std::string& folder = ".") {
  try {
    parse(j, folder);
    ADD_FAILURE() << "no error; expected " << field << ": " << reason;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "test.json");
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
  }
}

// A scratch folder removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ =
        fs::temp_directory_path() / ("tmu_host_" + std::to_string(::getpid()) + "_" + info->name());
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }
  std::string str() const { return path_.string(); }

 private:
  fs::path path_;
};

// --- the base scene --------------------------------------------------------------------------

TEST(HostSceneTest, BaseSceneParsesWithDefaults) {
  const Scene s = parse(base_scene());
  EXPECT_EQ(s.path, "test.json");
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0].name, "floor");  // file order, not alphabetical
  EXPECT_EQ(s.materials[1].name, "label");
  const texram::SamplerConfig& c = s.materials[0].sampler;
  EXPECT_EQ(c.kind, texram::TexelKind::kTrueColour);
  EXPECT_EQ(c.filter, texram::Filter::kTrilinear);
  EXPECT_EQ(c.border_u, texram::Border::kWrap);
  EXPECT_EQ(c.border_v, texram::Border::kWrap);
  EXPECT_EQ(c.combine, texram::Combine::kShade);
  EXPECT_EQ(c.border_rgba, 0x000000FFu);
  EXPECT_EQ(c.constant_rgba, 0xFFFFFFFFu);
  EXPECT_EQ(s.materials[0].unit, Material::Unit::kTrilinear);
  EXPECT_EQ(s.materials[0].mipmaps, Material::Mipmaps::kHost);
  EXPECT_EQ(s.camera.near, 0.05);
  EXPECT_EQ(s.camera.far, 1000);
  EXPECT_EQ(s.background, glm::dvec3(0));
  ASSERT_EQ(s.objects.size(), 3u);
  EXPECT_EQ(s.objects[1].material, 1);
  EXPECT_EQ(s.objects[1].transform.scale, glm::dvec3(1));
}

// --- missing and unknown keys ------------------------------------------------------------------

TEST(HostSceneTest, MissingRequiredKeysNameTheirPath) {
  Json j = base_scene();
  j.erase("camera");
  expect_error(j, "camera", "missing required key");
  j = base_scene();
  j["camera"].erase("fov");
  expect_error(j, "camera.fov", "missing required key");
  j = base_scene();
  j["materials"]["floor"].erase("texture");
  expect_error(j, "materials.floor.texture", "missing required key");
  j = base_scene();
  j["objects"][2].erase("material");
  expect_error(j, "objects[2].material", "missing required key");
  j = base_scene();
  j["objects"][0].erase("type");
  expect_error(j, "objects[0].type", "missing required key");
  j = base_scene();
  j["lights"][0].erase("colour");
  expect_error(j, "lights[0].colour", "missing required key");
  j = base_scene();
  j["materials"]["label"]["texture"].erase("text");
  expect_error(j, "materials.label.texture.text", "missing required key");
}

TEST(HostSceneTest, UnknownKeysAreErrorsAtEveryLevel) {
  Json j = base_scene();
  j["cameras"] = 1;
  expect_error(j, "cameras", "unknown key");
  j = base_scene();
  j["camera"]["zoom"] = 2;
  expect_error(j, "camera.zoom", "unknown key");
  j = base_scene();
  j["materials"]["floor"]["shiny"] = true;
  expect_error(j, "materials.floor.shiny", "unknown key");
  j = base_scene();
  j["materials"]["floor"]["texture"]["seed"] = 3;  // not a checker key
  expect_error(j, "materials.floor.texture.seed", "unknown key");
  j = base_scene();
  j["objects"][1]["colour"] = {1, 0, 0};
  expect_error(j, "objects[1].colour", "unknown key");
  j = base_scene();
  j["objects"][0]["radius"] = 1;  // a sphere's key on a plane
  expect_error(j, "objects[0].radius", "unknown key");
  j = base_scene();
  j["objects"][1]["transform"]["skew"] = {0, 0, 0};
  expect_error(j, "objects[1].transform.skew", "unknown key");
  j = base_scene();
  j["lights"][0]["direction"] = {0, -1, 0};  // ambient light has no direction
  expect_error(j, "lights[0].direction", "unknown key");
  j = base_scene();
  j["materials"]["floor"]["border"] = {{"u", "clamp"}, {"w", "wrap"}};
  expect_error(j, "materials.floor.border.w", "unknown key");
}

TEST(HostSceneTest, DuplicateKeyIsAnError) {
  const std::string text = base_scene().dump();
  const std::string dup = text.substr(0, text.size() - 1) + R"(,"camera":{}})";
  try {
    parse_scene(dup, "test.json", ".");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "camera");
    EXPECT_NE(e.reason().find("duplicate"), std::string::npos);
  }
  const std::string inner = R"({"camera": {"position": [0, 0, 1], "position": [0, 0, 2]}})";
  try {
    parse_scene(inner, "test.json", ".");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "camera.position");
  }
}

// --- types and ranges --------------------------------------------------------------------------

TEST(HostSceneTest, WrongTypesNameTheField) {
  Json j = base_scene();
  j["camera"]["fov"] = "50";
  expect_error(j, "camera.fov", "expected a number");
  j = base_scene();
  j["camera"]["position"] = {0, "a", 0};
  expect_error(j, "camera.position[1]", "expected a number");
  j = base_scene();
  j["camera"]["target"] = {0, 0};
  expect_error(j, "camera.target", "expected a list of 3 numbers");
  j = base_scene();
  j["objects"] = Json::object();
  expect_error(j, "objects", "expected a list");
  j = base_scene();
  j["materials"] = Json::array();
  expect_error(j, "materials", "expected an object");
  j = base_scene();
  j["camera"]["resolution"] = {320.5, 240};
  expect_error(j, "camera.resolution[0]", "expected an integer");
  j = base_scene();
  j["materials"]["floor"]["filter"] = 2;
  expect_error(j, "materials.floor.filter", "expected a string");
  j = base_scene();
  j["materials"]["floor"]["border"] = 1;
  expect_error(j, "materials.floor.border", "expected a border mode");
  j = base_scene();
  j["objects"][1]["transform"] = {1, 2, 3};
  expect_error(j, "objects[1].transform", "expected an object");
}

TEST(HostSceneTest, OutOfRangeValuesNameTheField) {
  Json j = base_scene();
  j["camera"]["fov"] = 0;
  expect_error(j, "camera.fov", "(0, 180)");
  j["camera"]["fov"] = 180;
  expect_error(j, "camera.fov", "(0, 180)");
  j = base_scene();
  j["camera"]["resolution"] = {0, 240};
  expect_error(j, "camera.resolution[0]", "1..4096");
  j["camera"]["resolution"] = {320, 5000};
  expect_error(j, "camera.resolution[1]", "1..4096");
  j = base_scene();
  j["camera"]["near"] = 0;
  expect_error(j, "camera.near", "> 0");
  j = base_scene();
  j["camera"]["near"] = 2;
  j["camera"]["far"] = 1;
  expect_error(j, "camera.far", "greater than near");
  j = base_scene();
  j["camera"]["up"] = {0, 2, 6};  // parallel to target - position
  expect_error(j, "camera.up", "parallel");
  j = base_scene();
  j["camera"]["target"] = {0, 2, 6};
  expect_error(j, "camera.target", "equals the camera position");
  j = base_scene();
  j["objects"][1]["radius"] = -1;
  expect_error(j, "objects[1].radius", "> 0");
  j = base_scene();
  j["objects"][1]["segments"] = {2, 8};
  expect_error(j, "objects[1].segments[0]", "3..");
  j["objects"][1]["segments"] = {3, 1};
  expect_error(j, "objects[1].segments[1]", "2..");
  j = base_scene();
  j["objects"][2]["segments"] = {24, 2};  // a torus tube needs 3
  expect_error(j, "objects[2].segments[1]", "3..");
  j = base_scene();
  j["objects"][0]["size"] = {8, 0};
  expect_error(j, "objects[0].size[1]", "> 0");
  j = base_scene();
  j["objects"][1]["transform"]["scale"] = {1, 0, 1};
  expect_error(j, "objects[1].transform.scale[1]", "must not be 0");
  j = base_scene();
  j["background"] = {0, 1.5, 0};
  expect_error(j, "background[1]", "0..1");
  j = base_scene();
  j["lights"][0]["colour"] = {0, -1, 0};
  expect_error(j, "lights[0].colour[1]", ">= 0");
  j = base_scene();
  j["materials"]["floor"]["border_colour"] = {0, 0, 0, 2};
  expect_error(j, "materials.floor.border_colour[3]", "0..1");
  j = base_scene();
  j["materials"]["floor"]["texture"]["size"] = {256, 100};  // not a power of two
  expect_error(j, "materials.floor.texture.size", "powers of two");
  j["materials"]["floor"]["texture"]["size"] = {2048, 256};  // beyond the TEXRAM
  expect_error(j, "materials.floor.texture.size", "powers of two up to 1024");
  j = base_scene();
  j["materials"]["floor"]["texture"]["cell"] = 0;
  expect_error(j, "materials.floor.texture.cell", "1..");
}

TEST(HostSceneTest, NamesMustExist) {
  Json j = base_scene();
  j["objects"][2]["material"] = "marble";
  expect_error(j, "objects[2].material", "unknown material 'marble'");
  j = base_scene();
  j["materials"]["floor"]["texture"]["pattern"] = "plaid";
  expect_error(j, "materials.floor.texture.pattern", "unknown value 'plaid'");
  j = base_scene();
  j["objects"][0]["type"] = "cone";
  expect_error(j, "objects[0].type", "unknown value 'cone'");
  j = base_scene();
  j["lights"][0]["type"] = "spot";
  expect_error(j, "lights[0].type", "unknown value 'spot'");
  j = base_scene();
  j["materials"]["floor"]["border"] = {{"u", "clamp"}, {"v", "repeat"}};
  expect_error(j, "materials.floor.border.v", "unknown value 'repeat'");
  j = base_scene();
  j["materials"]["floor"]["config"] = "palette";
  expect_error(j, "materials.floor.config", "unknown value");
}

TEST(HostSceneTest, MaterialRulesNameTheField) {
  Json j = base_scene();
  j["materials"]["floor"]["texture"] = Json::object();
  expect_error(j, "materials.floor.texture", "needs one of");
  j["materials"]["floor"]["texture"] = {{"pattern", "noise"}, {"image", "a.png"}};
  expect_error(j, "materials.floor.texture", "more than one");
  j = base_scene();
  j["materials"]["floor"]["channel"] = "g";  // config is rgba
  expect_error(j, "materials.floor.channel", "only applies to config single");
  j = base_scene();
  j["materials"]["floor"]["unit"] = "lowcost";  // needs ccc
  expect_error(j, "materials.floor.unit", "needs config ccc");
  j = base_scene();
  j["materials"]["floor"]["config"] = "index";
  j["materials"]["floor"]["mipmaps"] = "mipgen";
  expect_error(j, "materials.floor.mipmaps", "mipmap generator");
  j = base_scene();
  Json many = Json::object();
  for (int i = 0; i < 257; ++i) many[fmt::format("m{}", i)] = j["materials"]["floor"];
  j["materials"] = many;
  expect_error(j, "materials", "at most 256");
}

TEST(HostSceneTest, FootprintParsesWithDefaultsAndChecksItsFields) {
  Json j = base_scene();
  j["materials"]["label"]["footprint"] = Json::object();
  Scene s = parse(j);
  ASSERT_TRUE(s.materials[1].footprint.has_value());
  EXPECT_EQ(s.materials[1].footprint->log2_max_probes, 3);  // 8 probes
  EXPECT_EQ(s.materials[1].footprint->q_rule, footprint::QRule::kHeights);
  EXPECT_FALSE(s.materials[0].footprint.has_value());
  j["materials"]["label"]["footprint"] = {{"max_probes", 16}, {"q", "sides"}};
  s = parse(j);
  EXPECT_EQ(s.materials[1].footprint->log2_max_probes, 4);
  EXPECT_EQ(s.materials[1].footprint->q_rule, footprint::QRule::kSides);
  j["materials"]["label"]["footprint"] = {{"max_probes", 6}};
  expect_error(j, "materials.label.footprint.max_probes", "must be 1, 2, 4, 8 or 16");
  j["materials"]["label"]["footprint"] = {{"max_probes", 32}};
  expect_error(j, "materials.label.footprint.max_probes", "");
  j["materials"]["label"]["footprint"] = {{"q", "diagonals"}};
  expect_error(j, "materials.label.footprint.q", "heights");
  j["materials"]["label"]["footprint"] = {{"probes", 4}};
  expect_error(j, "materials.label.footprint.probes", "unknown key");
  j["materials"]["label"]["footprint"] = 8;
  expect_error(j, "materials.label.footprint", "");
}

TEST(HostSceneTest, DetailKeysParseWithDefaults) {
  Json j = base_scene();
  j["materials"]["floor"]["detail"] = {{"map", {{"pattern", "noise"}}}};
  j["materials"]["label"]["detail"] = {
      {"map", {{"pattern", "smooth"}, {"size", {256, 16}}}},
      {"offsets", {{"u", {{"pattern", "noise"}}}, {"v", {{"pattern", "gradient"}}}}},
      {"combine", "replace"},
      {"config", "rgba"}};
  j["materials"]["label"]["environment"] = {{"map", "sphere"}};
  j["materials"]["label"]["reflectance"] = {{"map", {{"pattern", "noise"}}},
                                            {"detail", {{"map", {{"pattern", "checker"}}}}}};
  const Scene s = parse(j);
  const Material& floor = s.materials[0];
  ASSERT_TRUE(floor.detail);
  EXPECT_TRUE(floor.has_detail());
  EXPECT_EQ(floor.detail->map.width, 64);  // a pattern's default: four regions a side
  EXPECT_EQ(floor.detail->map.height, 64);
  EXPECT_EQ(floor.detail->kind, texram::TexelKind::kLuminance);
  EXPECT_EQ(floor.detail->offsets, Detail::Offsets::kTiled);
  EXPECT_TRUE(floor.detail->modulate);
  EXPECT_FALSE(floor.reflectance.detail);
  const Material& label = s.materials[1];
  ASSERT_TRUE(label.detail);
  EXPECT_EQ(label.detail->map.width, 256);
  EXPECT_EQ(label.detail->map.height, 16);
  EXPECT_EQ(label.detail->kind, texram::TexelKind::kTrueColour);
  EXPECT_FALSE(label.detail->modulate);
  EXPECT_EQ(label.detail->offsets, Detail::Offsets::kImages);
  EXPECT_EQ(label.detail->offset_u.width, 128);  // the texture's size
  EXPECT_EQ(label.detail->offset_v.height, 32);
  ASSERT_TRUE(label.reflectance.detail);
  EXPECT_EQ(label.reflectance.detail->map.pattern, "checker");
}

TEST(HostSceneTest, DetailKeyErrorsNameTheFieldAndTheReason) {
  const auto with = [](const Json& detail) {
    Json j = base_scene();
    j["materials"]["label"]["detail"] = detail;
    return j;
  };
  const std::string at = "materials.label.detail";
  expect_error(with(Json::object()), at + ".map", "missing required key");
  expect_error(with(8), at, "expected an object");
  expect_error(with({{"map", {{"pattern", "noise"}}}, {"scale", 2}}), at + ".scale", "unknown key");
  expect_error(with({{"map", {{"pattern", "noise"}, {"size", {8, 8}}}}}), at + ".map.size",
               "powers of two from 16 (one region) to 256");
  expect_error(with({{"map", {{"pattern", "noise"}, {"size", {512, 16}}}}}), at + ".map.size",
               "it is 512x16");
  expect_error(with({{"map", {{"pattern", "noise"}, {"size", {48, 16}}}}}), at + ".map.size",
               "powers of two");
  expect_error(with({{"map", {{"pattern", "noise"}}}, {"combine", "add"}}), at + ".combine",
               "modulate");
  expect_error(with({{"map", {{"pattern", "noise"}}}, {"config", "index"}}), at + ".config",
               "luminance");
  expect_error(with({{"map", {{"pattern", "noise"}}}, {"offsets", "random"}}), at + ".offsets",
               "tiled");
  expect_error(
      with({{"map", {{"pattern", "noise"}}}, {"offsets", {{"u", {{"pattern", "noise"}}}}}}),
      at + ".offsets.v", "missing required key");
  expect_error(
      with({{"map", {{"pattern", "noise"}}},
            {"offsets",
             {{"u", {{"pattern", "noise"}, {"size", {64, 64}}}}, {"v", {{"pattern", "noise"}}}}}}),
      at + ".offsets.u.size", "128x32 (it is 64x64)");
  expect_error(with({{"map", {{"pattern", "noise"}}}, {"offsets", {{"w", 1}}}}), at + ".offsets.w",
               "unknown key");
  // Materials the chip cannot take: no other unit samples a detail map.
  Json j = with({{"map", {{"pattern", "noise"}}}});
  j["materials"]["label"]["mipmaps"] = "mipgen";
  expect_error(j, at, "mipmap generator");
  j = with({{"map", {{"pattern", "noise"}}}});
  j["materials"]["label"]["config"] = "ccc";
  j["materials"]["label"]["unit"] = "lowcost";
  expect_error(j, at, "not unit lowcost");
  // A reflectance's detail needs a reflectance map.
  j = base_scene();
  j["materials"]["label"]["environment"] = {{"map", "sphere"}};
  j["materials"]["label"]["reflectance"] = {{"detail", {{"map", {{"pattern", "noise"}}}}}};
  expect_error(j, "materials.label.reflectance.map", "missing required key");
  j["materials"]["label"]["reflectance"] = {
      {"map", {{"pattern", "noise"}}}, {"detail", {{"map", {{"pattern", "noise"}, {"size", 4}}}}}};
  expect_error(j, "materials.label.reflectance.detail.map.size", "expected a list");
}

TEST(HostSceneTest, DeflectionEffectsParseWithDefaults) {
  Json j = base_scene();
  j["materials"]["floor"]["bump"] = {{"heights", {{"pattern", "smooth"}}}, {"depth", 3}};
  j["materials"]["floor"]["specular"] = {{"colour", {0.5, 0.5, 0.5}}, {"exponent", 40}};
  j["materials"]["floor"]["reflectance"] = {{"map", {{"pattern", "noise"}}}};
  j["materials"]["label"]["environment"] = {{"map", "cube"}, {"size", 256}};
  j["materials"]["label"]["reflectance"] = 0.25;
  const Scene s = parse(j);
  const Material& floor = s.materials[0];
  ASSERT_TRUE(floor.bump);
  EXPECT_EQ(floor.bump->depth, 3);
  // A height field read at the texture's (u, v) takes the texture's size.
  EXPECT_EQ(floor.bump->heights.width, 256);
  EXPECT_EQ(floor.bump->heights.height, 256);
  EXPECT_EQ(floor.shading, Material::Shading::kMaps);  // a bump needs per-pixel shading
  EXPECT_EQ(floor.shading_map_size, 128);
  ASSERT_TRUE(floor.specular);
  EXPECT_EQ(floor.specular->exponent, 40);
  EXPECT_EQ(floor.specular->colour, glm::dvec3(0.5));
  ASSERT_TRUE(floor.reflectance.map);
  EXPECT_EQ(floor.reflectance.map->width, 256);
  EXPECT_TRUE(floor.uses_normal());
  const Material& label = s.materials[1];
  EXPECT_EQ(label.shading, Material::Shading::kVertex);
  ASSERT_TRUE(label.environment);
  EXPECT_EQ(label.environment->kind, Environment::Kind::kCube);
  EXPECT_EQ(label.environment->size, 256);
  EXPECT_EQ(label.reflectance.constant, glm::dvec3(0.25));
  EXPECT_TRUE(label.uses_normal());
  EXPECT_FALSE(parse(base_scene()).materials[0].uses_normal());  // no effect, no chain
}

TEST(HostSceneTest, DeflectionEffectRulesNameTheField) {
  const auto with = [](const char* key, const Json& value) {
    Json j = base_scene();
    j["materials"]["label"][key] = value;
    return j;
  };
  const Json smooth = {{"pattern", "smooth"}};
  expect_error(with("bump", {{"depth", 2}}), "materials.label.bump.heights", "missing");
  expect_error(with("bump", {{"heights", smooth}, {"depth", 100}}), "materials.label.bump.depth",
               "0..64");
  expect_error(with("bump", {{"heights", {{"pattern", "smooth"}, {"size", {64, 64}}}}}),
               "materials.label.bump.heights", "the texture's size 128x32");
  Json j = with("bump", {{"heights", smooth}});
  j["materials"]["label"]["shading"] = "vertex";
  expect_error(j, "materials.label.shading", "per-pixel shading");
  expect_error(with("shading", "phong"), "materials.label.shading", "vertex");
  expect_error(with("shading_map_size", 256), "materials.label.shading_map_size",
               "only applies to shading");
  j = with("shading", "maps");
  j["materials"]["label"]["shading_map_size"] = 300;
  expect_error(j, "materials.label.shading_map_size", "must be 128, 256, 512 or 1024");
  j["materials"]["label"]["shading_map_size"] = 64;
  expect_error(j, "materials.label.shading_map_size", "");
  expect_error(with("specular", {{"exponent", 0}}), "materials.label.specular.exponent", "1..1000");
  j = with("specular", Json::object());
  j["materials"]["label"]["environment"] = Json::object();
  expect_error(j, "materials.label.specular", "either the environment E or the specular term");
  expect_error(with("reflectance", 0.5), "materials.label.reflectance",
               "needs a specular term or an environment map");
  j = with("environment", {{"map", "sphere"}});
  j["materials"]["label"]["reflectance"] = 1.5;
  expect_error(j, "materials.label.reflectance", "0..1");
  j["materials"]["label"]["reflectance"] = {{"map", {{"pattern", "noise"}, {"size", {32, 32}}}}};
  expect_error(j, "materials.label.reflectance.map", "the texture's size");
  expect_error(with("environment", {{"map", "dome"}}), "materials.label.environment.map", "sphere");
  expect_error(with("environment", {{"size", 100}}), "materials.label.environment.size", "");
  expect_error(with("environment", {{"map", "cube"}, {"image", "x.png"}}),
               "materials.label.environment.image", "rendered from the room");
  expect_error(with("environment", {{"image", "missing.png"}}), "materials.label.environment.image",
               "file not found");
}

TEST(HostSceneTest, ProceduralMaterialsParseWithDefaults) {
  Json j = base_scene();
  j["materials"]["label"] = {
      {"procedural",
       {{"material", "brick"}, {"scale", 4}, {"brick", {0.5, 0.25}}, {"mortar", {0.02, 0.03}}}}};
  j["materials"]["floor"] = {{"procedural", {{"material", "fire"}, {"offset", -10}}},
                             {"combine", "one"}};
  const Scene s = parse(j);
  const Material& brick = s.materials[1];
  ASSERT_TRUE(brick.procedural);
  EXPECT_EQ(brick.procedural->kind, perlin::MaterialKind::kBrick);
  EXPECT_EQ(brick.solid_scale, 4);
  EXPECT_EQ(brick.procedural->brick, glm::dvec2(0.5, 0.25));
  EXPECT_EQ(brick.procedural->mortar, glm::dvec2(0.02, 0.03));
  EXPECT_FALSE(brick.procedural->colours.empty());  // the material's default stops
  EXPECT_EQ(brick.sampler.combine, texram::Combine::kShade);
  const Material& fire = s.materials[0];
  EXPECT_EQ(fire.procedural->kind, perlin::MaterialKind::kFire);
  EXPECT_EQ(fire.procedural->offset, -10);
  EXPECT_EQ(fire.sampler.combine, texram::Combine::kOne);
  EXPECT_EQ(fire.solid_scale, 1);
}

TEST(HostSceneTest, ProceduralRulesNameTheField) {
  const auto with = [](const Json& procedural) {
    Json j = base_scene();
    j["materials"]["label"] = {{"procedural", procedural}};
    return j;
  };
  expect_error(with({{"scale", 2}}), "materials.label.procedural.material", "missing");
  expect_error(with({{"material", "granite"}}), "materials.label.procedural.material", "marble");
  expect_error(with({{"material", "marble"}, {"rings", 3}}), "materials.label.procedural.rings",
               "not a key of the marble material");
  expect_error(with({{"material", "fog"}, {"colours", Json::array()}}),
               "materials.label.procedural.colours", "not a key of the fog material");
  expect_error(with({{"material", "marble"}, {"scale", 0}}), "materials.label.procedural.scale",
               "above 0");
  expect_error(with({{"material", "wood"}, {"slope", 200}}), "materials.label.procedural.slope",
               "-128..");
  expect_error(with({{"material", "cloud"}, {"cutoff", 3}}), "materials.label.procedural.cutoff",
               "-2..");
  expect_error(with({{"material", "brick"}, {"brick", {0.3, 0.5}}}),
               "materials.label.procedural.brick[0]", "power of two");
  expect_error(with({{"material", "brick"}, {"brick", {0.0625, 0.5}}}),
               "materials.label.procedural.brick", "leaves no brick");
  expect_error(with({{"material", "brick"}, {"mortar", {0.6, 0.01}}}),
               "materials.label.procedural.mortar[0]", "half the brick period");
  expect_error(with({{"material", "marble"}, {"colours", {{0.5, {1, 0, 0}}, {0.2, {0, 0, 1}}}}}),
               "materials.label.procedural.colours[1][0]", "increasing");
  expect_error(with({{"material", "marble"}, {"colours", {{1.5, {1, 0, 0}}}}}),
               "materials.label.procedural.colours[0][0]", "0..1");
  Json j = with({{"material", "marble"}});
  j["materials"]["label"]["texture"] = {{"pattern", "checker"}};
  expect_error(j, "materials.label.texture", "unknown key");
}

TEST(HostSceneTest, SyntaxErrorNamesLineAndColumn) {
  const std::string text = "{\n  \"camera\": {\n    \"fov\": 50,,\n  }\n}\n";
  try {
    parse_scene(text, "broken.json", ".");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "broken.json");
    EXPECT_EQ(e.field().rfind("line 3, column ", 0), 0u) << e.what();
    EXPECT_NE(e.reason().find("syntax error"), std::string::npos) << e.what();
  }
  try {
    parse_scene("", "empty.json", ".");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field().rfind("line 1, column ", 0), 0u) << e.what();
  }
}

// Found with the fuzz targets' checks (docs/robustness.md): a number beyond a double names its
// field; a vector too long or too short to normalize (the sum of squares overflows or
// underflows) is an error, not a NaN view matrix or light.
TEST(HostSceneTest, HugeNumbersNameTheField) {
  for (const auto& [text, field] :
       {std::pair<std::string, std::string>{R"({"camera": {"position": [0, 1e999, 0]}})",
                                            "camera.position[1]"},
        {R"({"camera": {"fov": -1e999}})", "camera.fov"}}) {
    try {
      parse_scene(text, "big.json", ".");
      ADD_FAILURE() << "no error for " << text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "big.json");
      EXPECT_EQ(e.field(), field) << e.what();
      EXPECT_NE(e.reason().find("number overflow"), std::string::npos) << e.what();
    }
  }
  Json j = base_scene();
  j["camera"]["position"] = {-1e308, 0, 0};
  j["camera"]["target"] = {1e308, 0, 0};
  expect_error(j, "camera.target", "too near to or too far");
  j = base_scene();
  j["camera"]["position"] = {0, 0, 1e200};
  expect_error(j, "camera.target", "too near to or too far");
  j = base_scene();
  j["camera"]["up"] = {0, 1e300, 0};
  expect_error(j, "camera.up", "too short or too long");
  j = base_scene();
  j["lights"] =
      Json::parse(R"([{"type": "directional", "direction": [1e300, 0, 0], "colour": [1, 1, 1]}])");
  expect_error(j, "lights[0].direction", "too short or too long");
  j = base_scene();
  j["camera"]["up"] = {0, 1e-160, 0};
  expect_error(j, "camera.up", "too short or too long");
  j = base_scene();
  j["camera"]["position"] = {0, 0, 1e-170};
  expect_error(j, "camera.target", "too near to or too far");
  j = base_scene();
  j["camera"]["up"] = {0, 1e-100, 0};  // short, but it normalizes
  EXPECT_EQ(parse(j).camera.up, glm::dvec3(0, 1e-100, 0));
}

// --- files -----------------------------------------------------------------------------------

TEST(HostSceneTest, MissingFilesAreResolvedAgainstTheSceneFolder) {
  const TempDir dir;
  Json j = base_scene();
  j["materials"]["photo"] = {{"texture", {{"image", "images/missing.png"}}}};
  expect_error(j, "materials.photo.texture.image",
               "file not found: " + (fs::path(dir.str()) / "images/missing.png").string(),
               dir.str());
  j = base_scene();
  j["objects"][0] = {{"type", "mesh"}, {"file", "models/none.obj"}, {"material", "floor"}};
  expect_error(j, "objects[0].file", "file not found", dir.str());
  j = base_scene();
  j["objects"][0] = {{"type", "mesh"}, {"material", "floor"}};
  expect_error(j, "objects[0].file", "missing required key", dir.str());
}

TEST(HostSceneTest, ImageSidesAreChecked) {
  const TempDir dir;
  write_image(dir / "odd.png", patterns::gradient(48, 32));
  Json j = base_scene();
  j["materials"]["photo"] = {{"texture", {{"image", "odd.png"}}}};
  expect_error(j, "materials.photo.texture.image", "powers of two", dir.str());
}

TEST(HostSceneTest, LoadSceneReportsAnUnreadableFile) {
  try {
    load_scene("/nonexistent/scene.json");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "/nonexistent/scene.json");
  }
}

// Every field a scene can set, from a file on disk with textures and a mesh beside it.
TEST(HostSceneTest, ValidSceneRoundTripsAllFields) {
  const TempDir dir;
  fs::create_directories(dir / "images");
  write_image(dir / "images/photo.png", patterns::gradient(64, 32));
  ccc::Texture cccx;
  cccx.width = 16;
  cccx.height = 8;
  cccx.blocks.assign(8, 0x01020304u);
  ccc::write_ccc(dir / "tiles.ccc", cccx);
  {
    std::ofstream obj(dir / "tri.obj");
    obj << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  }
  const Json j = Json::parse(R"({
    "camera": {"position": [1, 2, 3], "target": [0, 0.5, -1], "up": [0, 0, 1], "fov": 35.5,
               "resolution": [640, 480], "near": 0.5, "far": 80},
    "background": [0.05, 0.1, 1],
    "lights": [
      {"type": "ambient", "colour": [0.25, 0.5, 0.75]},
      {"type": "directional", "direction": [-1, -2, -1], "colour": [0.8, 0.8, 2]},
      {"type": "point", "position": [2, 3, 2], "colour": [1, 1, 1]}
    ],
    "materials": {
      "photo": {"texture": {"image": "images/photo.png"}, "config": "single", "channel": "b",
                "filter": "bilinear", "border": {"u": "clamp", "v": "mirror"},
                "border_colour": [0.2, 0.4, 0.6, 0.5], "combine": "constant",
                "constant": [1, 0.5, 0, 1], "mipmaps": "mipgen"},
      "tiles": {"texture": {"ccc": "tiles.ccc"}, "unit": "lowcost", "filter": "nearest",
                "border": "border", "combine": "one"},
      "words": {"texture": {"pattern": "text", "size": [64, 16], "text": "Hi!",
                            "colours": [[1, 0, 0], [0, 0, 1]]}, "config": "luminance"},
      "noise": {"texture": {"pattern": "noise", "size": [32, 1024], "seed": 4000000000}}
    },
    "objects": [
      {"type": "plane", "size": [8, 4], "uv_repeat": [4, 2], "material": "words"},
      {"type": "box", "size": [1, 2, 3], "material": "photo",
       "transform": {"translate": [0, 0.5, 0], "rotate": [10, 30, 45], "scale": [1, -2, 3]}},
      {"type": "sphere", "radius": 0.5, "segments": [12, 6], "material": "tiles"},
      {"type": "torus", "radius": 2, "tube": 0.5, "segments": [5, 3], "material": "noise"},
      {"type": "mesh", "file": "tri.obj", "uv_repeat": [2, 2], "material": "photo"}
    ]
  })");
  {
    std::ofstream out(dir / "scene.json");
    out << j.dump(2);
  }
  const Scene s = load_scene(dir / "scene.json");
  EXPECT_EQ(s.path, dir / "scene.json");
  EXPECT_EQ(s.camera.position, glm::dvec3(1, 2, 3));
  EXPECT_EQ(s.camera.target, glm::dvec3(0, 0.5, -1));
  EXPECT_EQ(s.camera.up, glm::dvec3(0, 0, 1));
  EXPECT_EQ(s.camera.fov_deg, 35.5);
  EXPECT_EQ(s.camera.width, 640);
  EXPECT_EQ(s.camera.height, 480);
  EXPECT_EQ(s.camera.near, 0.5);
  EXPECT_EQ(s.camera.far, 80);
  EXPECT_EQ(s.background, glm::dvec3(0.05, 0.1, 1));

  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_EQ(s.lights[0].kind, Light::Kind::kAmbient);
  EXPECT_EQ(s.lights[0].colour, glm::dvec3(0.25, 0.5, 0.75));
  EXPECT_EQ(s.lights[1].kind, Light::Kind::kDirectional);
  EXPECT_EQ(s.lights[1].vector, glm::dvec3(-1, -2, -1));
  EXPECT_EQ(s.lights[1].colour, glm::dvec3(0.8, 0.8, 2));
  EXPECT_EQ(s.lights[2].kind, Light::Kind::kPoint);
  EXPECT_EQ(s.lights[2].vector, glm::dvec3(2, 3, 2));

  ASSERT_EQ(s.materials.size(), 4u);
  const Material& photo = s.materials[0];
  EXPECT_EQ(photo.name, "photo");
  EXPECT_EQ(photo.texture.kind, TextureSource::Kind::kImage);
  EXPECT_EQ(photo.texture.path, (fs::path(dir.str()) / "images/photo.png").string());
  EXPECT_EQ(photo.texture.width, 64);
  EXPECT_EQ(photo.texture.height, 32);
  EXPECT_EQ(photo.sampler.kind, texram::TexelKind::kSingle);
  EXPECT_EQ(photo.sampler.single_channel, 2);
  EXPECT_EQ(photo.sampler.filter, texram::Filter::kBilinear);
  EXPECT_EQ(photo.sampler.border_u, texram::Border::kClamp);
  EXPECT_EQ(photo.sampler.border_v, texram::Border::kMirror);
  // round(255 x): 51, 102, 153, and 127.5 to the even 128.
  EXPECT_EQ(photo.sampler.border_rgba, texram::rgba(51, 102, 153, 128));
  EXPECT_EQ(photo.sampler.combine, texram::Combine::kConstant);
  EXPECT_EQ(photo.sampler.constant_rgba, texram::rgba(255, 128, 0, 255));
  EXPECT_EQ(photo.unit, Material::Unit::kTrilinear);
  EXPECT_EQ(photo.mipmaps, Material::Mipmaps::kMipgen);

  const Material& tiles = s.materials[1];
  EXPECT_EQ(tiles.texture.kind, TextureSource::Kind::kCcc);
  EXPECT_EQ(tiles.texture.path, (fs::path(dir.str()) / "tiles.ccc").string());
  EXPECT_EQ(tiles.texture.width, 16);
  EXPECT_EQ(tiles.texture.height, 8);
  EXPECT_EQ(tiles.sampler.kind, texram::TexelKind::kCcc);  // the default for a .ccc file
  EXPECT_EQ(tiles.unit, Material::Unit::kLowcost);
  EXPECT_EQ(tiles.sampler.filter, texram::Filter::kNearest);
  EXPECT_EQ(tiles.sampler.border_u, texram::Border::kBorder);
  EXPECT_EQ(tiles.sampler.border_v, texram::Border::kBorder);
  EXPECT_EQ(tiles.sampler.combine, texram::Combine::kOne);

  const Material& words = s.materials[2];
  EXPECT_EQ(words.texture.kind, TextureSource::Kind::kPattern);
  EXPECT_EQ(words.texture.pattern, "text");
  EXPECT_EQ(words.texture.text, "Hi!");
  EXPECT_EQ(words.texture.width, 64);
  EXPECT_EQ(words.texture.height, 16);
  ASSERT_EQ(words.texture.colours.size(), 2u);
  EXPECT_EQ(words.texture.colours[0], glm::dvec3(1, 0, 0));
  EXPECT_EQ(words.texture.colours[1], glm::dvec3(0, 0, 1));
  EXPECT_EQ(words.sampler.kind, texram::TexelKind::kLuminance);

  const Material& noise = s.materials[3];
  EXPECT_EQ(noise.texture.pattern, "noise");
  EXPECT_EQ(noise.texture.seed, 4000000000u);
  EXPECT_EQ(noise.texture.width, 32);
  EXPECT_EQ(noise.texture.height, 1024);

  ASSERT_EQ(s.objects.size(), 5u);
  EXPECT_EQ(s.objects[0].shape, Object::Shape::kPlane);
  EXPECT_EQ(s.objects[0].size.x, 8);
  EXPECT_EQ(s.objects[0].size.z, 4);
  EXPECT_EQ(s.objects[0].uv_repeat, glm::dvec2(4, 2));
  EXPECT_EQ(s.objects[0].material, 2);
  EXPECT_EQ(s.objects[1].shape, Object::Shape::kBox);
  EXPECT_EQ(s.objects[1].size, glm::dvec3(1, 2, 3));
  EXPECT_EQ(s.objects[1].transform.translate, glm::dvec3(0, 0.5, 0));
  EXPECT_EQ(s.objects[1].transform.rotate_deg, glm::dvec3(10, 30, 45));
  EXPECT_EQ(s.objects[1].transform.scale, glm::dvec3(1, -2, 3));
  EXPECT_EQ(s.objects[1].material, 0);
  EXPECT_EQ(s.objects[2].shape, Object::Shape::kSphere);
  EXPECT_EQ(s.objects[2].radius, 0.5);
  EXPECT_EQ(s.objects[2].segments, glm::ivec2(12, 6));
  EXPECT_EQ(s.objects[2].material, 1);
  EXPECT_EQ(s.objects[3].shape, Object::Shape::kTorus);
  EXPECT_EQ(s.objects[3].radius, 2);
  EXPECT_EQ(s.objects[3].tube, 0.5);
  EXPECT_EQ(s.objects[3].segments, glm::ivec2(5, 3));
  EXPECT_EQ(s.objects[3].material, 3);
  EXPECT_EQ(s.objects[4].shape, Object::Shape::kMesh);
  EXPECT_EQ(s.objects[4].file, (fs::path(dir.str()) / "tri.obj").string());
  EXPECT_EQ(s.objects[4].uv_repeat, glm::dvec2(2, 2));
}

TEST(HostSceneTest, CccTextureKeepsConfigCcc) {
  const TempDir dir;
  ccc::Texture t;
  t.width = t.height = 8;
  t.blocks.assign(4, 0);
  ccc::write_ccc(dir / "t.ccc", t);
  Json j = base_scene();
  j["materials"]["c"] = {{"texture", {{"ccc", "t.ccc"}}}, {"config", "rgba"}};
  expect_error(j, "materials.c.config", "ccc", dir.str());
  j["materials"]["c"]["config"] = "ccc";
  EXPECT_EQ(parse(j, dir.str()).materials[2].sampler.kind, texram::TexelKind::kCcc);
  // An image may be given the CCC configuration (encoded by the renderer).
  j["materials"]["floor"]["config"] = "ccc";
  EXPECT_EQ(parse(j, dir.str()).materials[0].sampler.kind, texram::TexelKind::kCcc);
  // The low-cost unit has no eq. 5 stage and no linked maps: no deflection chain behind it.
  j["materials"]["c"]["unit"] = "lowcost";
  j["materials"]["c"]["environment"] = Json::object();
  expect_error(j, "materials.c", "need the TEXRAM", dir.str());
}

// --- transform ---------------------------------------------------------------------------------

TEST(HostSceneTest, TransformScalesThenRotatesXYZThenTranslates) {
  Transform t;
  t.scale = {2, 3, 4};
  t.rotate_deg = {30, 45, 60};
  t.translate = {1, -2, 5};
  const auto rot = [](double deg, int axis) {
    const double c = std::cos(glm::radians(deg)), s = std::sin(glm::radians(deg));
    glm::dmat3 r(1.0);  // column-major: r[column][row]
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    r[a][a] = c;
    r[b][b] = c;
    r[a][b] = s;
    r[b][a] = -s;
    return r;
  };
  const glm::dvec3 p(0.3, -0.7, 1.1);
  glm::dvec3 expected = p * t.scale;
  expected = rot(30, 0) * expected;
  expected = rot(45, 1) * expected;
  expected = rot(60, 2) * expected;
  expected += t.translate;
  const glm::dvec3 got(t.matrix() * glm::dvec4(p, 1));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], expected[i], 1e-12) << i;
  // A right-handed rotation: +90 degrees about Z takes +X to +Y.
  Transform z;
  z.rotate_deg = {0, 0, 90};
  const glm::dvec3 y(z.matrix() * glm::dvec4(1, 0, 0, 1));
  EXPECT_NEAR(y.x, 0, 1e-15);
  EXPECT_NEAR(y.y, 1, 1e-15);
}

// --- the text pattern ---------------------------------------------------------------------------

TEST(HostTextPatternTest, DrawsGlyphsScaledToTheHeight) {
  const Rgb8 ink{255, 0, 0}, paper{0, 0, 255};
  // Height 18: two pixels per dot, glyph rows 2..15 (one dot of margin above and below).
  const ImageRgb8 img = patterns::text(24, 18, "T", ink, paper);
  ASSERT_EQ(img.width, 24);
  ASSERT_EQ(img.height, 18);
  for (int x = 0; x < 24; ++x) {
    EXPECT_EQ(img.at(x, 0), paper);
    EXPECT_EQ(img.at(x, 1), paper);
    EXPECT_EQ(img.at(x, 16), paper);
    EXPECT_EQ(img.at(x, 17), paper);
  }
  // The bar of the T: dots 0..4 of row 0 -> pixels 0..9 of rows 2 and 3.
  for (int x = 0; x < 10; ++x) EXPECT_EQ(img.at(x, 2), ink) << x;
  EXPECT_EQ(img.at(10, 2), paper);  // the space between glyphs
  // The stem: dot 2 -> pixels 4, 5 on rows 4..15.
  for (int y = 4; y < 16; ++y) {
    EXPECT_EQ(img.at(4, y), ink);
    EXPECT_EQ(img.at(5, y), ink);
    EXPECT_EQ(img.at(3, y), paper);
  }
  // "T " repeats every 12 dots = 24 pixels; the next T would start at x = 24.
  for (int x = 12; x < 24; ++x) EXPECT_EQ(img.at(x, 2), paper) << x;
}

TEST(HostTextPatternTest, LowercaseUnknownAndRepetition) {
  const Rgb8 ink{0, 0, 0}, paper{255, 255, 255};
  EXPECT_EQ(patterns::text(100, 9, "texram", ink, paper),
            patterns::text(100, 9, "TEXRAM", ink, paper));
  // An unknown character is a box: the outline of 5 x 7 dots.
  const ImageRgb8 box = patterns::text(6, 9, "~", ink, paper);
  for (int x = 0; x < 5; ++x) {
    EXPECT_EQ(box.at(x, 1), ink);
    EXPECT_EQ(box.at(x, 7), ink);
  }
  for (int y = 1; y < 8; ++y) {
    EXPECT_EQ(box.at(0, y), ink);
    EXPECT_EQ(box.at(4, y), ink);
  }
  EXPECT_EQ(box.at(2, 4), paper);
  // "AB" + space is 18 dots wide: the image repeats with that period.
  const ImageRgb8 rep = patterns::text(54, 9, "AB", ink, paper);
  for (int y = 0; y < 9; ++y) {
    for (int x = 0; x < 36; ++x) EXPECT_EQ(rep.at(x, y), rep.at(x + 18, y));
  }
  // Digits and punctuation are in the font (not boxes).
  EXPECT_NE(patterns::text(6, 9, "0", ink, paper), box);
  EXPECT_NE(patterns::text(6, 9, ".", ink, paper), box);
}

}  // namespace
}  // namespace tmu::host
