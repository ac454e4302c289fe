// Cost of a matching and the choice among matchings
// (correspondence_choice.h; Surazhsky & Gotsman 2001, section 6).
#include "stickmorph/internal/correspondence_choice.h"

#include <algorithm>
#include <complex>
#include <limits>
#include <utility>

#include "stickmorph/compatibility.h"
#include "stickmorph/errors.h"

namespace stickmorph::internal {

namespace {

struct SampleSet {
  std::vector<std::complex<double>> a, b;
  std::vector<double> w;
  void add(const Vec2& p, const Vec2& q, double weight) {
    a.emplace_back(p[0], p[1]);
    b.emplace_back(q[0], q[1]);
    w.push_back(weight);
  }
  Fit fit() const {
    double total = 0;
    std::complex<double> ca, cb;
    for (std::size_t k = 0; k < w.size(); ++k) {
      total += w[k];
      ca += w[k] * a[k];
      cb += w[k] * b[k];
    }
    Fit result;
    if (!(total > 0)) return result;
    ca /= total;
    cb /= total;
    std::complex<double> cross;
    double aa = 0, bb = 0;
    for (std::size_t k = 0; k < w.size(); ++k) {
      const std::complex<double> p = a[k] - ca, q = b[k] - cb;
      cross += w[k] * std::conj(p) * q;
      aa += w[k] * std::norm(p);
      bb += w[k] * std::norm(q);
    }
    if (!(aa > 0) || !(bb > 0)) {
      result.residual = (aa > 0) == (bb > 0) ? 0 : 1;
      return result;
    }
    result.residual = std::clamp(1.0 - std::norm(cross) / (aa * bb), 0.0, 1.0);
    result.rotation = std::arg(cross);
    return result;
  }
};

}  // namespace

Fit candidate_fit(const Skeleton& source, const Skeleton& target, const std::vector<ChainMatch>& chains,
                  int samples_per_chain) {
  double source_total = 0, target_total = 0;
  for (const Track& t : source.chains) source_total += t.length();
  for (const Track& t : target.chains) target_total += t.length();
  SampleSet set;
  for (const ChainMatch& match : chains) {
    const Track& s = source.chains[std::size_t(match.source_chain)];
    const Track& t = target.chains[std::size_t(match.target_chain)];
    const double weight = (s.length() / source_total + t.length() / target_total) / (2.0 * (samples_per_chain + 1));
    const int count = s.closed ? samples_per_chain : samples_per_chain + 1;
    for (int k = 0; k < count; ++k) {
      const double u = (s.closed ? match.map.u[0] : 0.0) + double(k) / samples_per_chain;
      const double w = run_parameter(match.map.to_target(u), match.reversed);
      set.add(point_at(*source.figure, s, u), point_at(*target.figure, t, w), weight);
    }
  }
  Fit fit = set.fit();
  fit.reference = source.reference_rotation;
  return fit;
}

std::size_t best_fit(const std::vector<Fit>& fits) {
  double least = std::numeric_limits<double>::infinity();
  for (const Fit& fit : fits) least = std::min(least, fit.cost());
  const double tie = least + kTieRelative * least + kTieAbsolute;
  std::size_t best = fits.size();
  for (std::size_t k = 0; k < fits.size(); ++k) {
    if (fits[k].cost() > tie) continue;
    if (best == fits.size() || fits[k].turn() < fits[best].turn()) best = k;
  }
  return best;
}

Candidate match_loops(const Skeleton& source, const Skeleton& target, const std::vector<PinPlace>& pins,
                      int& compared) {
  Candidate candidate;
  candidate.node_image.assign(source.figure->vertices.size(), -1);
  ChainMatch match;
  match.source_chain = 0;
  match.target_chain = 0;
  match.map.closed = true;
  if (!pins.empty()) {
    std::vector<std::pair<double, double>> anchors;
    for (const PinPlace& pin : pins) anchors.emplace_back(pin.u, pin.w);
    std::sort(anchors.begin(), anchors.end());
    // Counter-clockwise on both: the target parameters must increase once
    // unwrapped from the first pin's, within one turn.
    double previous = anchors[0].second;
    for (std::size_t k = 0; k < anchors.size(); ++k) {
      double w = anchors[k].second;
      while (w < previous) w += 1;
      if (k > 0 && !(w > previous)) w += 1;
      if (w >= anchors[0].second + 1)
        throw IncompatibleFiguresError(Incompatibility::PinsUnsatisfiable,
                                       "correspond: no matching respects every pin: the pinned vertices are not in "
                                       "the same counter-clockwise order around both loops");
      match.map.u.push_back(anchors[k].first);
      match.map.w.push_back(w);
      previous = w;
    }
    candidate.chains.push_back(match);
    candidate.fit = candidate_fit(source, target, candidate.chains, kLoopSamples);
    compared = 1;
    return candidate;
  }
  // Shifts on a grid of the samples' spacing; each local minimum of the
  // residual that could still win once its rotation is charged is refined
  // by golden-section search on the residual alone within a grid step (the
  // charge picks between fits, it must not pull a fit off its best shift),
  // and best_fit then decides by cost.
  auto fit_at = [&](double shift) {
    ChainMatch m = match;
    m.map.u = {0.0};
    m.map.w = {shift};
    return candidate_fit(source, target, {m}, kLoopSamples);
  };
  std::vector<Fit> grid(kLoopSamples);
  double least = std::numeric_limits<double>::infinity();
  for (int k = 0; k < kLoopSamples; ++k) {
    grid[std::size_t(k)] = fit_at(double(k) / kLoopSamples);
    least = std::min(least, grid[std::size_t(k)].cost());
  }
  const double tie = least + kTieRelative * least + kTieAbsolute;
  std::vector<std::pair<double, Fit>> refined;
  for (int k = 0; k < kLoopSamples; ++k) {
    const Fit& here = grid[std::size_t(k)];
    const Fit& before = grid[std::size_t((k + kLoopSamples - 1) % kLoopSamples)];
    const Fit& after = grid[std::size_t((k + 1) % kLoopSamples)];
    if (here.residual > tie || here.residual > before.residual || here.residual > after.residual) continue;
    double lo = double(k - 1) / kLoopSamples, hi = double(k + 1) / kLoopSamples;
    const double golden = 0.5 * (std::sqrt(5.0) - 1);
    double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
    double f1 = fit_at(x1).residual, f2 = fit_at(x2).residual;
    for (int iteration = 0; iteration < 40; ++iteration) {
      if (f1 <= f2) {
        hi = x2; x2 = x1; f2 = f1; x1 = hi - golden * (hi - lo); f1 = fit_at(x1).residual;
      } else {
        lo = x1; x1 = x2; f1 = f2; x2 = lo + golden * (hi - lo); f2 = fit_at(x2).residual;
      }
    }
    const double shift = 0.5 * (lo + hi);
    refined.emplace_back(shift - std::floor(shift), fit_at(shift));
  }
  compared = int(refined.size());
  std::vector<Fit> fits;
  for (const auto& [shift, fit] : refined) fits.push_back(fit);
  const auto& [shift, fit] = refined[best_fit(fits)];
  match.map.u = {0.0};
  match.map.w = {shift};
  candidate.chains.push_back(match);
  candidate.fit = fit;
  return candidate;
}

}  // namespace stickmorph::internal
