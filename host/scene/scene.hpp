// A scene as scenes/README.md documents it: camera, lights, materials, objects. load_scene()
// checks every key and reports the first problem with the file, the field path and the reason.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "footprint/footprint.hpp"
#include "nurbs/patch.hpp"
#include "nurbs/tau_map.hpp"
#include "perlin/colour_table.hpp"
#include "perlin/materials.hpp"
#include "texram/sampler_config.hpp"

namespace tmu::host {

struct Camera {
  glm::dvec3 position{0, 0, 5}, target{0, 0, 0}, up{0, 1, 0};
  double fov_deg = 50;
  int width = 320, height = 240;
  double near = 0.05, far = 1000;
};

struct Light {
  enum class Kind { kAmbient, kDirectional, kPoint };
  Kind kind = Kind::kAmbient;
  glm::dvec3 vector{0};  // directional: the direction it shines towards; point: its position
  glm::dvec3 colour{1};
};

struct TextureSource {
  enum class Kind { kImage, kCcc, kPattern };
  Kind kind = Kind::kPattern;
  std::string path;     // kImage, kCcc: resolved against the scene file's folder
  std::string pattern;  // checker, text, gradient, noise, smooth, default
  int width = 256, height = 256;
  int cell = 32;                    // checker
  std::string text;                 // text
  std::vector<glm::dvec3> colours;  // checker, text: 0..1
  uint32_t seed = 1;                // noise, smooth
};

// The bump map (001 §4.2): a height field's luminance (0..1) times `depth` texels, turned into
// bump texels (golden/deflect/bump_map.hpp) the size of the material's texture.
struct Bump {
  TextureSource heights;
  double depth = 2;
};

// The specular term of 001 eq. 10, k_spec (R . L)^n per light, held in the specular shading map.
struct Specular {
  glm::dvec3 colour{1};  // k_spec per channel
  double exponent = 20;  // n_s
};

// The environment map: 001's spherical map (a mirror ball in the view frame, read at (uN, vN))
// or 000 §7's cube (six faces, read at the reflection vector (uR, vR, wR)). Without an image
// the host renders its built-in room into the map.
struct Environment {
  enum class Kind { kSphere, kCube };
  Kind kind = Kind::kSphere;
  int size = 128;     // the sphere map's side or each cube face's, a power of two
  std::string image;  // sphere only: a mirror-ball picture, resolved path; empty: the room
};

// A detail map (000 §9, docs/detail.md) of a texture or reflectance map: below level 0 the map
// continues into `map`'s levels -1..-4, each level-0 texel pointing at a 16 x 16 region of it
// through two offset maps. Only the TEXRAM chip samples it (texsim render --chips N).
struct Detail {
  TextureSource map;                                       // sides powers of two, 16..256
  texram::TexelKind kind = texram::TexelKind::kLuminance;  // "config": luminance or rgba
  // The regions: kTiled, texel (x, y) at (16 x mod 256, 16 y mod 256) (a detail map seamless
  // across its regions then reads as one image); kImages, the offset maps' luminance
  // (offset_u, offset_v: the textured map's size).
  enum class Offsets { kTiled, kImages };
  Offsets offsets = Offsets::kTiled;
  TextureSource offset_u, offset_v;
  bool modulate = true;  // "combine": modulate (default) or replace
};

// A video map (000 §11-12, docs/video.md): the material's texture changes every frame. Frame k of
// the source goes through the video port, the mipmap generator and the page-row buffers into one
// of two buffers of a chip's memory; a chip-side swap of the DRF's base shows it (texsim render
// --chips N --frames A:B). Only the chip samples it.
struct Video {
  enum class Source { kGenerated, kFiles };
  Source source = Source::kGenerated;
  std::string pattern;  // kGenerated: "bars", "rings" or "noise" (render/video_pattern)
  std::string files;    // kFiles: the resolved path with one %d or %0Nd for the frame number
  int width = 64, height = 64;  // level-0 texels, powers of two up to 512
  bool interlaced = false;      // field 1 (even lines) then field 2 (odd lines)
  int planes = 4;               // 1 (luminance) or 4 (R G B A, as a material's default rgba)
  int frames = 1;               // frames 0 .. frames - 1
  double fps = 30;              // the port's rate: width x height x fps texels a second
};
// The file of frame `k` of a kFiles video (its pattern with the number put in).
std::string video_file(const Video& video, int k);

// R of 000 eq. 6-7: the register k_s, or a reflectance map k_s(u, v) read at the texture's
// (u, v), optionally with its own detail map.
struct Reflectance {
  glm::dvec3 constant{1};
  std::optional<TextureSource> map;
  std::optional<Detail> detail;
};

// A procedural material (002 §4.2): the material unit computes the colour from the solid
// texture coordinates (scenes/README.md "procedural"); physical values here, the host turns
// them into the unit's registers and colour tables.
struct Procedural {
  perlin::MaterialKind kind = perlin::MaterialKind::kMarble;
  std::vector<perlin::ColourStop> colours, mortar_colours;
  double turbulence = 32;         // g_t: colour entries per unit of turbulence / fractal sum
  double stripes = 8;             // marble g_v: entries per unit of v
  double rings = 16;              // wood g_r: entries per unit of u^2 + v^2
  double slope = 2;               // wood g_w: entries per unit of w
  double offset = 64;             // fire: index offset, entries
  double gain = 255;              // fog, cloud g_l: 8-bit levels per unit of the fractal sum
  double cutoff = 0;              // cloud
  glm::dvec2 brick{1, 0.5};       // brick period (W + 2 M_W, H + 2 M_H): powers of two
  glm::dvec2 mortar{0.05, 0.05};  // M_W, M_H
};

struct Material {
  std::string name;
  TextureSource texture;
  texram::SamplerConfig sampler;  // kind (config), channel, filter, borders, colours, combine
  enum class Unit { kTrilinear, kLowcost };
  Unit unit = Unit::kTrilinear;
  enum class Mipmaps { kHost, kMipgen };
  Mipmaps mipmaps = Mipmaps::kHost;
  // Footprint assembly (000 §10) in front of the trilinear unit; absent: isotropic sampling.
  std::optional<footprint::Config> footprint;
  std::optional<Detail> detail;  // the texture's detail map
  std::optional<Video> video;    // instead of "texture": a map that changes every frame
  // Per-pixel shading (001 §2.3, §5): the diffuse shading map (and the specular one) read at
  // the coordinates the (bump-deflected) normal gives, instead of the vertex shade I_d.
  enum class Shading { kVertex, kMaps };
  Shading shading = Shading::kVertex;
  int shading_map_size = 128;  // a power of two, 128..1024
  std::optional<Bump> bump;
  std::optional<Specular> specular;
  std::optional<Environment> environment;
  Reflectance reflectance;  // applies to the specular map or the environment
  // Procedural: no texture; the solid coordinates are the object-space position times
  // solid_scale.
  std::optional<Procedural> procedural;
  double solid_scale = 1;
  // The tau mapping of 004 (parameter to texture coordinates) and what a triangle
  // interpolates (claims 15-18); without a tau, the mesh's uv are the texture coordinates.
  std::optional<nurbs::TauMap> tau;
  enum class Order {
    kPc,        // claim 15: (s, t) per pixel, the tau unit maps them (hardware, per pixel)
    kTc,        // claim 16: tau at the vertices, (u, v) interpolated
    kTexture,   // claim 17: the texture colour at the vertices, interpolated
    kComposed,  // claim 18: texture and object colour composed at the vertices, interpolated
  };
  Order order = Order::kTc;
  // The mip level: per pixel from the derivatives, or per patch from the TC criteria (claim 12).
  enum class Lod { kPixel, kTc };
  Lod lod = Lod::kPixel;
  // The deflection chain (normal encoder, coordinate generator, ...) is built for this material.
  bool has_detail() const { return detail || reflectance.detail; }
  bool uses_normal() const { return shading == Shading::kMaps || environment.has_value(); }
};

struct Transform {
  glm::dvec3 translate{0}, rotate_deg{0}, scale{1};
  glm::dmat4 matrix() const;  // scale, then rotate X, Y, Z, then translate
};

// How finely a NURBS object is tessellated (004 claims 7-11): step lengths in MC (modelling
// units), DC (pixels) and TC (texels of level 0); the steps from MC and DC (the larger count
// when both are given) and from TC are combined by `combine` (claim 11's averaging g) and
// capped at max_steps per patch and direction. Without any threshold, dc = 4.
struct Tessellation {
  std::optional<double> mc, dc, tc;
  enum class Combine { kMean, kGeometric, kMax };
  Combine combine = Combine::kMean;
  int max_steps = 64;
};

struct Object {
  enum class Shape { kPlane, kBox, kSphere, kTorus, kMesh, kNurbs };
  Shape shape = Shape::kPlane;
  glm::dvec3 size{1};  // plane: x, z (size.y unused); box: x, y, z
  glm::dvec2 uv_repeat{1, 1};
  double radius = 1, tube = 0.25;
  glm::ivec2 segments{32, 16};
  std::string file;  // mesh: resolved OBJ path
  // nurbs: the patches in modelling coordinates; their knot domains are the object's parameter
  // coordinates (PC), normalised to [0, 1] over the rectangle that holds them all.
  std::vector<nurbs::Patch> patches;
  Tessellation tessellation;
  Transform transform;
  int material = 0;  // index into Scene::materials
};

struct Scene {
  std::string path;  // the file it came from
  Camera camera;
  glm::dvec3 background{0};
  std::vector<Light> lights;
  std::vector<Material> materials;  // in the order the file names them
  std::vector<Object> objects;
};

// Throws InputError(file, field path, reason) on the first problem.
Scene load_scene(const std::string& path);
// The same from text (for tests and fuzzing); `name` stands for the file in messages and
// `folder` resolves relative paths.
Scene parse_scene(const std::string& text, const std::string& name, const std::string& folder);

}  // namespace tmu::host
