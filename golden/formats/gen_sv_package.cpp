// Prints the SystemVerilog package generated from formats.def. rtl/CMakeLists.txt compiles
// and runs it at configure time, because the models are verilated at configure time.
#include <iostream>

#include "formats/formats.hpp"

int main() {
  std::cout << tmu::formats::sv_package();
  return std::cout ? 0 : 1;
}
