#include "render/effect_chain.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <memory>

#include "blocks/coord_gen/coord_gen_block.hpp"
#include "blocks/cube_address/cube_address_block.hpp"
#include "blocks/deflect/deflect_block.hpp"
#include "blocks/normal_encoder/normal_encoder_block.hpp"
#include "blocks/specular_combine/specular_combine_block.hpp"
#include "blocks/trilinear/trilinear_block.hpp"
#include "deflect/bump_map.hpp"
#include "deflect/coord_tables.hpp"
#include "deflect/cube_ideal.hpp"
#include "deflect/cube_map.hpp"
#include "deflect/deflect_ideal.hpp"
#include "deflect/view_maps.hpp"
#include "formats/formats.hpp"
#include "render/chip_stage.hpp"
#include "texram/trilinear_ideal.hpp"

namespace tmu::render {
namespace {

using deflect::SphereAngle;
using glm::dvec3;
using glm::dvec4;
using texram::chip::PixelParameter;

constexpr int kCoordValueBits = 10;  // the coordinate tables' W (the RTL's)

// Runs units one after the other and keeps each with the fragments of its outputs.
struct Runner {
  const ChainInput& in;
  std::vector<UnitRun>& units;
  std::vector<std::vector<size_t>>& outputs_of;

  std::vector<tb::Txn> run(UnitRun unit, std::vector<size_t> fragments_of_outputs) {
    return run_and_keep(std::move(unit), in.level, std::move(fragments_of_outputs), units,
                        outputs_of);
  }

  // A map read by a trilinear unit at (u, v, lambda) per item, as the addressing reads (u, v);
  // returns RGBA8888 per item.
  std::vector<uint32_t> sample(const std::string& what, const MapTexture& map,
                               const std::vector<std::array<int32_t, 3>>& uvl,
                               std::vector<size_t> fragments_of_outputs,
                               texram::Addressing addressing = texram::Addressing::kTexel) {
    UnitRun unit;
    unit.kind = "trilinear";
    unit.material = in.material.name;
    unit.role = what;
    texram::SamplerConfig config = map.sampler;
    config.addressing = addressing;
    const auto block = std::make_shared<tb::TrilinearBlock>(
        tb::BlockOptions{}, tb::TrilinearEnv{map.texture, config, what});
    attach(unit, block);
    unit.items = block->setup_items();  // the map's configuration (and CLUT)
    for (const auto& [u, v, lambda] : uvl)
      unit.items.push_back(tb::trilinear_sample_item(u, v, lambda));
    std::vector<uint32_t> rgba;
    for (const tb::Txn& t : run(std::move(unit), std::move(fragments_of_outputs)))
      rgba.push_back(static_cast<uint32_t>(t.f[0]));
    return rgba;
  }

