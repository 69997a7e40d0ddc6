"""Generated link geometry: capsules along the DH segments of each row.

URDF has no capsule primitive, so a capsule is a ``<cylinder>`` along the segment plus a
``<sphere>`` at each end (spheres shared by segments of one link are emitted once).

Which segments, and on which link (all coordinates in metres, in that link's frame):

``standard`` (A_i = Rz(θ_i)·Tz(d_i)·Tx(a_i)·Rx(α_i); ``link_i`` = dh_{i-1} after the motion)
    on ``link_i``: the d segment (0,0,0)→(0,0,d) along z_{i-1} and the a segment
    (0,0,d)→(a·cos θ, a·sin θ, d) along x_i, with d and θ the row's constant offsets.
``modified`` (A_i = Rx(α_{i-1})·Tx(a_{i-1})·Rz(θ_i)·Tz(d_i); ``link_i`` coincides with dh_i)
    on ``link_{i-1}`` (``dh_0`` for row 1): the a segment (0,0,0)→(a_{i-1},0,0) along
    x_{i-1}; on ``link_i``: the d segment (0,0,−d)→(0,0,0) along z_i.

For a prismatic joint the d segment is its constant offset ``d`` (it rides with the joint),
and the sliding rod ("ram") is drawn as one more segment of length ``upper − lower`` on
``link_i``, ending where the joint variable q ends and reaching back along z: in the link's
frame (0,0,−s)→(0,0,0) for ``standard`` and (0,0,−d−s)→(0,0,−d) for ``modified``, s the
stroke. So in any configuration the ram spans q − s … q along the sliding axis, measured
from where the motion starts, like a boom sliding through its bearing.

A non-zero tool translation adds a segment from the origin of dh_n to the tool point, on
``link_n``. Segments shorter than :data:`MIN_SEGMENT_LENGTH` are skipped.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np

from dh2urdf.math import dh_standard
from dh2urdf.names import body_link, dh_link
from dh2urdf.table import DHTable, Transform

__all__ = ["MIN_SEGMENT_LENGTH", "Segment", "segments", "capsule_axis_origin"]

#: Segments shorter than this (m) get no geometry.
MIN_SEGMENT_LENGTH = 1e-12

Point = tuple[float, float, float]


@dataclass(frozen=True, slots=True)
class Segment:
    """A straight piece of a link, expressed in the frame of the link it is attached to.

    Attributes
    ----------
    link : str
        URDF link carrying the geometry.
    start, end : tuple of float
        End points (m) in that link's frame.
    kind : {"a", "d", "ram", "tool"}
        Which segment it is (``ram``: the sliding rod of a prismatic joint).
    row : int
        1-based table row the segment comes from (n for the tool segment).
    """

    link: str
    start: Point
    end: Point
    kind: Literal["a", "d", "ram", "tool"]
    row: int

    @property
    def length(self) -> float:
        """Euclidean length (m)."""
        return math.dist(self.start, self.end)


def _point(v: np.ndarray | tuple[float, ...]) -> Point:
    return (float(v[0]) + 0.0, float(v[1]) + 0.0, float(v[2]) + 0.0)


def segments(table: DHTable) -> list[Segment]:
    """All non-degenerate geometry segments of a table, base to tip (see module docs)."""
    out: list[Segment] = []
    n = table.dof
    tool_xyz = np.array(table.tool.xyz)
    for i, joint in enumerate(table.joints, start=1):
        if joint.is_prismatic and joint.lower is not None and joint.upper is not None:
            stroke = joint.upper - joint.lower
            back = 0.0 if table.convention == "standard" else -joint.d
            out.append(Segment(body_link(i), (0.0, 0.0, back - stroke), (0.0, 0.0, back), "ram", i))
        if table.convention == "standard":
            ct, st = math.cos(joint.theta), math.sin(joint.theta)
            knee = (0.0, 0.0, joint.d)
            out.append(Segment(body_link(i), (0.0, 0.0, 0.0), knee, "d", i))
            out.append(
                Segment(body_link(i), knee, _point((joint.a * ct, joint.a * st, joint.d)), "a", i)
            )
        else:
            parent = body_link(i - 1) if i > 1 else dh_link(0)
            out.append(Segment(parent, (0.0, 0.0, 0.0), (joint.a, 0.0, 0.0), "a", i))
            out.append(Segment(body_link(i), (0.0, 0.0, -joint.d), (0.0, 0.0, 0.0), "d", i))
    if np.any(tool_xyz != 0.0):
        last = table.joints[-1]
        if table.convention == "standard":
            # dh_n seen from link_n: the row's constant part F_n (motion already removed).
            f = dh_standard(last.a, last.alpha, last.d, last.theta)
            start = f[:3, 3]
            end = start + f[:3, :3] @ tool_xyz
        else:
            start = np.zeros(3)
            end = tool_xyz
        out.append(Segment(body_link(n), _point(start), _point(end), "tool", n))
    return [s for s in out if s.length > MIN_SEGMENT_LENGTH]


def capsule_axis_origin(segment: Segment) -> Transform:
    """Origin of the segment's cylinder: centred on the segment, local z along it.

    The rotation is ``Rz(yaw) · Ry(pitch)`` with the spherical angles of the segment
    direction (the direction is flipped to z ≥ 0, a cylinder being symmetric), written
    exactly as ``rpy = (0, pitch, yaw)``.
    """
    p0 = np.array(segment.start)
    p1 = np.array(segment.end)
    u = (p1 - p0) / segment.length
    if u[2] < 0:
        u = -u
    yaw = math.atan2(u[1], u[0]) if math.hypot(u[0], u[1]) > 0.0 else 0.0
    pitch = math.atan2(math.hypot(u[0], u[1]), u[2])
    if pitch == 0.0:
        yaw = 0.0
    mid = _point((p0 + p1) / 2.0)
    return Transform(xyz=mid, rpy=(0.0, pitch + 0.0, yaw + 0.0))
