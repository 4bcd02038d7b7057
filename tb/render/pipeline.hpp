// A scene's texture pipeline: every material's texture, and every fragment through the chain
// of units its material names. Built from the scene, so a material that does not use a unit
// never makes one:
//   mipmaps "host"   : host pyramid                 -> trilinear (or lowcost)
//   mipmaps "mipgen" : mipgen unit fills the banks  -> trilinear
//   unit "lowcost"   : the CCC low-cost unit, ccc_cache_bilinear (bilinear at level 0), then
//                      eq. 5 on the host
//   "footprint"      : the footprint unit (000 §10): N trilinear probes per fragment, averaged;
//                      it holds its own trilinear unit (host or mipgen pyramid as above)
//   shading maps, "bump", "environment": the deflection chain (render/effect_chain.hpp)
//   "procedural"     : the material unit (render/procedural_chain.hpp), no texture
//   order "pc"       : the tau unit (render/tau_stage.hpp) in front of trilinear or footprint
// With chips (render/chip_stage.hpp) a material's maps are sampled by a TEXRAM chip instead of
// its trilinear, footprint and combine units; the mipgen units then write the chip's memory.
#pragma once

#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "ccc/ccc_texture.hpp"
#include "geometry/mesh.hpp"
#include "raster/fragment.hpp"
#include "raster/rasterizer.hpp"
#include "render/effect_maps.hpp"
#include "render/units.hpp"
#include "render/video_feed.hpp"
#include "scene/scene.hpp"
#include "texram/detail.hpp"
#include "texram/detail_ideal.hpp"
#include "texram/texture.hpp"
#include "texram/trilinear_ideal.hpp"

namespace tmu::render {

struct MaterialTexture {
  std::shared_ptr<const texram::TexramTexture> texram;  // the trilinear unit's banks
  std::shared_ptr<const texram::IdealTexture> ideal;    // its source, exactly (ideal renders)
  std::shared_ptr<const ccc::Texture> ccc;              // the low-cost unit's level 0
  glm::ivec2 size{1, 1};                                // level-0 texels
  EffectMaps effects;                                   // what the deflection chain reads
  // The detail maps of the texture and of the reflectance map (render/detail_maps), which only
  // the chip samples (its offsets and detail DRFs, render/drf_compile).
  std::shared_ptr<const texram::DetailMap> detail, reflectance_detail;
  // The same for the ideal renderer (Level::kIdeal), from the sources.
  std::shared_ptr<const texram::IdealDetailMap> ideal_detail, ideal_reflectance_detail;
  // texram holds the host pyramid until the mipmap generator writes the banks, which it does
  // for the material's first fragments (Pipeline::shade).
  bool mipgen_pending = false;
  // A video map (render/video_feed): its two buffers as they stand for this frame; texram is
  // then the front buffer. Only the chip samples it (drf_compile places both buffers).
  std::shared_ptr<const VideoBuffers> video;
};

// The unit that samples a material's texture (trilinear, or footprint in front of it; not the
// low-cost unit) for the fragments `frags` of `records`, with I_d = shades[k] for frags[k].
// `role` names what it samples for (UnitRun::role; "" for the material's fragments).
UnitRun texture_unit(const host::Material& material, const MaterialTexture& texture,
                     const std::vector<host::FragmentRecord>& records,
                     const std::vector<size_t>& frags, const std::vector<uint32_t>& shades,
                     const std::string& role = "");

// Orders texture and composed (004 claims 17, 18): the material samples its texture at the
// vertices (Pipeline::colour_vertices), and its fragments carry the interpolated colours.
bool samples_at_vertices(const host::Material& material);
bool samples_at_vertices_anywhere(const host::Scene& scene);

// The ideal model of texture_unit for one fragment, with `sampler` (the material's, or a copy).
glm::dvec4 ideal_texture(const host::Material& material, const MaterialTexture& texture,
                         const texram::SamplerConfig& sampler, const host::Fragment& fragment,
                         uint32_t shade);

// An ideal colour (0..255 per channel) rounded and clamped to RGBA8888.
uint32_t rgba_of(const glm::dvec4& colour);

// Called with (units done, fragments textured so far, fragments in all).
using Progress = std::function<void(uint64_t done, uint64_t total)>;

class ChipStage;

class Pipeline {
 public:
  // Loads every material's texture. A mipgen chain's mipgen unit runs (at `level`) when its
  // material's first fragments are shaded, so a material without any builds none; ideal builds
  // no unit and samples each texture's source through its own exact pyramid
  // (texram/trilinear_ideal.hpp). Throws InputError naming the scene and the material's
  // texture field.
  // With chips > 0 (not ideal), the materials whose maps a TEXRAM chip can sample go through
  // `chips` chips (render/chip_stage.hpp); the others through their separate units as with 0.
  // A material with a video takes its buffers from `video` (render/video_feed: the frame's), or
  // cells 0 without one; it needs chips (InputError naming materials.M.video otherwise).
  Pipeline(const host::Scene& scene, Level level, int chips = 0, const VideoState* video = nullptr);

