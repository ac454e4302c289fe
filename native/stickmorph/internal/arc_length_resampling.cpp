// Arc-length resampling of chain pairs (arc_length_resampling.h;
// Surazhsky & Gotsman 2001, section 6).
#include "stickmorph/internal/arc_length_resampling.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace stickmorph::internal {

namespace {

// A vertex pairs with one of the other figure when their arc lengths differ
// by less than this share of the spacing around both (then each has at most
// one candidate and the pairs keep their order along the chain).
constexpr double kMergeShare = 0.3;

}  // namespace

std::vector<MatchedItem> resample(const Track& s, const Track& t, const ChainMatch& match,
                           const std::vector<std::pair<int, int>>& pinned) {
  const bool closed = s.closed;
  const std::size_t first = closed ? 0 : 1;
  const std::size_t s_end = closed ? s.vertices.size() : s.vertices.size() - 1;
  const std::size_t t_end = closed ? t.vertices.size() : t.vertices.size() - 1;
  // The common parameter: the source's, unwrapped from the map's first
  // anchor for a loop so that sorting follows the loop.
  const double base = closed ? match.map.u[0] : 0.0;
  auto common = [&](double u) { return closed ? u - base - std::floor(u - base) : u; };
  std::vector<char> s_pinned(s.vertices.size(), 0), t_pinned(t.vertices.size(), 0);
  std::vector<MatchedItem> items;
  for (const auto& [sv, tv] : pinned) {
    std::size_t ks = first, kt = first;
    while (ks < s_end && s.vertices[ks] != sv) ++ks;
    while (kt < t_end && t.vertices[kt] != tv) ++kt;
    if (ks == s_end || kt == t_end) continue;  // a pin on another chain
    s_pinned[ks] = t_pinned[kt] = 1;
    const double u = vertex_parameter(s, ks);
    items.push_back({common(u), {sv, u}, {tv, vertex_parameter(t, kt)}});
  }
  struct Loose {
    double order;
    std::size_t slot;
  };
  std::vector<Loose> from_source, from_target;
  for (std::size_t k = first; k < s_end; ++k)
    if (!s_pinned[k]) from_source.push_back({common(vertex_parameter(s, k)), k});
  for (std::size_t k = first; k < t_end; ++k)
    if (!t_pinned[k]) {
      const double w = run_parameter(vertex_parameter(t, k), match.reversed);
      from_target.push_back({common(match.map.to_source(w)), k});
    }
  auto by_order = [](const Loose& a, const Loose& b) { return a.order < b.order; };
  std::sort(from_source.begin(), from_source.end(), by_order);
  std::sort(from_target.begin(), from_target.end(), by_order);
  // Spacing around each vertex on its own side: to its neighbours, the
  // chain's ends or pins (a loop wraps around).
  auto spacing = [&](const std::vector<Loose>& side, const std::vector<double>& fixed) {
    std::vector<double> all;
    for (const Loose& l : side) all.push_back(l.order);
    for (double f : fixed) all.push_back(f);
    std::sort(all.begin(), all.end());
    std::vector<double> gap(side.size(), 1.0);
    for (std::size_t k = 0; k < side.size(); ++k) {
      const double x = side[k].order;
      const auto at = std::lower_bound(all.begin(), all.end(), x);
      double g = 1.0;
      if (at != all.begin()) g = std::min(g, x - *(at - 1));
      else if (closed && all.size() > 1) g = std::min(g, x + 1 - all.back());
      if (at + 1 != all.end()) g = std::min(g, *(at + 1) - x);
      else if (closed && all.size() > 1) g = std::min(g, all.front() + 1 - x);
      gap[k] = g;
    }
    return gap;
  };
  std::vector<double> fixed;
  if (!closed) fixed = {0.0, 1.0};
  for (const MatchedItem& item : items) fixed.push_back(item.order);
  const std::vector<double> s_gap = spacing(from_source, fixed), t_gap = spacing(from_target, fixed);
  std::vector<int> partner(from_source.size(), -1);
  std::vector<char> t_taken(from_target.size(), 0);
  // The nearest target vertices on either side of each source vertex; on a
  // loop the sides wrap round the seam at the first anchor, where a vertex
  // just before the seam and one just after are neighbours.
  auto separation = [&](double a, double b) {
    const double d = std::abs(a - b);
    return closed ? std::min(d, 1.0 - d) : d;
  };
  for (std::size_t k = 0; k < from_source.size() && !from_target.empty(); ++k) {
    const double x = from_source[k].order;
    const std::size_t at =
        std::size_t(std::lower_bound(from_target.begin(), from_target.end(), Loose{x, 0}, by_order) -
                    from_target.begin());
    std::vector<std::size_t> sides;
    if (at < from_target.size()) sides.push_back(at);
    else if (closed) sides.push_back(0);
    if (at > 0) sides.push_back(at - 1);
    else if (closed) sides.push_back(from_target.size() - 1);
    for (const std::size_t j : sides) {
      if (t_taken[j] ||
          separation(from_target[j].order, x) >= kMergeShare * std::min(s_gap[k], t_gap[j]))
        continue;
      partner[k] = int(j);
      t_taken[j] = 1;
      break;
    }
  }
  for (std::size_t k = 0; k < from_source.size(); ++k) {
    const std::size_t slot = from_source[k].slot;
    const double u = vertex_parameter(s, slot);
    MatchedItem item{from_source[k].order, {s.vertices[slot], u}, {}};
    if (partner[k] >= 0) {
      const std::size_t ts = from_target[std::size_t(partner[k])].slot;
      item.target = {t.vertices[ts], vertex_parameter(t, ts)};
    } else {
      item.target = {-1, run_parameter(match.map.to_target(u), match.reversed)};
    }
    items.push_back(item);
  }
  for (std::size_t j = 0; j < from_target.size(); ++j) {
    if (t_taken[j]) continue;
    const std::size_t ts = from_target[j].slot;
    const double w = vertex_parameter(t, ts);
    const double u = match.map.to_source(run_parameter(w, match.reversed));
    items.push_back({from_target[j].order, {-1, u}, {t.vertices[ts], w}});
  }
  std::sort(items.begin(), items.end(), [](const MatchedItem& a, const MatchedItem& b) { return a.order < b.order; });
  return items;
}

}  // namespace stickmorph::internal
