// Fragments as stimulus, shared by the blocks that take them (footprint, footprint_setup): a
// centre (u, v) and the derivative vectors r1 = d(u,v)/dx and r2 = d(u,v)/dy of 000 §10, the
// directed hard cases of the setup (zero, parallel, isotropic, the rounding thresholds of k,
// the length cap, huge derivatives, the port's ends, a texture's edges), the random mixes, and
// the coverage cases of a fragment's shape under a setup configuration.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "blocks/registry.hpp"
#include "footprint/footprint.hpp"
#include "harness/block.hpp"

namespace tmu::tb::fragments {

// The setup's configuration drawn from the generator (at most 1, 2, 4, 8 or 16 probes, the
// larger counts more often; either q rule), what the options set (fp_*) overriding its draw;
// the first of a block drawn from options.seed. Throws std::invalid_argument for bad widths
// or a maximum probe count outside 0..4.
footprint::Config draw_setup(std::mt19937_64& rng, const BlockOptions& options);
footprint::Config first_setup(const BlockOptions& options);
// The setup's options a reproduce command repeats (--max-probes, --q-rule, --fp-widths), as set.
std::string setup_repro_options(const BlockOptions& options);
// The rtl variant key of the setup's widths ("" for the defaults, else d<D>t<T>f<F>).
std::string setup_variant(const footprint::Widths& widths);

// Raw port values saturated to TexCoord and TexDeriv, and a fragment of them.
int32_t clamp_coord(int64_t raw);
int32_t clamp_deriv(int64_t raw);
footprint::Request fragment(int64_t u, int64_t v, int64_t r1u, int64_t r1v, int64_t r2u,
                            int64_t r2v, uint32_t shade);

// The directed fragments over a texture of w x h (raw SQ16.8 units of level 0), a different
// shade each.
std::vector<footprint::Request> directed(int64_t w, int64_t h);
// A random fragment: isotropic, anisotropic up to ratio 64 at any angle (either vector the
// longer, sometimes sheared), magnified, degenerate (zero, parallel, a few LSB, equal lengths)
// or components anywhere in the port; centred mostly over the texture and around it.
footprint::Request random(std::mt19937_64& rng, int64_t w, int64_t h);

// The shape cases: the q rules and maximum probe counts given (those the configurations can
// take), every k up to the largest, and the shapes (clamped and capped k, lines, a zero
// vector, points, magnification, r2 the longer, equal lengths, huge derivatives, lambda < 0).
std::vector<std::string> shape_cases(const std::vector<footprint::QRule>& q_rules,
                                     const std::vector<int>& log2_max_probes);
void cover_shape(const footprint::Request& request, const footprint::Config& config,
                 const footprint::Plan& plan, Coverage& coverage);

}  // namespace tmu::tb::fragments
