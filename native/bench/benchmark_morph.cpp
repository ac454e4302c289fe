// Benchmark of whole stick-figure morphs (Algorithm 3 + Floater-Gotsman):
// Steiner counts, triangulation time, time per frame and peak memory
// against size, for polylines, trees and triangulations.
//
// Not a test: it prints Markdown tables. Each case runs in a child process
// so that its peak resident memory is its own.
//
//   stickmorph_benchmark_morph [--sizes 10,100,1000,10000] [--frames N]
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/SparseLU>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "stickmorph/compatibility.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/morph.h"

namespace stickmorph {
namespace {

constexpr double kPi = 3.14159265358979323846;

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

StickFigure make(std::vector<Vec2> vertices, const std::vector<Edge>& edges) {
  std::vector<std::array<std::int64_t, 2>> raw;
  for (const Edge& e : edges) raw.push_back({e[0], e[1]});
  return make_stick_figure(std::move(vertices), raw);
}

// A gentle twist about the figure's centre: smooth, so a compatible target
// when the figure's edges are short next to the twist's variation.
std::vector<Vec2> twisted(const std::vector<Vec2>& p, double strength) {
  double cx = 0, cy = 0, reach = 0;
  for (const Vec2& q : p) cx += q[0] / p.size(), cy += q[1] / p.size();
  for (const Vec2& q : p) reach = std::max(reach, std::hypot(q[0] - cx, q[1] - cy));
  std::vector<Vec2> out;
  for (const Vec2& q : p) {
    const double dx = q[0] - cx, dy = q[1] - cy;
    const double a = strength * std::hypot(dx, dy) / reach;
    out.push_back({cx + std::cos(a) * dx - std::sin(a) * dy + 0.3 * reach,
                   cy + std::sin(a) * dx + std::cos(a) * dy});
  }
  return out;
}

// A polyline winding as a sine wave.
std::pair<StickFigure, StickFigure> polyline_case(int n) {
  std::vector<Vec2> p;
  std::vector<Edge> e;
  for (int i = 0; i < n; ++i) {
    p.push_back({double(i), 3 * std::sin(i * 0.3)});
    if (i) e.push_back({i - 1, i});
  }
  std::vector<Vec2> q;
  for (int i = 0; i < n; ++i) q.push_back({double(i) * 0.8, 4 * std::cos(i * 0.17) + 0.01 * i});
  return {make(p, e), make(q, e)};
}

// A tree: a spine with alternating branches of two edges.
std::pair<StickFigure, StickFigure> tree_case(int n) {
  std::vector<Vec2> p;
  std::vector<Edge> e;
  const int spine = std::max(2, n / 3);
  for (int i = 0; i < spine; ++i) {
    p.push_back({double(i), 0});
    if (i) e.push_back({i - 1, i});
  }
  for (int i = 0; int(p.size()) + 2 <= n && i < spine; ++i) {
    const double side = i % 2 ? 1 : -1;
    const int a = int(p.size());
    p.push_back({i + 0.3, side * 1.0});
    p.push_back({i + 0.1, side * 2.0});
    e.push_back({i, a});
    e.push_back({a, a + 1});
  }
  return {make(p, e), make(twisted(p, 0.8), e)};
}

// A k by k grid triangulation, interior sheared.
std::pair<StickFigure, StickFigure> triangulation_case(int n) {
  const int k = std::max(2, int(std::lround(std::sqrt(double(n)))));
  std::vector<Vec2> p;
  std::vector<Edge> e;
  auto id = [k](int i, int j) { return i * k + j; };
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) p.push_back({double(j), double(i)});
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      if (j + 1 < k) e.push_back({id(i, j), id(i, j + 1)});
      if (i + 1 < k) e.push_back({id(i, j), id(i + 1, j)});
      if (i + 1 < k && j + 1 < k) e.push_back({id(i, j), id(i + 1, j + 1)});
    }
  return {make(p, e), make(twisted(p, 1.0), e)};
}

