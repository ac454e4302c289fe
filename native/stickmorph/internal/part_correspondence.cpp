// Correspondence of figures of several parts (part_correspondence.h;
// Surazhsky & Gotsman 2001, section 6, extended by issue 14).
#include "stickmorph/internal/part_correspondence.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "stickmorph/compatibility.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/errors.h"
#include "stickmorph/internal/connected_correspondence.h"
#include "stickmorph/internal/correspondence_pins.h"
#include "stickmorph/internal/correspondence_skeleton.h"
#include "stickmorph/internal/correspondence_track.h"
#include "stickmorph/internal/least_cost_assignment.h"
#include "stickmorph/internal/matched_parts.h"

namespace stickmorph::internal {

namespace {

// What a matching of two parts needs (compare_invariants): the number of
// independent cycles and the degrees of the nodes (vertices of degree
// other than 2), and nothing but a vertex for a lone vertex.
struct PartShape {
  int cycles = 0;
  std::vector<int> node_degrees;  // sorted
  bool operator==(const PartShape& other) const {
    return cycles == other.cycles && node_degrees == other.node_degrees;
  }
};

PartShape part_shape(const StickFigure& part) {
  PartShape shape;
  shape.cycles = int(part.edges.size()) - int(part.vertices.size()) + 1;
  std::vector<int> degree(part.vertices.size(), 0);
  for (const Edge& e : part.edges) ++degree[std::size_t(e[0])], ++degree[std::size_t(e[1])];
  for (int d : degree)
    if (d != 2) shape.node_degrees.push_back(d);
  std::sort(shape.node_degrees.begin(), shape.node_degrees.end());
  return shape;
}

std::string describe_shape(const PartShape& shape, std::size_t vertices) {
  if (vertices == 1) return "a lone vertex";
  int ends = 0;
  for (int d : shape.node_degrees) ends += d == 1;
  std::string text = plural(shape.cycles, "loop", "loops") + ", " + plural(ends, "end", "ends");
  const std::size_t junctions = shape.node_degrees.size() - std::size_t(ends);
  if (junctions) text += ", " + plural((long long)junctions, "junction", "junctions");
  return text;
}

// Where a part is in its figure: the centre and the diagonal of its
// bounding box, relative to the whole figure's box (centre at 0, diagonal
// 1). Boxes do not depend on how densely a stroke is sampled.
struct PartPlace {
  Vec2 center{0, 0};
  double size = 0;
};

std::vector<PartPlace> part_places(const StickFigure& whole, const FigureParts& parts) {
  auto box = [&](const std::vector<int>& vertices, Vec2& lo, Vec2& hi) {
    lo = hi = whole.vertices[std::size_t(vertices.front())];
    for (int v : vertices)
      for (int c = 0; c < 2; ++c) {
        lo[std::size_t(c)] = std::min(lo[std::size_t(c)], whole.vertices[std::size_t(v)][std::size_t(c)]);
        hi[std::size_t(c)] = std::max(hi[std::size_t(c)], whole.vertices[std::size_t(v)][std::size_t(c)]);
      }
  };
  std::vector<int> all(whole.vertices.size());
  std::iota(all.begin(), all.end(), 0);
  Vec2 lo, hi;
  box(all, lo, hi);
  const Vec2 center{0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
  double diagonal = distance(lo, hi);
  if (!(diagonal > 0)) diagonal = 1;
  std::vector<PartPlace> places;
  for (const std::vector<int>& vertices : parts.vertices) {
    Vec2 a, b;
    box(vertices, a, b);
    PartPlace place;
    place.center = {(0.5 * (a[0] + b[0]) - center[0]) / diagonal, (0.5 * (a[1] + b[1]) - center[1]) / diagonal};
    place.size = distance(a, b) / diagonal;
    places.push_back(place);
  }
  return places;
}

// What each part holds: its shape with the sorted contents of the parts
// directly inside it, recursively, so that a square holding a triangle is
// never paired with an empty hexagon (its triangle would have nowhere to
// go). Parts that may be paired have equal texts.
std::vector<std::string> nesting_contents(const std::vector<PartShape>& shapes, const PartNesting& nesting) {
  const std::size_t count = shapes.size();
  std::vector<std::string> text(count);
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return nesting.enclosing[a].size() > nesting.enclosing[b].size();
  });
  std::vector<std::vector<std::string>> inside(count);
  for (std::size_t part : order) {  // the deepest first
    std::sort(inside[part].begin(), inside[part].end());
    std::string t = std::to_string(shapes[part].cycles) + ":";
    for (int d : shapes[part].node_degrees) t += std::to_string(d) + ",";
    t += "(";
    for (const std::string& child : inside[part]) t += child + ";";
    text[part] = t + ")";
    if (nesting.parent_part[part] >= 0) inside[std::size_t(nesting.parent_part[part])].push_back(text[part]);
  }
  return text;
}

std::string without_prefix(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0 ? text.substr(prefix.size()) : text;
}

}  // namespace