  Level level() const { return level_; }
  // How many materials shade() runs at once, each on its own thread with its own engines
  // (default 1). An hls run stays serial: each SystemC run is a forked child.
  void set_jobs(int jobs) { jobs_ = level_ == Level::kHls ? 1 : jobs; }
  const ChipStage* chips() const { return chips_.get(); }  // null without chips
  const std::vector<MaterialTexture>& textures() const { return textures_; }
  std::vector<glm::ivec2> texture_sizes() const;
  // What the rasterizer scales each material's uv by: its texture size, or for an order-pc
  // material 256 times its tau grid's cells (render/tau_stage.hpp).
  std::vector<glm::ivec2> uv_scales() const;

  // Orders texture and composed: each vertex colour of the objects whose material samples at
  // the vertices (render/vertex_colours.cpp), through the material's texture unit (kept in
  // units(), role "vertices") or, at ideal, the ideal sampler. Before rasterizing.
  void colour_vertices(std::vector<host::Mesh>& meshes);

  // Textures the fragments (fixed-point records; ideal also takes the double fragments, in the
  // same order; orders texture and composed take their interpolated colours at every level).
  // Returns RGBA8888 per fragment; ideal_rgba receives the ideal model's unrounded colours (ideal
  // only).
  std::vector<uint32_t> shade(const std::vector<host::FragmentRecord>& records,
                              const std::vector<host::Fragment>* fragments,
                              std::vector<glm::dvec4>* ideal_rgba,
                              const Progress& progress = nullptr);

  // Every unit built so far, with its stimulus and results, in the order they ran (a
  // material's mipgen units before its chain).
  std::vector<UnitRun>& units() { return units_; }
  const std::vector<UnitRun>& units() const { return units_; }
  // The stages shade() computed on the host for the materials it shaded (not ideal), each once.
  const std::vector<HostWork>& host_work() const { return host_work_; }
  // For each unit (same order), the fragment index of each of its outputs (mipgen: none).
  const std::vector<std::vector<size_t>>& fragments_of_outputs() const {
    return fragment_of_output_;
  }

 private:
  const host::Scene& scene_;
  Level level_;
  // What shading one material built: its units in order, their outputs' fragments, host work.
  struct MaterialWork {
    std::vector<UnitRun> units;
    std::vector<std::vector<size_t>> outputs_of;
    std::vector<HostWork> host_work;
  };
  // The mipgen units of material m: its texture's levels written by the generator.
  void generate_mipmaps(size_t m, MaterialWork& work);
  int jobs_ = 1;

  std::vector<MaterialTexture> textures_;
  std::vector<UnitRun> units_;
  std::vector<std::vector<size_t>> fragment_of_output_;
  std::vector<HostWork> host_work_;
  std::shared_ptr<ChipStage> chips_;
  void note_host_work(const HostWork& w);
};

// The front end: every object's mesh (NURBS objects tessellated), the vertex colours of the
// orders texture and composed through `pipe`, rasterized for rows [row_begin, row_end).
std::vector<host::Fragment> front_end(const host::Scene& scene, Pipeline& pipe, int row_begin,
                                      int row_end, host::RasterStats* stats);

}  // namespace tmu::render
