#include "fuzz_common.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "stickmorph/figure_io.h"
#include "stickmorph/json.h"

namespace stickmorph::fuzz {

void report_finding(const std::string& what) {
  std::fprintf(stderr, "stickmorph fuzz finding: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

bool verification_is_finding() {
  static const bool enabled = [] {
    const char* value = std::getenv("STICKMORPH_FUZZ_VERIFICATION_IS_FINDING");
    return value != nullptr && std::strcmp(value, "1") == 0;
  }();
  return enabled;
}

bool tracing() {
  static const bool enabled = [] {
    const char* value = std::getenv("STICKMORPH_FUZZ_TRACE");
    return value != nullptr && std::strcmp(value, "1") == 0;
  }();
  return enabled;
}

void trace(const std::string& what) {
  if (tracing()) std::fprintf(stderr, "outcome: %s\n", what.c_str());
}

std::string figure_to_json(const StickFigure& figure) { return figure_json(figure, figure.name); }

bool same_figure(const StickFigure& a, const StickFigure& b) {
  // Bitwise comparison of the doubles: == would let -0.0 stand for 0.0,
  // and the writer promises the exact double back.
  if (a.vertices.size() != b.vertices.size() || a.edges != b.edges || a.name != b.name) return false;
  return a.vertices.empty() ||
         std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Vec2)) == 0;
}

}  // namespace stickmorph::fuzz

// ---------------------------------------------------------------------------
// The parts encoding (fuzz_common.h). Geometry is built in a group's local
// units, where the core disc has radius 0.8, then scaled and placed.
namespace stickmorph::fuzz {
namespace {

constexpr double kPartsPi = 3.14159265358979323846;

double turn_of(int signed_byte) { return double(signed_byte) / 128 * kPartsPi; }

Vec2 rotate_about(const Vec2& p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * p[0] - s * p[1], s * p[0] + c * p[1]};
}

// A direction drawn from a vertex index and a byte, for the wobble.
Vec2 wobble_direction(std::size_t vertex, std::uint8_t salt) {
  std::uint32_t h = std::uint32_t(vertex) * 2654435761u ^ (std::uint32_t(salt) * 40503u + 0x9e3779b9u);
  h ^= h >> 15;
  h *= 2246822519u;
  h ^= h >> 13;
  const double angle = double(h % 65536) / 65536 * 2 * kPartsPi;
  const double length = double((h >> 16) % 257) / 256;
  return {length * std::cos(angle), length * std::sin(angle)};
}

struct LocalPart {
  std::vector<Vec2> source, target;  // local coordinates about the group centre
  std::vector<std::array<std::int64_t, 2>> edges;  // local indices
};

// Turns a part's source about the centre into its target, then wobbles it.
void deform(LocalPart& part, double angle, std::uint8_t wobble, double clearance, std::size_t first_index) {
  part.target.resize(part.source.size());
  const double amplitude = double(wobble) / 256 * clearance;
  for (std::size_t v = 0; v < part.source.size(); ++v) {
    const Vec2 q = rotate_about(part.source[v], angle);
    const Vec2 d = wobble_direction(first_index + v, wobble);
    part.target[v] = {q[0] + amplitude * d[0], q[1] + amplitude * d[1]};
  }
}

}  // namespace

