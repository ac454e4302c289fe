#include "catch.h"

#include <functional>
#include <string>
#include <vector>

#include "stickmorph/errors.h"
#include "stickmorph/figure_io.h"

using namespace stickmorph;
using stickmorph_test::Contains;
using stickmorph_test::EndsWith;
using stickmorph_test::Equals;
using stickmorph_test::StartsWith;

namespace {

const std::string kData = STICKMORPH_TEST_DATA;

std::string malformed(const std::string& name) { return kData + "/malformed/" + name; }

// The message of the JsonError that parse_figure must throw.
std::string shape_error(const std::string& text) {
  try {
    parse_figure(text, "fig.json");
  } catch (const JsonError& error) {
    return error.what();
  }
  FAIL("parse_figure accepted: " << text);
  return {};
}

// The InvalidFigureError that `read` must throw.
InvalidFigureError figure_error(const std::function<void()>& read) {
  try {
    read();
  } catch (const InvalidFigureError& error) {
    return error;
  }
  FAIL("no InvalidFigureError");
  throw std::logic_error("unreachable");
}

// The message of the JsonError that reading the file must throw.
std::string file_json_error(const std::string& path) {
  try {
    read_figure_file(path);
  } catch (const JsonError& error) {
    return error.what();
  } catch (const FileError& error) {  // a file that cannot be read at all
    return error.what();
  }
  FAIL("read_figure_file accepted " << path);
  return {};
}

}  // namespace

TEST_CASE("parse_figure reads vertices, edges and name", "[figure_io]") {
  const StickFigure figure = parse_figure(
      R"({"name": "L", "vertices": [[0, 0], [1.5, 0], [1.5, -2e0]], "edges": [[0, 1], [2.0, 1]]})",
      "l.json");
  CHECK(figure.name == "L");
  REQUIRE(figure.vertices.size() == 3);
  CHECK(figure.vertices[1] == Vec2{1.5, 0.0});
  CHECK(figure.vertices[2] == Vec2{1.5, -2.0});
  REQUIRE(figure.edges.size() == 2);
  CHECK(figure.edges[0] == Edge{0, 1});
  CHECK(figure.edges[1] == Edge{2, 1});  // direction as given
}

TEST_CASE("parse_figure: name is optional and unknown fields are ignored", "[figure_io]") {
  const StickFigure figure = parse_figure(
      R"({"edges": [], "color": "red", "vertices": [[3, 4]], "meta": {"v": [1, 2]}})", "x");
  CHECK(figure.name.empty());
  CHECK(figure.vertices.size() == 1);
  CHECK(figure.edges.empty());
}

TEST_CASE("parse_figure: one vertex and one edge are valid figures", "[figure_io]") {
  CHECK(parse_figure(R"({"vertices": [[0, 0]], "edges": []})", "x").vertices.size() == 1);
  CHECK(parse_figure(R"({"vertices": [[0, 0], [0, 1]], "edges": [[1, 0]]})", "x").edges.size() == 1);
}

TEST_CASE("parse_figure: JSON syntax errors carry the origin and position", "[figure_io]") {
  CHECK_THAT(shape_error(""), Equals("fig.json: line 1, column 1: empty input, expected a JSON value"));
  CHECK_THAT(shape_error("{\"vertices\": [[0, 0]],\n \"edges\": [],}"),
             Equals("fig.json: line 2, column 13: trailing comma before '}'"));
  CHECK_THAT(shape_error("{\"vertices\": [[NaN, 0]], \"edges\": []}"),
             Equals("fig.json: line 1, column 16: NaN is not a JSON number (JSON has no NaN or "
                    "infinity)"));
  CHECK_THAT(shape_error("{\"vertices\": [[1e400, 0]], \"edges\": []}"),
             Equals("fig.json: line 1, column 16: number 1e400 overflows a double"));
  // Without an origin there is no prefix.
  try {
    parse_figure("[", "");
    FAIL("accepted");
  } catch (const JsonError& error) {
    CHECK_THAT(error.what(), StartsWith("line 1, column 2: "));
  }
}

