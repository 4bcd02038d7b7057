// The entry of the OpenImageIO plugin (oiio_plugin.hpp): the table of the functions built
// into it from golden/common/image_file_oiio.cpp and golden/texram/oiio_sampler.cpp.
#include "common/oiio_plugin.hpp"

extern "C" const tmu::OiioPlugin* tmu_oiio_plugin() {
  static const tmu::OiioPlugin table = [] {
    tmu::OiioPlugin t;
    t.open_image_file = &tmu::open_image_file;
    t.write_image_file = &tmu::write_image_file;
    t.write_image_file_rows = &tmu::write_image_file_rows;
    t.make_oiio_texture = &tmu::texram::make_oiio_texture;
    t.make_oiio_aniso_sampler = &tmu::texram::make_oiio_aniso_sampler;
    return t;
  }();
  return &table;
}
