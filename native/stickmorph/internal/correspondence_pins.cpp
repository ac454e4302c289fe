// Pins of the correspondence (correspondence_pins.h).
#include "stickmorph/internal/correspondence_pins.h"

#include <algorithm>
#include <string>

#include "stickmorph/errors.h"

namespace stickmorph {

// The public rule (figure_correspondence.h), here with the other pin stage.
PinCheck check_vertex_pins(const std::vector<int>& source_degree, const std::vector<int>& target_degree,
                           const std::vector<VertexPin>& pins) {
  const int ns = int(source_degree.size()), nt = int(target_degree.size());
  std::vector<bool> source_seen(std::size_t(ns), false), target_seen(std::size_t(nt), false);
  PinCheck check;
  auto refuse = [&](PinDefect defect, int k, std::string reason) {
    check.defect = defect;
    check.pin = k;
    check.reason = std::move(reason);
    return check;
  };
  for (std::size_t k = 0; k < pins.size(); ++k) {
    const VertexPin& pin = pins[k];
    const std::string name = "pin " + std::to_string(pin.source) + ":" + std::to_string(pin.target);
    if (pin.source < 0 || pin.source >= ns)
      return refuse(PinDefect::MissingSourceVertex, int(k),
                    name + ": the source has no vertex " + std::to_string(pin.source) + " (it has " +
                        internal::plural(ns, "vertex", "vertices") + ")");
    if (pin.target < 0 || pin.target >= nt)
      return refuse(PinDefect::MissingTargetVertex, int(k),
                    name + ": the target has no vertex " + std::to_string(pin.target) + " (it has " +
                        internal::plural(nt, "vertex", "vertices") + ")");
    if (source_seen[std::size_t(pin.source)])
      return refuse(PinDefect::SourcePinnedTwice, int(k),
                    "source vertex " + std::to_string(pin.source) + " is pinned twice");
    if (target_seen[std::size_t(pin.target)])
      return refuse(PinDefect::TargetPinnedTwice, int(k),
                    "target vertex " + std::to_string(pin.target) + " is pinned twice");
    source_seen[std::size_t(pin.source)] = target_seen[std::size_t(pin.target)] = true;
    const int ds = source_degree[std::size_t(pin.source)], dt = target_degree[std::size_t(pin.target)];
    if ((ds == 2) != (dt == 2) || (ds != 2 && ds != dt)) {
      check.source_degree = ds;
      check.target_degree = dt;
      return refuse(PinDefect::KindsDiffer, int(k),
                    name + " joins a vertex of degree " + std::to_string(ds) + " to one of degree " +
                        std::to_string(dt) +
                        " (a junction or end matches only one of the same degree, a vertex inside a "
                        "stroke only one inside a stroke)");
    }
  }
  return check;
}

namespace internal {

void check_pins(const std::vector<int>& source_degree, const std::vector<int>& target_degree,
                const std::vector<VertexPin>& pins) {
  const PinCheck check = check_vertex_pins(source_degree, target_degree, pins);
  if (!check.ok()) throw InvalidArgumentError("correspond: " + check.reason);
}

void classify_pins(const Skeleton& source, const Skeleton& target, const std::vector<VertexPin>& pins,
                   std::vector<std::pair<int, int>>& node_pins, std::vector<PinPlace>& chain_pins) {
  check_pins(source.degree, target.degree, pins);
  for (const VertexPin& pin : pins) {
    const int ds = source.degree[std::size_t(pin.source)];
    if (ds != 2) {
      node_pins.emplace_back(pin.source, pin.target);
      continue;
    }
    PinPlace place;
    place.source_chain = source.chain_of_vertex[std::size_t(pin.source)];
    place.target_chain = target.chain_of_vertex[std::size_t(pin.target)];
    place.u = vertex_parameter(source.chains[std::size_t(place.source_chain)],
                               std::size_t(source.slot_of_vertex[std::size_t(pin.source)]));
    place.w = vertex_parameter(target.chains[std::size_t(place.target_chain)],
                               std::size_t(target.slot_of_vertex[std::size_t(pin.target)]));
    chain_pins.push_back(place);
  }
}

std::optional<ParameterMap> chain_map(const std::vector<PinPlace>& pins, int source_chain, int target_chain,
                                      bool reversed) {
  std::vector<std::pair<double, double>> anchors{{0.0, 0.0}, {1.0, 1.0}};
  for (const PinPlace& pin : pins) {
    if (pin.source_chain != source_chain) continue;
    if (pin.target_chain != target_chain) return std::nullopt;
    anchors.emplace_back(pin.u, run_parameter(pin.w, reversed));
  }
  std::sort(anchors.begin(), anchors.end());
  ParameterMap map;
  for (std::size_t k = 0; k < anchors.size(); ++k) {
    if (k > 0 && !(anchors[k].second > anchors[k - 1].second)) return std::nullopt;
    map.u.push_back(anchors[k].first);
    map.w.push_back(anchors[k].second);
  }
  return map;
}

}  // namespace internal
}  // namespace stickmorph
