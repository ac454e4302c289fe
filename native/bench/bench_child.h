// The benchmarks' child processes: each case runs in a fork of its own with
// an address-space limit and an alarm, so that one case that runs out of
// memory or time is reported as such (and measured by its own ru_maxrss)
// instead of ending the whole run. Shared by stickmorph_benchmark_morph and
// stickmorph_benchmark_correspondence.
#pragma once

#include <signal.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <functional>
#include <iostream>
#include <new>
#include <string>

#include <algorithm>
#include <cmath>
#include <vector>

#include "stickmorph/errors.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/internal/compact_lu.h"
#include "stickmorph/morph.h"

namespace stickmorph::bench {

using Clock = std::chrono::steady_clock;
inline double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct ChildResult {
  std::string status;  ///< ok, failed, timeout, out_of_memory, crashed
  std::string body;    ///< the child's JSON fields (ok) or message
  double wall_ms = 0;
  long peak_kib = 0;
};

/// Runs `work` in a child with an address-space limit and an alarm; the child
/// writes "ok <json>" or "failed <message>" to a pipe.
inline ChildResult run_child(const std::function<std::string()>& work, int seconds, long memory_mib) {
  ChildResult result;
  int fds[2];
  if (pipe(fds) != 0) throw Error(std::string("pipe: ") + std::strerror(errno));
  std::cout.flush();
  std::cerr.flush();
  const auto start = Clock::now();
  const pid_t child = fork();
  if (child < 0) throw Error(std::string("fork: ") + std::strerror(errno));
  if (child == 0) {
    close(fds[0]);
    struct rlimit limit {};
    limit.rlim_cur = limit.rlim_max = rlim_t(memory_mib) * 1024 * 1024;
    setrlimit(RLIMIT_AS, &limit);
    alarm(unsigned(seconds));  // SIGALRM's default action ends the child
    std::string message;
    try {
      message = "ok " + work();
    } catch (const std::bad_alloc&) {
      message = "out_of_memory more than the " + std::to_string(memory_mib) + " MiB address-space limit";
    } catch (const std::exception& error) {
      message = std::string("failed ") + error.what();
    }
    for (char& c : message)
      if (c == '\n') c = ' ';
    std::size_t sent = 0;
    while (sent < message.size()) {
      const ssize_t wrote = write(fds[1], message.data() + sent, message.size() - sent);
      if (wrote <= 0) break;
      sent += std::size_t(wrote);
    }
    close(fds[1]);
    _exit(0);
  }
  close(fds[1]);
  std::string text;
  char chunk[4096];
  ssize_t got;
  while ((got = read(fds[0], chunk, sizeof chunk)) > 0) text.append(chunk, std::size_t(got));
  close(fds[0]);
  int status = 0;
  struct rusage usage {};
  wait4(child, &status, 0, &usage);
  result.wall_ms = ms_since(start);
  result.peak_kib = long(usage.ru_maxrss);  // kilobytes on Linux
  const std::size_t space = text.find(' ');
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM) {
    result.status = "timeout";
    result.body = "stopped after the " + std::to_string(seconds) + " s limit";
  } else if (WIFSIGNALED(status) || space == std::string::npos) {
    result.status = "crashed";
    result.body = WIFSIGNALED(status) ? "signal " + std::to_string(WTERMSIG(status))
                                      : "exit status " + std::to_string(WEXITSTATUS(status));
  } else {
    result.status = text.substr(0, space);
    result.body = text.substr(space + 1);
  }
  return result;
}

/// Issue 15's yardstick: a fresh sparse LU factorize-and-solve of the
/// morph's system at time t on `tri` ((I - W_interior(t)) x = W_boundary(t)
/// x_boundary, W(t) blending the mean value weights of tri.source and
/// tri.target), with the factorization MorphSolver uses (SparseLU on the
/// system ordered symmetrically by AMD, internal::SymmetricOrderedLU): symbolic
/// analysis, numeric factorization and the solve of both coordinates,
/// timed; the weights and the assembly are not. The median of `repeats`
/// runs, in milliseconds; -1 if the factorization failed.
inline double fresh_lu_ms(const FigureTriangulation& tri, double t, int repeats = 3) {
  using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  const RowMatrix w0 = barycentric_weights(tri, tri.source, WeightKind::MeanValue);
  const RowMatrix w1 = barycentric_weights(tri, tri.target, WeightKind::MeanValue);
  const RowMatrix w = (1 - t) * w0 + t * w1;
  const int nodes = tri.node_count();
  std::vector<int> interior_index(nodes, -1);
  int interior = 0;
  for (int v = 0; v < nodes; ++v)
    if (v < tri.figure_vertices || v >= tri.figure_vertices + tri.enclosure_vertices) interior_index[v] = interior++;
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::MatrixX2d b = Eigen::MatrixX2d::Zero(interior, 2);
  for (int v = 0; v < nodes; ++v) {
    if (interior_index[v] < 0) continue;
    triplets.emplace_back(interior_index[v], interior_index[v], 1.0);
    for (RowMatrix::InnerIterator it(w, v); it; ++it) {
      const int u = int(it.col());
      if (interior_index[u] >= 0) {
        triplets.emplace_back(interior_index[v], interior_index[u], -it.value());
      } else {
        b(interior_index[v], 0) += it.value() * tri.source[u][0];
        b(interior_index[v], 1) += it.value() * tri.source[u][1];
      }
    }
  }
  Eigen::SparseMatrix<double> a(interior, interior);
  a.setFromTriplets(triplets.begin(), triplets.end());
  a.makeCompressed();
  std::vector<double> times;
  for (int r = 0; r < std::max(1, repeats); ++r) {
    const auto start = Clock::now();
    internal::SymmetricOrderedLU lu;
    lu.analyzePattern(a);
    lu.factorize(a);
    const Eigen::MatrixX2d x = lu.solve(b);
    times.push_back(ms_since(start));
    if (lu.info() != Eigen::Success || !x.allFinite()) return -1;
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

/// The median of `values` (0 for none).
inline double median_of(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const std::size_t h = values.size() / 2;
  return values.size() % 2 ? values[h] : (values[h - 1] + values[h]) / 2;
}

}  // namespace stickmorph::bench