struct Row {
  std::string kind;
  int n = 0;
  int steiner[3] = {-1, -1, -1};  // aronov, sg2001, improved
  double triangulate_ms = 0;
  double per_frame_ms = 0;   // weights, assembly and solve, per frame
  double verify_frame_ms = 0;  // exact check, per frame
  int factorizations = 0;
  double fresh_lu_ms = 0;
  long peak_kib = 0;
  std::string note;
};

// A fresh factorisation and solve of one frame's system, for comparison
// with the morph's per-frame cost.
double fresh_lu_ms(const FigureTriangulation& tri) {
  const Eigen::SparseMatrix<double, Eigen::RowMajor> w = barycentric_weights(tri, tri.source, WeightKind::MeanValue);
  const int nodes = tri.node_count();
  std::vector<int> interior_index(nodes, -1);
  int interior = 0;
  for (int v = 0; v < nodes; ++v)
    if (v < tri.figure_vertices || v >= tri.figure_vertices + tri.enclosure_vertices) interior_index[v] = interior++;
  const auto start = Clock::now();
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd bx = Eigen::VectorXd::Zero(interior), by = Eigen::VectorXd::Zero(interior);
  for (int v = 0; v < nodes; ++v) {
    if (interior_index[v] < 0) continue;
    triplets.emplace_back(interior_index[v], interior_index[v], 1.0);
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(w, v); it; ++it) {
      const int u = int(it.col());
      if (interior_index[u] >= 0) triplets.emplace_back(interior_index[v], interior_index[u], -it.value());
      else bx[interior_index[v]] += it.value() * tri.source[u][0], by[interior_index[v]] += it.value() * tri.source[u][1];
    }
  }
  Eigen::SparseMatrix<double> a(interior, interior);
  a.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.analyzePattern(a);
  lu.factorize(a);
  const Eigen::VectorXd x = lu.solve(bx), y = lu.solve(by);
  const double ms = ms_since(start);
  if (!std::isfinite(x.sum() + y.sum())) return -1;
  return ms;
}

Row run_case(const std::string& kind, int n, int frames) {
  const auto [s, t] = kind == "polyline" ? polyline_case(n) : kind == "tree" ? tree_case(n) : triangulation_case(n);
  Row row;
  row.kind = kind;
  row.n = int(s.vertices.size());
  if (!check_compatibility(s, t).compatible()) {
    row.note = "target not compatible";
    return row;
  }
  // Steiner counts per method; the paper's spiderwebs grow as n^2 on long
  // thin faces, so aronov is measured up to a thousand vertices and sg2001
  // up to three thousand.
  const SteinerMethod methods[3] = {SteinerMethod::Aronov, SteinerMethod::Sg2001, SteinerMethod::Improved};
  FigureTriangulation improved;
  for (int m = 0; m < 3; ++m) {
    if ((m == 0 && row.n > 1000) || (m == 1 && row.n > 3000)) continue;
    FigureTriangulationOptions options;
    options.method = methods[m];
    try {
      const auto start = Clock::now();
      FigureTriangulation tri = triangulate_figures(s, t, options);
      if (m == 2) row.triangulate_ms = ms_since(start), improved = std::move(tri);
      else row.steiner[m] = tri.steiner_vertices;
    } catch (const std::exception& e) {
      row.note += std::string(m == 0 ? "aronov" : m == 1 ? "sg2001" : "improved") + " failed: " + std::string(e.what()).substr(0, 60) + "; ";
    }
  }
  if (improved.node_count() == 0) return row;
  row.steiner[2] = improved.steiner_vertices;
  MorphOptions options;
  options.frames = frames;
  try {
    const MorphResult result = morph_triangulation(improved, s, options);
    row.per_frame_ms = (result.stats.factorize_ms + result.stats.solve_ms) / frames;
    row.verify_frame_ms = result.stats.verify_ms / frames;
    row.factorizations = result.stats.factorizations;
  } catch (const std::exception& e) {
    row.note += std::string("morph failed: ") + std::string(e.what()).substr(0, 80);
  }
  row.fresh_lu_ms = fresh_lu_ms(improved);
  return row;
}

