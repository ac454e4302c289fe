#include "stickmorph/io/svg_output.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <sstream>

namespace stickmorph {
namespace {

constexpr double kPanel = 320;   // panel size in SVG units
constexpr double kMargin = 16;

// Length of the well-formed UTF-8 sequence at text[at] whose code point
// XML 1.0 allows in character data (section 2.2: no C0 control but tab,
// line feed and carriage return, no surrogates, no U+FFFE or U+FFFF), or 0.
std::size_t xml_character_length(const std::string& text, std::size_t at) {
  const auto byte = [&text](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(at);
  if (lead < 0x80) return lead >= 0x20 || lead == '\t' || lead == '\n' || lead == '\r' ? 1 : 0;
  std::size_t length = 0;
  std::uint32_t code = 0;
  if (lead >= 0xC2 && lead <= 0xDF) length = 2, code = lead & 0x1F;
  else if (lead >= 0xE0 && lead <= 0xEF) length = 3, code = lead & 0x0F;
  else if (lead >= 0xF0 && lead <= 0xF4) length = 4, code = lead & 0x07;
  else return 0;
  if (at + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(at + k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(at + k) & 0x3F);
  }
  const std::uint32_t least[] = {0, 0, 0x80, 0x800, 0x10000};
  if (code < least[length] || code > 0x10FFFF) return 0;          // overlong or beyond Unicode
  if ((code >= 0xD800 && code <= 0xDFFF) || code == 0xFFFE || code == 0xFFFF) return 0;
  return length;
}

// Text for an SVG element (names and file paths echoed from the input).
// Markup characters become entities; what XML cannot hold at all, even as
// a character reference (C0 controls, invalid UTF-8), is shown as \xNN,
// as the CLI's error lines show it, so that every SVG written parses.
std::string escape(const std::string& text) {
  std::string out;
  for (std::size_t at = 0; at < text.size();) {
    const char c = text[at];
    switch (c) {
      case '<': out += "&lt;"; ++at; continue;
      case '>': out += "&gt;"; ++at; continue;
      case '&': out += "&amp;"; ++at; continue;
      case '"': out += "&quot;"; ++at; continue;
      case '\'': out += "&apos;"; ++at; continue;
      default: break;
    }
    const std::size_t length = xml_character_length(text, at);
    if (length == 0) {
      char shown[8];
      std::snprintf(shown, sizeof shown, "\\x%02X", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += shown;
      ++at;
      continue;
    }
    out.append(text, at, length);
    at += length;
  }
  return out;
}

std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", v);
  return buffer;
}

// Maps a bounding box uniformly into a panel at (x0, y0), y pointing up.
struct Frame {
  double lo[2], scale, x0, y0, width, height;
  Frame(const std::vector<const std::vector<Vec2>*>& sets, std::size_t count, double px, double py) {
    lo[0] = lo[1] = std::numeric_limits<double>::infinity();
    double hi[2] = {-lo[0], -lo[1]};
    for (const auto* s : sets)
      for (std::size_t i = 0; i < std::min(count, s->size()); ++i)
        for (int c = 0; c < 2; ++c) lo[c] = std::min(lo[c], (*s)[i][c]), hi[c] = std::max(hi[c], (*s)[i][c]);
    width = hi[0] - lo[0];
    height = hi[1] - lo[1];
    const double extent = std::max({width, height, 1e-300});
    scale = (kPanel - 2 * kMargin) / extent;
    x0 = px + kMargin + 0.5 * (kPanel - 2 * kMargin - width * scale);
    y0 = py + kMargin + 0.5 * (kPanel - 2 * kMargin + height * scale);
  }
  std::string x(const Vec2& p) const { return number(x0 + (p[0] - lo[0]) * scale); }
  std::string y(const Vec2& p) const { return number(y0 - (p[1] - lo[1]) * scale); }
};

// A hue per vertex index, so corresponding vertices share a colour.
std::string vertex_colour(int v, int n) {
  const double hue = 360.0 * v / std::max(1, n);
  return "hsl(" + number(hue) + ",80%,45%)";
}

// Colour between the source (blue) and target (red).
std::string blend(double t) {
  const int r = int(std::lround(40 + 180 * t)), g = int(std::lround(90 - 40 * t)), b = int(std::lround(200 - 160 * t));
  return "rgb(" + std::to_string(r) + "," + std::to_string(g) + "," + std::to_string(b) + ")";
}

void draw_triangles(std::ostringstream& out, const Frame& f, const std::vector<Vec2>& pos,
                    const std::vector<std::array<int, 3>>& triangles) {
  out << "<g stroke=\"#b0b0b0\" stroke-width=\"0.4\" fill=\"none\">\n";
  for (const auto& t : triangles) {
    out << "<polygon points=\"";
    for (int j = 0; j < 3; ++j) out << f.x(pos[t[j]]) << "," << f.y(pos[t[j]]) << (j < 2 ? " " : "");
    out << "\"/>\n";
  }
  out << "</g>\n";
}

void draw_figure(std::ostringstream& out, const Frame& f, const StickFigure& source, const std::vector<Vec2>& pos,
                 const std::string& colour, double width, bool vertex_colours) {
  out << "<g stroke=\"" << colour << "\" stroke-width=\"" << number(width) << "\" stroke-linecap=\"round\">\n";
  for (const Edge& e : source.edges)
    out << "<line x1=\"" << f.x(pos[e[0]]) << "\" y1=\"" << f.y(pos[e[0]]) << "\" x2=\"" << f.x(pos[e[1]])
        << "\" y2=\"" << f.y(pos[e[1]]) << "\"/>\n";
  out << "</g>\n";
  const int n = int(source.vertices.size());
  for (int v = 0; v < n; ++v)
    out << "<circle cx=\"" << f.x(pos[v]) << "\" cy=\"" << f.y(pos[v]) << "\" r=\"" << number(width * 0.9)
        << "\" fill=\"" << (vertex_colours ? vertex_colour(v, n) : colour) << "\"/>\n";
}

std::string header(double width, double height, const std::string& title) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(width) + "\" height=\"" + number(height) +
         "\" viewBox=\"0 0 " + number(width) + " " + number(height) + "\">\n<title>" + escape(title) +
         "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

void caption(std::ostringstream& out, double x, double y, const std::string& text) {
  out << "<text x=\"" << number(x) << "\" y=\"" << number(y)
      << "\" font-family=\"sans-serif\" font-size=\"12\" text-anchor=\"middle\">" << escape(text) << "</text>\n";
}

}  // namespace

std::string triangulation_svg(const FigureTriangulation& tri, const StickFigure& source, const std::string& title) {
  std::ostringstream out;
  out << header(2 * kPanel, kPanel + 24, title);
  const int n = tri.figure_vertices, k = tri.enclosure_vertices;
  for (int side = 0; side < 2; ++side) {
    const std::vector<Vec2>& pos = side ? tri.target : tri.source;
    const Frame f({&pos}, pos.size(), side * kPanel, 0);
    draw_triangles(out, f, pos, tri.triangles);
    out << "<polygon fill=\"none\" stroke=\"#404040\" stroke-width=\"1\" points=\"";
    for (int j = 0; j < k; ++j) out << f.x(pos[n + j]) << "," << f.y(pos[n + j]) << " ";
    out << "\"/>\n";
    draw_figure(out, f, source, pos, side ? "#c03020" : "#2050c0", 2.0, true);
    out << "<g fill=\"black\">\n";
    for (int v = n + k; v < tri.node_count(); ++v)
      out << "<circle cx=\"" << f.x(pos[v]) << "\" cy=\"" << f.y(pos[v]) << "\" r=\"1.3\"/>\n";
    out << "</g>\n";
    caption(out, side * kPanel + kPanel / 2, kPanel + 16,
            std::string(side ? "target" : "source") + ": " + std::to_string(tri.steiner_vertices) +
                " Steiner vertices, " + std::to_string(tri.triangles.size()) + " triangles");
  }
  out << "</svg>\n";
  return out.str();
}

namespace {

// Snapshot frame indices spread evenly from first to last.
std::vector<int> snapshot_frames(int count, int snapshots) {
  snapshots = std::max(2, std::min(snapshots, count));
  std::vector<int> chosen;
  for (int i = 0; i < snapshots; ++i) chosen.push_back(int(std::lround(double(i) * (count - 1) / (snapshots - 1))));
  return chosen;
}

// One row of snapshots at height `row_y`, all drawn at the scale of `sets`
// so that motion and size changes show; `marked` snapshots get a red
// caption (the straight-line morph's self-intersecting frames). Captions
// are `label` and the time, or `captions[i]` where given.
void draw_filmstrip_row(std::ostringstream& out, const StickFigure& source, const std::vector<std::vector<Vec2>>& frames,
                        const std::vector<double>& times, const std::vector<int>& chosen,
                        const std::vector<const std::vector<Vec2>*>& sets, std::size_t count,
                        const FigureTriangulation* tri, double row_y, const std::string& label,
                        const std::vector<int>* marked, const std::vector<std::string>* captions = nullptr) {
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    const int f = chosen[i];
    const Frame frame(sets, count, double(i) * kPanel, row_y);
    if (tri) draw_triangles(out, frame, frames[f], tri->triangles);
    draw_figure(out, frame, source, frames[f], blend(times[f]), 2.0, false);
    const bool bad = marked && std::find(marked->begin(), marked->end(), f) != marked->end();
    std::string text = captions ? (*captions)[i] : label + "t = " + number(times[f]);
    if (bad) text += " (self-intersects)";
    out << "<text x=\"" << number(double(i) * kPanel + kPanel / 2) << "\" y=\"" << number(row_y + kPanel + 16)
        << "\" font-family=\"sans-serif\" font-size=\"12\" text-anchor=\"middle\" fill=\""
        << (bad ? "#c00000" : "black") << "\">" << escape(text) << "</text>\n";
  }
}

}  // namespace

std::string filmstrip_svg(const StickFigure& source, const std::vector<std::vector<Vec2>>& frames,
                          const std::vector<double>& times, int snapshots, const FigureTriangulation* tri,
                          const std::string& title) {
  const std::vector<int> chosen = snapshot_frames(int(frames.size()), snapshots);
  std::vector<const std::vector<Vec2>*> sets;
  for (int f : chosen) sets.push_back(&frames[f]);
  std::ostringstream out;
  out << header(double(chosen.size()) * kPanel, kPanel + 24, title);
  draw_filmstrip_row(out, source, frames, times, chosen, sets,
                     tri ? std::size_t(tri->node_count()) : source.vertices.size(), tri, 0, "", nullptr);
  out << "</svg>\n";
  return out.str();
}

std::string key_pose_filmstrip_svg(const StickFigure& figure, const std::vector<std::vector<Vec2>>& frames,
                                   const std::vector<double>& times, const std::vector<int>& key_frames,
                                   int between, const std::string& title) {
  // Every key, `between` frames evenly inside every segment, and the last
  // frame (key 1 again after a loop).
  std::vector<int> chosen;
  std::vector<std::string> captions;
  const int last = int(frames.size()) - 1;
  for (std::size_t k = 0; k < key_frames.size(); ++k) {
    const int from = key_frames[k], to = k + 1 < key_frames.size() ? key_frames[k + 1] : last;
    chosen.push_back(from);
    captions.push_back("key " + std::to_string(k + 1) + ", frame " + std::to_string(from));
    for (int i = 1; i <= between && to > from; ++i) {
      const int f = from + int(std::lround(double(i) * (to - from) / (between + 1)));
      if (f <= chosen.back() || f >= to) continue;
      chosen.push_back(f);
      captions.push_back("frame " + std::to_string(f));
    }
  }
  if (chosen.back() != last) {
    chosen.push_back(last);
    captions.push_back(key_frames.back() == last ? "key " + std::to_string(key_frames.size()) + ", frame " +
                                                       std::to_string(last)
                                                 : "key 1, frame " + std::to_string(last));
  }
  std::vector<const std::vector<Vec2>*> sets;
  for (int f : chosen) sets.push_back(&frames[f]);
  std::ostringstream out;
  out << header(double(chosen.size()) * kPanel, kPanel + 24, title);
  draw_filmstrip_row(out, figure, frames, times, chosen, sets, figure.vertices.size(), nullptr, 0, "", nullptr,
                     &captions);
  out << "</svg>\n";
  return out.str();
}

std::string comparison_filmstrip_svg(const StickFigure& source, const std::vector<std::vector<Vec2>>& ours,
                                     const std::vector<std::vector<Vec2>>& linear, const std::vector<double>& times,
                                     int snapshots, const std::vector<int>& linear_invalid, const std::string& title) {
  const std::vector<int> chosen = snapshot_frames(int(ours.size()), snapshots);
  // One scale for both rows, so the two morphs compare frame for frame.
  std::vector<const std::vector<Vec2>*> sets;
  for (int f : chosen) sets.push_back(&ours[f]), sets.push_back(&linear[f]);
  const std::size_t n = source.vertices.size();
  std::ostringstream out;
  out << header(double(chosen.size()) * kPanel, 2 * (kPanel + 24), title);
  draw_filmstrip_row(out, source, ours, times, chosen, sets, n, nullptr, 0, "stickmorph, ", nullptr);
  draw_filmstrip_row(out, source, linear, times, chosen, sets, n, nullptr, kPanel + 24, "straight lines, ",
                     &linear_invalid);
  out << "</svg>\n";
  return out.str();
}

}  // namespace stickmorph
