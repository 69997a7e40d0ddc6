"""Test helpers: an independent DH reference (elementary matrices) and Pinocchio/yourdfpy FK.

Nothing here uses ``dh2urdf.math``: the reference products are written from the
definitions so that the library is checked against an independent implementation.
"""

from __future__ import annotations

import io
import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import pinocchio as pin
import yourdfpy

from dh2urdf.table import DHTable

LENGTH_TO_M = {"m": 1.0, "cm": 100.0, "mm": 1000.0}


def rx(t: float) -> np.ndarray:
    m = np.eye(4)
    m[1:3, 1:3] = [[math.cos(t), -math.sin(t)], [math.sin(t), math.cos(t)]]
    return m


def ry(t: float) -> np.ndarray:
    m = np.eye(4)
    m[0, 0], m[0, 2], m[2, 0], m[2, 2] = math.cos(t), math.sin(t), -math.sin(t), math.cos(t)
    return m


def rz(t: float) -> np.ndarray:
    m = np.eye(4)
    m[0:2, 0:2] = [[math.cos(t), -math.sin(t)], [math.sin(t), math.cos(t)]]
    return m


def tr(x: float = 0.0, y: float = 0.0, z: float = 0.0) -> np.ndarray:
    m = np.eye(4)
    m[:3, 3] = (x, y, z)
    return m


def origin(xyz: Sequence[float], rpy: Sequence[float]) -> np.ndarray:
    """URDF origin: T(xyz) · Rz(yaw) · Ry(pitch) · Rx(roll)."""
    return tr(*xyz) @ rz(rpy[2]) @ ry(rpy[1]) @ rx(rpy[0])


def reference_chain(doc: Mapping[str, Any], q: Sequence[float]) -> list[np.ndarray]:
    """World poses of dh_0..dh_n and the tool from a table *document* (any units).

    ``q`` is in SI (rad for revolute/continuous, m for prismatic), without offsets.
    Built only from elementary rotations/translations (Rz·Tz·Tx·Rx or Rx·Tx·Rz·Tz).
    """
    units = doc.get("units") or {}
    ls = 1.0 / LENGTH_TO_M[units.get("length", "m")]
    angs = math.pi / 180.0 if units.get("angle", "rad") == "deg" else 1.0

    def transform(section: Any) -> np.ndarray:
        if not section:
            return np.eye(4)
        xyz = [v * ls for v in section.get("xyz", (0, 0, 0))]
        rpy = [v * angs for v in section.get("rpy", (0, 0, 0))]
        return origin(xyz, rpy)

    t = transform(doc.get("base"))
    frames = [t]
    for row, value in zip(doc["joints"], q, strict=True):
        a, d = row["a"] * ls, row["d"] * ls
        alpha, theta = row["alpha"] * angs, row["theta"] * angs
        if row.get("type", "revolute") == "prismatic":
            d += value
        else:
            theta += value
        if doc["convention"] == "standard":
            a_i = rz(theta) @ tr(z=d) @ tr(x=a) @ rx(alpha)
        else:
            a_i = rx(alpha) @ tr(x=a) @ rz(theta) @ tr(z=d)
        t = t @ a_i
        frames.append(t)
    frames.append(t @ transform(doc.get("tool")))
    return frames


def frame_names(n: int) -> list[str]:
    """dh_0..dh_n, tool."""
    return [f"dh_{i}" for i in range(n + 1)] + ["tool"]


def pin_q(model: pin.Model, q: Sequence[float]) -> np.ndarray:
    """Pinocchio configuration from one value per actuated joint (continuous -> cos, sin)."""
    out: list[float] = []
    for joint, value in zip(list(model.joints)[1:], q, strict=True):
        if joint.nq == 2:
            out += [math.cos(value), math.sin(value)]
        else:
            out.append(value)
    return np.array(out)


def pin_frames(urdf_text: str, q: Sequence[float], names: Sequence[str]) -> dict[str, np.ndarray]:
    """World poses (4×4) of the named frames by Pinocchio FK of the URDF text."""
    model = pin.buildModelFromXML(urdf_text)
    data = model.createData()
    pin.framesForwardKinematics(model, data, pin_q(model, q))
    out = {}
    for name in names:
        assert model.existFrame(name), name
        out[name] = data.oMf[model.getFrameId(name)].homogeneous.copy()
    return out


def yourdfpy_frames(
    urdf_text: str, q: Sequence[float], names: Sequence[str]
) -> dict[str, np.ndarray]:
    """World poses of the named links by yourdfpy FK of the URDF text."""
    robot = yourdfpy.URDF.load(io.BytesIO(urdf_text.encode("utf-8")), load_meshes=False)
    robot.update_cfg(np.asarray(q, dtype=float))
    return {name: robot.get_transform(name, "world") for name in names}


def random_q(table: DHTable, rng: np.random.Generator) -> np.ndarray:
    """A random configuration inside the joint limits (continuous: any angle)."""
    q = []
    for j in table.joints:
        if j.lower is None or j.upper is None:
            q.append(rng.uniform(-2 * math.pi, 2 * math.pi))
        else:
            q.append(rng.uniform(j.lower, j.upper))
    return np.array(q)
