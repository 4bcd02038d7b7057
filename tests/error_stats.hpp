// Per-channel errors of a model against its ideal, in 8-bit levels, and the figures the tests
// bound: the largest, the mean, a percentile, the share above a level. Shared by the suites that
// measure golden against an ideal (texram_trilinear_test.cpp, detail_test.cpp).
#pragma once

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace tmu::test {

struct ErrorStats {
  std::vector<double> errors;
  void add(double e) { errors.push_back(e); }
  void add(const ErrorStats& o) { errors.insert(errors.end(), o.errors.begin(), o.errors.end()); }
  double max() const {
    return errors.empty() ? 0 : *std::max_element(errors.begin(), errors.end());
  }
  double mean() const {
    return errors.empty()
               ? 0
               : std::accumulate(errors.begin(), errors.end(), 0.0) / double(errors.size());
  }
  double share_above(double bound) const {
    const auto n = std::count_if(errors.begin(), errors.end(), [&](double e) { return e > bound; });
    return errors.empty() ? 0 : double(n) / double(errors.size());
  }
  double percentile(double p) const {  // p in [0, 1]
    if (errors.empty()) return 0;
    std::vector<double> v = errors;
    const auto k = static_cast<size_t>(p * double(v.size() - 1));
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
    return v[k];
  }
};

}  // namespace tmu::test
