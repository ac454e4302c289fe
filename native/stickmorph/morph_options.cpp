#include "stickmorph/morph_options.h"

#include "stickmorph/compatible_triangulation.h"
#include "stickmorph/errors.h"
#include "stickmorph/frame_certificate.h"
#include "stickmorph/morph.h"
#include "stickmorph/morph_stick_figures.h"
#include "stickmorph/rigid_guide.h"
#include "stickmorph/similarity_motion.h"

namespace stickmorph {
namespace {

// The two reasons an option does not apply, as the messages quote them.
constexpr const char* kNoTriangulation = "the straight-line morph uses no triangulation";
constexpr const char* kRigidOnly = "only the rigid method factors out a rotation and follows a guide";

// A rule with no value constraints yet (the kind's fields are set by the
// callers below).
MorphOptionRule base_rule(Option option, MethodSet methods, const char* why, OptionValueKind kind) {
  MorphOptionRule rule;
  rule.option = option;
  rule.methods = methods;
  rule.refused_because = why;
  rule.kind = kind;
  return rule;
}

MorphOptionRule count_rule(Option option, MethodSet methods, const char* why, long long least, long long most,
                           long long default_count) {
  MorphOptionRule rule = base_rule(option, methods, why, OptionValueKind::Count);
  rule.least = least;
  rule.most = most;
  rule.default_count = default_count;
  return rule;
}

// Names through the engine's own name functions, so that a choice listed
// here is one its parse function accepts.
MorphOptionRule name_rule(Option option, MethodSet methods, const char* why, std::vector<std::string> choices,
                          std::string default_name) {
  MorphOptionRule rule = base_rule(option, methods, why, OptionValueKind::Name);
  rule.choices = std::move(choices);
  rule.default_name = std::move(default_name);
  return rule;
}

// Whether the caller asked for `option` (set means asked, even for the
// default value).
bool given(const MorphStickFiguresOptions& options, Option option) {
  switch (option) {
    case Option::Verify: return options.verify.has_value();
    case Option::FrameCheck: return options.frame_check.has_value();
    case Option::Weights: return options.weights.has_value();
    case Option::Steiner: return options.steiner.has_value();
    case Option::EnclosureSides: return options.enclosure_sides.has_value();
    case Option::Rotation: return options.rotation.has_value();
    case Option::Turns: return options.turns.has_value();
    case Option::Easing: return options.easing.has_value();
    case Option::Pins: return !options.pins.empty();
    case Option::Timing: return options.timing.has_value();
    default: return false;  // frames, method, correspond: always in effect
  }
}

}  // namespace

MethodSet method_bit(MorphMethod method) { return 1u << static_cast<unsigned>(method); }

const std::vector<MorphOptionRule>& morph_option_rules() {
  static const std::vector<MorphOptionRule> table = [] {
    const MethodSet triangulated = method_bit(MorphMethod::Rigid) | method_bit(MorphMethod::Barycentric);
    const MethodSet rigid = method_bit(MorphMethod::Rigid);
    std::vector<MorphOptionRule> rules;
    rules.push_back(count_rule(Option::Frames, kAllMethods, "", kMinMorphFrames, kMaxMorphFrames,
                               kDefaultMorphFrames));
    rules.push_back(name_rule(Option::Method, kAllMethods, "",
                              {morph_method_name(MorphMethod::Rigid), morph_method_name(MorphMethod::Barycentric),
                               morph_method_name(MorphMethod::Linear)},
                              morph_method_name(MorphMethod::Rigid)));
    // The triangulation's options, which the linear method would ignore.
    MorphOptionRule verify = base_rule(Option::Verify, triangulated, kNoTriangulation, OptionValueKind::Flag);
    verify.default_flag = true;
    rules.push_back(verify);
    rules.push_back(name_rule(Option::FrameCheck, triangulated, kNoTriangulation,
                              {frame_check_name(FrameCheck::Certificate), frame_check_name(FrameCheck::Full)},
                              frame_check_name(FrameCheck::Certificate)));
    rules.push_back(name_rule(Option::Weights, triangulated, kNoTriangulation,
                              {weight_kind_name(WeightKind::MeanValue), weight_kind_name(WeightKind::Uniform),
                               weight_kind_name(WeightKind::Floater)},
                              weight_kind_name(WeightKind::MeanValue)));
    rules.push_back(name_rule(Option::Steiner, triangulated, kNoTriangulation,
                              {steiner_method_name(SteinerMethod::Improved), steiner_method_name(SteinerMethod::Sg2001),
                               steiner_method_name(SteinerMethod::Aronov)},
                              steiner_method_name(SteinerMethod::Improved)));
    rules.push_back(count_rule(Option::EnclosureSides, triangulated, kNoTriangulation, kMinEnclosureSides,
                               kMaxEnclosureSides, kDefaultEnclosureSides));
    // The rigid method's own (issue 12).
    rules.push_back(name_rule(Option::Rotation, rigid, kRigidOnly,
                              {rotation_direction_name(RotationDirection::Short),
                               rotation_direction_name(RotationDirection::CounterClockwise),
                               rotation_direction_name(RotationDirection::Clockwise)},
                              rotation_direction_name(RotationDirection::Short)));
    rules.push_back(count_rule(Option::Turns, rigid, kRigidOnly, -kMaxExtraTurns, kMaxExtraTurns, 0));
    rules.push_back(name_rule(Option::Easing, rigid, kRigidOnly, {easing_name(Easing::None), easing_name(Easing::InOut)},
                              easing_name(Easing::None)));
    // Local timing (issue 31) delays parts of the rigid guide.
    rules.push_back(base_rule(Option::Timing, rigid, kRigidOnly, OptionValueKind::Timing));
    // Figures drawn separately (issue 13): every method.
    rules.push_back(name_rule(Option::Correspond, kAllMethods, "",
                              {correspondence_mode_name(CorrespondenceMode::ByIndex),
                               correspondence_mode_name(CorrespondenceMode::Auto)},
                              correspondence_mode_name(CorrespondenceMode::ByIndex)));
    rules.push_back(base_rule(Option::Pins, kAllMethods, "", OptionValueKind::Pins));
    return rules;
  }();
  return table;
}

const MorphOptionRule& morph_option_rule(Option option) {
  for (const MorphOptionRule& rule : morph_option_rules())
    if (rule.option == option) return rule;
  throw InternalError("morph_option_rule: option " + std::to_string(static_cast<int>(option)) +
                      " is not an option of the morph");
}

bool option_applies(Option option, MorphMethod method) {
  return (morph_option_rule(option).methods & method_bit(method)) != 0;
}

void check_count_option(Option option, long long value, MorphMethod method, OptionSpelling spelling,
                        const std::string& as_typed) {
  const MorphOptionRule& rule = morph_option_rule(option);
  if (rule.kind != OptionValueKind::Count)
    throw InternalError("check_count_option: " + describe_option(option, OptionSpelling::Keyword) +
                        " is not a count");
  if (!option_applies(option, method)) return;
  check_count(option, value, rule.least, rule.most, spelling, as_typed);
}

void check_pins_need_auto(CorrespondenceMode mode, const std::vector<VertexPin>& pins, OptionSpelling spelling,
                          const std::string& command) {
  if (pins.empty() || mode == CorrespondenceMode::Auto) return;
  throw InvalidArgumentError(command + describe_option(Option::Pins, spelling) +
                             (spelling == OptionSpelling::CommandLine ? " needs --correspond auto"
                                                                      : " need correspond='auto'") +
                             " (with the index correspondence every vertex is already paired)");
}

void check_morph_options(const MorphStickFiguresOptions& options) {
  check_frames(options.frames, options.spelling);
  // "--method linear" or "method='linear'", as the caller would have written it.
  const std::string method_text = options.spelling == OptionSpelling::CommandLine
                                      ? "--method " + morph_method_name(options.method)
                                      : "method='" + morph_method_name(options.method) + "'";
  // Options given that this method would ignore: the first one in the
  // table's order is refused. Node frames (no option of an interface, the
  // CLI's --svg-triangulation asks for them) come after the triangulation's
  // options and before the rigid method's, as they always did.
  bool node_frames_checked = false;
  for (const MorphOptionRule& rule : morph_option_rules()) {
    if (!node_frames_checked && rule.methods == method_bit(MorphMethod::Rigid)) {
      node_frames_checked = true;
      if (options.keep_node_frames && options.method == MorphMethod::Linear)
        throw InvalidArgumentError("node frames do not exist with " + method_text + " (" + kNoTriangulation + ")");
    }
    if (given(options, rule.option) && (rule.methods & method_bit(options.method)) == 0)
      throw InvalidArgumentError(describe_option(rule.option, options.spelling) + " has no effect with " +
                                 method_text + " (" + rule.refused_because + ")");
  }
  if (options.frame_check && options.verify == false)
    throw InvalidArgumentError(describe_option(Option::FrameCheck, options.spelling) + " has no effect with " +
                               (options.spelling == OptionSpelling::CommandLine ? "--no-verify" : "verify=False") +
                               " (no frame is checked)");
  if (options.enclosure_sides) check_enclosure_sides(*options.enclosure_sides, options.spelling);
  if (options.turns) check_turns(*options.turns, options.spelling);
  check_pins_need_auto(options.correspond, options.pins, options.spelling);
}

}  // namespace stickmorph
