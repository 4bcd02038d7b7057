// Orders texture and composed (004 claims 17, 18): the texture is sampled at the vertices,
// not per pixel. Each vertex of such an object becomes a request to the material's texture
// unit (a unit of its own, role "vertices"): tau(s, t) in texels at claim 12's level, the
// derivatives zero (one probe), and for composed the vertex's shade through the unit's eq. 5;
// the rasterizer interpolates the colours, and shade() composes (texture) or takes them as
// they are (composed).
#include <algorithm>
#include <glm/gtc/matrix_inverse.hpp>

#include "raster/shading.hpp"
#include "render/pipeline.hpp"

namespace tmu::render {

bool samples_at_vertices(const host::Material& m) {
  return m.order == host::Material::Order::kTexture || m.order == host::Material::Order::kComposed;
}

bool samples_at_vertices_anywhere(const host::Scene& scene) {
  return std::any_of(scene.materials.begin(), scene.materials.end(),
                     [](const host::Material& m) { return samples_at_vertices(m); });
}

std::vector<host::Fragment> front_end(const host::Scene& scene, Pipeline& pipe, int row_begin,
                                      int row_end, host::RasterStats* stats) {
  std::vector<host::Mesh> meshes = host::make_meshes(scene, pipe.texture_sizes());
  pipe.colour_vertices(meshes);
  return host::rasterize(scene, meshes, pipe.uv_scales(), row_begin, row_end, stats);
}

void Pipeline::colour_vertices(std::vector<host::Mesh>& meshes) {
  for (size_t o = 0; o < scene_.objects.size(); ++o) {
    const host::Object& obj = scene_.objects[o];
    const auto m = static_cast<size_t>(obj.material);
    const host::Material& mat = scene_.materials[m];
    host::Mesh& mesh = meshes[o];
    if (!samples_at_vertices(mat) || mesh.vertices.empty()) continue;
    if (textures_[m].mipgen_pending) {
      MaterialWork work;
      generate_mipmaps(m, work);
      for (UnitRun& u : work.units) units_.push_back(std::move(u));
      for (auto& f : work.outputs_of) fragment_of_output_.push_back(std::move(f));
    }
    const MaterialTexture& tex = textures_[m];
    // Order texture samples the texture alone: the composition comes per pixel.
    host::Material sampled = mat;
    if (mat.order == host::Material::Order::kTexture)
      sampled.sampler.combine = texram::Combine::kOne;

    const glm::dmat4 model = obj.transform.matrix();
    const glm::dmat3 normal_matrix = glm::inverseTranspose(glm::dmat3(model));
    std::vector<host::Fragment> requests;
    std::vector<host::FragmentRecord> records;
    std::vector<size_t> index;
    std::vector<uint32_t> shades;
    for (const host::Vertex& v : mesh.vertices) {
      host::Fragment f;
      f.material = obj.material;
      f.uv = v.uv * glm::dvec2(tex.size);
      f.lambda = v.lod;
      const glm::dvec3 n = normal_matrix * v.normal;
      const double len = glm::length(n);  // 0 only where the surface has no normal at all
      f.shade = host::shade(scene_.lights, len > 0 ? n / len : n,
                            glm::dvec3(model * glm::dvec4(v.position, 1.0)));
      index.push_back(records.size());
      records.push_back(host::quantize(f));
      shades.push_back(records.back().shade);
      requests.push_back(f);
    }
    if (level_ == Level::kIdeal) {
      for (size_t k = 0; k < records.size(); ++k)
        mesh.vertices[k].colour =
            ideal_texture(sampled, tex, sampled.sampler, requests[k], shades[k]);
      continue;
    }
    UnitRun run = texture_unit(sampled, tex, records, index, shades, "vertices");
    run_unit(run, level_, {});
    for (size_t k = 0; k < records.size(); ++k) {
      const auto c = static_cast<uint32_t>(run.result.outputs[k].f[0]);
      mesh.vertices[k].colour = {texram::channel(c, 0), texram::channel(c, 1),
                                 texram::channel(c, 2), texram::channel(c, 3)};
    }
    units_.push_back(std::move(run));
    fragment_of_output_.emplace_back();  // vertices, not fragments
  }
}

}  // namespace tmu::render
