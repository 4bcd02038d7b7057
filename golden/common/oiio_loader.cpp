// The OpenImageIO entry points (common/image_file.hpp, texram/oiio_sampler.hpp) of a program
// with the target property TMU_OIIO_PLUGIN (texsim, the test executables): each loads the
// plugin on first use (oiio_plugin.hpp says why) and calls its function. Everything else links
// their OpenImageIO definitions directly (tmu_oiio, golden/CMakeLists.txt).
#include <dlfcn.h>
#include <fmt/format.h>

#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "common/oiio_plugin.hpp"

namespace tmu {
namespace {

[[noreturn]] void fail(const std::string& why) {
  throw std::runtime_error(
      "cannot load the OpenImageIO plugin, through which every image file is read and written "
      "(it is built with the program): " +
      why);
}

// Beside the binary itself, wherever it is started from (a symlink resolves to it), else where
// the build put it.
std::string plugin_path() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path beside = exe.parent_path() / TMU_OIIO_PLUGIN_FILE;
    if (std::filesystem::exists(beside, ec)) return beside.string();
  }
  return TMU_OIIO_PLUGIN_BUILT;
}

const OiioPlugin& load() {
  const std::string path = plugin_path();
  // RTLD_LAZY as for a linked library; RTLD_LOCAL: OpenImageIO's libraries do not join the
  // global scope that the program's own symbol look-ups search.
  void* handle = dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
  if (!handle) fail(dlerror());  // names the file and the reason
  auto* entry = reinterpret_cast<const OiioPlugin* (*)()>(dlsym(handle, kOiioPluginEntry));
  if (!entry) fail(fmt::format("{}: it has no {}", path, kOiioPluginEntry));
  const OiioPlugin* table = entry();
  if (table->version != kOiioPluginVersion || table->size != sizeof(OiioPlugin)) {
    fail(fmt::format("{}: it is version {} ({} bytes), the program expects {} ({} bytes): rebuild",
                     path, table->version, table->size, kOiioPluginVersion, sizeof(OiioPlugin)));
  }
  return *table;  // never unloaded: its objects may outlive any caller
}

// Loaded once, by the first caller (thread-safe); a failed load throws and is tried again.
const OiioPlugin& plugin() {
  static const OiioPlugin& table = load();
  return table;
}

}  // namespace

void load_oiio_plugin() { plugin(); }

std::unique_ptr<ImageFileReader> open_image_file(const std::string& path, std::string* why) {
  return plugin().open_image_file(path, why);
}

ImageWrite write_image_file(const std::string& format_path, const std::string& file,
                            const ImageFileSpec& spec, const void* pixels, std::string* error) {
  return plugin().write_image_file(format_path, file, spec, pixels, error);
}

ImageWrite write_image_file_rows(const std::string& format_path, const std::string& file,
                                 const ImageFileSpec& spec, int band, const ImageRows& fill,
                                 std::string* error) {
  return plugin().write_image_file_rows(format_path, file, spec, band, fill, error);
}

namespace texram {

void make_oiio_texture(const std::string& path, int width, int height, std::vector<float> rgba) {
  plugin().make_oiio_texture(path, width, height, std::move(rgba));
}

std::unique_ptr<OiioAnisoSampler> make_oiio_aniso_sampler(const std::vector<OiioTextureFile>& files,
                                                          int max_probes) {
  return plugin().make_oiio_aniso_sampler(files, max_probes);
}

}  // namespace texram
}  // namespace tmu
