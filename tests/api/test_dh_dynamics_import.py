"""POST /robots/dh with per-row dynamics: stored, given back by GET /robots/{id}/dh, written
into the URDF; a bad mass, com or inertia is a 422 naming the field (``joints.1.inertia``)."""

from __future__ import annotations

import copy
import xml.etree.ElementTree as ET

import pytest
from fastapi.testclient import TestClient

from tests.helpers import problem

TABLE = {
    "name": "dyn2",
    "convention": "standard",
    "units": {"length": "mm", "angle": "deg"},
    "joints": [
        {
            "a": 400,
            "alpha": 0,
            "d": 0,
            "theta": 0,
            "mass": 2.5,
            "com": [-200, 0, 10],
            "inertia": [0.002, 0, 0, 0.03, 0, 0.03],
        },
        {"a": 300, "alpha": 0, "d": 0, "theta": 0, "mass": 1.5},
    ],
}


def test_dynamics_round_trip_through_the_api(client: TestClient) -> None:
    assert client.post("/robots/dh", json=TABLE).status_code == 201
    rows = client.get("/robots/dyn2/dh").json()["joints"]
    assert rows[0]["mass"] == 2.5 and rows[0]["com"] == [-0.2, 0.0, 0.01]
    assert rows[0]["inertia"] == [0.002, 0.0, 0.0, 0.03, 0.0, 0.03]
    assert rows[1]["mass"] == 1.5 and rows[1]["com"] == [0.0, 0.0, 0.0]
    urdf = ET.fromstring(client.get("/robots/dyn2/urdf").text)
    inertial = {
        link.get("name"): link.find("inertial")
        for link in urdf.iter("link")
        if link.find("inertial") is not None
    }
    assert set(inertial) == {"link_1", "link_2"}
    # frame 1 sits at the end of the 0.4 m link: the com (-0.2, 0, 0.01) is mid-link
    assert inertial["link_1"].find("origin").get("xyz") == "0.2 0.0 0.01"
    # and a table without dynamics still has none
    plain = copy.deepcopy(TABLE) | {"name": "plain2"}
    for row in plain["joints"]:
        for key in ("mass", "com", "inertia"):
            row.pop(key, None)
    assert client.post("/robots/dh", json=plain).status_code == 201
    assert "<inertial>" not in client.get("/robots/plain2/urdf").text
    assert "mass" not in client.get("/robots/plain2/dh").json()["joints"][0]


@pytest.mark.parametrize(
    "key, value, field",
    [
        ("mass", -1, "joints.1.mass"),
        ("mass", "heavy", "joints.1.mass"),
        ("com", [0, 0], "joints.1.com"),
        ("com", [0, None, 0], "joints.1.com.1"),
        ("inertia", [1, 0, 0, 1, 0, 3], "joints.1.inertia"),
        ("inertia", [1, 2, 0, 1, 0, 1], "joints.1.inertia"),
        ("inertia", [1, 0, 0, -1, 0, 1], "joints.1.inertia.3"),
        ("inertia", [1, 0, 0, 1, 0], "joints.1.inertia"),
    ],
)
def test_bad_dynamics_are_422_naming_the_field(client: TestClient, key, value, field) -> None:
    doc = copy.deepcopy(TABLE)
    doc["joints"][1][key] = value
    problem(client.post("/robots/dh", json=doc), 422, field)


def test_com_without_mass_names_the_mass(client: TestClient) -> None:
    doc = copy.deepcopy(TABLE)
    doc["joints"][1] = {"a": 300, "alpha": 0, "d": 0, "theta": 0, "com": [0, 0, 1]}
    body = problem(client.post("/robots/dh", json=doc), 422, "joints.1.mass")
    assert "com" in body["detail"]