TEST_CASE("parse_figure: the top level must be an object with vertices and edges", "[figure_io]") {
  CHECK_THAT(shape_error("[[0, 0]]"),
             Equals("fig.json: line 1, column 1: a figure file must hold a JSON object with "
                    "\"vertices\" and \"edges\", got an array"));
  CHECK_THAT(shape_error("null"), EndsWith("got null"));
  CHECK_THAT(shape_error("\n {\"edges\": []}"),
             Equals("fig.json: line 2, column 2: missing field \"vertices\" in the figure object"));
  CHECK_THAT(shape_error("{\"vertices\": [[0, 0]]}"),
             Equals("fig.json: line 1, column 1: missing field \"edges\" in the figure object"));
  CHECK_THAT(shape_error("{\"vertices\": {\"0\": [0, 0]}, \"edges\": []}"),
             Equals("fig.json: line 1, column 14: \"vertices\" must be an array of [x, y] pairs, "
                    "got an object"));
  CHECK_THAT(shape_error("{\"vertices\": [[0, 0]], \"edges\": 0}"),
             Equals("fig.json: line 1, column 33: \"edges\" must be an array of [i, j] vertex "
                    "index pairs, got a number"));
  CHECK_THAT(shape_error("{\"vertices\": [[0, 0]], \"edges\": [], \"name\": [\"x\"]}"),
             Equals("fig.json: line 1, column 45: \"name\" must be a string, got an array"));
  CHECK_THAT(shape_error("{\"vertices\": [[0, 0]], \"edges\": [], \"name\": null}"),
             EndsWith("\"name\" must be a string, got null"));
}

TEST_CASE("parse_figure: vertex shape errors name the vertex", "[figure_io]") {
  const std::string head = "{\"edges\": [],\n\"vertices\": [[0, 0], [1, 0], ";
  CHECK_THAT(shape_error(head + "\"2, 0\"]}"),
             Equals("fig.json: line 2, column 30: vertex 2 must be an array of 2 numbers [x, y], "
                    "got a string"));
  CHECK_THAT(shape_error(head + "[2, 0, 1]]}"),
             Equals("fig.json: line 2, column 30: vertex 2 must be an array of 2 numbers [x, y], "
                    "got an array of 3 values"));
  CHECK_THAT(shape_error(head + "[2]]}"), EndsWith("vertex 2 must be an array of 2 numbers [x, y], "
                                                   "got an array of 1 value"));
  CHECK_THAT(shape_error(head + "[]]}"), EndsWith("got an empty array"));
  CHECK_THAT(shape_error(head + "[2, \"0\"]]}"),
             Equals("fig.json: line 2, column 34: vertex 2: expected a number for y, got a string"));
  CHECK_THAT(shape_error(head + "[true, 0]]}"),
             Equals("fig.json: line 2, column 31: vertex 2: expected a number for x, got a boolean"));
  CHECK_THAT(shape_error(head + "[[2], 0]]}"), EndsWith("vertex 2: expected a number for x, got an array"));
}

TEST_CASE("parse_figure: edge shape errors name the edge", "[figure_io]") {
  const std::string head = "{\"vertices\": [[0, 0], [1, 0], [1, 1]],\n\"edges\": [[0, 1], ";
  CHECK_THAT(shape_error(head + "[1]]}"),
             Equals("fig.json: line 2, column 19: edge 1 must be an array of 2 vertex indices "
                    "[i, j], got an array of 1 value"));
  CHECK_THAT(shape_error(head + "{\"i\": 1, \"j\": 2}]}"),
             EndsWith("edge 1 must be an array of 2 vertex indices [i, j], got an object"));
  CHECK_THAT(shape_error(head + "[1, \"2\"]]}"),
             Equals("fig.json: line 2, column 23: edge 1: expected a vertex index (an integer), "
                    "got a string"));
  CHECK_THAT(shape_error(head + "[1.5, 2]]}"),
             Equals("fig.json: line 2, column 20: edge 1: vertex index 1.5 is not an integer"));
  CHECK_THAT(shape_error(head + "[1, 2.000001]]}"), EndsWith("vertex index 2.000001 is not an integer"));
  CHECK_THAT(shape_error(head + "[1, 1e30]]}"),
             EndsWith("edge 1: vertex index 1e+30 is outside the 64-bit integer range"));
  CHECK_THAT(shape_error(head + "[1, -1e19]]}"),
             EndsWith("vertex index -1e+19 is outside the 64-bit integer range"));
  CHECK_THAT(shape_error(head + "[1, 9223372036854775807]]}"),  // rounds to 2^63
             Contains("is outside the 64-bit integer range"));
}

