# Type stubs of stickmorph, which follows Surazhsky & Gotsman 2001, "Morphing Stick Figures
# Using Optimized Compatible Triangulations" (Pacific Graphics 2001).
#
# Hand-written from the bindings (native/python/*.cpp) and the runtime
# docstrings; tests/python/test_stubs.py checks them against the built module
# (names, signatures, classes, exception attributes, the Literal name sets and
# the keys and dtypes of the returned dicts). Update this file together with
# the bindings: a binding that changes without it fails that test.
#
# Conventions: inputs documented as "#V by 2 array-like" are ArrayLike (the
# engine converts them with numpy.asarray and checks shape and dtype itself);
# returned arrays are NDArray of the dtype the bindings create (float64
# coordinates, int64 indices). Names starting with "_" exist only here (the
# TypedDicts of the returned dicts, the Literal name sets), so that the stub
# adds no public name the module lacks. Only `typing` is used (no
# typing_extensions), so that the stub reads on Python 3.11 and later.

import os
from collections.abc import Sequence
from typing import Any, Literal, NotRequired, Self, SupportsFloat, SupportsIndex, TypeAlias, TypedDict

import numpy
from numpy.typing import ArrayLike, NDArray

__version__: str

# ---------------------------------------------------------------------------
# Argument types. The engine refuses bool where it wants a count or a number
# (to_count, to_time in conversions.cpp); bool being an int, that cannot be
# said in a type.

_Float64Array: TypeAlias = NDArray[numpy.float64]
_Int64Array: TypeAlias = NDArray[numpy.int64]
# to_flag: True or False, or a NumPy bool.
_Flag: TypeAlias = bool | numpy.bool_
# to_count: any object with __index__ (int, NumPy integers).
_Count: TypeAlias = SupportsIndex
# to_time and overlap=: a real number (int, float, NumPy scalars).
_Real: TypeAlias = SupportsFloat | SupportsIndex
_Path: TypeAlias = str | bytes | os.PathLike[str] | os.PathLike[bytes]

# The accepted names of morph()'s options (stickmorph.option_rules[...]["choices"],
# METHOD_NAMES, ROTATION_NAMES, EASING_NAMES); the test compares them.
_MethodName: TypeAlias = Literal["rigid", "barycentric", "linear"]
_SteinerName: TypeAlias = Literal["improved", "sg2001", "aronov"]
_WeightsName: TypeAlias = Literal["mvc", "uniform", "floater"]
_RotationName: TypeAlias = Literal["short", "ccw", "cw"]
_EasingName: TypeAlias = Literal["none", "in-out"]
_FrameCheckName: TypeAlias = Literal["certificate", "full"]
_CorrespondName: TypeAlias = Literal["index", "auto"]

# The names the bindings give the engine's enums (errors.cpp, bind_figures.cpp,
# drawing_cleaning.cpp); the test reads them from those switch statements.
_FigureDefect: TypeAlias = Literal[
    "no_vertices",
    "non_finite_coordinate",
    "coordinate_too_large",
    "edge_index_out_of_range",
    "self_loop",
    "duplicate_edge",
    "coincident_vertices",
    "crossing_edges",
    "overlapping_edges",
    "vertex_on_edge",
    "too_few_corners",
    "coincident_corners",
    "clockwise_corners",
    "closed_wedge",
    "self_overlapping_polygon",
]
_DrawingDefect: TypeAlias = Literal[
    "no_strokes",
    "too_few_points",
    "collapsed_stroke",
    "non_finite_coordinate",
    "coordinate_too_large",
    "index_out_of_range",
    "retrace",
    "overlap",
    "unresolved",
]
_Incompatibility: TypeAlias = Literal[
    "none",
    "vertex_count_differs",
    "edge_set_differs",
    "mirror_image",
    "rotation_differs",
    "exterior_differs",
    "nesting_differs",
    "topology_differs",
    "pins_unsatisfiable",
]
# check_pins returns None, not a dict, where the engine's name would be "none".
_PinDefect: TypeAlias = Literal[
    "missing_source_vertex",
    "missing_target_vertex",
    "source_pinned_twice",
    "target_pinned_twice",
    "kinds_differ",
]
_DrawingChangeKind: TypeAlias = Literal["merge", "snap", "crossing", "touch"]

# ---------------------------------------------------------------------------
# The dicts the functions return. Keys present only in some cases (a method,
# correspond="auto") are NotRequired.

