// Parts as figures and the matched parts put together (matched_parts.h).
#include "stickmorph/internal/matched_parts.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <utility>

#include "stickmorph/compatibility.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/errors.h"

namespace stickmorph::internal {

// Part `part` of a valid figure as a figure of its own. Valid by
// construction, so built without make_stick_figure's checks: its vertices
// are some of the whole figure's, at the same coordinates, and its edges are
// all the whole figure's edges between them (a part is a connected
// component, so an edge with one end in it has both); a subset of the
// vertices and edges of a plane graph with no coincident vertices, no
// duplicate edges and no crossings has none either.
PartFigure part_figure(const StickFigure& whole, const FigureParts& parts, int part) {
  PartFigure result;
  result.global_vertex = parts.vertices[std::size_t(part)];
  std::vector<int> local(whole.vertices.size(), -1);
  std::vector<Vec2> vertices;
  for (std::size_t k = 0; k < result.global_vertex.size(); ++k) {
    local[std::size_t(result.global_vertex[k])] = int(k);
    vertices.push_back(whole.vertices[std::size_t(result.global_vertex[k])]);
  }
  // Same order and direction as in the whole figure, so that a dummy's
  // fraction along its edge means the same in both.
  std::vector<Edge> edges;
  for (std::size_t e = 0; e < whole.edges.size(); ++e)
    if (local[std::size_t(whole.edges[e][0])] >= 0) {
      edges.push_back({local[std::size_t(whole.edges[e][0])], local[std::size_t(whole.edges[e][1])]});
      result.global_edge.push_back(int(e));
    }
  result.figure = StickFigure{std::move(vertices), std::move(edges), whole.name};
  return result;
}

FigureCorrespondence assemble_matched_parts(const StickFigure& source, const StickFigure& target,
                                            const std::vector<PartFigure>& source_pieces,
                                            const std::vector<PartFigure>& target_pieces,
                                            const std::vector<FigureCorrespondence>& matched,
                                            const std::vector<int>& partner) {
  const int k = int(matched.size());
  const int ns = int(source.vertices.size());
  FigureCorrespondence result;
  std::size_t largest = 0;
  double weight = 0;
  for (int a = 0; a < k; ++a) {
    const FigureCorrespondence& m = matched[std::size_t(a)];
    const PartFigure& sp = source_pieces[std::size_t(a)];
    result.skeleton_nodes += m.skeleton_nodes;
    result.skeleton_chains += m.skeleton_chains;
    result.candidates += m.candidates;
    // The residual of the whole: the parts' residuals weighted by their
    // matched vertices.
    result.residual += m.residual * double(m.source_places.size());
    weight += double(m.source_places.size());
    if (sp.figure.vertices.size() > largest) {
      largest = sp.figure.vertices.size();
      result.rotation_degrees = m.rotation_degrees;
    }
  }
  if (weight > 0) result.residual /= weight;

  // Put together: the source's vertices keep their numbers; the dummies of
  // every part follow, ordered by the target vertex they stand for.
  std::vector<std::pair<int, std::pair<int, int>>> dummies;  // (target vertex, (part, local matched index))
  for (int a = 0; a < k; ++a) {
    const FigureCorrespondence& m = matched[std::size_t(a)];
    const PartFigure& tp = target_pieces[std::size_t(partner[std::size_t(a)])];
    for (std::size_t i = source_pieces[std::size_t(a)].global_vertex.size(); i < m.source_places.size(); ++i)
      dummies.push_back({tp.global_vertex[std::size_t(m.target_places[i].vertex)], {a, int(i)}});
  }
  std::sort(dummies.begin(), dummies.end());
  std::vector<std::vector<int>> global_index(static_cast<std::size_t>(k));
  for (int a = 0; a < k; ++a) {
    global_index[std::size_t(a)] = source_pieces[std::size_t(a)].global_vertex;
    global_index[std::size_t(a)].resize(matched[std::size_t(a)].source_places.size(), -1);
  }
  for (std::size_t d = 0; d < dummies.size(); ++d)
    global_index[std::size_t(dummies[d].second.first)][std::size_t(dummies[d].second.second)] = ns + int(d);
  const std::size_t m_total = std::size_t(ns) + dummies.size();
  std::vector<Vec2> source_positions(m_total), target_positions(m_total);
  result.source_places.resize(m_total);
  result.target_places.resize(m_total);
  std::vector<std::array<std::int64_t, 2>> edges;
  auto globalise = [](MatchedPlace place, const PartFigure& piece) {
    if (place.vertex >= 0) place.vertex = piece.global_vertex[std::size_t(place.vertex)];
    if (place.edge >= 0) place.edge = piece.global_edge[std::size_t(place.edge)];
    return place;
  };
  for (int a = 0; a < k; ++a) {
    const FigureCorrespondence& m = matched[std::size_t(a)];
    const PartFigure& sp = source_pieces[std::size_t(a)];
    const PartFigure& tp = target_pieces[std::size_t(partner[std::size_t(a)])];
    const std::vector<int>& index = global_index[std::size_t(a)];
    for (std::size_t i = 0; i < m.source_places.size(); ++i) {
      const std::size_t g = std::size_t(index[i]);
      source_positions[g] = m.source.vertices[i];
      target_positions[g] = m.target.vertices[i];
      result.source_places[g] = globalise(m.source_places[i], sp);
      result.target_places[g] = globalise(m.target_places[i], tp);
    }
    for (const Edge& e : m.source.edges) edges.push_back({index[std::size_t(e[0])], index[std::size_t(e[1])]});
  }
  try {
    result.source = make_stick_figure(std::move(source_positions), edges, source.name);
    result.target = make_stick_figure(std::move(target_positions), edges, target.name);
  } catch (const InvalidFigureError& error) {
    // Each matched part is valid; together they can only fail where a dummy,
    // rounded off its edge, touches a part close by.
    throw VerificationError(std::string("correspond: the matched parts cannot be drawn in floating point: ") +
                            error.what());
  }
  // Each part pair is compatible by construction; the nesting is the pair's
  // own (the matched part i is the source's part i), and is checked here.
  CompatibilityReport report;
  result.pair = CompatiblePair::try_check(result.source, decompose(result.source), result.target,
                                          decompose(result.target), report);
  if (report.kind == Incompatibility::NestingDiffers)
    throw IncompatibleFiguresError(Incompatibility::NestingDiffers,
                                   "correspond: with the parts matched by shape and place, " + report.reason +
                                       " (vertices of the matched figure)",
                                   report.vertices);
  if (!report.compatible())
    throw InternalError("correspond: the matched figures are not compatible: " + report.reason);
  return result;
}

}  // namespace stickmorph::internal
