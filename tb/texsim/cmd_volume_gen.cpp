// `texsim volume-gen`: a volume data set as a raw file (8-bit voxels, x fastest, no header), the
// form a volume scene's {"file": ..., "size": [X, Y, Z]} reads: a CT-like scan of an engine
// part (host/volume/ct_scan.hpp), or the Marschner-Lobb and sphere test fields
// (golden/volume/sources.hpp). The same voxels as the scene's {"field": ...} of that kind.
#include <fmt/format.h>

#include <memory>
#include <string_view>

#include "common/atomic_file.hpp"
#include "texsim/commands.hpp"
#include "volume/volume_data.hpp"

namespace tmu::texsim {

void add_volume_gen_command(CLI::App& app, ExitCode& exit_code) {
  auto* cmd = app.add_subcommand(
      "volume-gen",
      "Write a volume data set as a raw file of 8-bit voxels, x fastest (docs/volume.md): "
      "engine, a CT-like scan of an engine part (aluminium block, steel liners, crankshaft and "
      "bolts; partial volumes, blur and scanner noise); marschner_lobb, the reconstruction test "
      "signal; sphere, a "
      "distance field. A volume scene reads it as {\"file\": \"OUT.raw\", \"size\": [X, Y, Z]}.");
  struct Args {
    std::string kind, out;
    std::vector<uint32_t> size = {64, 64, 64};
    uint32_t seed = 1;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("kind", a->kind, "engine | marschner_lobb | sphere")
      ->required()
      ->check(CLI::IsMember({"engine", "marschner_lobb", "sphere"}));
  cmd->add_option("output", a->out, "The raw file (written atomically)")->required();
  cmd->add_option("--size", a->size, "Voxels along x, y and z, 2..512 each")
      ->expected(3)
      ->delimiter(',')
      ->check(CLI::Range(2, 512))
      ->capture_default_str();
  cmd->add_option("--seed", a->seed, "engine: the scan noise's seed")->capture_default_str();
  cmd->callback([a, &exit_code] {
    host::VolumeData d;
    d.size = {a->size[0], a->size[1], a->size[2]};
    if (a->kind == "engine") {
      d.field = host::VolumeData::Field::kEngine;
      d.seed = a->seed;
    } else if (a->kind == "sphere") {
      d.field = host::VolumeData::Field::kSphere;
      d.radius = 3.0 / 8 * std::min({d.size[0], d.size[1], d.size[2]});  // the scene's default
    } else {
      d.field = host::VolumeData::Field::kMarschnerLobb;
    }
    const volume::VoxelGrid g = host::field_values(d);
    write_file_atomically(
        a->out, std::string_view(reinterpret_cast<const char*>(g.voxels.data()), g.voxels.size()));
    fmt::print("wrote {}: {} x {} x {} raw 8-bit voxels, x fastest ({} bytes)\n", a->out, g.nx,
               g.ny, g.nz, g.voxels.size());
    exit_code.value = 0;
  });
}

}  // namespace tmu::texsim