class _TriangulationStats(TypedDict):
    interior_faces: int
    cut_bends: int
    interior_steiner: int
    min_angle: float
    parts: int
    bridges: int
    bridge_bends: int

class _Triangulation(TypedDict):
    figure_vertices: int
    enclosure_vertices: int
    steiner_vertices: int
    source: _Float64Array
    target: _Float64Array
    triangles: _Int64Array
    stats: _TriangulationStats

class _Similarity(TypedDict):
    angle_degrees: float
    scale: float
    source_center: tuple[float, float]
    target_center: tuple[float, float]

class _SolverSimilarity(_Similarity):
    factored: bool

class _GuideFrames(TypedDict):
    exact: int
    blended: int
    barycentric: int

class _RigidStats(TypedDict):
    rotation: _RotationName
    turns: int
    easing: _EasingName
    similarity_factored: bool
    similarity: _Similarity
    guide_frames: _GuideFrames
    refinement_steiner_vertices: int

class _MorphMilliseconds(TypedDict):
    triangulate: float
    morph: float
    factorize: float
    solve: float
    verify: float
    correspond: NotRequired[float]  # with correspond="auto"

class _MatchingStats(TypedDict):
    matched_vertices: int
    source_dummies: int
    target_dummies: int
    skeleton_nodes: int
    skeleton_chains: int
    candidates: int
    residual: float
    rotation_degrees: float

class _CorrespondMilliseconds(TypedDict):
    correspond: float

class _CorrespondStats(_MatchingStats):
    milliseconds: _CorrespondMilliseconds

class _MorphStats(TypedDict):
    steiner_vertices: int
    triangles: int
    parts: int
    bridge_vertices: int
    milliseconds: _MorphMilliseconds
    method: _MethodName
    steiner_method: NotRequired[_SteinerName]  # rigid and barycentric
    enclosure_sides: NotRequired[int]  # rigid and barycentric
    weights: NotRequired[_WeightsName]  # rigid and barycentric
    verified: NotRequired[bool]  # rigid and barycentric
    refined_frames: int
    factorizations: int
    invalid_frames: NotRequired[list[int]]  # linear
    rigid: NotRequired[_RigidStats]  # rigid
    correspondence: NotRequired[_MatchingStats]  # correspond="auto"

class _Correspondence(TypedDict):
    source: _Int64Array
    target: _Int64Array
    source_edge: _Int64Array
    source_fraction: _Float64Array
    target_edge: _Int64Array
    target_fraction: _Float64Array

class _MorphResult(TypedDict):
    times: _Float64Array
    frames: _Float64Array  # (N, #V, 2)
    triangulation: _Triangulation | None  # None for method="linear"
    stats: _MorphStats
    edges: NotRequired[_Int64Array]  # correspond="auto"
    correspondence: NotRequired[_Correspondence]  # correspond="auto"

class _CorrespondResult(TypedDict):
    source_xy: _Float64Array
    target_xy: _Float64Array
    edges: _Int64Array
    correspondence: _Correspondence
    stats: _CorrespondStats

class _PolygonTriangulationStats(TypedDict):
    steiner_vertices: int
    spiderweb_steiner_vertices: int
    min_angle_before_smoothing: float
    min_angle_after_smoothing: float

class _PolygonTriangulation(TypedDict):
    triangles: _Int64Array
    corners: _Int64Array
    source_steiner: _Float64Array
    target_steiner: _Float64Array
    stats: _PolygonTriangulationStats

class _CyclicSequence(TypedDict):
    vertices: _Int64Array
    exterior: bool
    angle_sum: float

class _Figure(TypedDict):
    name: str
    vertices: _Float64Array
    edges: _Int64Array

class _PinProblem(TypedDict):
    pin: int
    defect: _PinDefect
    source_degree: int
    target_degree: int
    reason: str

class _DrawingChange(TypedDict):
    kind: _DrawingChangeKind
    stroke: int | None
    point: int | None
    other_stroke: int | None
    at: tuple[float, float]
    distance: float

class _SolverStats(TypedDict):
    factorizations: int
    factorize_ms: float
    solve_ms: float

class _Places(TypedDict):
    vertex: _Int64Array
    edge: _Int64Array
    fraction: _Float64Array

class _SegmentMilliseconds(TypedDict):
    triangulate: float
    morph: float

class _Segment(TypedDict):
    from_key: int
    to_key: int
    first_frame: int
    last_frame: int
    triangulation: _Triangulation
    steiner_vertices: int
    similarity_factored: bool
    guide_frames: _GuideFrames
    refined_frames: int
    milliseconds: _SegmentMilliseconds

