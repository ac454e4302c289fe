// The morph through a sequence of key poses; see key_pose_morph.h.
#include "stickmorph/key_pose_morph.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <tuple>
#include <utility>

#include "stickmorph/argument_limits.h"
#include "stickmorph/cancellation.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/errors.h"
#include "stickmorph/guided_morph.h"
#include "stickmorph/internal/rigid_morph_setup.h"
#include "stickmorph/key_pose_guide.h"
#include "stickmorph/local_timing.h"
#include "stickmorph/morph_options.h"
#include "stickmorph/rigid_guide.h"
#include "stickmorph/working_scale.h"

namespace stickmorph {
namespace {

std::string key_name(std::size_t k) { return "key " + std::to_string(k + 1); }

// One segment's stretch [t0, t1] of the sequence's guide, as the trajectory
// its GuidedMorph follows: morph parameter u is the segment's own time, and
// the morph does not retime it (key_pose_morph.h). With a local clock
// (local timing, issue 31) every edge runs at its local time of u within
// the segment, so that every key stays exact at its frame.
class KeyPoseStretch : public GuideTrajectory {
 public:
  KeyPoseStretch(std::shared_ptr<const KeyPoseGuide> guide, int segment, double t0, double t1,
                 std::shared_ptr<const LocalClock> clock)
      : guide_(std::move(guide)), segment_(segment), t0_(t0), t1_(t1), clock_(std::move(clock)) {}
  std::vector<Vec2> at(double u) const override {
    // The knots themselves at the ends, not t0 + (t1 - t0), which may round.
    if (u <= 0) return guide_->at(t0_);
    if (u >= 1) return guide_->at(t1_);
    if (clock_) {
      std::vector<Vec2> positions = guide_->in_segment(segment_, clock_->edge_times(u), u);
      clock_->place_parts(u, positions);
      return positions;
    }
    return guide_->at(t0_ + u * (t1_ - t0_));
  }
  double parameter_at(double t, Easing) const override { return t; }
  bool retimed_by_morph() const override { return false; }
  std::vector<double> vertex_times(double u) const override {
    return clock_ ? clock_->vertex_times(u) : std::vector<double>{};
  }

