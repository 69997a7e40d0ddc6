"""Per-row link dynamics (mass, com, inertia in frame i): checks, and where the URDF puts them.

The reference is the table document itself: frame i's world pose from elementary
rotations and translations (helpers.reference_chain), the com (table units) mapped through
it and the inertia rotated by it, compared with Pinocchio's body inertias of the URDF
dh2urdf writes (spatial inertias in world axes at the world origin), in both conventions.
"""

from __future__ import annotations

import copy
from typing import Any

import numpy as np
import pinocchio as pin
import pytest

from app.kinematics.errors import InvalidInputError
from app.robots.documents.dh import parse_dh_document
from dh2urdf.errors import DHError
from dh2urdf.table import DHTable
from dh2urdf.urdf import to_urdf

from .helpers import pin_q, reference_chain

LENGTH_TO_M = {"m": 1.0, "mm": 1e-3}


def doc(convention: str, units: str = "mm") -> dict[str, Any]:
    scale = 1000.0 if units == "mm" else 1.0
    return {
        "name": "dyn_arm",
        "convention": convention,
        "units": {"length": units, "angle": "deg"},
        "base": {"xyz": [10 * scale / 1000, -20 * scale / 1000, 300 * scale / 1000]},
        "joints": [
            {
                "a": 30 * scale / 1000,
                "alpha": -90,
                "d": 120 * scale / 1000,
                "theta": 15,
                "mass": 3.0,
                "com": [5 * scale / 1000, -40 * scale / 1000, 25 * scale / 1000],
                "inertia": [0.02, 0.001, -0.002, 0.03, 0.0015, 0.025],
            },
            {
                "a": 400 * scale / 1000,
                "alpha": 0,
                "d": 0,
                "theta": -90,
                "mass": 7.5,
                "com": [-200 * scale / 1000, 3 * scale / 1000, 60 * scale / 1000],
                "inertia": [0.01, 0, 0.003, 0.2, 0, 0.19],
            },
            {
                "type": "prismatic",
                "a": 0,
                "alpha": 90,
                "d": 50 * scale / 1000,
                "theta": 30,
                "lower": 0,
                "upper": 300 * scale / 1000,
                "mass": 1.2,
                "com": [0, 10 * scale / 1000, -80 * scale / 1000],
                "inertia": [0.004, 0, 0, 0.004, 0, 0.001],
            },
        ],
    }


def world_bodies(urdf: str, q: np.ndarray) -> list[pin.Inertia]:
    """Each joint's body inertia in world axes, about the world origin."""
    model = pin.buildModelFromXML(urdf)
    data = model.createData()
    pin.forwardKinematics(model, data, pin_q(model, q))
    return [data.oMi[j].act(model.inertias[j]) for j in range(1, model.njoints)]


@pytest.mark.parametrize("convention", ["standard", "modified"])
@pytest.mark.parametrize("units", ["mm", "m"])
@pytest.mark.parametrize("seed", range(3))
def test_inertial_is_in_frame_i(convention, units, seed):
    d = doc(convention, units)
    rng = np.random.default_rng(seed)
    q = np.array([rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(0, 0.3)])
    frames = reference_chain(d, q)
    bodies = world_bodies(to_urdf(DHTable.from_dict(d)), q)
    scale = LENGTH_TO_M[units]
    for i, (row, body) in enumerate(zip(d["joints"], bodies, strict=True), start=1):
        frame = frames[i]  # dh_i: the DH frame at the end of row i
        com = frame[:3, :3] @ (np.array(row["com"]) * scale) + frame[:3, 3]
        ixx, ixy, ixz, iyy, iyz, izz = row["inertia"]
        inertia = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
        assert body.mass == pytest.approx(row["mass"], abs=1e-15)
        np.testing.assert_allclose(body.lever, com, rtol=0, atol=1e-12)
        np.testing.assert_allclose(
            body.inertia, frame[:3, :3] @ inertia @ frame[:3, :3].T, rtol=0, atol=1e-12
        )