TEST_CASE("parse_figure: integral indices in any notation are accepted", "[figure_io]") {
  const StickFigure figure = parse_figure(
      R"({"vertices": [[0, 0], [1, 0], [1, 1]], "edges": [[0, 1.0], [1e0, 20e-1]]})", "x");
  CHECK(figure.edges[0] == Edge{0, 1});
  CHECK(figure.edges[1] == Edge{1, 2});
}

TEST_CASE("parse_figure: figure rule violations keep defect and indices", "[figure_io]") {
  const auto parse = [](const std::string& text) {
    return figure_error([&] { parse_figure(text, "fig.json"); });
  };
  SECTION("negative index") {
    const InvalidFigureError e = parse(R"({"vertices": [[0, 0], [1, 0]], "edges": [[0, 1], [-1, 0]]})");
    CHECK(e.defect() == FigureDefect::EdgeIndexOutOfRange);
    CHECK(e.edges() == std::vector<int>{1});
    CHECK_THAT(e.what(), StartsWith("fig.json: edge 1 "));
    CHECK_THAT(e.what(), Contains("-1"));
  }
  SECTION("the most negative 64-bit index reaches make_stick_figure") {
    const InvalidFigureError e =
        parse(R"({"vertices": [[0, 0], [1, 0]], "edges": [[0, -9223372036854775808]]})");
    CHECK(e.defect() == FigureDefect::EdgeIndexOutOfRange);
    CHECK_THAT(e.what(), Contains("-9223372036854775808"));
  }
  SECTION("index out of range, beyond int") {
    const InvalidFigureError e = parse(R"({"vertices": [[0, 0], [1, 0]], "edges": [[0, 4294967297]]})");
    CHECK(e.defect() == FigureDefect::EdgeIndexOutOfRange);
    CHECK(e.edges() == std::vector<int>{0});
    CHECK_THAT(e.what(), Contains("4294967297"));
  }
  SECTION("self-loop") {
    const InvalidFigureError e = parse(R"({"vertices": [[0, 0], [1, 0]], "edges": [[0, 1], [1, 1]]})");
    CHECK(e.defect() == FigureDefect::SelfLoop);
    CHECK(e.edges() == std::vector<int>{1});
    CHECK_THAT(e.what(), StartsWith("fig.json: edge 1 "));
  }
  SECTION("reversed duplicate edge") {
    const InvalidFigureError e = parse(R"({"vertices": [[0, 0], [1, 0]], "edges": [[0, 1], [1, 0]]})");
    CHECK(e.defect() == FigureDefect::DuplicateEdge);
    CHECK(e.edges() == std::vector<int>{0, 1});
  }
  SECTION("no vertices") {
    const InvalidFigureError e = parse(R"({"vertices": [], "edges": []})");
    CHECK(e.defect() == FigureDefect::NoVertices);
    CHECK_THAT(e.what(), StartsWith("fig.json: "));
  }
  SECTION("coordinate too large") {
    const InvalidFigureError e = parse(R"({"vertices": [[0, 0], [1e101, 0]], "edges": [[0, 1]]})");
    CHECK(e.defect() == FigureDefect::CoordinateTooLarge);
    CHECK(e.vertices() == std::vector<int>{1});
  }
}

