// The view frame the coordinate generator's tables are made for (coord_tables.hpp, eq. 17-22),
// as data: v_side, v_up, v_dir in object space (v_dir = v_side x v_up points towards the
// viewer). A definition only, no arithmetic: golden (coord_tables.hpp) and the ideal model
// (deflect_ideal.hpp) project onto it by their own code.
#pragma once

#include <array>

namespace tmu::deflect {

struct ViewFrame {
  std::array<double, 3> side{1, 0, 0}, up{0, 1, 0}, dir{0, 0, 1};  // object space, unit
};

}  // namespace tmu::deflect
