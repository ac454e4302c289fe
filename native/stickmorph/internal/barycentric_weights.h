// Convex-combination weights of one interior node (Floater & Gotsman 1999,
// the paper's [8]; section 2.2 of the paper).
//
// [8] represents a triangulation with a convex boundary by the weights with
// which every interior node is a positive convex combination of its
// neighbours (Tutte 1963, Floater 1997). Each kind here reproduces the
// embedding it is computed from (sum_j w_ij p_j = p_i), which is what makes
// the morph's frame 0 the source and its last frame the target; see
// WeightKind in morph.h for the three kinds.
#pragma once

#include <vector>

#include "stickmorph/internal/morph_topology.h"
#include "stickmorph/morph.h"

namespace stickmorph::internal {

// Each of these takes the neighbours' offsets q_j = p_j - p_i, in
// counter-clockwise order round p_i, scaled so that the largest coordinate
// is about 1 (all three kinds are invariant under scaling, and the scaling
// keeps squares and products of tiny or huge coordinates finite and
// normal), and returns one weight per neighbour, summing to 1.

/// Mean value coordinates (Floater 2003).
std::vector<double> mean_value_weights(const std::vector<Vec2>& q);
/// The same weights into w (resized to q's size), allocating nothing once
/// w has the capacity: the rigid morph takes them of every figure vertex in
/// every blended frame (guided_morph.cpp).
void mean_value_weights(const std::vector<Vec2>& q, std::vector<double>& w);
/// Floater's shape-preserving weights (Floater 1997).
std::vector<double> floater_weights(const std::vector<Vec2>& q);
/// The weights nearest to 1/deg that reproduce the embedding, blended
/// toward mean value coordinates just enough to stay positive.
std::vector<double> uniform_weights(const std::vector<Vec2>& q);

/// The weights of interior node v over topo.ring[v] at `positions`,
/// positive and summing to one (offsets scaled by a power of two, exactly).
/// @throws VerificationError if the star is too close to degenerate for
///         positive finite weights (a floating-point failure on a star
///         whose triangles the exact test found positive).
std::vector<double> node_weights(const FigureTriangulation& tri, const Topology& topo,
                                 const std::vector<Vec2>& positions, int v, WeightKind kind);

/// node_weights into w, with q as scratch for the offsets: false instead of
/// the throw (the weights are then not all positive and finite). Allocates
/// nothing once q and w have the capacity, for mean value weights.
bool try_node_weights(const Topology& topo, const std::vector<Vec2>& positions, int v, WeightKind kind,
                      std::vector<Vec2>& q, std::vector<double>& w);

}  // namespace stickmorph::internal
