// Eigen-decomposition of a symmetric 3x3 matrix, for the CCC encoder's inertia tensor
// (000 §3, eq. 1: "the eigenvector with the smallest eigenvalue is then calculated using
// standard methods").
//
// The encoder must produce the same bytes on every run, so the solver is deterministic in
// every respect a caller can observe: a fixed Jacobi sweep order, eigenvalues sorted with a
// fixed tie rule and eigenvector signs normalised.
#pragma once

#include <array>

namespace tmu::ccc {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;  // row-major; m[i][k]

struct SymmetricEigen {
  // Ascending. Values within a relative 1e-12 of each other count as equal and keep the
  // order of the diagonal positions they converged to (a stable sort), so a diagonal
  // matrix with repeated entries yields e_0 before e_1 before e_2.
  Vec3 values{};
  // vectors[i] is the unit eigenvector of values[i]; the eigenvectors are orthonormal. Its
  // sign is normalised: the first component with |x| > 1e-12 is positive.
  std::array<Vec3, 3> vectors{};
};

// Cyclic Jacobi with the fixed pivot order (0,1), (0,2), (1,2). Only the upper triangle
// of `m` is read; the matrix is taken to be symmetric. The zero matrix gives values 0 and
// the identity basis.
SymmetricEigen symmetric_eigen(const Mat3& m);

}  // namespace tmu::ccc
