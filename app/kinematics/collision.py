"""Collision checking: self-collision and collision with obstacles, through Pinocchio and coal.

Collision model
---------------
The robot's collision geometry is the URDF's ``<collision>`` elements, loaded as
``pin.buildGeomFromUrdfString(model, urdf, pin.COLLISION, package_dirs)`` loads them, each
mesh after its header check and on its own (:func:`app.kinematics.meshes.collision_geometry`),
into a ``pin.GeometryModel``: meshes become coal ``BVHModelOBBRSS`` objects, URDF primitives coal
``Box``/``Sphere``/``Cylinder`` shapes (the capsules of DH robots are a cylinder plus a
sphere at each end). Each geometry is attached to a *link* (the URDF link whose
``<collision>`` it is, a Pinocchio frame) and moves with that link's Pinocchio joint.

Two geometry modes:

``mesh`` (default)
    The meshes as given: exact, and the slowest. Distances between two meshes are unsigned:
    coal reports 0 for penetrating meshes.
``convex``
    Each mesh is replaced by its convex hull (coal ``BVHModel.buildConvexHull``, qhull),
    checked with GJK/EPA: several times faster, conservative (a hull contains its mesh, so
    it can report collisions the mesh does not have; its distances are never larger than
    the mesh's, up to GJK's 1e-6 m tolerance), and distances are signed (negative =
    penetration depth). Primitives are unchanged.

Checked pairs
-------------
The self-collision pairs and their rules (same-joint links, adjacent links, the SRDF) are
in :mod:`app.kinematics.collision_pairs`; each pair is reported once, with the smallest
distance over its geometry pairs. Obstacles are checked against every link that moves with
the configuration. Links fixed to the world (the base) are not checked against obstacles:
both are static, so their contact does not depend on the configuration (a table the base
stands on would otherwise make every configuration "in collision").

Margins and distances
---------------------
A pair is *in collision* when its distance is below ``margin`` (m; 0 = touching or
penetrating; coal's ``security_margin``). With ``distances`` every checked pair's distance
and witness points (the closest points, root frame) are computed; otherwise only the pairs
in collision are reported (with their distance).

Threads
-------
The Pinocchio/coal models are immutable once built and cached per robot
(``RobotModel.lazy``); the scratch space (``pin.Data``, ``pin.GeometryData``) is per thread.
GJK warm starts are off, so an answer never depends on what the thread checked before.
"""

from __future__ import annotations

import threading
import warnings
from collections import OrderedDict
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import coal
import numpy as np
import pinocchio as pin

from app.kinematics.collision_pairs import LinkPair, checked_link_pairs
from app.kinematics.errors import Cancelled, InvalidInputError
from app.kinematics.lazy import LazyKey
from app.kinematics.meshes import collision_geometry
from app.kinematics.models import RobotModel
from app.kinematics.obstacles import Obstacle

GEOMETRY_MODES = ("mesh", "convex")
#: The kinds of a colliding or nearest pair: link–link, or link–obstacle.
PAIR_KINDS = ("self", "environment")
#: Combined robot + obstacle models kept per robot and geometry mode (least recently used
#: dropped first).
MAX_CACHED_SCENES = 32


# ------------------------------------------------------------------------------- results
@dataclass(slots=True)
class PairReport:
    """One checked pair.

    ``a`` is a link; ``b`` a link (``kind == "self"``) or an obstacle name
    (``kind == "environment"``). ``distance`` is in metres (signed where coal gives a
    penetration depth, see module docs); ``point_a``/``point_b`` are the witness points on
    ``a`` and ``b`` in the root frame, present when distances were asked.
    """

    a: str
    b: str
    kind: str
    in_collision: bool
    distance: float
    point_a: np.ndarray | None = None
    point_b: np.ndarray | None = None


@dataclass(slots=True)
class CollisionReport:
    """Verdict for one configuration."""

    in_collision: bool
    self_collision: bool
    environment_collision: bool
    min_distance: float | None
    pairs: list[PairReport] = field(default_factory=list)
    checked_pairs: int = 0


