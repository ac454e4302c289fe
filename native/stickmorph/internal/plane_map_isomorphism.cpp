// Plane-map isomorphisms of skeletons (plane_map_isomorphism.h;
// Surazhsky & Gotsman 2001, sections 2.1 and 6).
#include "stickmorph/internal/plane_map_isomorphism.h"

#include <map>

#include "stickmorph/errors.h"

namespace stickmorph::internal {

std::optional<std::vector<int>> extend_isomorphism(const Skeleton& source, const Skeleton& target, int seed,
                                                   int image) {
  std::vector<int> forward(std::size_t(source.dart_count()), -1), backward(std::size_t(target.dart_count()), -1);
  std::vector<std::pair<int, int>> queue{{seed, image}};
  forward[std::size_t(seed)] = image;
  backward[std::size_t(image)] = seed;
  for (std::size_t next = 0; next < queue.size(); ++next) {
    const auto [d, e] = queue[next];
    if (source.degree[std::size_t(source.node_of(d))] != target.degree[std::size_t(target.node_of(e))])
      return std::nullopt;
    for (const auto& [dd, ee] : {std::pair{source.ccw_next(d), target.ccw_next(e)},
                                 std::pair{source.far_dart[std::size_t(d)], target.far_dart[std::size_t(e)]}}) {
      const int known = forward[std::size_t(dd)];
      if (known == ee) continue;
      if (known >= 0 || backward[std::size_t(ee)] >= 0) return std::nullopt;
      forward[std::size_t(dd)] = ee;
      backward[std::size_t(ee)] = dd;
      queue.emplace_back(dd, ee);
    }
  }
  return forward;
}

int exterior_dart(const Skeleton& skeleton) {
  const Decomposition& dec = skeleton.decomposition;
  for (int dart : dec.sequences[std::size_t(dec.exterior)].darts)
    if (skeleton.leaves_node(dart)) return dart;
  throw InternalError("correspond: the exterior face of a figure with nodes holds no dart leaving a node");
}

std::optional<Candidate> make_candidate(const Skeleton& source, const Skeleton& target, const std::vector<int>& map,
                                        const std::vector<std::pair<int, int>>& node_pins,
                                        const std::vector<PinPlace>& chain_pins, std::string& broken) {
  Candidate candidate;
  candidate.node_image.assign(source.figure->vertices.size(), -1);
  for (int dart = 0; dart < source.dart_count(); ++dart)
    if (source.leaves_node(dart))
      candidate.node_image[std::size_t(source.node_of(dart))] = target.node_of(map[std::size_t(dart)]);
  for (const auto& [s, t] : node_pins)
    if (candidate.node_image[std::size_t(s)] != t) {
      broken = "it would send source vertex " + std::to_string(s) + " to target vertex " +
               std::to_string(candidate.node_image[std::size_t(s)]) + ", not " + std::to_string(t);
      return std::nullopt;
    }
  for (std::size_t chain = 0; chain < source.chains.size(); ++chain) {
    const int e = map[std::size_t(source.chain_first[chain])];
    ChainMatch match;
    match.source_chain = int(chain);
    match.target_chain = target.chain_of_dart[std::size_t(e)];
    match.reversed = !target.forward[std::size_t(e)];
    std::optional<ParameterMap> pmap = chain_map(chain_pins, match.source_chain, match.target_chain, match.reversed);
    if (!pmap) {
      broken = "a pinned vertex inside a stroke would land on another stroke or out of order along it";
      return std::nullopt;
    }
    match.map = *pmap;
    candidate.chains.push_back(std::move(match));
  }
  return candidate;
}

IsomorphismSearch search_isomorphisms(const Skeleton& source, const Skeleton& target,
                           const std::vector<std::pair<int, int>>& node_pins, const std::vector<PinPlace>& chain_pins,
                           bool with_cost) {
  IsomorphismSearch search;
  // Seed at the node whose degree is rarest among the target's nodes: the
  // fewest images to try, each O(skeleton) to extend.
  std::map<int, int> degree_count;
  for (int node : target.nodes) ++degree_count[target.degree[std::size_t(node)]];
  int seed_node = source.nodes[0];
  for (int node : source.nodes)
    if (degree_count[source.degree[std::size_t(node)]] < degree_count[source.degree[std::size_t(seed_node)]])
      seed_node = node;
  search.seed = source.decomposition.rotation.outgoing_ccw[std::size_t(seed_node)][0];
  const int source_exterior = exterior_dart(source);
  const int target_exterior = target.decomposition.exterior;
  for (int image_node : target.nodes) {
    if (target.degree[std::size_t(image_node)] != source.degree[std::size_t(seed_node)]) continue;
    for (int image : target.decomposition.rotation.outgoing_ccw[std::size_t(image_node)]) {
      const std::optional<std::vector<int>> map = extend_isomorphism(source, target, search.seed, image);
      if (!map) continue;
      search.any_isomorphism = true;
      const int exterior_image = (*map)[std::size_t(source_exterior)];
      if (target.decomposition.sequence_of_dart[std::size_t(exterior_image)] != target_exterior) continue;
      search.any_exterior = true;
      std::string broken;
      const std::optional<Candidate> candidate = make_candidate(source, target, *map, node_pins, chain_pins, broken);
      if (!candidate) {
        if (search.pin_conflict.empty()) search.pin_conflict = broken;
        continue;
      }
      search.images.push_back(image);
      search.fits.push_back(with_cost ? candidate_fit(source, target, candidate->chains, kChainSamples) : Fit{});
    }
  }
  return search;
}

}  // namespace stickmorph::internal
