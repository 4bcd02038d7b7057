#include "render/pipeline.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <mutex>
#include <stdexcept>

#include "blocks/ccc_cache_bilinear/ccc_cache_bilinear_block.hpp"
#include "blocks/footprint/footprint_block.hpp"
#include "blocks/mipgen/mipgen_block.hpp"
#include "blocks/trilinear/trilinear_block.hpp"
#include "ccc/ccc_cache_bilinear.hpp"
#include "ccc/ccc_encoder.hpp"
#include "common/error.hpp"
#include "common/image.hpp"
#include "footprint/footprint_ideal.hpp"
#include "render/chip_stage.hpp"
#include "render/detail_maps.hpp"
#include "render/effect_chain.hpp"
#include "render/jobs.hpp"
#include "render/procedural_chain.hpp"
#include "render/tau_stage.hpp"
#include "render/texture_source.hpp"
#include "texram/mipgen_stream.hpp"
#include "texram/trilinear.hpp"
#include "texram/trilinear_ideal.hpp"

namespace tmu::render {
namespace {

// Level 0 of one byte plane of a host-built texture: what the mipgen unit receives.
texram::Level8 level0_plane(const texram::TexramTexture& t, int plane) {
  texram::Level8 l(t.geometry.texel_width(0), t.geometry.texel_height(0));
  for (uint32_t y = 0; y < l.height; ++y) {
    for (uint32_t x = 0; x < l.width; ++x) l.at(x, y) = t.cell(0, x, y, plane);
  }
  return l;
}

}  // namespace

UnitRun texture_unit(const host::Material& mat, const MaterialTexture& tex,
                     const std::vector<host::FragmentRecord>& records,
                     const std::vector<size_t>& frags, const std::vector<uint32_t>& shades,
                     const std::string& role) {
  UnitRun run;
  run.material = mat.name;
  run.role = role;
  if (mat.footprint) {
    run.kind = "footprint";
    const auto block = std::make_shared<tb::FootprintBlock>(
        tb::BlockOptions{}, tb::FootprintEnv{{tex.texram, mat.sampler, mat.name}, *mat.footprint});
    attach(run, block);
    run.items = block->setup_items();  // the configuration (and CLUT) of the texture
    for (size_t k = 0; k < frags.size(); ++k) {
      const host::FragmentRecord& r = records[frags[k]];
      run.items.push_back(
          tb::footprint_sample_item(r.u, r.v, r.r1[0], r.r1[1], r.r2[0], r.r2[1], shades[k]));
    }
  } else {
    run.kind = "trilinear";
    const auto block = std::make_shared<tb::TrilinearBlock>(
        tb::BlockOptions{}, tb::TrilinearEnv{tex.texram, mat.sampler, mat.name});
    attach(run, block);
    run.items = block->setup_items();  // the configuration (and CLUT) of the texture
    for (size_t k = 0; k < frags.size(); ++k) {
      const host::FragmentRecord& r = records[frags[k]];
      run.items.push_back(tb::trilinear_sample_item(r.u, r.v, r.lambda, shades[k]));
    }
  }
  return run;
}

glm::dvec4 ideal_texture(const host::Material& mat, const MaterialTexture& tex,
                         const texram::SamplerConfig& sampler, const host::Fragment& f,
                         uint32_t shade) {
  // A sample at (u, v, lambda): through the detail path where the material has a detail map.
  const auto sample = [&](double u, double v, double lambda) {
    if (!tex.ideal_detail) return texram::ideal_sample(*tex.ideal, sampler, u, v, lambda, shade);
    const auto combine =
        mat.detail->modulate ? texram::DetailCombine::kModulate : texram::DetailCombine::kReplace;
    return texram::ideal_detail_sample(*tex.ideal, sampler, *tex.ideal_detail, combine, u, v,
                                       lambda, shade);
  };
  std::array<double, 4> s;
  if (mat.footprint) {  // each probe sampled as the chip's probes are, detail and all
    const footprint::IdealConfig ic{mat.footprint->log2_max_probes, mat.footprint->q_rule,
                                    footprint::Direction::kLongerSide};
    s = footprint::ideal_march(ic, f.uv, f.r1, f.r2, sample);
  } else {
    s = sample(f.uv.x, f.uv.y, f.lambda);
  }
  return {s[0], s[1], s[2], s[3]};
}

namespace {

// A material's texture from its source (an image or a .ccc file) as its unit holds it: the
// low-cost unit's CCC blocks, or the TEXRAM's banks (and at ideal the exact texels). Throws
// InputError or std::invalid_argument; the caller names the scene's field.
void load_texture(const host::Material& mat, Level level, MaterialTexture& mt) {
  const bool ccc_file = mat.texture.kind == host::TextureSource::Kind::kCcc;
  if (mat.unit == host::Material::Unit::kLowcost) {
    ccc::Texture tex =
        ccc_file ? ccc::read_ccc(mat.texture.path) : ccc::encode(source_image(mat.texture));
    mt.size = {static_cast<int>(tex.width), static_cast<int>(tex.height)};
    mt.ccc = std::make_shared<const ccc::Texture>(std::move(tex));
  } else {
    texram::TexramTexture tex =
        ccc_file ? texram::import_ccc(ccc::read_ccc(mat.texture.path))
                 : texram::import_image(source_image(mat.texture), mat.sampler.kind,
                                        mat.sampler.single_channel);
    // The real-time mipmap generator runs when the first fragment of the material needs
    // the texture (shade()): a material with none in the frame or band builds no unit.
    mt.mipgen_pending = mat.mipmaps == host::Material::Mipmaps::kMipgen && level != Level::kIdeal;
    mt.size = {static_cast<int>(tex.geometry.texel_width(0)),
               static_cast<int>(tex.geometry.texel_height(0))};
    if (level == Level::kIdeal)
      mt.ideal = std::make_shared<const texram::IdealTexture>(texram::ideal_texture(tex.source));
    mt.texram = std::make_shared<const texram::TexramTexture>(std::move(tex));
  }
}

}  // namespace

uint32_t rgba_of(const glm::dvec4& c) {
  const auto ch = [](double v) {
    return static_cast<uint32_t>(std::lround(std::clamp(v, 0.0, 255.0)));
  };
  return texram::rgba(ch(c.r), ch(c.g), ch(c.b), ch(c.a));
}

Pipeline::Pipeline(const host::Scene& scene, Level level, int chips, const VideoState* video)
    : scene_(scene), level_(level) {
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    const host::Material& mat = scene.materials[m];
    const std::string field = "materials." + mat.name + ".texture";
    MaterialTexture mt;
    if (mat.procedural) {  // no texture: the material unit computes the colour
      textures_.push_back(std::move(mt));
      continue;
    }
    if (mat.video) {
      // The video port writes a chip's memory (000 §11-12): no separate unit has a video path.
      const std::string at = "materials." + mat.name + ".video";
      if (level == Level::kIdeal)
        throw InputError(scene.path, at, "a video map renders at golden, hls or rtl (on chips)");
      if (chips <= 0) {
        throw InputError(scene.path, at,
                         "the video port writes a TEXRAM chip's memory, and only the chip samples "
                         "a video map: render with --chips N");
      }
      mt.video =
          video && m < video->size() && (*video)[m] ? (*video)[m] : empty_video_buffers(*mat.video);
      mt.texram = mt.video->buffers[static_cast<size_t>(mt.video->front)];
      mt.size = {mat.video->width, mat.video->height};
      if (mt.video->by_unit) {
        note_host_work(
            {"video timing of " + mat.name + " at the scene's rate (000 §11-12)",
             "the chip's memory is what the video unit at the engine wrote "
             "(render/video_unit_feed, the chip's rows of a page); the cycles at the video's "
             "rate, in the video report, are the golden VideoMap's on the host, whose buffers "
             "and accesses are the unit's (docs/video.md)"});
      }
    } else {
      try {
        load_texture(mat, level, mt);
      } catch (const InputError& e) {
        throw InputError(scene.path, field, e.what());
      } catch (const std::invalid_argument& e) {
        throw InputError(scene.path, field, e.what());
      }
    }
    if (mat.uses_normal()) mt.effects = build_effect_maps(scene, mat);  // the rest of its chain
    // A video's detail maps too: its level 0 is the video's frame size, every frame.
    if (mat.has_detail()) {
      // Only the chip has the detail path (its offsets and detail DRFs): the separate units have
      // none, so at golden, hls and rtl a detail scene renders on chips or not at all. The ideal
      // renderer samples the detail maps exactly (texram/detail_ideal).
      const std::string at =
          "materials." + mat.name + (mat.detail ? ".detail" : ".reflectance.detail");
      if (level != Level::kIdeal && chips <= 0) {
        throw InputError(scene.path, at,
                         "detail maps are sampled by the TEXRAM chip only: render with --chips N");
      }
      try {
        if (level == Level::kIdeal) {
          if (mat.detail) mt.ideal_detail = build_ideal_detail_map(*mat.detail, mt.size);
          if (mat.reflectance.detail)
            mt.ideal_reflectance_detail = build_ideal_detail_map(*mat.reflectance.detail, mt.size);
        } else {
          if (mat.detail) mt.detail = build_detail_map(*mat.detail, mt.size);
          if (mat.reflectance.detail)
            mt.reflectance_detail = build_detail_map(*mat.reflectance.detail, mt.size);
        }
      } catch (const InputError& e) {
        throw InputError(scene.path, at, e.what());
      } catch (const std::invalid_argument& e) {
        throw InputError(scene.path, at, e.what());
      }
    }
    textures_.push_back(std::move(mt));
  }
  if (chips > 0 && level != Level::kIdeal) {
    chips_ = std::make_shared<ChipStage>(scene, textures_, chips);
  }
}