class _KeyPoseResult(TypedDict):
    frames: _Float64Array  # (N, #V, 2)
    times: _Float64Array
    edges: _Int64Array
    keys_at: list[int]
    places: list[_Places]
    correspondence: NotRequired[list[_MatchingStats]]  # correspond="auto"
    segments: list[_Segment]

# ---------------------------------------------------------------------------
# Module attributes: the engine's rules (bind_options.cpp).

class _Limits(TypedDict):
    min_frames: int
    max_frames: int
    default_frames: int
    min_enclosure_sides: int
    max_enclosure_sides: int
    default_enclosure_sides: int
    min_smoothing_rounds: int
    max_smoothing_rounds: int
    default_smoothing_rounds: int
    max_turns: int
    max_coordinate_magnitude: float

# option_rules entries by the kind of their value (OptionValueKind).
class _MethodsRule(TypedDict):
    methods: tuple[_MethodName, ...]

class _CountRule(_MethodsRule):
    min: int
    max: int
    default: int

class _FlagRule(_MethodsRule):
    default: bool

class _MethodChoiceRule(_MethodsRule):
    choices: tuple[_MethodName, ...]
    default: _MethodName

class _SteinerChoiceRule(_MethodsRule):
    choices: tuple[_SteinerName, ...]
    default: _SteinerName

class _WeightsChoiceRule(_MethodsRule):
    choices: tuple[_WeightsName, ...]
    default: _WeightsName

class _RotationChoiceRule(_MethodsRule):
    choices: tuple[_RotationName, ...]
    default: _RotationName

class _EasingChoiceRule(_MethodsRule):
    choices: tuple[_EasingName, ...]
    default: _EasingName

class _FrameCheckChoiceRule(_MethodsRule):
    choices: tuple[_FrameCheckName, ...]
    default: _FrameCheckName

class _CorrespondChoiceRule(_MethodsRule):
    choices: tuple[_CorrespondName, ...]
    default: _CorrespondName

class _OptionRules(TypedDict):
    frames: _CountRule
    method: _MethodChoiceRule
    verify: _FlagRule
    frame_check: _FrameCheckChoiceRule
    weights: _WeightsChoiceRule
    steiner: _SteinerChoiceRule
    enclosure_sides: _CountRule
    rotation: _RotationChoiceRule
    turns: _CountRule
    easing: _EasingChoiceRule
    delay: _MethodsRule  # no default; given with overlap=
    correspond: _CorrespondChoiceRule
    pins: _MethodsRule  # no default; only with correspond="auto"

limits: _Limits
# keyword of morph() -> the CLI's flag ("" where the CLI has none).
OPTION_NAMES: dict[str, str]
option_rules: _OptionRules
METHOD_NAMES: tuple[_MethodName, ...]
ROTATION_NAMES: tuple[_RotationName, ...]
EASING_NAMES: tuple[_EasingName, ...]

# ---------------------------------------------------------------------------
# Exceptions (errors.cpp). The attributes are set on the instances stickmorph
# raises and are None on the class, hence "| None".

class StickMorphError(ValueError): ...
class JsonError(StickMorphError): ...

class InvalidFigureError(StickMorphError):
    defect: _FigureDefect | None
    vertices: list[int] | None
    edges: list[int] | None
    role: str | None
    detail: str | None

class InvalidDrawingError(StickMorphError):
    defect: _DrawingDefect | None
    stroke: int | None
    point: int | None
    other_stroke: int | None

class InvalidArgumentError(StickMorphError): ...

class IncompatibleFiguresError(StickMorphError):
    kind: _Incompatibility | None
    vertices: list[int] | None
    reason: str | None

class VerificationError(StickMorphError): ...
class NumericRangeError(StickMorphError): ...

# Not StickMorphErrors: a bug, and a cancellation the caller asked for.
class InternalError(RuntimeError): ...
class CancelledError(Exception): ...

# errno, strerror and filename come from OSError.
class FileError(OSError, StickMorphError):
    def __str__(self) -> str: ...

class FigureFileNotFoundError(FileError, FileNotFoundError): ...
class FigureFileIsADirectoryError(FileError, IsADirectoryError): ...
class FigureFilePermissionError(FileError, PermissionError): ...
class FigureFileNotADirectoryError(FileError, NotADirectoryError): ...

# ---------------------------------------------------------------------------
# Classes. CompatibilityReport and CleanedDrawing have no constructor in
# Python (only stickmorph makes them), hence no __init__ here.

