#include "render/effect_maps.hpp"

#include <bit>
#include <glm/geometric.hpp>

#include "common/error.hpp"
#include "deflect/bump_map.hpp"
#include "deflect/view_maps.hpp"
#include "formats/formats.hpp"
#include "render/texture_source.hpp"

namespace tmu::render {
namespace {

using glm::dvec3;

dvec3 vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

dvec3 to_view(const deflect::ViewFrame& f, const dvec3& world) {
  return {glm::dot(world, vec(f.side)), glm::dot(world, vec(f.up)), glm::dot(world, vec(f.dir))};
}

// What the shading maps know of the lights: directions from the scene's centre of interest
// (the camera target), seen from far away.
std::vector<deflect::MapLight> map_lights(const host::Scene& scene, const deflect::ViewFrame& f) {
  std::vector<deflect::MapLight> out;
  for (const host::Light& l : scene.lights) {
    deflect::MapLight m;
    m.colour = l.colour;
    m.ambient = l.kind == host::Light::Kind::kAmbient;
    if (l.kind == host::Light::Kind::kDirectional) m.towards = -glm::normalize(l.vector);
    if (l.kind == host::Light::Kind::kPoint)
      m.towards = glm::normalize(l.vector - scene.camera.target);
    if (!m.ambient) m.towards = to_view(f, m.towards);
    out.push_back(m);
  }
  if (out.empty()) out.push_back({true, dvec3(0, 0, 1), dvec3(1)});  // no lights: unlit, as I_d = 1
  return out;
}

texram::SamplerConfig map_sampler(texram::Filter filter, texram::Border border) {
  texram::SamplerConfig s;
  s.kind = texram::TexelKind::kTrueColour;
  s.filter = filter;
  s.border_u = s.border_v = border;
  s.combine = texram::Combine::kOne;
  return s;
}

MapTexture map_texture(const ImageRgb8& image, const texram::SamplerConfig& sampler) {
  MapTexture m;
  m.texture = std::make_shared<const texram::TexramTexture>(
      texram::import_image(image, texram::TexelKind::kTrueColour));
  m.ideal = std::make_shared<const texram::IdealTexture>(texram::ideal_texture(m.texture->source));
  m.sampler = sampler;
  m.log2_side = std::countr_zero(static_cast<unsigned>(image.width));
  return m;
}

}  // namespace

deflect::ViewFrame camera_view_frame(const host::Camera& camera) {
  const dvec3 dir = glm::normalize(camera.position - camera.target);
  const dvec3 side = glm::normalize(glm::cross(camera.up, dir));
  const dvec3 up = glm::cross(dir, side);
  return {{side.x, side.y, side.z}, {up.x, up.y, up.z}, {dir.x, dir.y, dir.z}};
}

EffectMaps build_effect_maps(const host::Scene& scene, const host::Material& mat) {
  EffectMaps e;
  const deflect::ViewFrame view = camera_view_frame(scene.camera);
  const auto bilinear_clamp = map_sampler(texram::Filter::kBilinear, texram::Border::kClamp);
  std::string field = "materials." + mat.name;
  try {
    if (mat.bump) {
      field += ".bump.heights";
      const ImageRgb8 heights = source_image(mat.bump->heights);
      texram::SamplerConfig s = map_sampler(texram::Filter::kNearest, mat.sampler.border_u);
      s.border_v = mat.sampler.border_v;
      e.bump = map_texture(deflect::bump_map_from_heights(heights, mat.bump->depth, kChainGrid), s);
    }
    if (mat.shading == host::Material::Shading::kMaps) {
      const std::vector<deflect::MapLight> lights = map_lights(scene, view);
      e.diffuse = map_texture(deflect::diffuse_map(mat.shading_map_size, lights), bilinear_clamp);
      if (mat.specular) {
        e.specular =
            map_texture(deflect::specular_map(mat.shading_map_size, lights, mat.specular->colour,
                                              mat.specular->exponent),
                        bilinear_clamp);
      }
    }
    if (mat.environment) {
      field = "materials." + mat.name + ".environment";
      // The room is in world space; the maps hold it in the view frame.
      const deflect::Environment room = [&](const dvec3& v) {
        return deflect::sky_room(v.x * vec(view.side) + v.y * vec(view.up) + v.z * vec(view.dir));
      };
      const int side = mat.environment->size;
      if (mat.environment->kind == host::Environment::Kind::kCube) {
        const auto faces = deflect::cube_environment(std::countr_zero(unsigned(side)), room);
        for (size_t f = 0; f < 6; ++f) e.cube[f] = map_texture(faces[f], bilinear_clamp);
      } else if (!mat.environment->image.empty()) {
        const ImageRgb8 ball = read_image(mat.environment->image);
        if (ball.width != ball.height || !std::has_single_bit(unsigned(ball.width)) ||
            ball.width < 128 || ball.width > 1024) {
          throw InputError(mat.environment->image, "",
                           "a sphere map is square, 128 to 1024 texels, a power of two");
        }
        e.sphere = map_texture(ball, bilinear_clamp);
      } else {
        e.sphere = map_texture(deflect::sphere_environment(side, room), bilinear_clamp);
      }
    }
    if (mat.reflectance.map) {
      field = "materials." + mat.name + ".reflectance.map";
      texram::SamplerConfig s = mat.sampler;
      s.kind = texram::TexelKind::kTrueColour;
      s.combine = texram::Combine::kOne;
      e.reflectance = map_texture(source_image(*mat.reflectance.map), s);
    }
  } catch (const InputError& err) {
    throw InputError(scene.path, field, err.what());
  }
  return e;
}

uint32_t reflectance_register(const glm::dvec3& k) {
  const auto ch = [](double v) {
    return static_cast<uint32_t>(formats::Channel::from_double(255.0 * v).raw());
  };
  return texram::rgba(ch(k.r), ch(k.g), ch(k.b), 255);
}

}  // namespace tmu::render