def test_no_dynamics_no_inertial_and_round_trip():
    d = doc("standard")
    plain = copy.deepcopy(d)
    for row in plain["joints"]:
        for key in ("mass", "com", "inertia"):
            row.pop(key)
    assert "<inertial>" not in to_urdf(DHTable.from_dict(plain))
    assert not DHTable.from_dict(plain).has_dynamics
    table = DHTable.from_dict(d)
    assert table.has_dynamics and to_urdf(table).count("<inertial>") == 3
    assert DHTable.from_dict(table.to_dict()) == table
    # com in table units (mm here), mass and inertia always SI
    assert table.joints[0].dynamics.com == (0.005, -0.04, 0.025)
    assert table.joints[1].dynamics.mass == 7.5


def test_mass_alone_is_a_point_mass_at_frame_i_origin_and_partial_rows_are_kept():
    d = doc("standard", "m")
    for key in ("com", "inertia"):
        d["joints"][0].pop(key)
    for key in ("mass", "com", "inertia"):
        d["joints"][2].pop(key)
    table = DHTable.from_dict(d)
    assert table.joints[0].dynamics.com == (0.0, 0.0, 0.0)
    assert table.joints[0].dynamics.inertia == (0.0,) * 6
    assert table.joints[2].dynamics is None
    assert to_urdf(table).count("<inertial>") == 2


def set_row(key: str, value: Any, row: int = 1):
    def mutate(d: dict[str, Any]) -> None:
        if value is DROP:
            d["joints"][row].pop(key)
        else:
            d["joints"][row][key] = value

    return mutate


DROP = object()


@pytest.mark.parametrize(
    "mutate, field, reason",
    [
        (set_row("mass", -1.0), "joints[1].mass", ">= 0"),
        (set_row("mass", "7"), "joints[1].mass", "expected a number"),
        (set_row("mass", float("nan")), "joints[1].mass", "finite"),
        (set_row("mass", 2e6), "joints[1].mass", "not accepted"),
        (set_row("mass", True), "joints[1].mass", "expected a number"),
        (set_row("mass", DROP), "joints[1].mass", "field required"),
        (set_row("com", [0, 0]), "joints[1].com", "3 numbers"),
        (set_row("com", [0, "x", 0]), "joints[1].com[1]", "expected a number"),
        (set_row("com", [0, 0, float("inf")]), "joints[1].com[2]", "finite"),
        (set_row("com", [0, 0, 2e9]), "joints[1].com[2]", "not accepted"),
        (set_row("com", 5), "joints[1].com", "3 numbers"),
        (set_row("inertia", [1, 0, 0, 1, 0]), "joints[1].inertia", "6 numbers"),
        (set_row("inertia", "0.1"), "joints[1].inertia", "6 numbers"),
        (set_row("inertia", [1, 0, 0, 1, 0, None]), "joints[1].inertia[5]", "expected a number"),
        (set_row("inertia", [-0.1, 0, 0, 1, 0, 1]), "joints[1].inertia[0]", "ixx must be >= 0"),
        (set_row("inertia", [1, 0, 0, 1, 0, 2e6]), "joints[1].inertia[5]", "not accepted"),
        (set_row("inertia", [1, 2, 0, 1, 0, 1]), "joints[1].inertia", "positive semi-definite"),
        (set_row("inertia", [1, 0, 0, 1, 0, 3]), "joints[1].inertia", "triangle inequality"),
        (set_row("inertia", [0.066, 0, 0, 0.086, 0, 0.0125]), "joints[1].inertia", "triangle"),
    ],
)
def test_bad_dynamics_name_the_field(mutate, field, reason):
    d = doc("standard", "m")
    mutate(d)
    with pytest.raises(DHError) as e:
        DHTable.from_dict(d)
    assert e.value.field == field
    assert reason in e.value.reason


def test_api_names_the_field_dotted():
    import json

    d = doc("standard", "m")
    d["joints"][2]["mass"] = -3
    with pytest.raises(InvalidInputError) as e:
        parse_dh_document(json.dumps(d), "json")
    assert e.value.field == "joints.2.mass"


def test_triangle_equality_and_a_massless_link_with_inertia_are_accepted():
    d = doc("standard", "m")
    d["joints"][0].update(mass=0.0, com=[0, 0, 0], inertia=[0.175, 0, 0, 0.35, 0, 0.175])
    table = DHTable.from_dict(d)
    assert table.joints[0].dynamics.mass == 0.0
