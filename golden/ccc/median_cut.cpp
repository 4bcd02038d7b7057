#include "ccc/median_cut.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tmu::ccc {
namespace {

// A distinct colour (distinct after rounding to 8 bits) with the weighted mean of the
// exact inputs that round to it, so quantization sees the inputs' sub-LSB precision.
struct UniqueColour {
  Vec3 rgb{};
  uint64_t weight = 0;
  uint32_t key = 0;  // packed rounded RGB; unique, so it breaks every ordering tie
};

// A median-cut box: a contiguous range of the unique colours.
struct Box {
  size_t begin = 0;
  size_t end = 0;
  Vec3 mean{};
  double sse = 0.0;  // weighted squared distance of the colours to `mean`
};

double distance2(const Vec3& a, const Vec3& b) {
  const double dr = a[0] - b[0];
  const double dg = a[1] - b[1];
  const double db = a[2] - b[2];
  return dr * dr + dg * dg + db * db;
}

std::vector<UniqueColour> merge_duplicates(std::span<const WeightedColour> colours) {
  std::vector<UniqueColour> all;
  all.reserve(colours.size());
  for (const WeightedColour& c : colours) {
    if (c.weight == 0) continue;
    Vec3 clamped{};
    for (int k = 0; k < 3; ++k) clamped[k] = std::clamp(c.rgb[k], 0.0, 255.0);
    all.push_back({clamped, c.weight, pack_rgb(round_colour(clamped))});
  }
  // Stable, so the summation order below (and hence every bit of the means) depends only
  // on the input order.
  std::stable_sort(all.begin(), all.end(),
                   [](const UniqueColour& x, const UniqueColour& y) { return x.key < y.key; });
  std::vector<UniqueColour> unique;
  for (size_t i = 0; i < all.size();) {
    UniqueColour u{{0.0, 0.0, 0.0}, 0, all[i].key};
    Vec3 sum{};
    for (; i < all.size() && all[i].key == u.key; ++i) {
      const double w = static_cast<double>(all[i].weight);
      for (int k = 0; k < 3; ++k) sum[k] += w * all[i].rgb[k];
      u.weight += all[i].weight;
    }
    for (int k = 0; k < 3; ++k) u.rgb[k] = sum[k] / static_cast<double>(u.weight);
    unique.push_back(u);
  }
  return unique;
}

Box make_box(const std::vector<UniqueColour>& u, size_t begin, size_t end) {
  Box box{begin, end, {}, 0.0};
  Vec3 sum{};
  double total = 0.0;
  for (size_t i = begin; i < end; ++i) {
    const double w = static_cast<double>(u[i].weight);
    for (int k = 0; k < 3; ++k) sum[k] += w * u[i].rgb[k];
    total += w;
  }
  for (int k = 0; k < 3; ++k) box.mean[k] = sum[k] / total;
  // Two passes: the one-pass sum(w x^2) - W mean^2 cancels catastrophically.
  for (size_t i = begin; i < end; ++i) {
    box.sse += static_cast<double>(u[i].weight) * distance2(u[i].rgb, box.mean);
  }
  return box;
}

// Heckbert's cut: along the box's longest side (ties to the lower channel, R < G < B) at
// the weighted median, both halves non-empty.
std::pair<Box, Box> split(std::vector<UniqueColour>& u, const Box& box) {
  Vec3 lo = u[box.begin].rgb;
  Vec3 hi = lo;
  for (size_t i = box.begin; i < box.end; ++i) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], u[i].rgb[k]);
      hi[k] = std::max(hi[k], u[i].rgb[k]);
    }
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
  }
  const auto first = u.begin() + static_cast<std::ptrdiff_t>(box.begin);
  const auto last = u.begin() + static_cast<std::ptrdiff_t>(box.end);
  std::sort(first, last, [axis](const UniqueColour& x, const UniqueColour& y) {
    return x.rgb[axis] != y.rgb[axis] ? x.rgb[axis] < y.rgb[axis] : x.key < y.key;
  });
  uint64_t total = 0;
  for (size_t i = box.begin; i < box.end; ++i) total += u[i].weight;
  // The median colour goes to the lower half: cut after the first colour at which the
  // running weight reaches half the total.
  size_t cut = box.begin;
  uint64_t running = 0;
  while (cut < box.end) {
    running += u[cut].weight;
    ++cut;
    if (2 * running >= total) break;
  }
  cut = std::clamp(cut, box.begin + 1, box.end - 1);
  return {make_box(u, box.begin, cut), make_box(u, cut, box.end)};
}

