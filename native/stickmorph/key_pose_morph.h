// The morph through a sequence of key poses (issue 28): one continuous,
// valid motion that shows key k exactly at frame F_k.
//
// Each segment, key s to key s + 1 (and the last key back to the first with
// `loop`), is a rigid morph (guided_morph.h) of that compatible pair with
// its own compatible triangulation, as the pair morph makes it
// (internal/rigid_morph_setup.h); what joins the segments into one motion is
// the guide they all follow: one KeyPoseGuide (key_pose_guide.h) through all
// keys, C1 at the interior keys, each segment following its own stretch of
// it at the sequence's own times (not retimed for even speed, which would
// break the speed's continuity at the keys). Where every star of a frame's
// guide is valid the frame is the guide, so the figure's velocity is
// continuous through every key the morph meets on the guide.
//
// Why switching triangulations at a key is safe: a frame's validity is a
// property of the figure alone (the figure drawn without crossings and with
// the source's rotation system, Section 2.1), not of the triangulation that
// made it. Both segments meeting at key k show exactly key k there (each
// GuidedMorph's end frames are its pair's figures exactly), every frame of
// each segment is verified (the certificate of frame_certificate.h against
// its own triangulation, or verify_frame), and the keys are compatible with
// each other (each consecutive pair is checked: the same rotation system
// and the same nesting of parts), so every frame of the sequence is a valid
// drawing of the same stick figure.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "stickmorph/figure_correspondence.h"
#include "stickmorph/figure_triangulation.h"
#include "stickmorph/key_pose_correspondence.h"
#include "stickmorph/morph.h"
#include "stickmorph/morph_stick_figures.h"
#include "stickmorph/similarity_motion.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// The frames per segment that the default frame count gives: N = 49 S + 1.
constexpr int kDefaultFramesPerSegment = 49;

struct KeyPoseMorphOptions {
  /// ByIndex: the keys share their vertices and edges. Auto: keys drawn
  /// separately are matched onto one common figure first
  /// (key_pose_correspondence.h), and the frames are that figure's.
  CorrespondenceMode correspond = CorrespondenceMode::ByIndex;
  /// With Auto: per consecutive pair of keys, the vertices that must match
  /// (key_pose_correspondence.h). Refused by index.
  std::vector<std::vector<VertexPin>> pins;
  /// N, the frames of the whole sequence; default kDefaultFramesPerSegment
  /// times the segments, plus 1.
  std::optional<long long> frames;
  /// F_k, the frame of every key: strictly increasing, the first 0, the
  /// last N - 1 (below N - 1 with `loop`, whose last frame is the first key
  /// again). Empty: F_k = round(k (N - 1) / S), S the segments.
  std::vector<long long> keys_at;
  /// After the last key the motion returns to the first (frame N - 1).
  bool loop = false;
  /// Per key (empty: none): the motion stops at that key.
  std::vector<bool> hold;
  /// Per segment (empty: None everywhere). InOut eases the segment in and
  /// out: the motion starts it from rest and comes to rest at its end, so
  /// it holds both of the segment's keys (a spline through the keys cannot
  /// slow a segment's ends without stopping there, or the speed would jump
  /// at the key; at a held key both neighbouring segments are at rest).
  std::vector<Easing> easing;
  /// Per segment (empty: Short and no extra turns): which way the figure
  /// turns from a key to the next, and its extra whole turns.
  std::vector<RotationDirection> rotation;
  std::vector<long long> turns;
  // As the pair morph's (MorphStickFiguresOptions), for every segment.
  std::optional<SteinerMethod> steiner;
  std::optional<WeightKind> weights;
  std::optional<long long> enclosure_sides;
  std::optional<bool> verify;
  std::optional<FrameCheck> frame_check;
  /// Delay weights per vertex of key 1 and an overlap (local_timing.h,
  /// issue 31). Each segment runs them on its own clock, from its first key
  /// to its next: every key stays exact at its frame, and the lagging parts
  /// catch up by every key. Unset, or overlap 0: the plain sequence.
  std::optional<LocalTiming> timing;
};