 private:
  std::shared_ptr<const KeyPoseGuide> guide_;
  int segment_;
  double t0_, t1_;
  std::shared_ptr<const LocalClock> clock_;
};

void check_same_graph(const std::vector<StickFigure>& keys) {
  const StickFigure& first = keys[0];
  for (std::size_t k = 1; k < keys.size(); ++k) {
    const StickFigure& key = keys[k];
    if (key.vertices.size() != first.vertices.size())
      throw InvalidArgumentError(key_name(k) + " has " + std::to_string(key.vertices.size()) +
                                 " vertices, key 1 has " + std::to_string(first.vertices.size()));
    if (key.edges.size() != first.edges.size())
      throw InvalidArgumentError(key_name(k) + " has " + std::to_string(key.edges.size()) + " edges, key 1 has " +
                                 std::to_string(first.edges.size()));
    for (std::size_t e = 0; e < key.edges.size(); ++e)
      if (key.edges[e] != first.edges[e])
        throw InvalidArgumentError("edge " + std::to_string(e) + " is (" + std::to_string(first.edges[e][0]) + ", " +
                                   std::to_string(first.edges[e][1]) + ") in key 1 and (" +
                                   std::to_string(key.edges[e][0]) + ", " + std::to_string(key.edges[e][1]) +
                                   ") in " + key_name(k) + ": the keys must correspond by index");
  }
}

// N and F_k, checked.
std::pair<int, std::vector<int>> frame_plan(const KeyPoseMorphOptions& options, std::size_t keys,
                                            std::size_t segments) {
  const long long minimum = static_cast<long long>(segments) + 1;
  const long long frames =
      options.frames.value_or(static_cast<long long>(kDefaultFramesPerSegment) * static_cast<long long>(segments) + 1);
  if (frames < minimum || frames > kMaxMorphFrames)
    throw InvalidArgumentError("frames must be between " + std::to_string(minimum) + " (one more than the " +
                               std::to_string(segments) + " segments) and " + std::to_string(kMaxMorphFrames) +
                               ", got " + std::to_string(frames));
  const int n = int(frames);
  std::vector<int> at;
  if (options.keys_at.empty()) {
    for (std::size_t k = 0; k < keys; ++k)
      at.push_back(int(std::lround(double(k) * double(n - 1) / double(segments))));
    return {n, at};
  }
  if (options.keys_at.size() != keys)
    throw InvalidArgumentError("one key frame per key: " + std::to_string(keys) + " keys, " +
                               std::to_string(options.keys_at.size()) + " frames");
  if (options.keys_at[0] != 0)
    throw InvalidArgumentError("key 1 must be at frame 0, got " + std::to_string(options.keys_at[0]));
  for (std::size_t k = 1; k < keys; ++k)
    if (!(options.keys_at[k] > options.keys_at[k - 1]))
      throw InvalidArgumentError("the key frames must increase strictly: " + key_name(k) + " at " +
                                 std::to_string(options.keys_at[k]) + " is not after " + key_name(k - 1) + " at " +
                                 std::to_string(options.keys_at[k - 1]));
  const long long last = options.keys_at.back();
  if (options.loop ? last >= frames - 1 : last != frames - 1)
    throw InvalidArgumentError(key_name(keys - 1) + " must be at frame " +
                               (options.loop ? "below " : "") + std::to_string(frames - 1) +
                               (options.loop ? " (with loop the last frame is key 1 again)" : " (the last frame)") +
                               ", got " + std::to_string(last));
  for (long long f : options.keys_at) at.push_back(int(f));
  return {n, at};
}

// Every option, before any figure is looked at (as the pair morph checks
// its options first): the shared ones as the pair morph checks them, the
// per-key and per-segment lists by their lengths, and the frame plan.
void check_key_pose_options(const KeyPoseMorphOptions& options, std::size_t count) {
  const std::size_t segments = options.loop ? count : count - 1;
  MorphStickFiguresOptions shared;
  shared.method = MorphMethod::Rigid;
  shared.steiner = options.steiner;
  shared.weights = options.weights;
  shared.enclosure_sides = options.enclosure_sides;
  shared.verify = options.verify;
  shared.frame_check = options.frame_check;
  check_morph_options(shared);
  const auto per_entry = [&](const char* option, std::size_t size, std::size_t wanted, const char* what) {
    if (size != 0 && size != wanted)
      throw InvalidArgumentError(std::string(option) + ": one entry per " + what + ": " + std::to_string(wanted) +
                                 " " + what + "s, " + std::to_string(size) + " entries");
  };
  per_entry("turns", options.turns.size(), segments, "segment");
  per_entry("rotation", options.rotation.size(), segments, "segment");
  per_entry("hold", options.hold.size(), count, "key");
  per_entry("easing", options.easing.size(), segments, "segment");
  for (std::size_t s = 0; s < options.turns.size(); ++s)
    if (std::llabs(options.turns[s]) > kMaxExtraTurns)
      throw InvalidArgumentError("turns: segment " + std::to_string(s + 1) + " asks for " +
                                 std::to_string(options.turns[s]) + " whole turns, more than " +
                                 std::to_string(kMaxExtraTurns) + " either way");
  frame_plan(options, count, segments);
  if (options.correspond == CorrespondenceMode::ByIndex)
    for (const std::vector<VertexPin>& pins : options.pins)
      check_pins_need_auto(options.correspond, pins, OptionSpelling::Keyword, "");
}

}  // namespace

// The solver's state: the keys on one vertex set (by index, or matched),
// their checked pairs, the guide through all of them and one GuidedMorph
// per segment. The pairs and decompositions stay here, beside the morphs
// made from them.
struct KeyPoseMorphSolver::State {
  std::vector<StickFigure> keys;
  std::optional<KeyPoseCorrespondence> correspondence;
  int frames = 0;
  std::vector<int> key_frames;
  std::vector<Decomposition> decompositions;
  std::vector<CompatiblePair> pairs;
  std::shared_ptr<const KeyPoseGuide> guide;
  std::vector<GuidedMorph> morphs;
  std::vector<KeyPoseSegment> segments;
  bool verify = true;
  FrameCheck check = FrameCheck::Certificate;
};

KeyPoseMorphSolver::KeyPoseMorphSolver(const std::vector<StickFigure>& input_keys, const KeyPoseMorphOptions& options)
    : state_(std::make_unique<State>()) {
  if (input_keys.size() < 2)
    throw InvalidArgumentError("a key-pose sequence needs at least two keys, got " +
                               std::to_string(input_keys.size()));
  check_key_pose_options(options, input_keys.size());
  State& st = *state_;
  if (options.correspond == CorrespondenceMode::Auto) {
    report_stage("correspond");
    KeyPoseCorrespondenceOptions matching;
    matching.pins = options.pins;
    st.correspondence = correspond_key_poses(input_keys, matching);
    st.keys = st.correspondence->keys;
  } else {
    st.keys = input_keys;
  }
  // The delay weights are key 1's; on the common figure a dummy on one of
  // key 1's edges takes the weight interpolated along it.
  std::optional<LocalTiming> timing;
  if (options.timing) {
    options.timing->check_vertex_count(input_keys[0].vertices.size(), "key 1");
    timing = st.correspondence ? options.timing->on_matched_figure(st.correspondence->places[0], input_keys[0].edges)
                               : *options.timing;
  }
  const std::vector<StickFigure>& keys = st.keys;
  report_stage("check");
  check_same_graph(keys);
  const std::size_t count = keys.size();
  const std::size_t segments = options.loop ? count : count - 1;
  std::tie(st.frames, st.key_frames) = frame_plan(options, count, segments);
  const int frames = st.frames;
  const std::vector<int>& key_frames = st.key_frames;

  // The keys at their own scale only, for now: the working scale that
  // brings a pair into the numeric stages' range (working_scale.h) is not
  // yet carried through a sequence.
  for (std::size_t k = 1; k < count; ++k)
    if (working_scale_exponent(keys[0], keys[k]) != 0)
      throw NumericRangeError("key-pose sequences are morphed at their own scale, with coordinates between 2^-" +
                              std::to_string(kComfortableExponent) + " and 2^" +
                              std::to_string(kComfortableExponent) + " in magnitude; key 1 and " + key_name(k) +
                              " are not (scale the keys)");

  // Algorithm 1 once per key; each segment's pair checked (the keys must be
  // compatible from one to the next, which makes them all compatible).
  st.decompositions.reserve(count);
  for (const StickFigure& key : keys) {
    poll_cancellation();
    st.decompositions.push_back(decompose(key));
  }
  st.pairs.reserve(segments);  // never reallocated: the morphs are made from them
  for (std::size_t s = 0; s < segments; ++s) {
    poll_cancellation();
    const std::size_t next = (s + 1) % count;
    check_numeric_range(keys[s], keys[next], MorphMethod::Rigid);
    try {
      st.pairs.push_back(CompatiblePair::check(keys[s], st.decompositions[s], keys[next], st.decompositions[next]));
    } catch (const IncompatibleFiguresError& error) {
      throw IncompatibleFiguresError(error.kind(), key_name(s) + " and " + key_name(next) + ": " + error.what(),
                                     error.vertices());
    }
  }

  // The guide through all keys, at the sequence's times.
  const double last = double(frames - 1);
  std::vector<double> key_times;
  for (int f : key_frames) key_times.push_back(double(f) / last);
  std::vector<std::vector<Vec2>> key_vertices;
  for (const StickFigure& key : keys) key_vertices.push_back(key.vertices);
  KeyPoseGuideOptions guide_options;
  guide_options.loop = options.loop;
  // Held keys: those asked for, and both keys of every eased segment.
  guide_options.hold = options.hold;
  if (!options.easing.empty()) {
    guide_options.hold.resize(count, false);
    for (std::size_t s = 0; s < segments; ++s)
      if (options.easing[s] == Easing::InOut) guide_options.hold[s] = guide_options.hold[(s + 1) % count] = true;
  }
  guide_options.rotation = options.rotation;
  for (long long t : options.turns) guide_options.turns.push_back(int(t));
  st.guide = std::make_shared<const KeyPoseGuide>(key_vertices, keys[0].edges, key_times, guide_options);
  const std::vector<double>& knots = st.guide->knot_times();

  FigureTriangulationOptions paper;
  paper.method = options.steiner.value_or(SteinerMethod::Improved);
  paper.enclosure_sides = options.enclosure_sides ? int(*options.enclosure_sides) : kDefaultEnclosureSides;
  const WeightKind weights = options.weights.value_or(WeightKind::MeanValue);
  st.verify = options.verify.value_or(true);
  st.check = options.frame_check.value_or(FrameCheck::Certificate);
  // Not counted in segments: each segment's triangulation counts its own
  // steps (figure_triangulation.cpp), and two counts would fight.
  report_stage("triangulate");
  for (std::size_t s = 0; s < segments; ++s) {
    poll_cancellation();
    const std::size_t next = (s + 1) % count;
    KeyPoseSegment segment;
    segment.from_key = int(s);
    segment.to_key = int(next);
    segment.first_frame = key_frames[s];
    segment.last_frame = next == 0 ? frames - 1 : key_frames[next];
    const RotationDirection direction = options.rotation.empty() ? RotationDirection::Short : options.rotation[s];
    const int extra_turns = options.turns.empty() ? 0 : int(options.turns[s]);
    const CompatiblePair& pair = st.pairs[s];
    const SimilarityMotion similarity =
        fit_similarity(pair.source().vertices, pair.target().vertices, direction, extra_turns);
    segment.stats.similarity = similarity;
    const double t0 = knots[s], t1 = knots[s + 1];
    const std::shared_ptr<const KeyPoseGuide>& guide = st.guide;
    // Each segment on its own clock: the delays restart at every key.
    std::shared_ptr<const LocalClock> clock;
    if (timing && !timing->is_plain())
      clock = std::make_shared<const LocalClock>(*timing, keys[0].edges, guide->part(), guide->part_count(),
                                                 keys[s].vertices, keys[next].vertices);
    st.morphs.push_back(internal::prepare_guided_morph(
        pair, similarity,
        [&]() -> std::unique_ptr<const GuideTrajectory> {
          return std::make_unique<const KeyPoseStretch>(guide, int(s), t0, t1, clock);
        },
        paper, weights, Easing::None, segment.stats));
    segment.stats.morph_ms = segment.stats.factorize_ms;
    segment.triangulation = st.morphs.back().triangulation();
    st.segments.push_back(std::move(segment));
  }
}

KeyPoseMorphSolver::~KeyPoseMorphSolver() = default;
KeyPoseMorphSolver::KeyPoseMorphSolver(KeyPoseMorphSolver&&) noexcept = default;
KeyPoseMorphSolver& KeyPoseMorphSolver::operator=(KeyPoseMorphSolver&&) noexcept = default;

int KeyPoseMorphSolver::frame_count() const { return state_->frames; }
const std::vector<int>& KeyPoseMorphSolver::key_frames() const { return state_->key_frames; }
const std::vector<StickFigure>& KeyPoseMorphSolver::keys() const { return state_->keys; }
const std::optional<KeyPoseCorrespondence>& KeyPoseMorphSolver::correspondence() const {
  return state_->correspondence;
}
const std::vector<KeyPoseSegment>& KeyPoseMorphSolver::segments() const { return state_->segments; }

std::vector<Vec2> KeyPoseMorphSolver::segment_frame(std::size_t s, double u, int label) {
  State& st = *state_;
  KeyPoseSegment& segment = st.segments[s];
  const std::string context = "segment " + std::to_string(s + 1) + " (" + key_name(std::size_t(segment.from_key)) +
                              " to " + key_name(std::size_t(segment.to_key)) + "), ";
  const auto start = std::chrono::steady_clock::now();
  GuidedFrame frame;
  try {
    frame = st.morphs[s].frame(u, label, st.verify, context, st.check);
  } catch (const InvalidArgumentError& error) {
    throw InternalError(std::string("morph_key_poses: the engine refused its own intermediate result: ") +
                        error.what());
  }
  MorphStickFiguresStats& stats = segment.stats;
  // Interior frames only, as the pair morph counts them: a segment's end
  // frames are its keys, exactly, whatever the guide.
  if (u > 0 && u < 1) {
    if (frame.fit == GuideFit::Exact) ++stats.guide_exact_frames;
    if (frame.fit == GuideFit::Blended) ++stats.guide_blended_frames;
    if (frame.fit == GuideFit::Barycentric) ++stats.guide_barycentric_frames;
  }
  if (frame.refined) ++stats.refined_frames;
  stats.morph_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const GuidedMorphStats& guided = st.morphs[s].stats();
  stats.solve_ms = guided.guide_ms + guided.solve_ms;
  stats.verify_ms = guided.verify_ms;
  stats.factorizations = guided.factorizations;
  const std::size_t n = st.keys[0].vertices.size();
  return {frame.positions.begin(), frame.positions.begin() + std::ptrdiff_t(n)};
}

std::vector<Vec2> KeyPoseMorphSolver::frame(int f) {
  const State& st = *state_;
  if (f < 0 || f >= st.frames)
    throw InvalidArgumentError("frame must be between 0 and " + std::to_string(st.frames - 1) + ", got " +
                               std::to_string(f));
  // The segment whose frames (first_frame, last_frame] hold f; frame 0 is
  // the first segment's first.
  std::size_t s = 0;
  while (s + 1 < st.segments.size() && f > st.segments[s].last_frame) ++s;
  const KeyPoseSegment& segment = st.segments[s];
  const int span = segment.last_frame - segment.first_frame;
  const double u = f == segment.last_frame ? 1.0 : double(f - segment.first_frame) / double(span);
  return segment_frame(s, u, f);
}

std::vector<Vec2> KeyPoseMorphSolver::solve(double time) {
  const State& st = *state_;
  if (!(time >= 0 && time <= 1))
    throw InvalidArgumentError("time must be between 0 and 1 (the whole sequence), got " + format_double(time));
  const std::vector<double>& knots = st.guide->knot_times();
  std::size_t s = 0;
  while (s + 1 < st.segments.size() && time > knots[s + 1]) ++s;
  const double u = time >= knots[s + 1] ? 1.0 : (time - knots[s]) / (knots[s + 1] - knots[s]);
  return segment_frame(s, std::clamp(u, 0.0, 1.0), -1);
}

KeyPoseMorphResult morph_key_poses(const std::vector<StickFigure>& keys, const KeyPoseMorphOptions& options) {
  KeyPoseMorphSolver solver(keys, options);
  const int frames = solver.frame_count();
  KeyPoseMorphResult result;
  result.key_frames = solver.key_frames();
  result.times.resize(std::size_t(frames));
  for (int f = 0; f < frames; ++f) result.times[std::size_t(f)] = double(f) / double(frames - 1);
  result.frames.reserve(std::size_t(frames));
  report_stage("frames", frames);
  for (int f = 0; f < frames; ++f) {
    report_progress(f, frames);  // and a caller's cancel stops here, between frames
    result.frames.push_back(solver.frame(f));
  }
  report_progress(frames, frames);
  // Every key exactly at its frame: the segments' end frames are their
  // pairs' figures (GuidedMorph), so this holds by construction; a
  // mismatch is a bug, not a user's error.
  const std::vector<StickFigure>& common = solver.keys();
  for (std::size_t k = 0; k < common.size(); ++k)
    if (result.frames[std::size_t(result.key_frames[k])] != common[k].vertices)
      throw InternalError("morph_key_poses: frame " + std::to_string(result.key_frames[k]) + " is not " +
                          key_name(k));
  if (options.loop && result.frames.back() != common[0].vertices)
    throw InternalError("morph_key_poses: the loop's last frame is not key 1");
  result.segments = solver.segments();
  result.correspondence = solver.correspondence();
  return result;
}

}  // namespace stickmorph
