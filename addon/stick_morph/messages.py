"""User messages for the engine's exceptions, naming the objects where the
engine says "source" and "target" (it reads the exceptions' attributes; no
text is parsed)."""

from __future__ import annotations

from .native import load_engine

def _without_prefix(text: str, prefix: str) -> str:
    return text[len(prefix):] if text.startswith(prefix) else text


def match_error_message(error: Exception, source_name: str, target_name: str, pins=(),
                        index_report=None) -> str:
    """A user message for stickmorph.correspond's IncompatibleFiguresError
    (kind topology_differs, mirror_image, exterior_differs or
    pins_unsatisfiable). index_report: the by-index check's report when the
    bake tried that first (Correspondence Automatic), said too."""
    # The engine prefixes its reason with "correspond: ", the function's
    # name, which means nothing in Blender.
    reason = _without_prefix(getattr(error, "reason", None) or str(error), "correspond: ")
    kind = getattr(error, "kind", None)
    if index_report is not None and not index_report and getattr(index_report, "kind", None) == NESTING_DIFFERS:
        # Automatic checked by index first (the meshes have the same edges,
        # so the same parts) and found a part in another face: that is what
        # the user changed, in the meshes' own vertex numbers; the matching
        # (whose numbers are the matched figure's) cannot undo it.
        text = nesting_message(index_report.reason, source_name, target_name)
        if kind == NESTING_DIFFERS:
            return text + " (matched by shape, the parts nest differently too)"
        return text + f" (nor can they be matched by shape: {reason})"
    if kind == "pins_unsatisfiable":
        listing = "; ".join(f"'{pin.name}': vertex {pin.source} of '{source_name}' to vertex {pin.target} "
                            f"of '{target_name}'" for pin in pins)
        text = f"the pins cannot all hold: {reason} (pins {listing})"
    elif kind == "mirror_image":
        text = f"cannot match '{source_name}' and '{target_name}': '{target_name}' is a mirror image of " \
               f"'{source_name}': {reason}"
    elif kind == NESTING_DIFFERS:
        text = nesting_message(reason, source_name, target_name)
    else:
        text = f"cannot match '{source_name}' and '{target_name}': {reason}"
    if index_report is not None and not index_report:
        text += f" (nor are they compatible by index: {_without_prefix(index_report.reason, 'incompatible figures: ')})"
    return text


# The kind of IncompatibleFiguresError (and CompatibilityReport) for a pair
# of figures with several parts where a part lies in another face of another
# part in the target than in the source (issue 14).
NESTING_DIFFERS = "nesting_differs"


def nesting_message(reason: str, source_name: str, target_name: str) -> str:
    """The message for kind nesting_differs: the engine's reason names the
    part ("part 1", parts numbered by their smallest vertex, figure_parts)."""
    reason = _without_prefix(_without_prefix(reason, "correspond: "), "incompatible figures: ")
    return f"'{source_name}' and '{target_name}': a part changes face: {reason}"


def _where(vertices) -> str:
    """' (vertex 3)', ' (vertices 0, 2)' or '' for the vertices a report names."""
    listed = ", ".join(str(v) for v in vertices)
    if len(vertices) == 1:
        return f" (vertex {listed})"
    return f" (vertices {listed})" if listed else ""


def engine_error_message(error: Exception, source_name: str, target_name: str) -> str:
    """A user message for an exception raised by the native module, naming the
    objects where the engine says "source" or "target" (the exceptions' role,
    detail, kind, vertices and reason attributes; the text is not parsed)."""
    engine = load_engine()
    text = str(error)
    if isinstance(error, engine.InvalidFigureError):
        if error.role in ("source", "target"):
            text = f"'{source_name if error.role == 'source' else target_name}': {error.detail}"
        defect = error.defect or ""
        if defect == "crossing_edges":
            return f"crossing edges: {text} (mesh edge indices)"
        if defect in ("overlapping_edges", "vertex_on_edge", "coincident_vertices"):
            return f"the figure touches itself: {text}"
        return f"invalid figure: {text}"
    if isinstance(error, engine.IncompatibleFiguresError):
        # The morph's own compatibility check of the pair it is given (a
        # matched pair passes it): its exception carries the report (kind,
        # vertices, reason). A matching's refusal is match_error_message's.
        where = _where(error.vertices or [])
        if error.kind == NESTING_DIFFERS:
            return nesting_message(error.reason or text, source_name, target_name)
        if error.kind == "mirror_image":
            return (f"incompatible figures: '{target_name}' is a mirror image of '{source_name}'"
                    f"{where}: {error.reason}")
        return f"incompatible figures '{source_name}' and '{target_name}'{where}: {error.reason}"
    if isinstance(error, engine.VerificationError):
        return f"the morph failed exact verification: {text}"
    if isinstance(error, engine.InternalError):
        return f"internal error in the stickmorph engine (a bug): {text}"
    return f"stickmorph: {text}"