TEST_CASE("read_figure_file reads every golden pair", "[figure_io]") {
  const std::vector<std::string> names = {
      "compatible/letter_a",      "compatible/letter_b",         "compatible/tree_junction",
      "compatible/polygon",       "compatible/polyline",         "compatible/single_vertex",
      "compatible/single_edge",   "compatible/square_with_spikes", "compatible/wheel",
      "incompatible/junction_rotation", "incompatible/mirror_image",
      "incompatible/exterior_differs",  "incompatible/polygon_reversed",
      "incompatible/edge_set_differs",  "incompatible/vertex_count_differs"};
  for (const std::string& name : names) {
    for (const char* role : {".source.json", ".target.json"}) {
      const std::string path = kData + "/pairs/" + name + role;
      INFO(path);
      const StickFigure figure = read_figure_file(path);
      CHECK_FALSE(figure.vertices.empty());
      CHECK_FALSE(figure.name.empty());
    }
  }
  const StickFigure a = read_figure_file(kData + "/pairs/compatible/letter_a.source.json");
  CHECK(a.name == "letter A");
  CHECK(a.vertices.size() == 5);
  CHECK(a.edges.size() == 5);
}

TEST_CASE("read_figure_file: files that cannot be read", "[figure_io]") {
  const std::string missing = kData + "/malformed/does_not_exist.json";
  CHECK_THAT(file_json_error(missing), Equals(missing + ": cannot read file: No such file or directory"));
  CHECK_THAT(file_json_error(kData + "/malformed"),
             Equals(kData + "/malformed: cannot read file: Is a directory"));
  CHECK_THAT(file_json_error(""), Equals(": cannot read file: No such file or directory"));
}

TEST_CASE("read_figure_file: malformed JSON files", "[figure_io]") {
  const std::string empty = malformed("empty.json");
  CHECK_THAT(file_json_error(empty), Equals(empty + ": line 1, column 1: empty input, expected a JSON value"));
  CHECK_THAT(file_json_error(malformed("whitespace_only.json")), EndsWith("no JSON value, only whitespace"));
  CHECK_THAT(file_json_error(malformed("syntax_missing_comma.json")),
             EndsWith("line 8, column 3: unexpected character '\"' in an object, expected ',' or '}'"));
  CHECK_THAT(file_json_error(malformed("unclosed.json")),
             EndsWith("line 12, column 3: unexpected end of input, the array opened at line 8, column 12 is not closed"));
  CHECK_THAT(file_json_error(malformed("trailing_comma.json")),
             EndsWith("line 11, column 11: trailing comma before ']'"));
  CHECK_THAT(file_json_error(malformed("comment.json")),
             EndsWith("line 2, column 3: comments are not allowed in JSON"));
  CHECK_THAT(file_json_error(malformed("duplicate_key.json")),
             EndsWith("line 9, column 3: duplicate key \"edges\" (first at line 2, column 3)"));
  CHECK_THAT(file_json_error(malformed("trailing_garbage.json")),
             EndsWith("line 14, column 1: unexpected character '{' after the JSON value"));
  CHECK_THAT(file_json_error(malformed("nan.json")), EndsWith("line 4, column 6: NaN is not a JSON "
                                                              "number (JSON has no NaN or infinity)"));
  CHECK_THAT(file_json_error(malformed("infinity.json")),
             Contains("line 5, column 9: -Infinity is not a JSON number"));
  CHECK_THAT(file_json_error(malformed("overflow.json")),
             EndsWith("line 6, column 9: number 1e400 overflows a double"));
  CHECK_THAT(file_json_error(malformed("leading_zero.json")),
             EndsWith("line 4, column 6: a number must not have a leading zero"));
  CHECK_THAT(file_json_error(malformed("single_quotes.json")), Contains("JSON strings use double quotes"));
  const std::string binary = malformed("binary.bin");
  CHECK_THAT(file_json_error(binary), Equals(binary + ": line 1, column 1: unexpected byte 0x00, "
                                                      "expected a JSON value"));
}

