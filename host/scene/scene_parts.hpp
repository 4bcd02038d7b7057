// The parts of a scene file, each parsed and checked by its own function (scene.cpp puts them
// together). Every function throws InputError naming the file, the field path and the reason.
#pragma once

#include <string>
#include <vector>

#include "scene/json_node.hpp"
#include "scene/scene.hpp"

namespace tmu::host {

Camera parse_camera(const JsonNode& node);
std::vector<Light> parse_lights(const JsonNode& node);
// `folder` resolves texture paths.
std::vector<Material> parse_materials(const JsonNode& node, const std::string& folder);
// `folder` resolves mesh paths; material names index `materials`.
std::vector<Object> parse_objects(const JsonNode& node, const std::vector<Material>& materials,
                                  const std::string& folder);
Transform parse_transform(const JsonNode& node);
// A texture source: {"image": path} | {"ccc": path} | {"pattern": name, ...}.
TextureSource parse_texture(const JsonNode& node, const std::string& folder);
// The material keys of the deflection chain (shading, shading_map_size, bump, specular,
// environment, reflectance) into `material`, whose texture is already parsed.
void parse_effects(const JsonNode& node, const std::string& folder, Material& material);
// "detail": {...} of a map of `texture_size` (the material's texture or reflectance map).
Detail parse_detail(const JsonNode& node, const std::string& folder, glm::ivec2 texture_size);
// "video": {...} of a material (scene/video.cpp).
Video parse_video(const JsonNode& node, const std::string& folder);
// A "nurbs" object's keys (surface or patches, tessellation) into `object`.
void parse_nurbs_object(const JsonNode& node, Object& object);
// The material keys "tau", "order" and "lod" (004) into `material`.
void parse_tau(const JsonNode& node, Material& material);
// "procedural": {...} into `material` (its scale into solid_scale).
void parse_procedural(const JsonNode& node, Material& material);

// `relative` against `folder` (absolute paths are kept); the file must exist, else `node`
// fails with "file not found: <resolved path>".
std::string resolve_existing_file(const JsonNode& node, const std::string& folder);

}  // namespace tmu::host