RawPartsPair decode_parts_pair(ByteStream& bytes, std::size_t max_vertices) {
  RawPartsPair pair;
  const int exponent = int(bytes.next()) - 128;
  const double unit = std::ldexp(1.0, exponent);
  const Vec2 offset = {std::ldexp(double(bytes.next_signed()), exponent + 14),
                       std::ldexp(double(bytes.next_signed()), exponent + 14)};
  const std::uint8_t renumber_seed = bytes.next();

  struct Placed {
    Vec2 centre;
    double radius;
  };
  std::vector<Placed> placed;

  auto add_part = [&](LocalPart& part, const Vec2& centre, double scale) {
    if (part.source.empty() || pair.source.size() + part.source.size() > max_vertices) return;
    const std::int64_t base = std::int64_t(pair.source.size());
    for (std::size_t v = 0; v < part.source.size(); ++v) {
      pair.source.push_back({centre[0] + scale * part.source[v][0], centre[1] + scale * part.source[v][1]});
      pair.target.push_back({centre[0] + scale * part.target[v][0], centre[1] + scale * part.target[v][1]});
    }
    for (const auto& e : part.edges) pair.edges.push_back({base + e[0], base + e[1]});
    ++pair.parts;
  };

  const int groups = 1 + bytes.next() % 4;
  for (int g = 0; g < groups; ++g) {
    const int rings = bytes.next() % 5;
    const double scale = unit * std::ldexp(1.0, bytes.next() % 16);
    const double gap_fraction = (double(bytes.next()) + 1) / 512;
    const double y_shift_fraction = double(bytes.next_signed()) / 128;
    // The parts are read first (their extent decides the placement), then
    // placed; indices are only assigned when placed.
    std::vector<LocalPart> parts;
    const std::uint8_t core = bytes.next() % 4;
    if (core == 1 || core == 2) {
      const int dots = core == 1 ? 1 : 1 + bytes.next() % 4;
      for (int k = 0; k < dots; ++k) {
        LocalPart dot;
        dot.source.push_back({double(bytes.next_signed()) / 128 * 0.55, double(bytes.next_signed()) / 128 * 0.55});
        const double turn = turn_of(bytes.next_signed());
        deform(dot, turn, bytes.next(), 0.05, parts.size());
        parts.push_back(std::move(dot));
      }
    } else if (core == 3) {
      LocalPart tree;
      const int n = 2 + bytes.next() % 5;
      for (int i = 0; i < n; ++i)
        tree.source.push_back({double(bytes.next_signed()) / 128 * 0.35, double(bytes.next_signed()) / 128 * 0.35});
      for (int i = 1; i < n; ++i) tree.edges.push_back({i, bytes.next() % i});
      const int extra = bytes.next() % (n + 1);
      for (int k = 0; k < extra; ++k) {
        const std::int64_t a = bytes.next() % n;
        tree.edges.push_back({a, bytes.next() % n});
      }
      const double turn = turn_of(bytes.next_signed());
      deform(tree, turn, bytes.next(), 0.05, parts.size());
      parts.push_back(std::move(tree));
    }

    double previous_outer = 0.8;  // the core disc
    for (int r = 0; r < rings; ++r) {
      const int sides = 3 + bytes.next() % 10;
      const double gap = (double(bytes.next()) + 1) / 2550;
      const double phase = double(bytes.next()) / 256 * 2 * kPartsPi;
      const double pull = double(bytes.next() % 32) / 256;
      const std::uint8_t collinear = bytes.next();
      const double turn = turn_of(bytes.next_signed());
      const std::uint8_t wobble = bytes.next();
      const double inner = previous_outer * (1 + gap);
      const double radius = inner / ((1 - pull) * std::cos(kPartsPi / sides));
      const double band = inner - previous_outer;

      const int items = bytes.next() % 4;
      for (int j = 0; j < items; ++j) {
        const std::uint8_t kind = bytes.next();
        const double angle = double(bytes.next()) / 256 * 2 * kPartsPi;
        const std::uint8_t span = bytes.next();
        const double item_turn = turn_of(bytes.next_signed());
        const std::uint8_t item_wobble = bytes.next();
        const double lo = previous_outer + band * (j + 0.15) / items;
        const double hi = previous_outer + band * (j + 0.85) / items;
        LocalPart item;
        if (kind % 4 == 1) {
          const int m = 2 + (kind / 4) % 5;
          const double step_max = 2 * std::acos(lo / hi) * 0.95;
          const double total = std::min((m - 1) * step_max, (double(span) + 1) / 256 * 2 * kPartsPi * 0.95);
          for (int v = 0; v < m; ++v) {
            const double a = angle + total * v / (m - 1);
            item.source.push_back({hi * std::cos(a), hi * std::sin(a)});
            if (v > 0) item.edges.push_back({v - 1, v});
          }
        } else if (kind % 4 == 2) {
          const double t = 0.1 + 0.8 * double(span) / 255;
          for (double rho : {lo, lo + t * (hi - lo), hi}) item.source.push_back({rho * std::cos(angle), rho * std::sin(angle)});
          item.edges = {{0, 1}, {1, 2}};
        } else {
          const double rho = (lo + hi) / 2;
          item.source.push_back({rho * std::cos(angle), rho * std::sin(angle)});
        }
        deform(item, item_turn, item_wobble, 0.3 * band / items, parts.size() * 64);
        parts.push_back(std::move(item));
      }

      LocalPart ring;
      for (int j = 0; j < sides; ++j) {
        const double a = phase + 2 * kPartsPi * j / sides;
        const double rho = (j % 2 == 1) ? radius * (1 - pull) : radius;
        ring.source.push_back({rho * std::cos(a), rho * std::sin(a)});
      }
      // Midpoints of chosen edges: collinear vertices on the ring.
      std::vector<Vec2> with_midpoints;
      for (int j = 0; j < sides; ++j) {
        const Vec2 a = ring.source[std::size_t(j)], b = ring.source[std::size_t((j + 1) % sides)];
        with_midpoints.push_back(a);
        if ((collinear >> (j % 8)) & 1) with_midpoints.push_back({(a[0] + b[0]) / 2, (a[1] + b[1]) / 2});
      }
      ring.source = std::move(with_midpoints);
      const std::int64_t m = std::int64_t(ring.source.size());
      for (std::int64_t j = 0; j < m; ++j) ring.edges.push_back({j, (j + 1) % m});
      deform(ring, turn, wobble, 0.15 * band / std::max(1, items), parts.size() * 64);
      parts.push_back(std::move(ring));
      previous_outer = radius;
    }
    if (parts.empty()) {
      LocalPart dot;
      dot.source.push_back({0, 0});
      dot.target.push_back({0, 0});
      parts.push_back(std::move(dot));
    }

    // Beside every earlier group, circumcircles apart by the gap.
    const double outer = previous_outer * scale;
    Vec2 centre = {0, 0};
    if (!placed.empty()) {
      centre[1] = placed.back().centre[1] + y_shift_fraction * outer;
      double x = -std::numeric_limits<double>::infinity();
      for (const Placed& other : placed) {
        const double reach = other.radius + outer + gap_fraction * std::min(other.radius, outer);
        const double dy = centre[1] - other.centre[1];
        x = std::max(x, other.centre[0] + std::sqrt(std::max(0.0, reach * reach - dy * dy)));
      }
      centre[0] = x;
    }
    placed.push_back({centre, outer});
    for (LocalPart& part : parts) add_part(part, centre, scale);
  }

  // The whole target turned, scaled and moved; both offset far out.
  const double angle = double(bytes.next()) / 256 * 2 * kPartsPi;
  const double target_scale = std::exp2((double(bytes.next() % 64) - 32) / 8);
  const Vec2 shift = {std::ldexp(double(bytes.next_signed()), exponent + 10),
                      std::ldexp(double(bytes.next_signed()), exponent + 10)};
  for (Vec2& p : pair.source) p = {p[0] + offset[0], p[1] + offset[1]};
  for (Vec2& p : pair.target) {
    const Vec2 q = rotate_about(p, angle);
    p = {target_scale * q[0] + offset[0] + shift[0], target_scale * q[1] + offset[1] + shift[1]};
  }

  if (renumber_seed != 0) {
    const std::size_t n = pair.source.size();
    std::vector<std::int64_t> image(n);
    for (std::size_t i = 0; i < n; ++i) image[i] = std::int64_t(i);
    std::uint32_t state = renumber_seed;
    for (std::size_t i = n; i-- > 1;) {
      state = state * 1664525u + 1013904223u;
      std::swap(image[i], image[(state >> 8) % (i + 1)]);
    }
    std::vector<Vec2> source(n), target(n);
    for (std::size_t i = 0; i < n; ++i) {
      source[std::size_t(image[i])] = pair.source[i];
      target[std::size_t(image[i])] = pair.target[i];
    }
    pair.source = std::move(source);
    pair.target = std::move(target);
    for (auto& e : pair.edges) e = {image[std::size_t(e[0])], image[std::size_t(e[1])]};
  }
  return pair;
}

}  // namespace stickmorph::fuzz