std::vector<Vec3> median_cut_means(std::vector<UniqueColour>& u, size_t max_colours) {
  std::vector<Box> boxes = {make_box(u, 0, u.size())};
  while (boxes.size() < max_colours) {
    // Split the box that holds the most squared error; ties to the older box.
    size_t worst = boxes.size();
    for (size_t i = 0; i < boxes.size(); ++i) {
      if (boxes[i].end - boxes[i].begin < 2 || boxes[i].sse <= 0.0) continue;
      if (worst == boxes.size() || boxes[i].sse > boxes[worst].sse) worst = i;
    }
    if (worst == boxes.size()) break;  // every box is one colour
    auto [lower, upper] = split(u, boxes[worst]);
    boxes[worst] = lower;
    boxes.push_back(upper);
  }
  std::vector<Vec3> means;
  for (const Box& b : boxes) means.push_back(b.mean);
  return means;
}

Palette palette_from(std::vector<Rgb8> entries) {
  std::sort(entries.begin(), entries.end(),
            [](Rgb8 x, Rgb8 y) { return pack_rgb(x) < pack_rgb(y); });
  entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
  Palette p;
  p.used = static_cast<uint32_t>(entries.size());
  std::copy(entries.begin(), entries.end(), p.clut.begin());
  return p;
}

// Lloyd iterations on the rounded palette: assign every colour to its nearest entry, move
// each entry to the rounded weighted mean of its colours. Entries that serve nobody stay.
std::vector<Rgb8> refine(const std::vector<UniqueColour>& u, std::vector<Rgb8> entries) {
  for (int iter = 0; iter < kLloydIterations; ++iter) {
    Palette current;
    current.used = static_cast<uint32_t>(entries.size());
    std::copy(entries.begin(), entries.end(), current.clut.begin());
    const PaletteSearch search(current);
    std::vector<Vec3> sum(entries.size(), Vec3{});
    std::vector<double> weight(entries.size(), 0.0);
    for (const UniqueColour& c : u) {
      const uint8_t i = search.nearest(c.rgb);
      const double w = static_cast<double>(c.weight);
      for (int k = 0; k < 3; ++k) sum[i][k] += w * c.rgb[k];
      weight[i] += w;
    }
    bool moved = false;
    for (size_t i = 0; i < entries.size(); ++i) {
      if (weight[i] == 0.0) continue;
      const Rgb8 next =
          round_colour({sum[i][0] / weight[i], sum[i][1] / weight[i], sum[i][2] / weight[i]});
      moved = moved || next != entries[i];
      entries[i] = next;
    }
    if (!moved) break;  // a fixed point; further iterations would change nothing
  }
  return entries;
}

}  // namespace

uint8_t round_channel(double v) {
  return static_cast<uint8_t>(std::floor(std::clamp(v, 0.0, 255.0) + 0.5));
}

Rgb8 round_colour(const Vec3& rgb) {
  return {round_channel(rgb[0]), round_channel(rgb[1]), round_channel(rgb[2])};
}

Palette median_cut(std::span<const WeightedColour> colours, int max_colours) {
  if (max_colours < 1 || max_colours > 256) {
    throw std::invalid_argument("median_cut: max_colours must be 1..256");
  }
  std::vector<UniqueColour> unique = merge_duplicates(colours);
  if (unique.empty()) throw std::invalid_argument("median_cut: no colour has a weight");
  const auto limit = static_cast<size_t>(max_colours);
  std::vector<Rgb8> entries;
  if (unique.size() <= limit) {
    for (const UniqueColour& c : unique) entries.push_back(unpack_rgb(c.key));
    return palette_from(std::move(entries));
  }
  for (const Vec3& m : median_cut_means(unique, limit)) entries.push_back(round_colour(m));
  return palette_from(refine(unique, std::move(entries)));
}

