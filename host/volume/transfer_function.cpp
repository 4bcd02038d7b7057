#include "volume/transfer_function.hpp"

#include <algorithm>
#include <stdexcept>

namespace tmu::host {

TransferFunction::TransferFunction(std::vector<TransferPoint> points) : points_(std::move(points)) {
  if (points_.empty()) throw std::invalid_argument("transfer function: no point");
  for (size_t i = 1; i < points_.size(); ++i) {
    if (!(points_[i].value > points_[i - 1].value))
      throw std::invalid_argument("transfer function: values not increasing");
  }
}

Classified TransferFunction::operator()(double value) const {
  const auto& p = points_;
  if (value <= p.front().value) return {p.front().colour, p.front().opacity};
  if (value >= p.back().value) return {p.back().colour, p.back().opacity};
  // The first point above the value; the one before it is at or below.
  const auto hi = std::upper_bound(p.begin(), p.end(), value,
                                   [](double v, const TransferPoint& q) { return v < q.value; });
  const auto lo = hi - 1;
  const double t = (value - lo->value) / (hi->value - lo->value);
  return {lo->colour + (hi->colour - lo->colour) * t,
          lo->opacity + (hi->opacity - lo->opacity) * t};
}

}  // namespace tmu::host
