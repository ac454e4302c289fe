// Typed errors of the stickmorph engine.
//
// Errors are part of the interface: every bad input gets an exception whose
// message names what is wrong and where (vertex indices, edge indices, faces).
// The CLI prints `error: <what()>` and exits 2; the Python module maps each
// class onto a `ValueError` subclass with the same message (FileError also
// onto OSError, InternalError onto RuntimeError, CancelledError onto its own
// class outside ValueError), and carries the fields
// below as attributes.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
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

/// A file that cannot be read at all (missing, a directory, no permission,
/// too large): an operating-system failure, not a JSON one, so that callers
/// can tell "fix the path" from "fix the file". `error_number` is the errno
/// value (EFBIG for a file over the size limit); `path` the file as given.
class FileError : public Error {
 public:
  FileError(std::string path, int error_number, std::string message)
      : Error(std::move(message)), path_(std::move(path)), error_number_(error_number) {}
  const std::string& path() const { return path_; }
  int error_number() const { return error_number_; }

 private:
  std::string path_;
  int error_number_;
};

/// What is wrong with a stick figure. A stick figure is a straight-line
/// plane graph (paper, section 1), of one part or several (issue 14).
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
  // Defects of a polygon given by its corner sequence (triangulate_polygon,
  // compatible_triangulation): a weakly simple polygon needs at least three
  // corners, distinct consecutive positions, counter-clockwise order and
  // one wedge per corner.
  TooFewCorners,         ///< fewer than 3 corners
  CoincidentCorners,     ///< two corners at one position, or a corner repeating its successor
  ClockwiseCorners,      ///< a corner opens onto the outside: the order is not counter-clockwise
  ClosedWedge,           ///< a corner's wedge is closed by another edge or claimed by another corner
  SelfOverlappingPolygon,///< the interior does not triangulate into #corners - 2 triangles
};

/// A stick figure that violates one of the rules above. `vertices` and
/// `edges` hold the indices named in the message, in that order. `role`
/// says which figure of a pair it is ("source" or "target"), empty for a
/// figure on its own, so that callers need not parse the message for it.
class InvalidFigureError : public Error {
 public:
  InvalidFigureError(FigureDefect defect, std::string message,
                     std::vector<int> vertices = {}, std::vector<int> edges = {}, std::string role = {})
      : Error(std::move(message)),
        defect_(defect),
        vertices_(std::move(vertices)),
        edges_(std::move(edges)),
        role_(std::move(role)) {}
  FigureDefect defect() const { return defect_; }
  const std::vector<int>& vertices() const { return vertices_; }
  const std::vector<int>& edges() const { return edges_; }
  const std::string& role() const { return role_; }

 private:
  FigureDefect defect_;
  std::vector<int> vertices_;
  std::vector<int> edges_;
  std::string role_;
};

/// What is wrong with a drawing that clean_drawing (drawing_cleaning.h)
/// cannot make into a stick figure.
enum class DrawingDefect {
  NoStrokes,            ///< no strokes (or a figure with no vertices)
  TooFewPoints,         ///< a stroke of no point or a single point
  CollapsedStroke,      ///< a stroke whose points all merge into one
  NonFiniteCoordinate,  ///< NaN or infinity
  CoordinateTooLarge,   ///< |x| or |y| above kMaxCoordinateMagnitude
  IndexOutOfRange,      ///< an edge of a figure naming a vertex that does not exist
  Retrace,              ///< a stroke runs back along itself for a length
  Overlap,              ///< two strokes run along each other for a length
  Unresolved,           ///< the cleaned drawing is still not a valid figure
};

/// A drawing that cannot be cleaned. `stroke` and `point` name where (the
/// point's index within its stroke; for a figure an edge and a vertex),
/// `other_stroke` the second stroke of an overlap; -1 where none applies.
class InvalidDrawingError : public Error {
 public:
  InvalidDrawingError(DrawingDefect defect, std::string message, int stroke = -1, int point = -1,
                      int other_stroke = -1)
      : Error(std::move(message)), defect_(defect), stroke_(stroke), point_(point), other_stroke_(other_stroke) {}
  DrawingDefect defect() const { return defect_; }
  int stroke() const { return stroke_; }
  int point() const { return point_; }
  int other_stroke() const { return other_stroke_; }

 private:
  DrawingDefect defect_;
  int stroke_;
  int point_;
  int other_stroke_;
};

/// Arguments that are malformed independently of geometry: arrays of the
/// wrong shape, an unknown option name, a frame count below 2, ...
class InvalidArgumentError : public Error {
 public:
  using Error::Error;
};

/// Why two figures are not compatible; defined in compatibility.h (the
/// opaque declaration keeps this header free of the figure types).
enum class Incompatibility;

/// A pair of figures that cannot be morphed because they are not compatible
/// (paper, section 2.1). `check` reports this as a result, not an error;
/// operations that need compatibility throw it, with the report's kind and
/// the vertices its reason names.
class IncompatibleFiguresError : public Error {
 public:
  IncompatibleFiguresError(Incompatibility kind, std::string message, std::vector<int> vertices = {})
      : Error(std::move(message)), kind_(kind), vertices_(std::move(vertices)) {}
  Incompatibility kind() const { return kind_; }
  const std::vector<int>& vertices() const { return vertices_; }

 private:
  Incompatibility kind_;
  std::vector<int> vertices_;
};

/// A pair whose numbers the engine cannot carry through its floating-point
/// stages, refused before any work (or, for a result whose frames cannot be
/// written back in doubles, after it): for example source and target sizes
/// further apart than the barycentric method resolves. The message says
/// which ratio or magnitude and the supported limit (docs/FORMAT.md,
/// "Numeric range").
class NumericRangeError : public Error {
 public:
  using Error::Error;
};

/// A result failed exact verification and could not be repaired: the engine
/// refuses to return it. The message names the face and the triangle.
class VerificationError : public Error {
 public:
  using Error::Error;
};

/// The caller cancelled the call (Progress::cancel, cancellation.h): the
/// engine stopped at its next check and returns nothing. Not the input's
/// fault and not a bug; the message names the stage it stopped in.
class CancelledError : public Error {
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