void Pipeline::generate_mipmaps(size_t m, MaterialWork& w) {
  // The real-time mipmap generator (000 §12) writes every level into the banks from the
  // level-0 texels, one stream per byte plane; the trilinear unit then reads what it wrote.
  // (Ideal computes the exact box pyramid of level 0 itself: texram/trilinear_ideal.hpp.)
  MaterialTexture& mt = textures_[m];
  const host::Material& mat = scene_.materials[m];
  const texram::TexramTexture& tex = *mt.texram;
  const texram::Geometry& g = tex.geometry;
  texram::TexramTexture generated{tex.kind, g, {}, tex.clut, tex.source};
  for (auto& b : generated.banks) b.assign(g.bank_cells(), 0);
  const auto block = std::make_shared<tb::MipgenBlock>();
  for (int p = 0; p < g.planes(); ++p) {
    const texram::MipgenConfig cfg{g.log2_width(), g.log2_height(), false, g.planes(), p};
    UnitRun run;
    run.kind = "mipgen";
    run.material = mat.name + (g.planes() > 1 ? fmt::format(".plane{}", p) : "");
    attach(run, block);
    run.items = tb::mipgen_items(cfg, level0_plane(tex, p));
    run_unit(run, level_, {});
    for (const tb::Txn& out : run.result.outputs) {
      const texram::CellWrite cw = tb::mipgen_txn_write(out);
      generated.banks[cw.cell.bank][cw.cell.address] = cw.value;
    }
    w.units.push_back(std::move(run));
    w.outputs_of.emplace_back();
  }
  mt.texram = std::make_shared<const texram::TexramTexture>(std::move(generated));
  mt.mipgen_pending = false;
  if (chips_) chips_->write_generated(m, mt.texram);  // the generator writes the chip's memory
}