TEST_CASE("read_figure_file: files of the wrong shape", "[figure_io]") {
  CHECK_THAT(file_json_error(malformed("top_level_array.json")), Contains("got an array"));
  CHECK_THAT(file_json_error(malformed("missing_vertices.json")),
             EndsWith("line 1, column 1: missing field \"vertices\" in the figure object"));
  CHECK_THAT(file_json_error(malformed("missing_edges.json")),
             EndsWith("missing field \"edges\" in the figure object"));
  CHECK_THAT(file_json_error(malformed("vertices_not_array.json")),
             EndsWith("line 2, column 15: \"vertices\" must be an array of [x, y] pairs, "
                      "got an object"));
  CHECK_THAT(file_json_error(malformed("edges_not_array.json")), EndsWith("got a string"));
  CHECK_THAT(file_json_error(malformed("vertex_wrong_length.json")),
             EndsWith("line 5, column 5: vertex 2 must be an array of 2 numbers [x, y], got an array of 3 values"));
  CHECK_THAT(file_json_error(malformed("vertex_not_array.json")),
             EndsWith("line 4, column 5: vertex 1 must be an array of 2 numbers [x, y], got a string"));
  CHECK_THAT(file_json_error(malformed("string_coordinate.json")),
             EndsWith("line 6, column 9: vertex 3: expected a number for y, got a string"));
  CHECK_THAT(file_json_error(malformed("null_coordinate.json")),
             EndsWith("line 3, column 6: vertex 0: expected a number for x, got null"));
  CHECK_THAT(file_json_error(malformed("edge_wrong_length.json")),
             EndsWith("line 10, column 5: edge 1 must be an array of 2 vertex indices [i, j], got an array of 1 value"));
  CHECK_THAT(file_json_error(malformed("string_index.json")),
             EndsWith("line 11, column 6: edge 2: expected a vertex index (an integer), got a string"));
  CHECK_THAT(file_json_error(malformed("non_integer_index.json")),
             EndsWith("line 10, column 6: edge 1: vertex index 1.5 is not an integer"));
  CHECK_THAT(file_json_error(malformed("huge_index.json")),
             EndsWith("line 11, column 9: edge 2: vertex index 1e+30 is outside the 64-bit integer range"));
  CHECK_THAT(file_json_error(malformed("name_not_string.json")),
             EndsWith("line 2, column 11: \"name\" must be a string, got a number"));
}

TEST_CASE("read_figure_file: figures that break the rules", "[figure_io]") {
  struct Case {
    const char* file;
    FigureDefect defect;
    std::vector<int> vertices;
    std::vector<int> edges;
    const char* text;  // part of the message
  };
  const std::vector<Case> cases = {
      {"no_vertices.json", FigureDefect::NoVertices, {}, {}, "no vertices"},
      {"coordinate_too_large.json", FigureDefect::CoordinateTooLarge, {2}, {}, "vertex 2"},
      {"negative_index.json", FigureDefect::EdgeIndexOutOfRange, {}, {2}, "edge 2"},
      {"index_out_of_range.json", FigureDefect::EdgeIndexOutOfRange, {}, {1}, "edge 1"},
      {"self_loop.json", FigureDefect::SelfLoop, {3}, {3}, "edge 3"},
      {"duplicate_edge.json", FigureDefect::DuplicateEdge, {0, 1}, {0, 3}, "edges 0 and 3"},
      {"duplicate_edge_reversed.json", FigureDefect::DuplicateEdge, {1, 2}, {1, 3}, "edges 1 and 3"},
      {"coincident_vertices.json", FigureDefect::CoincidentVertices, {1, 3}, {}, "vertices 1 and 3"},
      {"crossing_edges.json", FigureDefect::CrossingEdges, {}, {3, 4}, "edges 3 (0-2) and 4 (1-3)"},
      {"collinear_overlap.json", FigureDefect::OverlappingEdges, {}, {0, 3}, "edges 0 (0-1) and 3 (0-4)"},
      {"vertex_on_edge.json", FigureDefect::VertexOnEdge, {4}, {0}, "vertex 4"},
  };
  for (const Case& c : cases) {
    const std::string path = malformed(c.file);
    INFO(path);
    const InvalidFigureError e = figure_error([&] { read_figure_file(path); });
    CHECK(e.defect() == c.defect);
    CHECK(e.vertices() == c.vertices);
    CHECK(e.edges() == c.edges);
    CHECK_THAT(e.what(), StartsWith(path + ": "));
    CHECK_THAT(e.what(), Contains(c.text));
  }
}
