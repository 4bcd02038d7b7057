#include "volume/volume_scene.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/error.hpp"
#include "scene/json_node.hpp"
#include "scene/scene_parts.hpp"
#include "volume/slabs.hpp"

namespace tmu::host {
namespace {

VolumeData parse_volume_data(const JsonNode& node, const std::string& folder, VolumeFormat format) {
  node.expect_object();
  VolumeData d;
  if (node.has("field") == node.has("file")) node.fail("give one of field and file");
  const JsonNode size = node.at("size");
  size.expect_array();
  if (size.size() != 3) size.fail("expected a list of 3 integers (voxels along x, y, z)");
  for (size_t a = 0; a < 3; ++a) d.size[a] = static_cast<uint32_t>(size[a].integer(2, 512));
  if (const auto f = node.find("file")) {
    node.allow_keys({"file", "size"});
    d.field = VolumeData::Field::kFile;
    d.file = resolve_existing_file(*f, folder);
    const uint64_t bytes_per_voxel = format == VolumeFormat::kRgba ? 4 : 1;
    const uint64_t want = uint64_t{d.size[0]} * d.size[1] * d.size[2] * bytes_per_voxel;
    const uint64_t have = std::filesystem::file_size(d.file);
    if (have != want) {
      f->fail(fmt::format("{} holds {} bytes; {} x {} x {} {} voxels are {} bytes", d.file, have,
                          d.size[0], d.size[1], d.size[2],
                          format == VolumeFormat::kRgba ? "RGBA" : "raw 8-bit", want));
    }
    return d;
  }
  const std::string field = node.at("field").one_of({"marschner_lobb", "sphere", "engine"});
  if (field == "marschner_lobb") {
    node.allow_keys({"field", "size", "f_m", "alpha"});
    d.field = VolumeData::Field::kMarschnerLobb;
    if (const auto f = node.find("f_m")) d.marschner_lobb.f_m = f->positive();
    if (const auto a = node.find("alpha")) d.marschner_lobb.alpha = a->positive();
  } else if (field == "sphere") {
    node.allow_keys({"field", "size", "radius", "slope"});
    d.field = VolumeData::Field::kSphere;
    d.radius = 3.0 / 8 * std::min({d.size[0], d.size[1], d.size[2]});
    if (const auto r = node.find("radius")) d.radius = r->positive();
    if (const auto s = node.find("slope")) d.slope = s->positive();
  } else {
    node.allow_keys({"field", "size", "seed"});
    d.field = VolumeData::Field::kEngine;
    if (const auto s = node.find("seed")) d.seed = static_cast<uint32_t>(s->integer(0, 1 << 30));
  }
  return d;
}

std::vector<TransferPoint> parse_transfer(const JsonNode& node) {
  node.expect_array();
  if (node.size() == 0) node.fail("expected at least one point");
  std::vector<TransferPoint> points;
  for (size_t i = 0; i < node.size(); ++i) {
    const JsonNode p = node[i];
    p.expect_object();
    p.allow_keys({"value", "colour", "opacity"});
    TransferPoint t;
    const JsonNode value = p.at("value");
    t.value = value.number();
    if (t.value < 0 || t.value > 255) value.fail("must be in 0..255 (voxel values)");
    if (!points.empty() && !(t.value > points.back().value)) {
      value.fail(fmt::format("values must increase from point to point ({} after {})", t.value,
                             points.back().value));
    }
    t.colour = p.at("colour").colour3(0, 1);
    const JsonNode opacity = p.at("opacity");
    t.opacity = opacity.number();
    if (t.opacity < 0 || t.opacity > 1) opacity.fail("must be in 0..1 (per voxel of path)");
    points.push_back(t);
  }
  return points;
}

std::optional<Termination> parse_termination(const JsonNode& node) {
  if (node.json().is_boolean()) {
    if (node.json().get<bool>()) return Termination{};
    return std::nullopt;
  }
  if (!node.json().is_object()) node.fail("expected false, true or {\"alpha\": a, \"segment\": n}");
  node.allow_keys({"alpha", "segment"});
  Termination t;
  if (const auto a = node.find("alpha")) {
    t.alpha = a->number();
    if (!(t.alpha > 0 && t.alpha <= 1)) a->fail("must be in (0, 1] (accumulated opacity)");
  }
  if (const auto s = node.find("segment")) t.segment = static_cast<uint32_t>(s->integer(1, 65535));
  return t;
}

}  // namespace

volume::Mode volume_mode(const VolumeScene& scene) {
  return scene.format == VolumeFormat::kRaw ? volume::Mode::kRaw : volume::Mode::kValue;
}

VolumeScene parse_volume_scene(const std::string& text, const std::string& name,
                               const std::string& folder) {
  const Json doc = parse_json(text, name);
  const JsonNode root(doc, "", name);
  root.expect_object();
  root.allow_keys({"volume", "camera", "background", "lights"});
  VolumeScene s;
  s.path = name;
  const JsonNode camera = root.at("camera");
  s.camera = parse_camera(camera);
  for (const char* key : {"near", "far"}) {
    if (camera.has(key))
      camera.at(key).fail("not used by a volume scene: its rays start at the eye");
  }
  if (const auto bg = root.find("background")) s.background = bg->colour3(0, 1);

  const JsonNode v = root.at("volume");
  v.expect_object();
  v.allow_keys({"data", "format", "transfer", "step", "weight_bits", "early_termination", "chips",
                "slab_axis"});
  if (const auto f = v.find("format"))
    s.format = f->one_of({"raw", "rgba"}) == "rgba" ? VolumeFormat::kRgba : VolumeFormat::kRaw;
  s.data = parse_volume_data(v.at("data"), folder, s.format);
  const bool rgba_file =
      s.format == VolumeFormat::kRgba && s.data.field == VolumeData::Field::kFile;
  if (const auto t = v.find("transfer")) {
    if (rgba_file) t->fail("a pre-classified (rgba) file needs no transfer function");
    s.transfer = TransferFunction(parse_transfer(*t));
  } else if (!rgba_file) {
    v.fail(s.format == VolumeFormat::kRaw
               ? "missing required key 'transfer' (raw data is classified by the host)"
               : "missing required key 'transfer' (a generated field is pre-classified with it)");
  }
  if (const auto lights = root.find("lights")) {
    if (s.format == VolumeFormat::kRgba) {
      lights->fail(
          "shading needs the gradient, which the unit returns for raw data only (format raw)");
    }
    s.lights = parse_lights(*lights);
  }
  if (const auto st = v.find("step")) {
    s.step = st->number();
    if (!(s.step >= kMinStep && s.step <= kMaxStep))
      st->fail(fmt::format("must be in {}..{} voxels", kMinStep, kMaxStep));
  }
  if (const auto w = v.find("weight_bits")) s.weight_bits = static_cast<int>(w->integer(1, 8));
  if (const auto t = v.find("early_termination")) s.termination = parse_termination(*t);
  if (const auto a = v.find("slab_axis")) {
    const std::string axis = a->one_of({"x", "y", "z"});
    s.slab_axis = axis[0] - 'x';
  }
  // The slabs (one, the whole volume, without "chips") must fit the chips' banks.
  const auto chips = v.find("chips");
  if (chips) s.chips = static_cast<int>(chips->integer(1, kMaxChips));
  if (const std::string why = slab_problem(s.data.size, s.chips, s.slab_axis, volume_mode(s));
      !why.empty()) {
    if (chips) chips->fail(why);
    v.at("data").at("size").fail(why + " (one chip: give \"chips\")");
  }
  return s;
}

VolumeScene load_volume_scene(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path, "", "cannot read the scene file");
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  return parse_volume_scene(text.str(), path, folder.empty() ? "." : folder.string());
}

bool is_volume_scene(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  try {
    const auto doc = nlohmann::json::parse(text.str());
    return doc.is_object() && doc.contains("volume");
  } catch (const std::exception&) {
    return false;  // the scene parser reports what is wrong
  }
}

}  // namespace tmu::host
