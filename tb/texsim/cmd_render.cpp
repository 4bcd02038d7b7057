// `texsim render` and `texsim merge`: scenes through the texture unit at any model level.
#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <thread>

#include "common/error.hpp"
#include "common/image.hpp"
#include "common/oiio_plugin.hpp"
#include "render/bands.hpp"
#include "render/flyover.hpp"
#include "render/render.hpp"
#include "render/tiles.hpp"
#include "render/video_render.hpp"
#include "render/volume_render.hpp"
#include "texsim/commands.hpp"
#include "volume/volume_scene.hpp"

namespace tmu::texsim {

void add_render_command(CLI::App& app, ExitCode& exit_code) {
  auto* cmd = app.add_subcommand(
      "render",
      "Render a scene (scenes/README.md) through the texture unit: the host front end rasterizes "
      "it, every\n"
      "fragment goes through the units its material's chain calls for, at the chosen model level.\n"
      "Writes OUT/render.png (and render.exr for ideal) and OUT/render.report.{json,txt}.\n"
      "A volume scene (a \"volume\" section) is ray-cast through the volume unit (000 §13) at "
      "ideal or golden.\n"
      "A scene with a video map (a material's \"video\", 000 §11-12) renders with --chips N as "
      "frames: OUT/video.frame-NNNN.png\nand OUT/video.report.{json,txt} (docs/video.md).");
  struct Args {
    std::string scene, engine = "golden", check, compare, tile, frames;
    bool waveform = false, no_progress = false;
    int bands = 0;
    render::RenderOptions options;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("scene", a->scene, "Scene file (JSON)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--engine", a->engine, "ideal | golden | hls | rtl")
      ->check(CLI::IsMember({"ideal", "golden", "hls", "rtl"}))
      ->capture_default_str();
  cmd->add_option("--out", a->options.out_dir, "Output directory")->capture_default_str();
  cmd->add_option("--check", a->check,
                  "Also render with this engine and compare every fragment bit for bit; exit 1 on "
                  "a mismatch\n"
                  "(writes render.check-diff.png, a heat map of the differing pixels)")
      ->check(CLI::IsMember({"golden", "hls", "rtl"}));
  cmd->add_flag("--waveform", a->waveform,
                "With --check and --engine rtl: an FST window around the first mismatch");
  cmd->add_option("--compare", a->compare,
                  "Compare the image with the ideal engine's: PSNR, max error, "
                  "render.compare-error.png")
      ->check(CLI::IsMember({"ideal"}));
  cmd->add_option("--tile", a->tile,
                  "Render band i of n of the frame (i/n); join the bands with texsim merge");
  cmd->add_option("--bands", a->bands,
                  "Render the frame as N bands on parallel threads (--jobs at a time), each band "
                  "--tile i/N's\nrender with its own models and files, joined into render.png "
                  "(a surface scene)")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--save-trace", a->options.save_trace,
                  "Write the fragment records (a trace) to this file");
  cmd->add_option("--replay", a->options.replay_trace,
                  "Take the fragment records from a trace instead of the front end")
      ->check(CLI::ExistingFile);
  cmd->add_option("--inject-fault", a->options.inject_fault,
                  "Flip a bit of fragment N's result (to see --check fail); a volume scene at hls "
                  "or rtl: of the value of chip 0's unit's output N");
  cmd->add_option("--frames", a->frames,
                  "A fly-over scene (a \"flyover\" section, render/flyover.hpp) or a scene with a "
                  "video map (a material's\n\"video\", with --chips N; render/video_render.hpp): "
                  "the frames A:B or A-B (default every frame)");
  cmd->add_option(
         "--chips", a->options.chips,
         "TEXRAM chips (000 §14). A surface scene: its materials' maps sampled on them, each "
         "material compiled\nto DRFs (texsim drf shows them), its maps and specular "
         "combine one texram_chip unit; the report\nlists the materials that stay on "
         "separate units and why (0: every map its own unit). A volume scene\n(docs/"
         "volume.md): its volume in this many slabs, one a chip (0: the scene's \"chips\", "
         "else 1)")
      ->check(CLI::Range(0, 64))
      ->capture_default_str();
  a->options.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  cmd->add_option("--jobs", a->options.jobs,
                  "Materials shaded at once, each on its own thread with its own models, or with "
                  "--bands the bands\nrendered at once (the image and report are the same for "
                  "any number; hls runs one at a time)")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  cmd->add_flag("--no-progress", a->no_progress, "No progress bar");
  cmd->callback([a, &exit_code] {
    load_oiio_plugin();  // before the report's clock starts
    render::RenderOptions o = a->options;
    o.level = *render::parse_level(a->engine);
    if (!a->check.empty()) o.check = render::parse_level(a->check);
    o.compare_ideal = !a->compare.empty();
    o.waveform = a->waveform;
    o.progress = !a->no_progress;
    if (!a->tile.empty()) std::tie(o.tile, o.tiles) = render::parse_tile(a->tile);
    if (a->bands > 0 && (host::is_volume_scene(a->scene) || render::is_flyover(a->scene))) {
      throw InputError(a->scene, "", "--bands is for a surface scene");
    }
    if (host::is_volume_scene(a->scene)) {
      if (!a->frames.empty()) throw InputError(a->scene, "", "--frames is for a fly-over scene");
      exit_code.value = render::render_volume(a->scene, o, std::cout);
      return;
    }
    if (render::is_flyover(a->scene)) {
      if (o.chips > 0) {
        throw InputError(a->scene, "flyover",
                         "--chips: a fly-over samples its clip-map through the clip-map unit "
                         "(003), not a TEXRAM chip");
      }
      const render::FrameRange range =
          a->frames.empty() ? render::FrameRange{} : render::parse_frame_range(a->frames);
      exit_code.value = render::render_flyover(a->scene, o, range, std::cout);
      return;
    }
    if (render::is_video_scene(a->scene)) {
      if (a->bands > 0) throw InputError(a->scene, "", "--bands is for a scene without a video");
      const render::FrameRange range =
          a->frames.empty() ? render::FrameRange{} : render::parse_frame_range(a->frames);
      exit_code.value = render::render_video(a->scene, o, range, std::cout);
      return;
    }
    if (!a->frames.empty())
      throw InputError(a->scene, "", "--frames is for a fly-over scene or a scene with a video");
    exit_code.value = a->bands > 0 ? render::render_bands(a->scene, o, a->bands, std::cout)
                                   : render::render_scene(a->scene, o, std::cout);
  });

  auto* merge =
      app.add_subcommand("merge", "Join the bands of `texsim render --tile i/n` into one image");
  auto out = std::make_shared<std::string>();
  auto bands = std::make_shared<std::vector<std::string>>();
  merge->add_option("output", *out, "The whole frame (written atomically)")->required();
  merge->add_option("bands", *bands, "Every band's image, any order")
      ->required()
      ->check(CLI::ExistingFile);
  merge->callback([out, bands] {
    const ImageRgb8 frame = render::merge_bands(*bands);
    write_image(*out, frame);
    fmt::print("merged {} bands into {} ({}x{})\n", bands->size(), *out, frame.width, frame.height);
  });
}

}  // namespace tmu::texsim