FigureCorrespondence correspond_parts(const StickFigure& source, const StickFigure& target,
                                      const CorrespondenceOptions& options, const FigureParts& source_parts,
                                      const FigureParts& target_parts) {
  const auto start = std::chrono::steady_clock::now();
  const int k = source_parts.count();
  // The pins' own rules first: a bad pin is the caller's mistake whatever
  // the figures are.
  auto degrees = [](const StickFigure& f) {
    std::vector<int> degree(f.vertices.size(), 0);
    for (const Edge& e : f.edges) ++degree[std::size_t(e[0])], ++degree[std::size_t(e[1])];
    return degree;
  };
  check_pins(degrees(source), degrees(target), options.pins);
  if (target_parts.count() != k)
    topology_differs("the source has " + plural(k, "part", "parts") + " and the target " +
                     std::to_string(target_parts.count()) + " (parts are the connected pieces of a figure)");

  std::vector<PartFigure> source_pieces, target_pieces;
  std::vector<PartShape> source_shapes, target_shapes;
  for (int p = 0; p < k; ++p) {
    source_pieces.push_back(part_figure(source, source_parts, p));
    target_pieces.push_back(part_figure(target, target_parts, p));
    source_shapes.push_back(part_shape(source_pieces.back().figure));
    target_shapes.push_back(part_shape(target_pieces.back().figure));
  }
  // Nesting depth: how many parts enclose a part. Matched parts must agree.
  const PartNesting source_nesting = part_nesting(source, decompose(source), source_parts);
  const PartNesting target_nesting = part_nesting(target, decompose(target), target_parts);
  const std::vector<std::string> source_contents = nesting_contents(source_shapes, source_nesting);
  const std::vector<std::string> target_contents = nesting_contents(target_shapes, target_nesting);

  // Pins pair parts.
  std::vector<int> forced(std::size_t(k), -1), forced_by(std::size_t(k), -1);
  std::vector<std::string> forcing_pin(static_cast<std::size_t>(k));
  for (const VertexPin& pin : options.pins) {
    const int a = source_parts.part_of_vertex[std::size_t(pin.source)];
    const int b = target_parts.part_of_vertex[std::size_t(pin.target)];
    const std::string name = "pin " + std::to_string(pin.source) + ":" + std::to_string(pin.target);
    if ((forced[std::size_t(a)] >= 0 && forced[std::size_t(a)] != b) ||
        (forced_by[std::size_t(b)] >= 0 && forced_by[std::size_t(b)] != a))
      throw IncompatibleFiguresError(Incompatibility::PinsUnsatisfiable,
                                     "correspond: " + name + " and " +
                                         forcing_pin[std::size_t(forced[std::size_t(a)] >= 0 ? a : forced_by[std::size_t(b)])] +
                                         " pair one part of a figure with two parts of the other");
    forced[std::size_t(a)] = b;
    forced_by[std::size_t(b)] = a;
    forcing_pin[std::size_t(a)] = name;
  }

  const std::vector<PartPlace> source_places = part_places(source, source_parts);
  const std::vector<PartPlace> target_places = part_places(target, target_parts);
  auto allowed = [&](int a, int b) {
    return source_contents[std::size_t(a)] == target_contents[std::size_t(b)] &&
           source_nesting.enclosing[std::size_t(a)].size() == target_nesting.enclosing[std::size_t(b)].size() &&
           (forced[std::size_t(a)] < 0 || forced[std::size_t(a)] == b) &&
           (forced_by[std::size_t(b)] < 0 || forced_by[std::size_t(b)] == a);
  };

  // The reference pair: the source's largest part and the target part of
  // its shape and depth nearest in size. Its match gives the whole figure's
  // rotation and scale, which place the other parts (a target turned a
  // quarter turn has its parts a quarter turn round) and which symmetric
  // parts are charged from (Skeleton::reference_rotation).
  int reference = 0;
  for (int a = 1; a < k; ++a)
    if (source_places[std::size_t(a)].size > source_places[std::size_t(reference)].size) reference = a;
  int reference_partner = -1;
  for (int b = 0; b < k; ++b)
    if (allowed(reference, b) &&
        (reference_partner < 0 || std::abs(target_places[std::size_t(b)].size - source_places[std::size_t(reference)].size) <
                                      std::abs(target_places[std::size_t(reference_partner)].size -
                                               source_places[std::size_t(reference)].size)))
      reference_partner = b;
  std::vector<FigureCorrespondence> matched(static_cast<std::size_t>(k));
  std::vector<bool> done(std::size_t(k), false);
  auto match_pair = [&](int a, int b, double reference_rotation) {
    const PartFigure& sp = source_pieces[std::size_t(a)];
    const PartFigure& tp = target_pieces[std::size_t(b)];
    CorrespondenceOptions local;
    for (const VertexPin& pin : options.pins)
      if (source_parts.part_of_vertex[std::size_t(pin.source)] == a) {
        VertexPin l;
        l.source = int(std::find(sp.global_vertex.begin(), sp.global_vertex.end(), pin.source) - sp.global_vertex.begin());
        l.target = int(std::find(tp.global_vertex.begin(), tp.global_vertex.end(), pin.target) - tp.global_vertex.begin());
        local.pins.push_back(l);
      }
    const std::string which = "correspond: " + describe_part(source_parts, a) + " of the source and " +
                              describe_part(target_parts, b) + " of the target (numbered within each part): ";
    try {
      matched[std::size_t(a)] = correspond_connected(sp.figure, tp.figure, local, reference_rotation);
    } catch (const IncompatibleFiguresError& error) {
      throw IncompatibleFiguresError(error.kind(), which + without_prefix(error.what(), "correspond: "),
                                     {sp.global_vertex.front()});
    } catch (const InvalidArgumentError& error) {
      throw InvalidArgumentError(which + without_prefix(error.what(), "correspond: "));
    }
    done[std::size_t(a)] = true;
  };
  double rotation = 0, scale = 1;
  if (reference_partner >= 0) {
    match_pair(reference, reference_partner, 0.0);
    rotation = matched[std::size_t(reference)].rotation_degrees * kPi / 180.0;
    if (source_places[std::size_t(reference)].size > 0 && target_places[std::size_t(reference_partner)].size > 0)
      scale = target_places[std::size_t(reference_partner)].size / source_places[std::size_t(reference)].size;
  }
  // Where part a would be in the target if the whole figure moved like the
  // reference pair.
  auto predicted = [&](int a) {
    if (reference_partner < 0) return source_places[std::size_t(a)].center;
    const Vec2& o = source_places[std::size_t(reference)].center;
    const Vec2& p = source_places[std::size_t(a)].center;
    const double dx = p[0] - o[0], dy = p[1] - o[1];
    const double c = std::cos(rotation), s = std::sin(rotation);
    const Vec2& q = target_places[std::size_t(reference_partner)].center;
    return Vec2{q[0] + scale * (c * dx - s * dy), q[1] + scale * (s * dx + c * dy)};
  };

  // The parts paired level by level from the outside in, so that a part's
  // partner lies in its parent's partner (the matched figures then nest
  // alike wherever the parents' faces correspond). A pairing that cannot
  // match costs more than any that can (kBarred), so that the assignment
  // uses one only where nothing else is left.
  constexpr double kBarred = 1e12;
  std::vector<int> partner(std::size_t(k), -1);
  std::size_t deepest = 0;
  for (int a = 0; a < k; ++a) deepest = std::max(deepest, source_nesting.enclosing[std::size_t(a)].size());
  for (std::size_t depth = 0; depth <= deepest; ++depth) {
    std::vector<int> rows, columns;
    for (int a = 0; a < k; ++a)
      if (source_nesting.enclosing[std::size_t(a)].size() == depth) rows.push_back(a);
    for (int b = 0; b < k; ++b)
      if (target_nesting.enclosing[std::size_t(b)].size() == depth) columns.push_back(b);
    if (rows.empty()) continue;
    if (rows.size() != columns.size()) {
      // Name a part of the figure that has more at this depth: its smallest
      // (the part that moved is more often a dot or a counter than the
      // part around it).
      const bool source_more = rows.size() > columns.size();
      const std::vector<int>& more = source_more ? rows : columns;
      const std::vector<PartPlace>& places = source_more ? source_places : target_places;
      int named = more.front();
      for (int part : more)
        if (places[std::size_t(part)].size < places[std::size_t(named)].size) named = part;
      const std::string where = depth == 0 ? std::string("at the top level (inside no other part)")
                                           : "inside " + plural((long long)depth, "other part", "other parts");
      throw IncompatibleFiguresError(
          Incompatibility::NestingDiffers,
          "correspond: the parts nest differently: the source has " + plural((long long)rows.size(), "part", "parts") +
              " " + where + " and the target " + std::to_string(columns.size()) + " (" +
              describe_part(source_more ? source_parts : target_parts, named) + " of the " +
              (source_more ? "source" : "target") + " is one of them)",
          source_more ? std::vector<int>{source_parts.vertices[std::size_t(named)].front()} : std::vector<int>{});
    }
    std::vector<std::vector<double>> cost(rows.size(), std::vector<double>(columns.size(), 0.0));
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (std::size_t j = 0; j < columns.size(); ++j) {
        const int a = rows[i], b = columns[j];
        const int parent = source_nesting.parent_part[std::size_t(a)];
        bool possible = allowed(a, b) &&
                        (parent < 0 || partner[std::size_t(parent)] == target_nesting.parent_part[std::size_t(b)]) &&
                        (a != reference || reference_partner < 0 || b == reference_partner);
        const Vec2 x = predicted(a);
        const PartPlace& y = target_places[std::size_t(b)];
        const double dx = x[0] - y.center[0], dy = x[1] - y.center[1];
        const double ds = scale * source_places[std::size_t(a)].size - y.size;
        cost[i][j] = (possible ? 0.0 : kBarred) + dx * dx + dy * dy + 0.25 * ds * ds;
      }
    const std::vector<int> chosen = least_cost_assignment(cost);
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const int a = rows[i], b = columns[std::size_t(chosen[i])];
      if (cost[i][std::size_t(chosen[i])] >= kBarred) {
        const PartShape& shape = source_shapes[std::size_t(a)];
        std::string why = "no part of the target is left for " + describe_part(source_parts, a) + " of the source (" +
                          describe_shape(shape, source_parts.vertices[std::size_t(a)].size()) + ", inside " +
                          plural((long long)depth, "other part", "other parts") +
                          ") that has its shape, holds the same parts and lies in the part matched to its parent";
        if (forced[std::size_t(a)] >= 0) {
          why += "; " + forcing_pin[std::size_t(a)] + " pairs it with " +
                 describe_part(target_parts, forced[std::size_t(a)]) + " of the target";
          throw IncompatibleFiguresError(Incompatibility::PinsUnsatisfiable, "correspond: " + why,
                                         {source_parts.vertices[std::size_t(a)].front()});
        }
        topology_differs(why);
      }
      partner[std::size_t(a)] = b;
    }
  }

  // Each pair matched on its own, charged from the whole figure's rotation.
  for (int a = 0; a < k; ++a)
    if (!done[std::size_t(a)]) match_pair(a, partner[std::size_t(a)], rotation);
  FigureCorrespondence result =
      assemble_matched_parts(source, target, source_pieces, target_pieces, matched, partner);
  result.milliseconds = milliseconds_since(start);
  return result;
}

}  // namespace stickmorph::internal