# ------------------------------------------------------------------------------- models
class _Scratch:
    """Per-thread scratch for one compiled model: Data, GeometryData, current margin."""

    __slots__ = ("data", "geom_data", "margin")

    def __init__(self, model: pin.Model, gm: pin.GeometryModel) -> None:
        self.data = model.createData()
        self.geom_data = pin.GeometryData(gm)
        self.margin = 0.0
        # Deterministic answers: no GJK warm start from the previous query, so a result
        # never depends on what this thread checked before.
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", DeprecationWarning)
            for req in (*self.geom_data.collisionRequests, *self.geom_data.distanceRequests):
                req.enable_cached_gjk_guess = False


class _Compiled:
    """A GeometryModel (robot geometry + obstacles) with its pairs, ready to check.

    Geometry pair ``k`` belongs to reported pair ``pair_names[k]`` (``swap[k]`` when the
    geometry order is reversed with respect to ``(a, b)``); pairs ``k < n_self`` are
    self-collision pairs, the rest environment pairs.
    """

    def __init__(
        self,
        robot: RobotModel,
        base: pin.GeometryModel,
        geom_links: list[str],
        link_pairs: Sequence[LinkPair],
        obstacles: Sequence[Obstacle],
    ) -> None:
        self.robot = robot
        gm = base.copy()
        gm.removeAllCollisionPairs()
        names: list[LinkPair] = []
        swap: list[bool] = []
        by_link: dict[str, list[int]] = {}
        for g, link in enumerate(geom_links):
            by_link.setdefault(link, []).append(g)
        for a, b in link_pairs:
            for ga in by_link[a]:
                for gb in by_link[b]:
                    gm.addCollisionPair(pin.CollisionPair(ga, gb))
                    names.append((a, b))
                    swap.append(ga > gb)  # CollisionPair stores (min, max)
        self.n_self = len(names)
        movable = [g for g, go in enumerate(base.geometryObjects) if go.parentJoint != 0]
        for i, obstacle in enumerate(obstacles):
            go = pin.GeometryObject(
                f"obstacle/{i}", 0, 0, obstacle.placement(), obstacle.geometry()
            )
            gid = gm.addGeometryObject(go)
            for g in movable:
                gm.addCollisionPair(pin.CollisionPair(g, gid))
                names.append((geom_links[g], obstacle.name))
                swap.append(False)
        self.gm = gm
        self.checked_pairs = len(set(names))
        self.pair_names = names
        self.swap = swap
        self.npairs = len(names)
        self._local = threading.local()

    def scratch(self, margin: float) -> _Scratch:
        """This thread's scratch, its collision requests set to ``margin``."""
        s = getattr(self._local, "s", None)
        if s is None:
            s = self._local.s = _Scratch(self.robot.model, self.gm)
        if s.margin != margin:
            for req in s.geom_data.collisionRequests:
                req.security_margin = margin
            s.margin = margin
        return s