  // A sphere map read at each fragment's (uN, vN): the unit's sphere addressing makes them
  // texels.
  std::vector<uint32_t> sample_sphere(const std::string& what, const MapTexture& map,
                                      const std::vector<deflect::MapCoords>& coords) {
    std::vector<std::array<int32_t, 3>> uvl;
    for (const deflect::MapCoords& m : coords) uvl.push_back({m.un, m.vn, 0});
    return sample(what, map, uvl, in.frags, texram::Addressing::kSphere);
  }
};

// A bump texel's angles by the format's definition (deflect/bump_map.hpp), in the ideal's own
// arithmetic: phi = R + 256 (B & 0x7F) nodes modulo 4Q, |theta| = min(G, Q - 1) nodes, negative
// when bit 7 of B is set.
deflect::ideal::Angles ideal_bump_angles(const dvec4& texel) {
  const auto r = static_cast<int64_t>(texel.r), g = static_cast<int64_t>(texel.g),
             b = static_cast<int64_t>(texel.b);
  const auto q = static_cast<int64_t>(kChainGrid.quarter());
  const int64_t phi = (r + 256 * (b & 0x7F)) % (4 * q), mag = std::min(g, q - 1);
  return {static_cast<double>(phi) * kChainGrid.step(),
          static_cast<double>((b & 0x80) ? -mag : mag) * kChainGrid.step()};
}

// The chip's pass over the pixels once their map coordinates are known: each pixel brings the
// parameters of the DRFs that take them, in the chain's order (render/drf_compile.cpp):
// [diffuse at (uN, vN)], the texture at (u, v, lambda) with the vertex shade, [the environment
// at (uN, vN), or a cube face and (u, v) on it from the cube address unit]. The reflectance map
// reads the texture's (u, v, lambda); eq. 5-7 happen in the chip.
std::vector<uint32_t> chip_pass(const ChainInput& in,
                                const std::vector<deflect::MapCoords>& map_coords,
                                std::vector<UnitRun>& units,
                                std::vector<std::vector<size_t>>& outputs_of) {
  const host::Material& mat = in.material;
  const EffectMaps& maps = in.texture.effects;
  const size_t n = in.frags.size();
  std::vector<std::vector<PixelParameter>> params(n);
  for (size_t k = 0; k < n; ++k) {
    const host::FragmentRecord& r = in.records[in.frags[k]];
    const deflect::MapCoords& c = map_coords[k];
    if (maps.diffuse) params[k].push_back({1, {c.un, c.vn, 0, r.shade}});
    params[k].push_back(texture_parameter(mat, r, r.shade));
    if (mat.specular || mat.environment) {
      if (maps.specular || maps.sphere) params[k].push_back({1, {c.un, c.vn, 0, 0}});
    }
  }
  if ((mat.specular || mat.environment) && maps.cube[0]) {
    UnitRun cube;
    cube.kind = "cube_address";
    cube.material = mat.name;
    attach(cube, std::make_shared<tb::CubeAddressBlock>());
    for (const deflect::MapCoords& c : map_coords)
      cube.items.push_back(tb::cube_item(c.ur, c.vr, c.wr, maps.cube[0].log2_side));
    const std::vector<tb::Txn> address =
        run_and_keep(std::move(cube), in.level, in.frags, units, outputs_of);
    for (size_t k = 0; k < n; ++k) {
      PixelParameter p{1,
                       {static_cast<int32_t>(address[k].f[tb::desc::cube_address::out_u]),
                        static_cast<int32_t>(address[k].f[tb::desc::cube_address::out_v]), 0, 0}};
      p.face = static_cast<int>(address[k].f[tb::desc::cube_address::out_face]);
      params[k].push_back(p);
    }
  }
  const size_t pass = maps.bump ? 1 : 0;
  return in.chip->run_pass(in.material_index, pass, std::move(params), in.frags, in.level, units,
                           outputs_of);
}

}  // namespace

std::vector<uint32_t> run_effect_chain(const ChainInput& in, std::vector<UnitRun>& units,
                                       std::vector<std::vector<size_t>>& outputs_of) {
  Runner runner{in, units, outputs_of};
  const host::Material& mat = in.material;
  const EffectMaps& maps = in.texture.effects;
  const std::vector<size_t>& frags = in.frags;
  const size_t n = frags.size();
  const auto record = [&](size_t k) -> const host::FragmentRecord& { return in.records[frags[k]]; };

  // The normal's angles.
  UnitRun encoder;
  encoder.kind = "normal_encoder";
  encoder.material = mat.name;
  attach(encoder, std::make_shared<tb::NormalEncoderBlock>(tb::BlockOptions{}));
  for (size_t k = 0; k < n; ++k) {
    const auto& nrm = record(k).normal;
    encoder.items.push_back(tb::normal_item(nrm[0], nrm[1], nrm[2]));
  }
  std::vector<SphereAngle> normal;
  for (const tb::Txn& t : runner.run(std::move(encoder), frags)) {
    normal.push_back({static_cast<uint32_t>(t.f[tb::desc::normal_encoder::out_phi]),
                      static_cast<uint32_t>(t.f[tb::desc::normal_encoder::out_theta])});
  }

  // The bump: the texel at (u, v) (on a chip its first pass, the emit DRF), then the
  // deflection.
  if (maps.bump) {
    std::vector<uint32_t> texels;
    if (in.chip) {
      std::vector<std::vector<PixelParameter>> params;
      for (size_t k = 0; k < n; ++k) params.push_back({{1, {record(k).u, record(k).v, 0, 0}}});
      in.chip->run_pass(in.material_index, 0, std::move(params), frags, in.level, units, outputs_of,
                        &texels);
    } else {
      std::vector<std::array<int32_t, 3>> uvl;
      for (size_t k = 0; k < n; ++k) uvl.push_back({record(k).u, record(k).v, 0});
      texels = runner.sample("bump", maps.bump, uvl, frags);
    }
    UnitRun deflect;
    deflect.kind = "deflect";
    deflect.material = mat.name;
    attach(deflect, std::make_shared<tb::DeflectBlock>(tb::BlockOptions{}));
    // The map's RGBA8888 texel on the unit's Rgb888 port: wiring, alpha unused.
    for (size_t k = 0; k < n; ++k)
      deflect.items.push_back(tb::deflect_texel_item(normal[k], texels[k] >> 8));
    const std::vector<tb::Txn> out = runner.run(std::move(deflect), frags);
    // The report's MBR hits, misses and bypasses, from the results' access codes.
    for (auto& c : tb::map_access_counters(out)) units.back().result.counters.push_back(c);
    for (size_t k = 0; k < n; ++k) normal[k] = tb::deflect_output(out[k]);
  }

  // The map coordinates, from tables loaded for the camera's view frame.
  UnitRun coords;
  coords.kind = "coord_gen";
  coords.material = mat.name;
  attach(coords, std::make_shared<tb::CoordGenBlock>(tb::BlockOptions{}));
  coords.items = tb::coord_load_items(deflect::CoordTables(
      deflect::TableConfig{kChainGrid, kCoordValueBits}, camera_view_frame(in.scene.camera)));
  for (const SphereAngle& a : normal)
    coords.items.push_back(tb::coord_request_item(a.phi, a.theta));
  std::vector<deflect::MapCoords> map_coords;
  for (const tb::Txn& t : runner.run(std::move(coords), frags))
    map_coords.push_back(tb::coord_gen_output(t));

  if (in.chip) return chip_pass(in, map_coords, units, outputs_of);

  // I_d: the diffuse shading map, or the vertex shade.
  std::vector<uint32_t> shade;
  if (maps.diffuse) {
    shade = runner.sample_sphere("diffuse", maps.diffuse, map_coords);
  } else {
    for (size_t k = 0; k < n; ++k) shade.push_back(record(k).shade);
  }

  // C_d: the texture, eq. 5.
  std::vector<uint32_t> colour;
  for (const tb::Txn& t :
       runner.run(texture_unit(mat, in.texture, in.records, frags, shade), frags))
    colour.push_back(static_cast<uint32_t>(t.f[0]));
  if (!mat.specular && !mat.environment) return colour;

  // E or I_s.
  std::vector<uint32_t> specular;
  if (maps.specular || maps.sphere) {
    specular = runner.sample_sphere(maps.specular ? "specular" : "environment",
                                    maps.specular ? maps.specular : maps.sphere, map_coords);
  } else {
    const int face_log2 = maps.cube[0].log2_side;
    UnitRun cube;
    cube.kind = "cube_address";
    cube.material = mat.name;
    attach(cube, std::make_shared<tb::CubeAddressBlock>());
    for (const deflect::MapCoords& c : map_coords)
      cube.items.push_back(tb::cube_item(c.ur, c.vr, c.wr, face_log2));
    const std::vector<tb::Txn> address = runner.run(std::move(cube), frags);
    // Each face is its own map (000 §7: six environment maps); a face no fragment sees is not
    // read.
    specular.assign(n, 0);
    for (uint32_t face = 0; face < 6; ++face) {
      std::vector<std::array<int32_t, 3>> uvl;
      std::vector<size_t> which, fragments;
      for (size_t k = 0; k < n; ++k) {
        if (address[k].f[tb::desc::cube_address::out_face] != face) continue;
        uvl.push_back({static_cast<int32_t>(address[k].f[tb::desc::cube_address::out_u]),
                       static_cast<int32_t>(address[k].f[tb::desc::cube_address::out_v]), 0});
        which.push_back(k);
        fragments.push_back(frags[k]);
      }
      if (which.empty()) continue;
      const std::vector<uint32_t> e = runner.sample(
          std::string("environment") + kCubeFaceNames[face], maps.cube[face], uvl, fragments);
      for (size_t j = 0; j < which.size(); ++j) specular[which[j]] = e[j];
    }
  }

  // R: the reflectance map at the texture's (u, v, lambda), or the register k_s.
  std::vector<uint32_t> reflectance;
  if (maps.reflectance) {
    std::vector<std::array<int32_t, 3>> uvl;
    for (size_t k = 0; k < n; ++k) uvl.push_back({record(k).u, record(k).v, record(k).lambda});
    reflectance = runner.sample("reflectance", maps.reflectance, uvl, frags);
  } else {
    reflectance.assign(n, reflectance_register(mat.reflectance.constant));
  }

  // C = C_d + R . (E | I_s).
  UnitRun combine;
  combine.kind = "specular_combine";
  combine.material = mat.name;
  attach(combine, std::make_shared<tb::SpecularCombineBlock>());
  for (size_t k = 0; k < n; ++k) {
    combine.items.push_back(tb::specular_combine_item(colour[k], specular[k], reflectance[k]));
  }
  std::vector<uint32_t> out;
  for (const tb::Txn& t : runner.run(std::move(combine), frags))
    out.push_back(static_cast<uint32_t>(t.f[tb::desc::specular_combine::out_colour]));
  return out;
}

std::vector<HostWork> effect_chain_host_work(const host::Material& mat, const EffectMaps& maps,
                                             bool on_chip) {
  std::vector<HostWork> w;
  if (maps.cube[0] && !on_chip) {  // a chip's DRF 7 holds the six faces
    w.push_back({"cube-face dispatch: each sample to its face's trilinear unit",
                 "tmu_cube_address selects the face; the six faces are six maps in six units "
                 "until one TEXRAM memory holds them"});
  }
  if ((mat.specular || mat.environment) && !maps.reflectance) {
    w.push_back({"reflectance register k_s (the scene's constant as RGBA8888)",
                 "a register value the host computes and writes; tmu_specular_combine reads it "
                 "with every pixel"});
  }
  return w;
}

std::vector<dvec4> ideal_effect_chain(const ChainInput& in,
                                      const std::vector<host::Fragment>& fragments) {
  const host::Material& mat = in.material;
  const EffectMaps& maps = in.texture.effects;
  const deflect::ViewFrame view = camera_view_frame(in.scene.camera);
  const auto sample = [](const MapTexture& map, double u, double v, double lambda) {
    const auto s = texram::ideal_sample(*map.ideal, map.sampler, u, v, lambda);
    return dvec4(s[0], s[1], s[2], s[3]);
  };
  const auto sphere_sample = [&](const MapTexture& map, const deflect::ideal::Coords& c) {
    const double side = double(1 << map.log2_side);
    return sample(map, (c.un + 1) / 2 * side, (1 - c.vn) / 2 * side, 0);
  };
  // R: the reflectance map at the texture's (u, v, lambda), through its detail map when it has
  // one (the detail sample's exact rules, texram/detail_ideal).
  const auto reflectance = [&](const host::Fragment& f) {
    const texram::IdealDetailMap* detail = in.texture.ideal_reflectance_detail.get();
    if (!detail) return sample(maps.reflectance, f.uv.x, f.uv.y, f.lambda);
    const auto combine = mat.reflectance.detail->modulate ? texram::DetailCombine::kModulate
                                                          : texram::DetailCombine::kReplace;
    const auto s = texram::ideal_detail_sample(*maps.reflectance.ideal, maps.reflectance.sampler,
                                               *detail, combine, f.uv.x, f.uv.y, f.lambda);
    return dvec4(s[0], s[1], s[2], s[3]);
  };
  texram::SamplerConfig unshaded = mat.sampler;
  if (unshaded.combine == texram::Combine::kShade) unshaded.combine = texram::Combine::kOne;

  std::vector<dvec4> out;
  for (size_t k = 0; k < in.frags.size(); ++k) {
    const host::Fragment& f = fragments[in.frags[k]];
    dvec3 n = glm::normalize(f.normal);
    if (maps.bump) {
      // nearest: a stored texel, the host's encoding of the bump, taken as given
      const dvec4 t = sample(maps.bump, f.uv.x, f.uv.y, 0);
      n = deflect::ideal::deflect(deflect::ideal::to_angles(n), ideal_bump_angles(t));
    }
    const deflect::ideal::Coords c = deflect::ideal::map_coords(view, n);
    dvec4 colour;
    if (maps.diffuse && mat.sampler.combine == texram::Combine::kShade) {
      colour =
          ideal_texture(mat, in.texture, unshaded, f, 0) * sphere_sample(maps.diffuse, c) / 255.0;
    } else {  // the vertex shade, as the record carries it
      colour = ideal_texture(mat, in.texture, mat.sampler, f, in.records[in.frags[k]].shade);
    }
    if (mat.specular || mat.environment) {
      dvec4 e;
      if (maps.specular || maps.sphere) {
        e = sphere_sample(maps.specular ? maps.specular : maps.sphere, c);
      } else {
        const int face_log2 = maps.cube[0].log2_side;
        const deflect::CubeIdeal a = deflect::cube_address_ideal(c.ur, c.vr, c.wr, face_log2);
        e = sample(maps.cube[a.face], a.u, a.v, 0);
      }
      const dvec3 r = maps.reflectance ? dvec3(reflectance(f)) : 255.0 * mat.reflectance.constant;
      for (int ch = 0; ch < 3; ++ch) colour[ch] = std::min(255.0, colour[ch] + e[ch] * r[ch] / 255);
    }
    out.push_back(colour);
  }
  return out;
}

}  // namespace tmu::render
