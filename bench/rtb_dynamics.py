"""The Robotics Toolbox's rigid-body dynamics of its DH Puma 560 and UR5 as a test fixture.

Run with the bench venv's interpreter (``make rtb-fixtures``; the toolbox needs another
NumPy than the service, so it never runs in ``.venv``)::

    .venv-bench/bin/python bench/rtb_dynamics.py [tests/kinematics/data/rtb_dynamics.json]

Besides, ``mdh3``: a modified-DH (Craig) arm of this script's own (:data:`MDH_ARM`, two
revolute joints and a prismatic one, offsets, full inertias), the convention the catalog's
robots do not use, built from the toolbox's ``RevoluteMDH``/``PrismaticMDH`` links.

For each robot, at fixed-seed random states (q within the toolbox's joint limits, q̇ and q̈
uniform in ±2 rad/s and ±3 rad/s²) it writes the toolbox's answers: ``rne`` (τ), ``gravload``
(g), ``inertia`` (M), ``coriolis`` (C) and ``C·q̇``. The toolbox's models are the published
ones (``roboticstoolbox.models.DH.Puma560`` and ``.UR5``, standard DH, link frame i at the
end of row i, ``r`` and ``I`` in it) made rigid-body only: motor inertia ``Jm = 0``, gear
ratio ``G = 1``, viscous ``B = 0`` and Coulomb ``Tc = 0`` friction on every link, so ``rne``
is ``M q̈ + C q̇ + g`` of the links alone; gravity ``[0, 0, −9.81]`` m/s² in the world, as the
service's. The few values the service's catalog tables (robots/dh/) give differently are set
here to the catalog's, each with its reason in ``OVERRIDES`` (and in the fixture): neither
changes what the test compares against the published model except where a published
inertia is not one a rigid body can have.

This module imports nothing from the service; tests/kinematics/test_dynamics_rtb.py
compares the service's ``compute_dynamics`` on the catalog robots ``puma560`` and
``ur5_dh`` (DH → URDF by dh2urdf) with it.
"""

from __future__ import annotations

import json
import sys
from importlib.metadata import version
from pathlib import Path

import numpy as np
import roboticstoolbox as rtb

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "tests" / "kinematics" / "data" / "rtb_dynamics.json"
SEED = 20261204
STATES = 8
GRAVITY = [0.0, 0.0, -9.81]

#: (toolbox model, catalog id, {link index (0-based): {attribute: value}}, reason).
OVERRIDES = {
    "puma560": [
        (
            0,
            "I",
            [0.175, 0.35, 0.175],
            "link 1's published inertia (0, 0.35, 0) is no rigid body's (0 + 0 < 0.35); "
            "Ixx = Izz = 0.175 never enter a joint torque (link 1 turns about y1 only)",
        ),
        (
            2,
            "I",
            [0.066, 0.086, 0.0200],
            "link 3's published moments break the triangle inequality "
            "(0.066 + 0.0125 < 0.086); the catalog raises Izz to 0.0200",
        ),
    ],
    "mdh3": [],
    "ur5_dh": [
        (
            0,
            "d",
            0.089159,
            "the toolbox's d1 = 0.089459 is a typo of UR's 0.089159 (a shift along the "
            "vertical base axis: no torque changes)",
        ),
    ],
}


#: A modified-DH (Craig) arm of this script's own, 2 revolute joints and a prismatic one with
#: every offset, twist and an off-axis com and full inertia: the convention the catalog's
#: robots do not use. Rows as a dh2urdf table's (SI; ``inertia`` its six URDF entries);
#: the test builds the same table from these rows.
MDH_ARM = [
    {
        "type": "revolute",
        "a": 0.0,
        "alpha": 0.0,
        "d": 0.3,
        "theta": 0.2,
        "mass": 4.0,
        "com": [0.02, -0.01, -0.12],
        "inertia": [0.05, 0.002, -0.001, 0.04, 0.003, 0.03],
    },
    {
        "type": "revolute",
        "a": 0.1,
        "alpha": -1.5707963267948966,
        "d": 0.05,
        "theta": -0.4,
        "mass": 3.0,
        "com": [0.2, 0.01, 0.03],
        "inertia": [0.01, 0.0, 0.002, 0.06, 0.0, 0.055],
    },
    {
        "type": "prismatic",
        "a": 0.45,
        "alpha": 1.5707963267948966,
        "d": 0.1,
        "theta": 0.3,
        "lower": 0.0,
        "upper": 0.5,
        "mass": 1.5,
        "com": [0.0, 0.02, -0.15],
        "inertia": [0.012, 0.001, 0.0, 0.012, -0.001, 0.004],
    },
]