class CollisionModel:
    """A robot's collision model in one geometry mode, with a cache of obstacle sets.

    Build it with :func:`collision_model` (cached per robot and mode).

    Attributes
    ----------
    geometry : pin.GeometryModel
        The robot geometry (no pairs).
    geom_links : list of str
        Link of each geometry.
    link_pairs : list of (str, str)
        Checked self-collision link pairs.
    moving_links : list of str
        Links checked against obstacles (those not fixed to the world).
    """

    def __init__(self, robot: RobotModel, mode: str = "mesh") -> None:
        if mode not in GEOMETRY_MODES:
            raise InvalidInputError(
                f"unknown geometry mode {mode!r}; expected one of {', '.join(GEOMETRY_MODES)}",
                "geometry",
            )
        self.robot = robot
        self.mode = mode
        try:
            gm = collision_geometry(
                robot.model, robot.urdf_text, robot.package_dirs, robot.mesh_limits
            )
        except InvalidInputError as exc:
            raise InvalidInputError(
                f"the collision geometry of robot {robot.id!r} cannot be loaded ({exc.message})",
                "robot_id",
            ) from None
        except (ValueError, RuntimeError, OSError, IndexError, KeyError, TypeError):
            raise InvalidInputError(
                f"the collision geometry of robot {robot.id!r} cannot be loaded", "robot_id"
            ) from None
        if mode == "convex":
            for go in gm.geometryObjects:
                if isinstance(go.geometry, coal.BVHModelBase):
                    go.geometry.buildConvexHull(True, "Qt")
                    go.geometry = go.geometry.convex
        self.geometry = gm
        self.geom_links = [robot.model.frames[go.parentFrame].name for go in gm.geometryObjects]
        link_joints = {
            link: int(go.parentJoint)
            for link, go in zip(self.geom_links, gm.geometryObjects, strict=True)
        }
        self.link_pairs = checked_link_pairs(robot, link_joints)
        self.moving_links = [link for link, j in link_joints.items() if j != 0]
        self._base = _Compiled(robot, gm, self.geom_links, self.link_pairs, ())
        self._scenes: OrderedDict[tuple[Obstacle, ...], _Compiled] = OrderedDict()
        self._lock = threading.Lock()

    # ------------------------------------------------------------------ compiled variants
    def compiled(self, obstacles: Sequence[Obstacle] = ()) -> _Compiled:
        """The model with ``obstacles`` added (cached, least recently used dropped)."""
        if not obstacles:
            return self._base
        key = tuple(obstacles)
        with self._lock:
            comp = self._scenes.get(key)
            if comp is not None:
                self._scenes.move_to_end(key)
                return comp
        comp = _Compiled(self.robot, self.geometry, self.geom_links, self.link_pairs, key)
        with self._lock:
            self._scenes[key] = comp
            while len(self._scenes) > MAX_CACHED_SCENES:
                self._scenes.popitem(last=False)
        return comp

    # ------------------------------------------------------------------------- checks
    def collides(
        self, q: np.ndarray, obstacles: Sequence[Obstacle] = (), margin: float = 0.0
    ) -> bool:
        """Whether wire configuration ``q`` is in (self or environment) collision.

        The fastest check: stops at the first pair closer than ``margin``.
        """
        comp = self.compiled(obstacles)
        s = comp.scratch(margin)
        return bool(
            pin.computeCollisions(
                self.robot.model, s.data, comp.gm, s.geom_data, self.robot.to_pin(q), True
            )
        )

    def check(
        self,
        q: np.ndarray,
        obstacles: Sequence[Obstacle] = (),
        *,
        margin: float = 0.0,
        distances: bool = False,
        pair_distances: bool = True,
    ) -> CollisionReport:
        """Check wire configuration ``q`` against itself and ``obstacles``.

        Parameters
        ----------
        q
            Wire configuration (n,), rad / m.
        obstacles
            Obstacles in the root frame.
        margin
            Pairs closer than this (m) count as in collision (≥ 0).
        distances
            Compute every checked pair's distance and witness points; ``min_distance`` is
            then the smallest over all checked pairs.
        pair_distances
            Without ``distances``: also compute the distance of the pairs in collision
            (one coal distance query per such pair). Batches turn it off.

        Returns
        -------
        CollisionReport
            Pairs are sorted by distance (closest first) when distances are known.
        """
        comp = self.compiled(obstacles)
        s = comp.scratch(margin)
        model, gm, gd = self.robot.model, comp.gm, s.geom_data
        qp = self.robot.to_pin(q)
        if distances:
            pin.computeDistances(model, s.data, gm, gd, qp)
            hit = pin.computeCollisions(gm, gd, False)
        else:
            hit = pin.computeCollisions(model, s.data, gm, gd, qp, False)
            if not hit:
                return CollisionReport(False, False, False, None, [], comp.checked_pairs)
        results = gd.collisionResults
        colliding = [k for k in range(comp.npairs) if results[k].isCollision()] if hit else []
        if distances:
            wanted = range(comp.npairs)
        else:
            wanted = colliding
        best: dict[tuple[str, str, str], PairReport] = {}
        hit_set = set(colliding)
        for k in wanted:
            a, b = comp.pair_names[k]
            kind = "self" if k < comp.n_self else "environment"
            dist = np.nan
            pa = pb = None
            if distances:
                dr = gd.distanceResults[k]
                dist = float(dr.min_distance)
                pa, pb = np.array(dr.getNearestPoint1()), np.array(dr.getNearestPoint2())
                if comp.swap[k]:
                    pa, pb = pb, pa
                if not (np.isfinite(pa).all() and np.isfinite(pb).all()):
                    pa = pb = None
            elif pair_distances:
                dist = float(pin.computeDistance(gm, gd, k).min_distance)
            if not np.isfinite(dist):  # degenerate input (e.g. a prismatic joint at 1e300)
                dist = np.nan
            key = (a, b, kind)
            prev = best.get(key)
            coll = k in hit_set
            if prev is None:
                best[key] = PairReport(a, b, kind, coll, dist, pa, pb)
            else:
                prev.in_collision = prev.in_collision or coll
                if dist < prev.distance or np.isnan(prev.distance):
                    prev.distance, prev.point_a, prev.point_b = dist, pa, pb
        pairs = list(best.values())
        known = [p.distance for p in pairs if not np.isnan(p.distance)]
        if known:
            pairs.sort(key=lambda p: p.distance)
        self_hit = any(p.in_collision and p.kind == "self" for p in pairs)
        env_hit = any(p.in_collision and p.kind == "environment" for p in pairs)
        return CollisionReport(
            in_collision=self_hit or env_hit,
            self_collision=self_hit,
            environment_collision=env_hit,
            min_distance=min(known) if known else None,
            pairs=pairs,
            checked_pairs=comp.checked_pairs,
        )

    def check_batch(
        self,
        qs: np.ndarray,
        obstacles: Sequence[Obstacle] = (),
        *,
        margin: float = 0.0,
        distances: bool = False,
        cancel: threading.Event | None = None,
    ) -> list[CollisionReport]:
        """:meth:`check` for each row of ``qs`` (N, n); no per-pair distances unless asked.

        ``cancel``, once set (the caller's client went away), stops the batch before the
        next row with :class:`~app.kinematics.errors.Cancelled`.
        """
        out = []
        for q in qs:
            if cancel is not None and cancel.is_set():
                raise Cancelled()
            out.append(
                self.check(q, obstacles, margin=margin, distances=distances, pair_distances=False)
            )
        return out


