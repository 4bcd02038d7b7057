// The entry of texsim's OpenImageIO plugin (oiio_plugin.hpp): the table of the functions built
// into it from golden/common/image_file_oiio.cpp and golden/texram/oiio_sampler.cpp.
#include "texsim/oiio_plugin.hpp"

extern "C" const tmu::texsim::OiioPlugin* tmu_texsim_oiio_plugin() {
  static const tmu::texsim::OiioPlugin table = [] {
    tmu::texsim::OiioPlugin t;
    t.open_image_file = &tmu::open_image_file;
    t.write_image_file = &tmu::write_image_file;
    t.make_oiio_texture = &tmu::texram::make_oiio_texture;
    t.make_oiio_aniso_sampler = &tmu::texram::make_oiio_aniso_sampler;
    return t;
  }();
  return &table;
}
