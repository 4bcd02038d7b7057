#include "ccc/symmetric_eigen.hpp"

#include <cmath>
#include <utility>

namespace tmu::ccc {
namespace {

// Jacobi converges quadratically; 3x3 matrices settle in fewer than 10 sweeps, so 50 is
// only a guard against a pathological input looping forever.
constexpr int kMaxSweeps = 50;
constexpr double kTieTolerance = 1e-12;
constexpr double kSignThreshold = 1e-12;

constexpr std::array<std::pair<int, int>, 3> kPivotOrder = {{{0, 1}, {0, 2}, {1, 2}}};

double off_diagonal_norm2(const Mat3& a) {
  return a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
}

// Applies the Jacobi rotation that zeroes a[p][q] to a (both sides) and v (columns).
void rotate(Mat3& a, Mat3& v, int p, int q) {
  const double apq = a[p][q];
  if (apq == 0.0) return;
  // Numerical Recipes' stable form: t = tan(theta) with the smaller root.
  const double theta = (a[q][q] - a[p][p]) / (2.0 * apq);
  const double t =
      (theta >= 0.0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
  const double c = 1.0 / std::sqrt(t * t + 1.0);
  const double s = t * c;
  // A' = J^T A J with J the rotation in the (p, q) plane.
  for (int k = 0; k < 3; ++k) {
    const double akp = a[k][p];
    const double akq = a[k][q];
    a[k][p] = c * akp - s * akq;
    a[k][q] = s * akp + c * akq;
  }
  for (int k = 0; k < 3; ++k) {
    const double apk = a[p][k];
    const double aqk = a[q][k];
    a[p][k] = c * apk - s * aqk;
    a[q][k] = s * apk + c * aqk;
  }
  a[p][q] = a[q][p] = 0.0;  // exact by construction; rounding must not leave residue
  for (int k = 0; k < 3; ++k) {
    const double vkp = v[k][p];
    const double vkq = v[k][q];
    v[k][p] = c * vkp - s * vkq;
    v[k][q] = s * vkp + c * vkq;
  }
}

void normalise_sign(Vec3& x) {
  for (double c : x) {
    if (std::fabs(c) > kSignThreshold) {
      if (c < 0.0) {
        for (double& e : x) e = -e;
      }
      return;
    }
  }
}

}  // namespace

SymmetricEigen symmetric_eigen(const Mat3& m) {
  Mat3 a{};
  for (int i = 0; i < 3; ++i) {
    for (int k = i; k < 3; ++k) a[i][k] = a[k][i] = m[i][k];
  }
  Mat3 v{};  // columns are the eigenvectors
  for (int i = 0; i < 3; ++i) v[i][i] = 1.0;

  double scale2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) scale2 += a[i][k] * a[i][k];
  }
  // Off-diagonal mass below (machine epsilon * |A|)^2 no longer changes the eigenvalues.
  const double done2 = scale2 * 1e-32;
  for (int sweep = 0; sweep < kMaxSweeps && off_diagonal_norm2(a) > done2; ++sweep) {
    for (const auto& [p, q] : kPivotOrder) rotate(a, v, p, q);
  }

  SymmetricEigen out;
  std::array<int, 3> order = {0, 1, 2};
  const double tol = kTieTolerance * std::sqrt(scale2);
  // Stable insertion sort: move an entry left only if it is smaller beyond the tolerance.
  for (int i = 1; i < 3; ++i) {
    for (int j = i; j > 0 && a[order[j]][order[j]] < a[order[j - 1]][order[j - 1]] - tol; --j) {
      std::swap(order[j], order[j - 1]);
    }
  }
  for (int i = 0; i < 3; ++i) {
    const int col = order[i];
    out.values[i] = a[col][col];
    out.vectors[i] = {v[0][col], v[1][col], v[2][col]};
    normalise_sign(out.vectors[i]);
  }
  return out;
}

}  // namespace tmu::ccc
