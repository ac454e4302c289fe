// Typed errors of the stickmorph engine.
//
// Errors are part of the interface: every bad input gets an exception whose
// message names what is wrong and where (vertex indices, edge indices, faces).
// The CLI prints `error: <what()>` and exits 2; the Python module maps each
// class onto a `ValueError` subclass with the same message.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace stickmorph {

/// Base of every error the engine reports about its input or its work.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A file or text that is not valid JSON, or JSON of the wrong shape
/// (missing field, string where a number belongs, NaN, overflow, ...).
class JsonError : public Error {
 public:
  using Error::Error;
};

/// What is wrong with a stick figure. A stick figure is a connected
/// straight-line plane graph (paper, section 1).
enum class FigureDefect {
  NoVertices,            ///< the vertex list is empty
  NonFiniteCoordinate,   ///< NaN or infinity
  CoordinateTooLarge,    ///< |x| or |y| above kMaxCoordinateMagnitude
  EdgeIndexOutOfRange,   ///< negative, or >= number of vertices
  SelfLoop,              ///< an edge from a vertex to itself
  DuplicateEdge,         ///< two edges join the same two vertices
  CoincidentVertices,    ///< two vertices at the same position
  CrossingEdges,         ///< two edges cross at a point interior to both
  OverlappingEdges,      ///< two collinear edges share more than a point
  VertexOnEdge,          ///< a vertex lies on an edge not incident to it
  Disconnected,          ///< the graph has more than one component
};

/// A stick figure that violates one of the rules above. `vertices` and
/// `edges` hold the indices named in the message, in that order.
class InvalidFigureError : public Error {
 public:
  InvalidFigureError(FigureDefect defect, std::string message,
                     std::vector<int> vertices = {}, std::vector<int> edges = {})
      : Error(std::move(message)),
        defect_(defect),
        vertices_(std::move(vertices)),
        edges_(std::move(edges)) {}
  FigureDefect defect() const { return defect_; }
  const std::vector<int>& vertices() const { return vertices_; }
  const std::vector<int>& edges() const { return edges_; }

 private:
  FigureDefect defect_;
  std::vector<int> vertices_;
  std::vector<int> edges_;
};

/// Arguments that are malformed independently of geometry: arrays of the
/// wrong shape, an unknown option name, a frame count below 2, ...
class InvalidArgumentError : public Error {
 public:
  using Error::Error;
};

/// A pair of figures that cannot be morphed because they are not compatible
/// (paper, section 2.1). `check` reports this as a result, not an error;
/// operations that need compatibility throw it.
class IncompatibleFiguresError : public Error {
 public:
  using Error::Error;
};

/// A result failed exact verification and could not be repaired: the engine
/// refuses to return it. The message names the face and the triangle.
class VerificationError : public Error {
 public:
  using Error::Error;
};

/// An internal consistency check failed. This is a bug in stickmorph, never
/// the user's fault; the message says which invariant broke and where.
class InternalError : public Error {
 public:
  using Error::Error;
};

}  // namespace stickmorph
