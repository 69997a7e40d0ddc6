"""MuJoCo itself as the reference for the MJCF corpus: kinematics, colours, meshes, contacts.

Everything here reads the case's MJCF with the ``mujoco`` package (MuJoCo's own compiler:
default classes, ``childclass``, ``<compiler>`` settings, includes, keyframes), never with
the service's reader, so a test that compares the service's answers with these is a
comparison with the format's own toolchain.

Conventions: poses are 4×4 homogeneous matrices of a body or site frame in MuJoCo's world
frame (metres); joint values are radians (hinge) or metres (slide), keyed by joint name.

Collision reference: MuJoCo's narrow phase (``mj_geomDistance``: signed distance, negative
when the geoms overlap) between the *collision geoms* (``contype`` or ``conaffinity``
non-zero) of two bodies. MuJoCo collides a mesh as its convex hull, so the service is asked
for its ``convex`` geometry. The pair filter is the service's documented rule
(``app/kinematics/collision_pairs.py``), applied here to the MJCF tree without the service's
code: each body with collision geoms is a link (the world body's geoms, such as a scene's
floor, are the environment, not the robot's); links moved by the same joint (a jointless
body is welded to its parent) are never checked; links whose moving joints are one joint
apart in the tree, bridging joints whose bodies carry no collision geom, are adjacent and
never checked. MuJoCo's own ``<contact><exclude>`` and parent/child filters are *not* used
(the service documents no such rule).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import mujoco
import numpy as np

from tests.corpus.pair_rules import bridged_adjacent

#: Joint types a kinematic arm may have (hinge: radians, slide: metres).
_MOVING = {int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE)}
#: MuJoCo's default geom rgba; a geom rgba other than this overrides its material's.
_DEFAULT_RGBA = (0.5, 0.5, 0.5, 1.0)


@dataclass
class Coupling:
    """A joint equality ``q1 - ref1 = c0 + c1 (q2 - ref2)`` (MuJoCo's polycoef, linear)."""

    joint1: str
    joint2: str
    c0: float
    c1: float
    ref1: float
    ref2: float


@dataclass
class Reference:
    """A compiled MJCF model and the facts the corpus tests compare with.

    Attributes
    ----------
    model
        MuJoCo's compiled model of the uploaded description file.
    joints
        Hinge and slide joints: name → (lower, upper); unlimited joints get (-π, π)
        for sampling (hinge) — their limits are not compared.
    couplings
        Linear joint equalities (a follower joint set by a leader).
    """

    model: mujoco.MjModel
    data: mujoco.MjData = field(init=False)
    joints: dict[str, tuple[float, float]] = field(init=False)
    couplings: list[Coupling] = field(init=False)

    def __post_init__(self) -> None:
        m = self.model
        self.data = mujoco.MjData(m)
        self.joints = {}
        for j in range(m.njnt):
            if int(m.jnt_type[j]) not in _MOVING:
                continue
            lo, hi = m.jnt_range[j] if m.jnt_limited[j] else (-np.pi, np.pi)
            self.joints[m.joint(j).name] = (float(lo), float(hi))
        self.couplings = []
        for e in range(m.neq):
            if int(m.eq_type[e]) != int(mujoco.mjtEq.mjEQ_JOINT) or m.eq_obj2id[e] < 0:
                continue
            j1, j2 = int(m.eq_obj1id[e]), int(m.eq_obj2id[e])
            poly = m.eq_data[e][:5]
            assert np.all(poly[2:] == 0), "only linear joint equalities are references"
            self.couplings.append(
                Coupling(
                    m.joint(j1).name,
                    m.joint(j2).name,
                    float(poly[0]),
                    float(poly[1]),
                    float(m.qpos0[m.jnt_qposadr[j1]]),
                    float(m.qpos0[m.jnt_qposadr[j2]]),
                )
            )

    # -- configurations -------------------------------------------------------------------

    def complete(self, values: dict[str, float]) -> dict[str, float]:
        """``values`` with every coupled joint set from its partner by the MJCF equality."""
        out = dict(values)
        for c in self.couplings:
            if c.joint2 in out and c.joint1 not in out:
                out[c.joint1] = c.ref1 + c.c0 + c.c1 * (out[c.joint2] - c.ref2)
            elif c.joint1 in out and c.joint2 not in out:
                out[c.joint2] = c.ref2 + (out[c.joint1] - c.ref1 - c.c0) / c.c1
        return out

    def qpos(self, values: dict[str, float]) -> np.ndarray:
        """MuJoCo's qpos with ``values`` (joint name → value) set, the rest at qpos0."""
        m = self.model
        q = m.qpos0.copy()
        for name, v in self.complete(values).items():
            q[m.jnt_qposadr[m.joint(name).id]] = v
        return q

    def _forward(self, values: dict[str, float]) -> mujoco.MjData:
        self.data.qpos[:] = self.qpos(values)
        mujoco.mj_kinematics(self.model, self.data)
        return self.data

    # -- kinematics -----------------------------------------------------------------------

    def poses(self, values: dict[str, float]) -> dict[str, np.ndarray]:
        """World pose (4×4) of every named body (but the world body) and every named site."""
        m, d = self.model, self._forward(values)
        out: dict[str, np.ndarray] = {}
        for b in range(1, m.nbody):
            out[m.body(b).name] = _homogeneous(d.xpos[b], d.xmat[b])
        for s in range(m.nsite):
            name = m.site(s).name
            if name:
                out[name] = _homogeneous(d.site_xpos[s], d.site_xmat[s])
        return out

    # -- geometry -------------------------------------------------------------------------

    def visual_colours(self) -> dict[str, list[np.ndarray]]:
        """Body name → rgba of each of its visual-only geoms (contype = conaffinity = 0),
        as MuJoCo colours it: the geom's ``rgba`` when it differs from MuJoCo's default
        (0.5 0.5 0.5 1: "it takes precedence over the material"), else its material's."""
        m = self.model
        out: dict[str, list[np.ndarray]] = {}
        for g in range(m.ngeom):
            if m.geom_contype[g] or m.geom_conaffinity[g] or not m.geom_bodyid[g]:
                continue
            body = m.body(int(m.geom_bodyid[g])).name
            mat = int(m.geom_matid[g])
            own = np.array(m.geom_rgba[g], dtype=float)
            default = np.allclose(own, _DEFAULT_RGBA, rtol=0, atol=1e-7)
            rgba = m.mat_rgba[mat] if mat >= 0 and default else own
            out.setdefault(body, []).append(np.array(rgba, dtype=float))
        return out

    def collision_geoms(self) -> dict[str, list[int]]:
        """Body name → its collision geoms (``contype`` or ``conaffinity`` non-zero); the
        world body's geoms (a scene's floor) are the environment, not a link of the robot."""
        m = self.model
        out: dict[str, list[int]] = {}
        for g in range(m.ngeom):
            if m.geom_bodyid[g] and (m.geom_contype[g] or m.geom_conaffinity[g]):
                out.setdefault(m.body(int(m.geom_bodyid[g])).name, []).append(g)
        return out

    def checked_pairs(self) -> set[frozenset[str]]:
        """Link pairs the service's documented rules check (see the module docstring)."""
        m = self.model
        geoms = self.collision_geoms()

        def mover(b: int) -> int:  # the body whose joint moves b (0: the world)
            while b and not m.body_jntnum[b]:
                b = int(m.body_parentid[b])
            return b

        def joint_parent(b: int) -> int:
            return mover(int(m.body_parentid[b])) if b else -1

        movers = {name: mover(m.body(name).id) for name in geoms}
        with_geometry = set(movers.values())
        nodes = {0} | {b for b in range(1, m.nbody) if m.body_jntnum[b]}
        adjacent = bridged_adjacent(
            {n: joint_parent(n) if n else None for n in nodes}, with_geometry
        )
        names = sorted(geoms)
        pairs: set[frozenset[str]] = set()
        for i, a in enumerate(names):
            for b in names[i + 1 :]:
                ja, jb = movers[a], movers[b]
                if ja != jb and frozenset((ja, jb)) not in adjacent:
                    pairs.add(frozenset((a, b)))
        return pairs

    def pair_distances(
        self, values: dict[str, float], pairs: set[frozenset[str]], distmax: float = 0.05
    ) -> dict[frozenset[str], float]:
        """Signed distance (m; < 0: overlap) of each link pair, by MuJoCo's narrow phase
        (``mj_geomDistance`` over the two links' collision geoms; capped at ``distmax``)."""
        m, d = self.model, self._forward(values)
        geoms = self.collision_geoms()
        out: dict[frozenset[str], float] = {}
        for pair in pairs:
            a, b = sorted(pair)
            best = distmax
            for ga in geoms[a]:
                for gb in geoms[b]:
                    best = min(best, mujoco.mj_geomDistance(m, d, ga, gb, distmax, None))
            out[pair] = float(best)
        return out


def _homogeneous(pos: np.ndarray, xmat: np.ndarray) -> np.ndarray:
    T = np.eye(4)
    T[:3, :3] = np.asarray(xmat, dtype=float).reshape(3, 3)
    T[:3, 3] = pos
    return T


def load(description: Path) -> Reference:
    """MuJoCo's compiled model of an MJCF file (its includes and meshes resolved by MuJoCo)."""
    return Reference(mujoco.MjModel.from_xml_path(str(description)))


def mesh_files(description: Path, package_root: Path) -> dict[str, tuple[float, float, float]]:
    """The mesh files the MJCF names (paths relative to ``package_root``) → their scale,
    as MuJoCo's compiler resolves them (``meshdir``, default classes)."""
    spec = mujoco.MjSpec.from_file(str(description))
    meshdir = spec.meshdir or ""
    out: dict[str, tuple[float, float, float]] = {}
    for mesh in spec.meshes:
        if not mesh.file:
            continue
        path = (description.parent / meshdir / mesh.file).resolve()
        out[path.relative_to(package_root.resolve()).as_posix()] = tuple(
            float(s) for s in mesh.scale
        )
    return out