class CompatibilityReport:
    @property
    def compatible(self) -> bool: ...
    @property
    def kind(self) -> _Incompatibility: ...
    @property
    def reason(self) -> str: ...
    @property
    def vertices(self) -> list[int]: ...
    def __bool__(self) -> bool: ...
    def __repr__(self) -> str: ...

class CleanedDrawing:
    @property
    def vertices(self) -> _Float64Array: ...
    @property
    def edges(self) -> _Int64Array: ...
    @property
    def stroke_vertices(self) -> list[_Int64Array]: ...
    @property
    def point_vertex(self) -> list[_Int64Array]: ...
    @property
    def cyclic(self) -> list[bool]: ...
    @property
    def tolerance(self) -> float: ...
    @property
    def junctions_made(self) -> int: ...
    @property
    def ends_snapped(self) -> int: ...
    @property
    def points_merged(self) -> int: ...
    @property
    def changes(self) -> list[_DrawingChange]: ...
    def summary(self) -> str: ...
    def __repr__(self) -> str: ...

class Progress:
    def __init__(self) -> None: ...
    def cancel(self) -> None: ...
    @property
    def cancelled(self) -> bool: ...
    @property
    def stage(self) -> str | None: ...
    @property
    def done(self) -> int: ...
    @property
    def total(self) -> int: ...
    @property
    def fraction(self) -> float | None: ...
    @property
    def stages(self) -> list[tuple[str, float]]: ...
    def summary(self) -> str: ...
    def begin_stage(self, name: str, total: int = ...) -> None: ...
    def set_progress(self, done: int, total: int) -> None: ...
    def finish(self) -> None: ...
    def __enter__(self) -> Self: ...
    # Always False: a `with progress:` block never swallows an exception.
    def __exit__(self, *args: object) -> Literal[False]: ...

class MorphSolver:
    # The dict triangulate_figures returns, or one built by hand (a dict, not
    # any Mapping: the binding checks isinstance(dict)).
    def __init__(
        self,
        triangulation: _Triangulation | dict[str, Any],
        edges: ArrayLike,
        weights: _WeightsName = ...,
    ) -> None: ...
    def solve(self, t: _Real, *, all_nodes: _Flag = ..., verify: _Flag = ...) -> _Float64Array: ...
    @property
    def weights(self) -> _WeightsName: ...
    @property
    def stats(self) -> _SolverStats: ...

class RigidMorphSolver:
    def __init__(
        self,
        source_xy: ArrayLike,
        target_xy: ArrayLike,
        edges: ArrayLike,
        steiner: _SteinerName | None = ...,
        weights: _WeightsName | None = ...,
        enclosure_sides: _Count | None = ...,
        rotation: _RotationName | None = ...,
        turns: _Count | None = ...,
        easing: _EasingName | None = ...,
        target_edges: ArrayLike | None = ...,
        delay: ArrayLike | None = ...,
        overlap: _Real | None = ...,
    ) -> None: ...
    def solve(self, t: _Real, *, all_nodes: _Flag = ..., verify: _Flag = ...) -> _Float64Array: ...
    @property
    def triangulation(self) -> _Triangulation: ...
    @property
    def similarity(self) -> _SolverSimilarity: ...

class KeyPoseMorphSolver:
    # keys_xy: K arrays #V by 2 (a sequence, or one (K, #V, 2) array); edges:
    # one #E by 2 list for every key or, with correspond="auto", one per key;
    # rotation, turns, easing: one for every segment or one per segment;
    # pins: one #P by 2 list or one per pair of keys.
    def __init__(
        self,
        keys_xy: Sequence[ArrayLike] | NDArray[Any],
        edges: ArrayLike,
        frames: _Count | None = ...,
        keys_at: Sequence[_Count] | None = ...,
        loop: _Flag = ...,
        hold: Sequence[_Flag] | None = ...,
        rotation: _RotationName | Sequence[_RotationName] | None = ...,
        turns: _Count | Sequence[_Count] | None = ...,
        steiner: _SteinerName | None = ...,
        weights: _WeightsName | None = ...,
        enclosure_sides: _Count | None = ...,
        verify: _Flag | None = ...,
        frame_check: _FrameCheckName | None = ...,
        correspond: _CorrespondName | None = ...,
        pins: ArrayLike | None = ...,
        easing: _EasingName | Sequence[_EasingName] | None = ...,
        progress: Progress | None = ...,
        delay: ArrayLike | None = ...,
        overlap: _Real | None = ...,
    ) -> None: ...
    def solve(self, t: _Real) -> _Float64Array: ...
    def frame(self, f: _Count) -> _Float64Array: ...
    @property
    def frame_count(self) -> int: ...
    @property
    def keys_at(self) -> list[int]: ...
    @property
    def edges(self) -> _Int64Array: ...
    @property
    def places(self) -> list[_Places]: ...
    @property
    def segments(self) -> list[_Segment]: ...