uint8_t nearest_index(const Palette& palette, const Vec3& rgb) {
  uint32_t best = 0;
  double best_d = distance2(to_vec(palette.clut[0]), rgb);
  for (uint32_t i = 1; i < palette.used; ++i) {
    const double d = distance2(to_vec(palette.clut[i]), rgb);
    if (d < best_d) {
      best = i;
      best_d = d;
    }
  }
  return static_cast<uint8_t>(best);
}

PaletteSearch::PaletteSearch(const Palette& palette) {
  if (palette.used < 1 || palette.used > 256) {
    throw std::invalid_argument("PaletteSearch: palette must have 1..256 used entries");
  }
  for (uint32_t i = 0; i < palette.used; ++i) {
    sorted_.push_back({to_vec(palette.clut[i]), static_cast<uint8_t>(i)});
  }
  Vec3 lo = sorted_[0].rgb;
  Vec3 hi = lo;
  for (const Entry& e : sorted_) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], e.rgb[k]);
      hi[k] = std::max(hi[k], e.rgb[k]);
    }
  }
  // The widest channel separates the entries best, so it prunes the most.
  for (int k = 1; k < 3; ++k) {
    if (hi[k] - lo[k] > hi[axis_] - lo[axis_]) axis_ = k;
  }
  const int axis = axis_;
  std::sort(sorted_.begin(), sorted_.end(), [axis](const Entry& x, const Entry& y) {
    return x.rgb[axis] != y.rgb[axis] ? x.rgb[axis] < y.rgb[axis] : x.index < y.index;
  });
}

template <typename Consider, typename Bound>
void PaletteSearch::walk(const Vec3& rgb, Consider&& consider, Bound&& bound) const {
  const double q = rgb[axis_];
  const auto start =
      std::lower_bound(sorted_.begin(), sorted_.end(), q,
                       [this](const Entry& e, double v) { return e.rgb[axis_] < v; });
  // The full distance is never below the squared axis gap, and the gap only grows
  // outward, so a walk stops once the gap exceeds the bound. An equal gap may still tie
  // with a lower index, hence `>` rather than `>=`.
  for (auto it = start; it != sorted_.end(); ++it) {
    const double gap = it->rgb[axis_] - q;
    if (gap * gap > bound()) break;
    consider(*it);
  }
  for (auto it = start; it != sorted_.begin();) {
    --it;
    const double gap = q - it->rgb[axis_];
    if (gap * gap > bound()) break;
    consider(*it);
  }
}

uint8_t PaletteSearch::nearest(const Vec3& rgb) const {
  uint8_t best = 0;
  double best_d = INFINITY;
  walk(
      rgb,
      [&](const Entry& e) {
        const double d = distance2(e.rgb, rgb);
        if (d < best_d || (d == best_d && e.index < best)) {
          best = e.index;
          best_d = d;
        }
      },
      [&] { return best_d; });
  return best;
}

std::vector<uint8_t> PaletteSearch::nearest(const Vec3& rgb, size_t k) const {
  k = std::min(k, sorted_.size());
  if (k == 0) return {};
  std::vector<std::pair<double, uint8_t>> best;  // ascending (distance, index), at most k
  best.reserve(k + 1);
  walk(
      rgb,
      [&](const Entry& e) {
        const std::pair<double, uint8_t> c{distance2(e.rgb, rgb), e.index};
        if (best.size() == k && !(c < best.back())) return;
        best.insert(std::upper_bound(best.begin(), best.end(), c), c);
        if (best.size() > k) best.pop_back();
      },
      [&] { return best.size() < k ? INFINITY : best.back().first; });
  std::vector<uint8_t> out;
  for (const auto& [d, index] : best) out.push_back(index);
  return out;
}

}  // namespace tmu::ccc