/// One segment: its frames [first_frame, last_frame] of the sequence, the
/// compatible triangulation it used (output space) and what it measured.
struct KeyPoseSegment {
  int from_key = 0, to_key = 0;  ///< 0-based; to_key is 0 for a loop's last segment
  int first_frame = 0, last_frame = 0;
  FigureTriangulation triangulation;
  MorphStickFiguresStats stats;
};

struct KeyPoseMorphResult {
  std::vector<double> times;                ///< N times f / (N - 1)
  std::vector<std::vector<Vec2>> frames;    ///< N frames of the figure's n vertices; frames[F_k] is key k exactly
  std::vector<int> key_frames;              ///< F_k per key
  std::vector<KeyPoseSegment> segments;     ///< S segments, in order
  /// With CorrespondenceMode::Auto: the common figure on every key (its
  /// edges are the frames' edges) and where its vertices are on each key.
  std::optional<KeyPoseCorrespondence> correspondence;
};

/// The morph through key poses as a stateful solver (geometry-central's
/// one-shot function plus solver): the keys matched and checked, the guide
/// and every segment's GuidedMorph set up once; then any frame of the
/// sequence, or the figure at any time, each verified as morph_key_poses'
/// frames are. For scrubbing: frames may be asked in any order.
class KeyPoseMorphSolver {
 public:
  /// @throws as morph_key_poses, for everything but the frames themselves.
  KeyPoseMorphSolver(const std::vector<StickFigure>& keys, const KeyPoseMorphOptions& options = {});
  ~KeyPoseMorphSolver();
  KeyPoseMorphSolver(KeyPoseMorphSolver&&) noexcept;
  KeyPoseMorphSolver& operator=(KeyPoseMorphSolver&&) noexcept;

  int frame_count() const;                       ///< N
  const std::vector<int>& key_frames() const;    ///< F_k per key
  /// The keys on the frames' vertices and edges: the input keys by index,
  /// the matched keys (correspondence()->keys) with CorrespondenceMode::Auto.
  const std::vector<StickFigure>& keys() const;
  const std::optional<KeyPoseCorrespondence>& correspondence() const;
  /// The segments, their triangulations and what their frames so far cost.
  const std::vector<KeyPoseSegment>& segments() const;

  /// Frame f of N: morph_key_poses' frames[f], bit for bit.
  /// @throws InvalidArgumentError for f outside [0, N - 1];
  ///         VerificationError as morph_key_poses.
  std::vector<Vec2> frame(int f);
  /// The figure at `time` in [0, 1] of the whole sequence (key k at
  /// F_k / (N - 1), exactly), verified; between frames too.
  /// @throws InvalidArgumentError for a time outside [0, 1] or not a number;
  ///         VerificationError as morph_key_poses.
  std::vector<Vec2> solve(double time);

 private:
  std::vector<Vec2> segment_frame(std::size_t segment, double u, int label);
  struct State;
  std::unique_ptr<State> state_;
};

/// The morph through `keys` (K >= 2 stick figures made by
/// make_stick_figure: on the same vertices and edges, or drawn separately
/// with CorrespondenceMode::Auto), the rigid method's motion.
/// @throws InvalidArgumentError for fewer than two keys, keys of other
///         vertex counts or edges (naming the key), and options out of
///         range (naming the option and the entry), pins by index;
///         IncompatibleFiguresError naming the two keys and, as the pair
///         check does, the vertices; NumericRangeError for keys beyond the
///         numeric range the morph carries; VerificationError if a frame
///         fails its exact check (naming the segment and the frame).
KeyPoseMorphResult morph_key_poses(const std::vector<StickFigure>& keys, const KeyPoseMorphOptions& options = {});

}  // namespace stickmorph