# ---------------------------------------------------------------------------
# Functions.

def validate(vertices: ArrayLike, edges: ArrayLike) -> None: ...
def load_figure(path: _Path) -> _Figure: ...
def decompose(vertices: ArrayLike, edges: ArrayLike) -> list[_CyclicSequence]: ...
def rotation_system(vertices: ArrayLike, edges: ArrayLike) -> list[_Int64Array]: ...
def check_compatibility(
    source_vertices: ArrayLike,
    target_vertices: ArrayLike,
    edges: ArrayLike,
    target_edges: ArrayLike | None = ...,
) -> CompatibilityReport: ...
def correspond(
    source_xy: ArrayLike,
    target_xy: ArrayLike,
    edges: ArrayLike,
    *,
    target_edges: ArrayLike | None = ...,
    pins: ArrayLike | None = ...,
) -> _CorrespondResult: ...
def figure_parts(vertex_count: _Count, edges: ArrayLike) -> list[list[int]]: ...
def edge_set_difference(source_edges: ArrayLike, target_edges: ArrayLike) -> tuple[_Int64Array, _Int64Array]: ...
def check_pins(
    source_vertex_count: _Count,
    source_edges: ArrayLike,
    target_vertex_count: _Count,
    target_edges: ArrayLike,
    pins: ArrayLike,
) -> _PinProblem | None: ...
def clean_drawing(
    strokes: Sequence[ArrayLike],
    cyclic: Sequence[_Flag] | None = ...,
    tolerance: float | None = ...,
) -> CleanedDrawing: ...
def clean_figure(vertices: ArrayLike, edges: ArrayLike, tolerance: float | None = ...) -> CleanedDrawing: ...
def compatible_triangulation(
    source: ArrayLike,
    target: ArrayLike,
    steiner: _SteinerName = ...,
    corners: ArrayLike | None = ...,
    smoothing_rounds: _Count = ...,
) -> _PolygonTriangulation: ...
def triangulate_figures(
    source: ArrayLike,
    target: ArrayLike,
    edges: ArrayLike,
    target_edges: ArrayLike | None = ...,
    steiner: _SteinerName = ...,
    enclosure_sides: _Count = ...,
) -> _Triangulation: ...
def morph(
    source_xy: ArrayLike,
    target_xy: ArrayLike,
    edges: ArrayLike,
    frames: _Count = ...,
    steiner: _SteinerName | None = ...,
    weights: _WeightsName | None = ...,
    enclosure_sides: _Count | None = ...,
    method: _MethodName | None = ...,
    verify: _Flag | None = ...,
    target_edges: ArrayLike | None = ...,
    rotation: _RotationName | None = ...,
    turns: _Count | None = ...,
    easing: _EasingName | None = ...,
    correspond: _CorrespondName | None = ...,
    pins: ArrayLike | None = ...,
    frame_check: _FrameCheckName | None = ...,
    progress: Progress | None = ...,
    delay: ArrayLike | None = ...,
    overlap: _Real | None = ...,
) -> _MorphResult: ...
def morph_key_poses(
    keys_xy: Sequence[ArrayLike] | NDArray[Any],
    edges: ArrayLike,
    frames: _Count | None = ...,
    keys_at: Sequence[_Count] | None = ...,
    loop: _Flag = ...,
    hold: Sequence[_Flag] | None = ...,
    rotation: _RotationName | Sequence[_RotationName] | None = ...,
    turns: _Count | Sequence[_Count] | None = ...,
    steiner: _SteinerName | None = ...,
    weights: _WeightsName | None = ...,
    enclosure_sides: _Count | None = ...,
    verify: _Flag | None = ...,
    frame_check: _FrameCheckName | None = ...,
    correspond: _CorrespondName | None = ...,
    pins: ArrayLike | None = ...,
    easing: _EasingName | Sequence[_EasingName] | None = ...,
    progress: Progress | None = ...,
    delay: ArrayLike | None = ...,
    overlap: _Real | None = ...,
) -> _KeyPoseResult: ...