def collision_key(mode: str) -> LazyKey[CollisionModel]:
    """The model's lazy-cache key of its collision model in ``mode``."""
    return LazyKey(f"collision.{mode}", CollisionModel)


def collision_model_built(robot: RobotModel, mode: str) -> bool:
    """Whether the collision model in ``mode`` is built already (nothing is built)."""
    return robot.cached(collision_key(mode)) is not None


def collision_model(robot: RobotModel, mode: str = "mesh") -> CollisionModel:
    """The robot's collision model in ``mode`` (built once per robot, then cached)."""
    if mode not in GEOMETRY_MODES:
        raise InvalidInputError(
            f"unknown geometry mode {mode!r}; expected one of {', '.join(GEOMETRY_MODES)}",
            "geometry",
        )
    return robot.lazy(collision_key(mode), lambda r: CollisionModel(r, mode))


def collision_filter(
    robot: RobotModel,
    obstacles: Sequence[Obstacle] = (),
    *,
    margin: float = 0.0,
    mode: str = "mesh",
) -> Callable[[np.ndarray], bool]:
    """An ``accept(q)`` predicate for IK: true when wire configuration ``q`` is collision-free.

    Self-collision and collision with ``obstacles`` (closer than ``margin`` counts) are
    rejected. The model is built (and its obstacle variant compiled) here, not on first call.
    """
    cm = collision_model(robot, mode)
    comp_obstacles = tuple(obstacles)
    cm.compiled(comp_obstacles)

    def accept(q: np.ndarray) -> bool:
        return not cm.collides(np.asarray(q, dtype=float), comp_obstacles, margin)

    return accept


def report_json(report: CollisionReport, *, witness: bool) -> dict[str, Any]:
    """Wire form of a :class:`CollisionReport` (single-configuration response body part)."""
    pairs = []
    for p in report.pairs:
        item: dict[str, Any] = {
            "a": p.a,
            "b": p.b,
            "kind": p.kind,
            "in_collision": p.in_collision,
            "distance": None if np.isnan(p.distance) else p.distance,
        }
        if witness and p.point_a is not None:
            item["point_a"] = p.point_a.tolist()
            item["point_b"] = p.point_b.tolist()
        pairs.append(item)
    return {
        "in_collision": report.in_collision,
        "self_collision": report.self_collision,
        "environment_collision": report.environment_collision,
        "min_distance": report.min_distance,
        "pairs": pairs,
        "checked_pairs": report.checked_pairs,
    }
