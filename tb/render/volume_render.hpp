// `texsim render` of a volume scene (host/volume/volume_scene.hpp): the frame through the volume
// unit at the chosen engine (render/volume_cast.hpp), written like every render: OUT/render.png
// (and render.exr at ideal), OUT/render.report.{txt,json}; with --compare ideal the PSNR against
// the ideal engine's frame and render.compare-error.png; with --check the same frame at another
// engine, every resample and counter compared bit for bit.
#pragma once

#include <iosfwd>
#include <string>

#include "common/image.hpp"
#include "render/render.hpp"
#include "render/volume_cast.hpp"
#include "render/volume_report.hpp"

namespace tmu::render {

// Renders; prints the text report to `log` and writes the files into out_dir (nothing before
// the scene, the options and the data are known good). Returns 0, or 1 when the check finds a
// difference; throws InputError on bad input.
int render_volume(const std::string& scene_path, const RenderOptions& options, std::ostream& log,
                  VolumeReport* report = nullptr);

// The frame's pixels as 8-bit RGB: round(255 v), half up, clamped.
ImageRgb8 volume_image(const VolumeFrame& frame);

// The host's stages of a volume render, for the report.
std::vector<HostWork> volume_host_work(const host::VolumeScene& scene, int chips);

}  // namespace tmu::render