// Runs one case in a child process; returns its row text (one line).
std::string run_isolated(const std::string& kind, int n, int frames) {
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) return "| " + kind + " | " + std::to_string(n) + " | pipe failed |";
  const pid_t child = fork();
  if (child == 0) {
    close(pipe_fds[0]);
    const Row r = run_case(kind, n, frames);
    struct rusage usage {};
    getrusage(RUSAGE_SELF, &usage);
    auto cell = [](int v) { return v < 0 ? std::string("-") : std::to_string(v); };
    char buffer[640];
    std::snprintf(buffer, sizeof buffer,
                  "| %s | %d | %s | %s | %s | %.2f | %.1f | %.3f | %.3f | %.1f | %.3f | %d | %ld | %s |\n",
                  r.kind.c_str(), r.n, cell(r.steiner[0]).c_str(), cell(r.steiner[1]).c_str(),
                  cell(r.steiner[2]).c_str(), r.n ? double(std::max(0, r.steiner[2])) / r.n : 0.0, r.triangulate_ms,
                  r.per_frame_ms, r.fresh_lu_ms, r.fresh_lu_ms > 0 && r.per_frame_ms > 0 ? r.fresh_lu_ms / r.per_frame_ms : 0.0,
                  r.verify_frame_ms, r.factorizations, long(usage.ru_maxrss) / 1024, r.note.c_str());
    const ssize_t written = write(pipe_fds[1], buffer, std::strlen(buffer));
    (void)written;
    close(pipe_fds[1]);
    _exit(0);
  }
  close(pipe_fds[1]);
  std::string text;
  char chunk[512];
  ssize_t got;
  while ((got = read(pipe_fds[0], chunk, sizeof chunk)) > 0) text.append(chunk, std::size_t(got));
  close(pipe_fds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (text.empty()) text = "| " + kind + " | " + std::to_string(n) + " | crashed (status " + std::to_string(status) + ") |\n";
  return text;
}

}  // namespace
}  // namespace stickmorph

int main(int argc, char** argv) {
  std::vector<int> sizes = {10, 100, 1000, 10000};
  int frames = 100;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if ((arg == "--sizes" || arg == "--frames") && i + 1 < argc) {
      const std::string value = argv[++i];
      if (arg == "--frames") {
        frames = std::atoi(value.c_str());
      } else {
        sizes.clear();
        std::stringstream list(value);
        for (std::string item; std::getline(list, item, ',');) sizes.push_back(std::atoi(item.c_str()));
      }
    } else if (arg == "--help" || arg == "-h") {
      std::printf("usage: stickmorph_benchmark_morph [--sizes 10,100,1000,10000] [--frames N]\n");
      return 0;
    } else {
      std::fprintf(stderr, "error: unknown argument '%s'\n", arg.c_str());
      return 2;
    }
  }
  if (frames < 2 || sizes.empty()) {
    std::fprintf(stderr, "error: --frames must be at least 2 and --sizes non-empty\n");
    return 2;
  }
  std::printf("# Morph benchmark\n\n%d frames per morph; Steiner counts per method (aronov up to 1000 "
              "vertices, sg2001 up to 3000); solve ms per frame = weights, assembly, factorizations and the anchored "
              "iterative solves, amortised over the frames, "
              "against a fresh sparse LU (assemble, analyse, factorise, solve) of one frame's system; the exact "
              "check of each frame is listed apart; peak resident memory of the case's process.\n\n",
              frames);
  std::printf("| figure | n | aronov | sg2001 | improved | improved / n | triangulate ms | solve ms per frame | "
              "fresh LU ms | fresh LU / solve | verify ms per frame | factorizations | peak MiB | note |\n"
              "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|---|\n");
  for (const char* kind : {"polyline", "tree", "triangulation"})
    for (int n : sizes) {
      std::printf("%s", stickmorph::run_isolated(kind, n, frames).c_str());
      std::fflush(stdout);
    }
  return 0;
}
