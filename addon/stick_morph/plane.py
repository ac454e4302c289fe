"""The common plane of two figures and the way onto it and back (core.py's
docstring has the geometry: heights, u x v = n, why one projection)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .common import StickMorphError

PLANES = ("AUTO", "XY", "XZ", "YZ")


# Orthonormal (u, v) of the axis planes; n = u x v. XZ is seen from the front
# (looking along +Y), YZ from the right (looking along -X), as in Blender's
# front and right views.
_AXIS_PLANES = {
    "XY": ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0)),
    "XZ": ((1.0, 0.0, 0.0), (0.0, 0.0, 1.0)),
    "YZ": ((0.0, 1.0, 0.0), (0.0, 0.0, 1.0)),
}


@dataclass
class Plane:
    origin: np.ndarray  # (3,)
    u: np.ndarray  # (3,)
    v: np.ndarray  # (3,)
    normal: np.ndarray  # (3,)
    name: str  # "AUTO", "XY", ...

    def describe(self) -> str:
        if self.name != "AUTO":
            return f"the {self.name} plane"
        n = self.normal
        return f"the best-fit plane (normal {n[0]:.3f}, {n[1]:.3f}, {n[2]:.3f})"


def _unit(vector) -> np.ndarray:
    vector = np.asarray(vector, dtype=np.float64)
    return vector / np.linalg.norm(vector)


def _canonical_sign(vector: np.ndarray) -> np.ndarray:
    """The vector or its negation, whichever has a positive largest component."""
    k = int(np.argmax(np.abs(vector)))
    return vector if vector[k] >= 0 else -vector


def fit_plane(source_world: np.ndarray, target_world: np.ndarray, plane: str = "AUTO") -> Plane:
    """The common plane of both figures (fit_plane_of for two)."""
    return fit_plane_of([source_world, target_world], plane)


def fit_plane_of(figures, plane: str = "AUTO") -> Plane:
    """The common plane of one or more figures ((V_k, 3) world points each):
    of a pair (fit_plane) or of the K key poses of a sequence.

    AUTO: the normal is the smallest right-singular vector of all point sets,
    each centred on its own centroid, so that figures in parallel planes
    (side by side at different depths) share the right normal. The normal
    points to the same side as the nearest axis plane's (XY: +Z, XZ: -Y, YZ:
    +X), and u is that plane's u axis projected into the fitted plane. If all
    points are collinear, the plane holds the line and is the one closest to
    an axis plane.
    """
    if plane not in PLANES:
        raise StickMorphError(f"unknown plane {plane!r} (choose one of {', '.join(PLANES)})")
    figures = [np.asarray(world, dtype=np.float64).reshape(-1, 3) for world in figures]
    both = np.vstack(figures)
    origin = both.mean(axis=0) if len(both) else np.zeros(3)
    if plane != "AUTO":
        u, v = (np.array(a) for a in _AXIS_PLANES[plane])
        return Plane(origin, u, v, np.cross(u, v), plane)

    centred = np.vstack([world - world.mean(axis=0) for world in figures if len(world)] or [np.zeros((0, 3))])
    # Only the right singular vectors are wanted: reduce the (M, 3) points
    # to a 3 by 3 matrix with the same singular values and right vectors
    # first (R of a QR; zero rows below 3 points). A full SVD of the points
    # builds an M by M U: 2 GB at 16,000 points, out of memory at 10^4 per
    # key of a 4-key sequence.
    if len(centred) > 3:
        centred = np.linalg.qr(centred, mode="r")
    elif len(centred) < 3:
        centred = np.vstack([centred, np.zeros((3 - len(centred), 3))])
    _, singular, vt = np.linalg.svd(centred, full_matrices=False)
    largest = singular[0] if len(singular) else 0.0
    if largest == 0.0:
        # Every figure is a single point: any plane; take XY.
        u, v = (np.array(a) for a in _AXIS_PLANES["XY"])
        return Plane(origin, u, v, np.cross(u, v), "AUTO")
    direction = _canonical_sign(vt[0])
    second = singular[1] if len(singular) > 1 else 0.0
    if second <= 1e-12 * largest:
        # Collinear: the axis most perpendicular to the line, made exactly
        # perpendicular, is the normal.
        axes = np.eye(3)
        k = int(np.argmin(np.abs(axes @ direction)))
        normal = _unit(axes[k] - (axes[k] @ direction) * direction)
    else:
        normal = _unit(vt[2])
    # The in-plane axes follow the nearest axis plane: its normal's side is
    # the viewing side and its u axis, projected into the plane, is u. A
    # figure drawn in an axis plane thus gets exactly that plane's 2D
    # coordinates, and a tilted one the view a user expects.
    nearest = max(_AXIS_PLANES, key=lambda p: abs(np.cross(*_AXIS_PLANES[p]) @ normal))
    axis_u, axis_v = (np.array(a) for a in _AXIS_PLANES[nearest])
    if np.cross(axis_u, axis_v) @ normal < 0:
        normal = -normal
    # |u| >= 1/sqrt(3): the nearest plane's normal axis holds at least 1/3 of
    # normal's squared length, so axis_u, another axis, at most 2/3.
    u = _unit(axis_u - (axis_u @ normal) * normal)
    v = np.cross(normal, u)
    return Plane(origin, u, _unit(v), normal, "AUTO")


def project(points_world: np.ndarray, plane: Plane) -> tuple[np.ndarray, np.ndarray]:
    """(V, 2) in-plane coordinates and (V,) heights of world points."""
    d = np.asarray(points_world, dtype=np.float64).reshape(-1, 3) - plane.origin
    xy = np.stack([d @ plane.u, d @ plane.v], axis=1)
    return xy, d @ plane.normal


def unproject(xy: np.ndarray, heights: np.ndarray, plane: Plane) -> np.ndarray:
    """World points from in-plane coordinates (..., V, 2) and heights (..., V)."""
    xy = np.asarray(xy, dtype=np.float64)
    heights = np.asarray(heights, dtype=np.float64)
    # One output written in place: a bake's frames are (250, 10^4, 3) and
    # more, and the plain broadcast sum made four temporaries of that size
    # (0.7 s of a 4.2 s bake at 10^4 vertices and 250 frames, issue 29).
    out = np.matmul(xy, np.stack([plane.u, plane.v]))
    out += heights[..., None] * plane.normal
    out += plane.origin
    return out


def planarity_deviation(heights: np.ndarray) -> tuple[float, int]:
    """Largest distance of a vertex from the figure's own plane (parallel to the
    common one, through the figure's mean height), and that vertex."""
    heights = np.asarray(heights, dtype=np.float64)
    if len(heights) == 0:
        return 0.0, -1
    deviations = np.abs(heights - heights.mean())
    k = int(np.argmax(deviations))
    return float(deviations[k]), k


def check_planarity(named_heights, size: float, tolerance: float, fitted: Plane, plane: str) -> None:
    """Raises StickMorphError naming the mesh and the vertex farthest from its
    own plane (planarity_deviation) if that is more than tolerance * size.
    named_heights: (object name, heights) of every figure; plane: the
    setting (AUTO, XY, ...) that chose fitted."""
    worst = (0.0, -1, named_heights[0][0] if named_heights else "")
    for name, heights in named_heights:
        deviation, vertex = planarity_deviation(heights)
        if deviation > worst[0]:
            worst = (deviation, vertex, name)
    limit = tolerance * size
    if worst[0] > limit:
        raise StickMorphError(
            f"the meshes are not planar: vertex {worst[1]} of '{worst[2]}' is {worst[0]:.6g} "
            f"away from {fitted.describe()} (largest deviation {worst[0]:.6g}; allowed "
            f"{limit:.3g}, {tolerance:g} of the size {size:.6g})"
            + ("" if plane == "AUTO" else "; try plane AUTO"))
