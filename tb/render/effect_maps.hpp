// The maps a material's deflection chain reads (scenes/README.md "bump and reflection"), built
// by the host when the pipeline is made: the bump map from the height field, the shading maps
// from the scene's lights, the environment (sphere map or six cube faces) and the reflectance
// map, each a TEXRAM texture with the sampler the chain reads it with. Only what the material
// names is built.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "deflect/coord_tables.hpp"
#include "deflect/sphere_grid.hpp"
#include "scene/scene.hpp"
#include "texram/sampler_config.hpp"
#include "texram/texture.hpp"
#include "texram/trilinear_ideal.hpp"

namespace tmu::render {

// The sphere grid of the chain's units: the RTL's (A = 9, 512 x 256).
inline constexpr deflect::SphereGrid kChainGrid{9};

struct MapTexture {
  std::shared_ptr<const texram::TexramTexture> texture;
  std::shared_ptr<const texram::IdealTexture> ideal;  // its source, exactly (the ideal chain)
  texram::SamplerConfig sampler;
  int log2_side = 0;  // sphere maps and cube faces (square)
  explicit operator bool() const { return texture != nullptr; }
};

// The cube faces' names in EffectMaps::cube's order, for labels.
inline constexpr const char* kCubeFaceNames[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};

struct EffectMaps {
  MapTexture bump;                 // nearest, the material's borders
  MapTexture diffuse, specular;    // shading maps: bilinear, clamp
  MapTexture sphere;               // spherical environment
  std::array<MapTexture, 6> cube;  // +X, -X, +Y, -Y, +Z, -Z
  MapTexture reflectance;          // the material's filter and borders
};

// The view frame of the scene's camera in world space (the fragments' normals are world
// space): v_dir from the target to the eye, v_side = up x v_dir normalised, v_up = v_dir x v_side.
deflect::ViewFrame camera_view_frame(const host::Camera& camera);

// The register k_s of eq. 6 (R without a reflectance map) as RGBA8888.
uint32_t reflectance_register(const glm::dvec3& k);

// Throws InputError (scene file, the material's field, reason) for an unreadable image.
EffectMaps build_effect_maps(const host::Scene& scene, const host::Material& material);

}  // namespace tmu::render
