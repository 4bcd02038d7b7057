// A frame in bands on parallel threads (`texsim render --bands N`): band i is `--tile i/N`'s
// render, with its own pipeline, units and Verilated models, and up to `jobs` bands run at once;
// when every band has rendered, they are joined into OUT/render.png (render/tiles.hpp: equal to
// the whole frame's render bit for bit, every fragment's colour depending on its own inputs).
// Each band keeps its files (render.tile-i-of-N.*) and report; the bands' reports go to `log`
// in band order, so the output is the same for every number of jobs.
//
// Why bands: a scene whose time is one material (grazing: the floor's footprint unit) gains
// nothing from shading materials on threads (Pipeline::set_jobs); its bands are independent.
// A band's units see only its rows, so their cycles and page faults are those of that band's
// `--tile` run, not a share of the whole frame's single unit (a hardware analogue: one texture
// unit per band of the screen).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "render/render.hpp"
#include "render/report.hpp"

namespace tmu::render {

// Renders bands 0..bands-1 of `options`' frame (options.tile/tiles must be 0/1) with
// options.jobs bands at a time (hls: one at a time; each band shades its materials serially).
// Returns 0, or 1 when a band's check found a mismatch (the frame is then not joined); throws
// InputError on bad input (before any band writes a file). `reports` receives each band's.
int render_bands(const std::string& scene_path, const RenderOptions& options, int bands,
                 std::ostream& log, std::vector<RenderReport>* reports = nullptr);

}  // namespace tmu::render
