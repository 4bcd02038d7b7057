#include "scene/scene.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/error.hpp"
#include "scene/json_node.hpp"
#include "scene/scene_parts.hpp"

namespace tmu::host {

Scene parse_scene(const std::string& text, const std::string& name, const std::string& folder) {
  const Json doc = parse_json(text, name);
  const JsonNode root(doc, "", name);
  root.allow_keys({"camera", "background", "lights", "materials", "objects"});
  Scene scene;
  scene.path = name;
  scene.camera = parse_camera(root.at("camera"));
  if (auto bg = root.find("background")) scene.background = bg->colour3(0, 1);
  if (auto lights = root.find("lights")) scene.lights = parse_lights(*lights);
  scene.materials = parse_materials(root.at("materials"), folder);
  scene.objects = parse_objects(root.at("objects"), scene.materials, folder);
  return scene;
}

Scene load_scene(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path, "", "cannot read the scene file");
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  return parse_scene(text.str(), path, folder.empty() ? "." : folder.string());
}

std::string resolve_existing_file(const JsonNode& node, const std::string& folder) {
  namespace fs = std::filesystem;
  const std::string relative = node.string();
  if (relative.empty()) node.fail("empty path");
  fs::path p(relative);
  if (p.is_relative()) p = fs::path(folder) / p;
  std::error_code ec;
  if (!fs::is_regular_file(p, ec)) node.fail("file not found: " + p.string());
  return p.string();
}

}  // namespace tmu::host