def _mdh_arm() -> rtb.DHRobot:
    links = []
    for row in MDH_ARM:
        ixx, ixy, ixz, iyy, iyz, izz = row["inertia"]
        inertia = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
        common = {
            "a": row["a"],
            "alpha": row["alpha"],
            "m": row["mass"],
            "r": row["com"],
            "I": inertia,
        }
        if row["type"] == "prismatic":
            link = rtb.PrismaticMDH(
                theta=row["theta"], offset=row["d"], qlim=[row["lower"], row["upper"]], **common
            )
        else:
            link = rtb.RevoluteMDH(d=row["d"], offset=row["theta"], **common)
        links.append(link)
    return rtb.DHRobot(links, name="mdh3")


def model(robot_id: str) -> rtb.DHRobot:
    """The toolbox's model, rigid-body only (module docstring), overrides applied."""
    if robot_id == "mdh3":
        robot = _mdh_arm()
    else:
        robot = rtb.models.DH.Puma560() if robot_id == "puma560" else rtb.models.DH.UR5()
    for link in robot.links:
        link.Jm = 0.0
        link.G = 1.0
        link.B = 0.0
        link.Tc = [0.0, 0.0]
    for index, attribute, value, _ in OVERRIDES[robot_id]:
        setattr(robot.links[index], attribute, value)
    robot.gravity = GRAVITY
    return robot


def states(robot: rtb.DHRobot, rng: np.random.Generator) -> list[tuple[np.ndarray, ...]]:
    if robot.qlim is None or not np.all(np.isfinite(robot.qlim)):
        lower = np.full(robot.n, -np.pi)
        upper = np.full(robot.n, np.pi)
        for j, link in enumerate(robot.links):
            if link.qlim is not None and np.all(np.isfinite(link.qlim)):
                lower[j], upper[j] = link.qlim
    else:
        lower, upper = robot.qlim
    lower = np.maximum(lower, -np.pi)
    upper = np.minimum(upper, np.pi)
    out = []
    for _ in range(STATES):
        q = rng.uniform(lower, upper)
        qd = rng.uniform(-2.0, 2.0, robot.n)
        qdd = rng.uniform(-3.0, 3.0, robot.n)
        out.append((q, qd, qdd))
    return out


def answers(robot: rtb.DHRobot, q: np.ndarray, qd: np.ndarray, qdd: np.ndarray) -> dict:
    tau = np.asarray(robot.rne(q, qd, qdd, gravity=GRAVITY), dtype=float)
    g = np.asarray(robot.gravload(q, gravity=GRAVITY), dtype=float)
    m = np.asarray(robot.inertia(q), dtype=float)
    c = np.asarray(robot.coriolis(q, qd), dtype=float)
    return {
        "q": q.tolist(),
        "qd": qd.tolist(),
        "qdd": qdd.tolist(),
        "torques": tau.tolist(),
        "gravity": g.tolist(),
        "mass_matrix": m.tolist(),
        "coriolis_matrix": c.tolist(),
        "coriolis_torques": (c @ qd).tolist(),
    }


def main(argv: list[str]) -> int:
    out = Path(argv[1]) if len(argv) > 1 else OUT
    rng = np.random.default_rng(SEED)
    robots = {}
    for robot_id in ("puma560", "ur5_dh", "mdh3"):
        robot = model(robot_id)
        robots[robot_id] = {
            "model": type(robot).__name__
            if robot_id != "mdh3"
            else "DHRobot (RevoluteMDH, PrismaticMDH) of MDH_ARM",
            **({"rows": MDH_ARM} if robot_id == "mdh3" else {}),
            "overrides": [
                {"link": i + 1, "attribute": a, "value": v, "why": why}
                for i, a, v, why in OVERRIDES[robot_id]
            ],
            "states": [answers(robot, *s) for s in states(robot, rng)],
        }
    doc = {
        "source": "bench/rtb_dynamics.py (make rtb-fixtures)",
        "roboticstoolbox": version("roboticstoolbox-python"),
        "numpy": np.__version__,
        "seed": SEED,
        "gravity": GRAVITY,
        "rigid_body_only": "Jm = 0, G = 1, B = 0, Tc = 0 on every link",
        "robots": robots,
    }
    out.write_text(json.dumps(doc, indent=1) + "\n", encoding="utf-8")
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
