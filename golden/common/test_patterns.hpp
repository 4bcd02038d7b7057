// Deterministic generated images: test inputs and the project's built-in textures. No
// external data, and the same arguments give the same pixels on every platform (random
// numbers are taken straight from std::mt19937, whose output the standard fixes, never
// through std::*_distribution, whose algorithms it leaves to the library).
#pragma once

#include <cstdint>
#include <string>

#include "common/image.hpp"

namespace tmu::patterns {

// R rises left to right, G top to bottom, B along the anti-diagonal: every block has a
// smooth, non-degenerate colour ramp.
ImageRgb8 gradient(int width, int height);

// Squares of `cell` x `cell` texels, c0 at the top-left.
ImageRgb8 checker(int width, int height, int cell, Rgb8 c0, Rgb8 c1);

// Independent uniform random bytes per channel: the worst case for any block coder.
ImageRgb8 noise(int width, int height, uint32_t seed);

// Photo-like: per channel a sum of a few low-frequency sinusoids at random orientations,
// a little grain, and a couple of sharp-edged discs.
ImageRgb8 smooth_field(int width, int height, uint32_t seed);

// The bundled demo image: a landscape (sky, sun, hills, a chequered path) with smooth
// shading, grain and hard edges. Colourful enough to exercise the 256-entry CLUT.
ImageRgb8 default_image(int width, int height);

// `text` in the built-in 5 x 7 bitmap font (A-Z, 0-9, space and . , : ; ! ? - + = / ( ) [ ] ' "
// _ * # % & < > @; lowercase is drawn as uppercase, any other character as a box), ink on paper.
// One font dot is max(1, height / 9) pixels square, so the 7 rows of a glyph fill the height
// with one dot of margin above and below (centred); glyphs are 6 dots apart (5 + 1 of space),
// and the text, followed by a space, repeats from the left edge until the width is full.
ImageRgb8 text(int width, int height, const std::string& text, Rgb8 ink, Rgb8 paper);

}  // namespace tmu::patterns
