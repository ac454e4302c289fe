// The engine's option rules and limits as module attributes, for the add-on
// and help texts to read instead of keeping copies: stickmorph.limits,
// stickmorph.OPTION_NAMES, the names tuples and stickmorph.option_rules
// (which methods each option of morph() applies to, its range or names and
// its default), all built from the tables the engine's checks use
// (argument_limits.h, morph_options.h).
#include <pybind11/pybind11.h>

#include <cmath>

#include "bindings.h"
#include "conversions.h"
#include "stickmorph/argument_limits.h"
#include "stickmorph/morph_options.h"
#include "stickmorph/morph_stick_figures.h"

namespace stickmorph::python {
namespace {

// stickmorph.limits: the engine's bounds by name, for range checks and help
// texts outside the engine (the add-on's properties, its preferences).
py::dict limits_dict() {
  py::dict limits;
  for (const auto& [name, value] : engine_limits()) {
    // Counts as ints; the coordinate bound (1e100) is a float.
    if (value == std::floor(value) && std::abs(value) < 1e15)
      limits[name.c_str()] = static_cast<long long>(value);
    else
      limits[name.c_str()] = value;
  }
  return limits;
}

// stickmorph.OPTION_NAMES: keyword -> CLI flag ("" where the CLI has none),
// from the engine's one table.
py::dict option_names_dict() {
  py::dict names;
  for (const sm::OptionName& row : sm::option_names()) names[row.keyword] = row.command_line;
  return names;
}

py::tuple names_tuple(const std::vector<std::string>& names) {
  py::list list;
  for (const std::string& name : names) list.append(name);
  return py::tuple(list);
}

// stickmorph.option_rules: morph_option_rules() keyed by keyword.
py::dict option_rules_dict() {
  const sm::MorphMethod methods[] = {sm::MorphMethod::Rigid, sm::MorphMethod::Barycentric,
                                     sm::MorphMethod::Linear};
  py::dict rules;
  for (const sm::MorphOptionRule& rule : sm::morph_option_rules()) {
    py::list applies;
    for (const sm::MorphMethod method : methods)
      if (rule.methods & sm::method_bit(method)) applies.append(sm::morph_method_name(method));
    py::dict entry;
    entry["methods"] = py::tuple(applies);
    switch (rule.kind) {
      case sm::OptionValueKind::Count:
        entry["min"] = rule.least;
        entry["max"] = rule.most;
        entry["default"] = rule.default_count;
        break;
      case sm::OptionValueKind::Name:
        entry["choices"] = names_tuple(rule.choices);
        entry["default"] = rule.default_name;
        break;
      case sm::OptionValueKind::Flag: entry["default"] = rule.default_flag; break;
      case sm::OptionValueKind::Pins: break;    // none by default; only with correspond="auto"
      case sm::OptionValueKind::Timing: break;  // none by default; with overlap=
    }
    rules[sm::describe_option(rule.option, sm::OptionSpelling::Keyword).c_str()] = entry;
  }
  return rules;
}

}  // namespace

void bind_options(py::module_& m) {
  m.attr("limits") = limits_dict();
  m.attr("OPTION_NAMES") = option_names_dict();
  // The accepted names, from the same table as option_rules.
  m.attr("METHOD_NAMES") = names_tuple(sm::morph_option_rule(sm::Option::Method).choices);
  m.attr("ROTATION_NAMES") = names_tuple(sm::morph_option_rule(sm::Option::Rotation).choices);
  m.attr("EASING_NAMES") = names_tuple(sm::morph_option_rule(sm::Option::Easing).choices);
  m.attr("option_rules") = option_rules_dict();
}

}  // namespace stickmorph::python
