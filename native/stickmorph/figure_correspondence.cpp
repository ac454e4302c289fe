// Automatic correspondence (figure_correspondence.h): skeletons matched as
// plane maps, chains resampled by arc length with dummy vertices (Surazhsky
// & Gotsman 2001, section 6).
//
// The public entry only: the working scale, the parsing of modes and pins,
// and is_valid. The stages are in internal/: correspondence_skeleton (step
// 1), plane_map_isomorphism (2), correspondence_choice (3), corner_anchors,
// arc_length_resampling and dummy_placement (4), correspondence_track and
// correspondence_pins (shared by them), connected_correspondence (steps 1-4
// for one connected pair) and part_correspondence with
// least_cost_assignment (figures of several parts, issue 14).
#include "stickmorph/figure_correspondence.h"
#include "stickmorph/working_scale.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "stickmorph/errors.h"
#include "stickmorph/figure_parts.h"
#include "stickmorph/internal/connected_correspondence.h"
#include "stickmorph/internal/correspondence_track.h"
#include "stickmorph/internal/part_correspondence.h"

namespace stickmorph {

CorrespondenceMode parse_correspondence_mode(const std::string& name) {
  if (name == "index") return CorrespondenceMode::ByIndex;
  if (name == "auto") return CorrespondenceMode::Auto;
  throw InvalidArgumentError("unknown correspondence '" + name + "' (choose index or auto)");
}

std::string correspondence_mode_name(CorrespondenceMode mode) {
  return mode == CorrespondenceMode::Auto ? "auto" : "index";
}

VertexPin parse_vertex_pin(const std::string& text) {
  const std::size_t colon = text.find(':');
  auto whole = [](const std::string& part, int& value) {
    if (part.empty() || part.size() > 9) return false;
    for (char c : part)
      if (c < '0' || c > '9') return false;
    value = std::stoi(part);
    return true;
  };
  VertexPin pin;
  if (colon == std::string::npos || !whole(text.substr(0, colon), pin.source) ||
      !whole(text.substr(colon + 1), pin.target))
    throw InvalidArgumentError("a pin is SOURCE:TARGET, two vertex indices such as 3:7, got '" + text + "'");
  return pin;
}

namespace {

using internal::correspond_connected;
using internal::correspond_parts;
using internal::point_on;

FigureCorrespondence correspond_at_scale(const StickFigure& source, const StickFigure& target,
                                         const CorrespondenceOptions& options) {
  const FigureParts source_parts = figure_parts(source), target_parts = figure_parts(target);
  if (source_parts.count() == 1 && target_parts.count() == 1) return correspond_connected(source, target, options);
  return correspond_parts(source, target, options, source_parts, target_parts);
}

// A matched figure found in the working scale 2^exponent, written back at
// the figures' own scale through make_stick_figure (InvalidFigureError):
// multiplying by 2^-exponent is exact but for a dummy vertex that lands
// within 2^-1022 of 0 and may round onto another vertex or edge.
StickFigure figure_at_own_scale(const StickFigure& matched, int exponent) {
  std::vector<Vec2> vertices = matched.vertices;
  for (Vec2& p : vertices)
    for (double& c : p) c = std::ldexp(c, -exponent);
  std::vector<std::array<std::int64_t, 2>> edges;
  edges.reserve(matched.edges.size());
  for (const Edge& e : matched.edges) edges.push_back({e[0], e[1]});
  return make_stick_figure(std::move(vertices), edges, matched.name);
}

}  // namespace

FigureCorrespondence correspond_figures(const StickFigure& source, const StickFigure& target,
                                        const CorrespondenceOptions& options) {
  // In the morph's working scale (working_scale.h): the similarity fits and
  // arc lengths square coordinates, which overflow for figures near 1e99
  // (a NaN residual) and underflow near 1e-200. The match is scale-free
  // (its residual and rotation are ratios); only the matched positions
  // are multiplied back.
  const int exponent = working_scale_exponent(source, target);
  if (exponent == 0) return correspond_at_scale(source, target, options);
  FigureCorrespondence matched =
      correspond_at_scale(scaled_figure(source, exponent), scaled_figure(target, exponent), options);
  // Exact but for dummies that land within 2^-1022 of 0: the figures are
  // rebuilt through the checked constructor, and the matching checked again.
  const char* const below_normal =
      "the matched figures, once written at the figures' own scale, are no longer valid: "
      "their dummy vertices round below the smallest normal double";
  try {
    matched.source = figure_at_own_scale(matched.source, exponent);
    matched.target = figure_at_own_scale(matched.target, exponent);
  } catch (const InvalidFigureError&) {
    throw NumericRangeError(below_normal);
  }
  if (!is_valid(matched, source, target)) throw NumericRangeError(below_normal);
  // The checked pair goes back too, or the morph would run on the
  // working-scale figures and write its frames there (a fuzz finding). It
  // keeps its proof only if every coordinate went back exactly; otherwise
  // the morph checks the written figures again.
  if (matched.pair) {
    bool exact = false;
    CompatiblePair own_scale = scaled_pair(*matched.pair, -exponent, &exact);
    if (exact)
      matched.pair = std::move(own_scale);
    else
      matched.pair.reset();
  }
  return matched;
}

bool is_valid(const FigureCorrespondence& c, const StickFigure& source, const StickFigure& target) {
  const std::size_t m = c.source.vertices.size();
  if (c.target.vertices.size() != m || c.source_places.size() != m || c.target_places.size() != m) return false;
  if (c.source.edges != c.target.edges || !is_valid(c.source) || !is_valid(c.target)) return false;
  auto check_side = [&](const StickFigure& figure, const StickFigure& matched, const std::vector<MatchedPlace>& places) {
    std::vector<int> seen(figure.vertices.size(), 0);
    for (std::size_t i = 0; i < m; ++i) {
      const MatchedPlace& place = places[i];
      if (place.vertex >= 0) {
        if (place.vertex >= int(figure.vertices.size()) || seen[std::size_t(place.vertex)]++) return false;
        if (matched.vertices[i] != figure.vertices[std::size_t(place.vertex)]) return false;
        continue;
      }
      if (place.edge < 0 || place.edge >= int(figure.edges.size())) return false;
      if (!(place.fraction > 0 && place.fraction < 1)) return false;
      const Edge& e = figure.edges[std::size_t(place.edge)];
      if (matched.vertices[i] != point_on(figure.vertices[std::size_t(e[0])], figure.vertices[std::size_t(e[1])],
                                          place.fraction))
        return false;
    }
    if (std::find(seen.begin(), seen.end(), 0) != seen.end()) return false;
    // Every matched edge on one original edge: its ends are that edge's
    // vertices or dummies on it, and the original edges are covered once.
    std::vector<double> covered(figure.edges.size(), 0.0);
    for (const Edge& me : matched.edges) {
      const MatchedPlace& a = places[std::size_t(me[0])];
      const MatchedPlace& b = places[std::size_t(me[1])];
      int edge = a.vertex < 0 ? a.edge : b.vertex < 0 ? b.edge : -1;
      if (edge < 0) {
        edge = find_edge(figure, a.vertex, b.vertex);
        if (edge < 0) return false;
      }
      const Edge& e = figure.edges[std::size_t(edge)];
      auto along = [&](const MatchedPlace& p) -> double {
        if (p.vertex < 0) return p.edge == edge ? p.fraction : -1.0;
        return p.vertex == e[0] ? 0.0 : p.vertex == e[1] ? 1.0 : -1.0;
      };
      const double fa = along(a), fb = along(b);
      if (fa < 0 || fb < 0 || fa == fb) return false;
      covered[std::size_t(edge)] += std::abs(fb - fa);
    }
    for (double share : covered)
      if (std::abs(share - 1.0) > 1e-9) return false;
    return true;
  };
  return check_side(source, c.source, c.source_places) && check_side(target, c.target, c.target_places);
}

}  // namespace stickmorph
