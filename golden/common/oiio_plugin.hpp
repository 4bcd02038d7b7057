// The project's OpenImageIO plugin, libtmu_oiio_plugin.so: every function of the project that
// calls OpenImageIO (common/image_file.hpp, texram/oiio_sampler.hpp), built into a library that
// texsim and the test executables load with dlopen the first time they read or write an image.
//
// Why: OpenImageIO brings ~250 shared libraries (OpenCV, ffmpeg, GDAL, ...). Linked into a
// program, the dynamic linker loaded and relocated all of them at every start, ~0.3 s of CPU and
// 130 MB before main: texsim's commands that touch no image (help, formats) now start in a few
// ms, and so does each of the ~550 CTest processes (the suite's start-ups were about half of its
// CPU time). Such a program (the target property TMU_OIIO_PLUGIN) defines those functions itself
// (oiio_loader.cpp, the library tmu_oiio_loader): each forwards to this table.
#pragma once

#include <cstddef>

#include "common/image_file.hpp"
#include "texram/oiio_sampler.hpp"

namespace tmu {

// Bumped whenever OiioPlugin changes: the loader refuses a plugin built from other sources rather
// than calling through a table of another shape.
// 2: ImageFileReader reads MIP levels' tiles; 3: write_image_file_rows.
inline constexpr int kOiioPluginVersion = 3;

struct OiioPlugin {
  int version = kOiioPluginVersion;
  size_t size = sizeof(OiioPlugin);
  decltype(&tmu::open_image_file) open_image_file = nullptr;
  decltype(&tmu::write_image_file) write_image_file = nullptr;
  decltype(&tmu::write_image_file_rows) write_image_file_rows = nullptr;
  void (*make_oiio_texture)(const std::string&, int, int, std::vector<float>) = nullptr;
  decltype(&tmu::texram::make_oiio_aniso_sampler) make_oiio_aniso_sampler = nullptr;
};

// Loads the plugin now, if no image has yet. For texsim's commands that report the time of a
// whole run that reads images (render, sweep, levels --scene): their figures then leave the
// loading out, as they did when OpenImageIO was linked into texsim. Throws what the first image
// would.
void load_oiio_plugin();

// The plugin's one exported symbol (oiio_plugin.map): returns its table.
inline constexpr const char* kOiioPluginEntry = "tmu_oiio_plugin";
extern "C" const OiioPlugin* tmu_oiio_plugin();

}  // namespace tmu