std::vector<glm::ivec2> Pipeline::texture_sizes() const {
  std::vector<glm::ivec2> sizes;
  for (const MaterialTexture& t : textures_) sizes.push_back(t.size);
  return sizes;
}

std::vector<glm::ivec2> Pipeline::uv_scales() const {
  std::vector<glm::ivec2> scales;
  for (size_t m = 0; m < textures_.size(); ++m) {
    const host::Material& mat = scene_.materials[m];
    scales.push_back(mat.order == host::Material::Order::kPc ? pc_uv_scale(mat)
                                                             : textures_[m].size);
  }
  return scales;
}

std::vector<uint32_t> Pipeline::shade(const std::vector<host::FragmentRecord>& records,
                                      const std::vector<host::Fragment>* fragments,
                                      std::vector<glm::dvec4>* ideal_rgba,
                                      const Progress& progress) {
  std::vector<uint32_t> out(records.size(), 0);
  if (ideal_rgba) ideal_rgba->assign(records.size(), glm::dvec4(0));
  // The fragments of each material, in frame order.
  std::vector<std::vector<size_t>> of_material(scene_.materials.size());
  for (size_t i = 0; i < records.size(); ++i) of_material[records[i].material].push_back(i);

  // The materials' chains are independent: each runs on its own thread (its own engines and
  // models) with its own list of units, joined in material order, so the result is the serial
  // run's whatever the number of jobs. The fragments' colours are disjoint slots of `out`.
  std::atomic<uint64_t> done{0};
  std::mutex progress_mutex;
  const bool serial = jobs_ <= 1;
  const auto advance = [&](uint64_t n) {
    const uint64_t now = done += n;
    if (!progress) return;
    const std::lock_guard<std::mutex> lock(progress_mutex);
    progress(now, records.size());
  };
  const auto shade_one = [&](size_t m, MaterialWork& w) {
    const std::vector<size_t>& frags = of_material[m];
    if (textures_[m].mipgen_pending) generate_mipmaps(m, w);
    const host::Material& mat = scene_.materials[m];
    const MaterialTexture& tex = textures_[m];
    const bool lowcost = mat.unit == host::Material::Unit::kLowcost;
    const bool pc = mat.order == host::Material::Order::kPc;

    if (samples_at_vertices(mat)) {
      if (!fragments || fragments->size() != records.size()) {
        throw InputError(scene_.path, "materials." + mat.name + ".order",
                         "the orders texture and composed interpolate vertex colours, which "
                         "only the front end gives (not a replayed trace)");
      }
      const bool compose = mat.order == host::Material::Order::kTexture;
      for (size_t i : frags) {
        const host::Fragment& f = (*fragments)[i];
        if (level_ == Level::kIdeal) {
          glm::dvec4 c = f.colour;
          if (compose && mat.sampler.combine != texram::Combine::kOne) {
            const uint32_t k = mat.sampler.combine == texram::Combine::kConstant
                                   ? mat.sampler.constant_rgba
                                   : records[i].shade;
            for (int ch = 0; ch < 4; ++ch) c[ch] *= texram::channel(k, ch) / 255.0;
          }
          (*ideal_rgba)[i] = c;
          out[i] = rgba_of(c);
        } else {
          out[i] = compose ? texram::combine(rgba_of(f.colour), mat.sampler, records[i].shade)
                           : rgba_of(f.colour);
        }
      }
      if (level_ != Level::kIdeal) {
        w.host_work.push_back(
            compose ? HostWork{"order texture: the interpolated vertex texture colour "
                               "composed with the pixel's shade (texram::combine)",
                               "004 claim 17 composes after the rasterizer's "
                               "interpolation, outside the texture unit"}
                    : HostWork{"order composed: the vertex colours interpolated",
                               "004 claim 18 leaves nothing per pixel but the "
                               "rasterizer's interpolation"});
      }
      advance(frags.size());
      return;
    }
    if (mat.procedural) {
      const ChainInput in{scene_, mat, tex, level_, records, frags};
      if (level_ == Level::kIdeal) {
        const std::vector<glm::dvec4> c = ideal_procedural(in, *fragments);
        for (size_t k = 0; k < frags.size(); ++k) {
          (*ideal_rgba)[frags[k]] = c[k];
          out[frags[k]] = rgba_of(c[k]);
        }
      } else {
        const std::vector<uint32_t> rgba = run_procedural(in, w.units, w.outputs_of);
        for (size_t k = 0; k < frags.size(); ++k) out[frags[k]] = rgba[k];
      }
      advance(frags.size());
      return;
    }
    if (level_ == Level::kIdeal && mat.uses_normal()) {
      const std::vector<glm::dvec4> c =
          ideal_effect_chain({scene_, mat, tex, level_, records, frags}, *fragments);
      for (size_t k = 0; k < frags.size(); ++k) {
        (*ideal_rgba)[frags[k]] = c[k];
        out[frags[k]] = rgba_of(c[k]);
      }
      advance(frags.size());
      return;
    }
    if (level_ == Level::kIdeal) {
      for (size_t i : frags) {
        const host::Fragment& f = (*fragments)[i];
        const uint32_t shade = records[i].shade;
        glm::dvec4 c;
        if (lowcost) {
          const auto rgb = ccc::ideal_bilinear(*tex.ccc, f.uv.x, f.uv.y);
          c = {rgb[0], rgb[1], rgb[2], 255.0};
          if (mat.sampler.combine == texram::Combine::kShade) {
            c *= glm::dvec4(f.shade, 1.0);
          }
        } else {
          c = ideal_texture(mat, tex, mat.sampler, pc ? ideal_tau(mat, tex.size, f) : f, shade);
        }
        (*ideal_rgba)[i] = c;
        out[i] = rgba_of(c);
      }
      advance(frags.size());
      return;
    }

    ChipStage* chip = chips_ && chips_->samples(m) ? chips_.get() : nullptr;
    if (mat.uses_normal()) {
      for (const HostWork& h : effect_chain_host_work(mat, tex.effects, chip != nullptr))
        w.host_work.push_back(h);
      const std::vector<uint32_t> rgba = run_effect_chain(
          {scene_, mat, tex, level_, records, frags, chip, m}, w.units, w.outputs_of);
      for (size_t k = 0; k < frags.size(); ++k) out[frags[k]] = rgba[k];
      advance(frags.size());
      return;
    }
    if (chip) {  // one parameter a pixel: the texture's request (from the tau unit in order pc)
      const std::vector<host::FragmentRecord> tau =
          pc ? run_tau(mat, tex.size, records, frags, level_, w.units, w.outputs_of)
             : std::vector<host::FragmentRecord>{};
      const std::vector<host::FragmentRecord>& at = pc ? tau : records;
      std::vector<std::vector<texram::chip::PixelParameter>> params;
      for (size_t i : frags) params.push_back({texture_parameter(mat, at[i], records[i].shade)});
      const std::vector<uint32_t> rgba =
          chip->run_pass(m, 0, std::move(params), frags, level_, w.units, w.outputs_of);
      for (size_t k = 0; k < frags.size(); ++k) out[frags[k]] = rgba[k];
      advance(frags.size());
      return;
    }
    UnitRun run;
    if (lowcost) {
      run.kind = "ccc_cache_bilinear";
      run.material = mat.name;
      const auto block = std::make_shared<tb::CccCacheBilinearBlock>(tb::BlockOptions{}, tex.ccc);
      attach(run, block);
      run.items = block->setup_items();  // the texture's configuration and CLUT
      for (size_t i : frags)
        run.items.push_back(tb::bilinear_sample_item(records[i].u, records[i].v));
    } else {
      std::vector<uint32_t> shades;
      for (size_t i : frags) shades.push_back(records[i].shade);
      run = pc ? texture_unit(mat, tex,
                              run_tau(mat, tex.size, records, frags, level_, w.units, w.outputs_of),
                              frags, shades)
               : texture_unit(mat, tex, records, frags, shades);
    }
    tb::RunOptions options;
    if (progress && serial) {  // within the unit too, when one unit runs at a time
      const uint64_t base = done;
      options.progress = [&, base](uint64_t n) { progress(base + n, records.size()); };
    }
    run_unit(run, level_, options);
    for (size_t k = 0; k < frags.size(); ++k) {
      uint32_t c = static_cast<uint32_t>(run.result.outputs[k].f[0]);
      if (lowcost) {  // RGB888 -> RGBA8888; the low-cost unit has no eq. 5 stage: the host does it
        c = (c << 8) | 0xFF;
        if (mat.sampler.combine != texram::Combine::kOne)
          c = texram::combine(c, mat.sampler, records[frags[k]].shade);
      }
      out[frags[k]] = c;
    }
    if (lowcost && mat.sampler.combine != texram::Combine::kOne) {
      w.host_work.push_back(
          {"low-cost unit's eq. 5 combine (texram::combine)",
           "the low-cost unit of 000 §4 has no eq. 5 stage (eq. 5 is the TEXRAM's, §7); "
           "the project applies the scene's combine to its RGB888"});
    }
    w.units.push_back(std::move(run));
    w.outputs_of.push_back(frags);
    advance(frags.size());
  };

  std::vector<size_t> materials;
  for (size_t m = 0; m < scene_.materials.size(); ++m) {
    if (!of_material[m].empty()) materials.push_back(m);  // no fragment, no unit
  }
  std::vector<MaterialWork> work(scene_.materials.size());
  run_jobs(materials.size(), serial ? 1 : jobs_,
           [&](size_t i) { shade_one(materials[i], work[materials[i]]); });
  for (MaterialWork& w : work) {
    for (UnitRun& u : w.units) units_.push_back(std::move(u));
    for (std::vector<size_t>& f : w.outputs_of) fragment_of_output_.push_back(std::move(f));
    for (const HostWork& h : w.host_work) note_host_work(h);
  }
  return out;
}

void Pipeline::note_host_work(const HostWork& w) {
  if (std::find(host_work_.begin(), host_work_.end(), w) == host_work_.end())
    host_work_.push_back(w);
}

}  // namespace tmu::render
