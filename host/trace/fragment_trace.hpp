// Fragment traces: the front end's output saved to a file and replayed, so any rtl run is
// reproducible without the front end. CSV: '#' comment lines carry the scene path and the
// frame size; a header names the FragmentRecord's fields (x,y,material,u,v,lambda,shade,
// r1u,r1v,r2u,r2v,su,sv,sw,nx,ny,nz,vx,vy,vz); values are the raw fixed-point integers
// (shade as 0xRRGGBBAA).
#pragma once

#include <istream>
#include <string>
#include <vector>

#include "raster/fragment.hpp"

namespace tmu::host {

struct FragmentTrace {
  std::string scene;  // the scene file the trace was made from
  int width = 0, height = 0;
  std::vector<FragmentRecord> records;
};

void write_trace(const std::string& path, const FragmentTrace& trace);  // atomic
// Throws InputError naming the file, line and column.
FragmentTrace read_trace(const std::string& path);
// The same from a stream (tests, fuzzing); `name` stands for the file in messages.
FragmentTrace read_trace(std::istream& in, const std::string& name);

}  // namespace tmu::host
