"""POST /robots/urdf: uploads, and every kind of bad or hostile URDF (nothing stored)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.main import create_app
from app.operations.settings import Settings
from tests.helpers import problem


def joint(
    name: str,
    parent: str,
    child: str,
    jtype: str = "revolute",
    *,
    xyz: str = "0 0 0.5",
    axis: str = "0 0 1",
    limit: str = 'lower="-2" upper="2"',
    extra: str = "",
) -> str:
    lim = f'<limit {limit} effort="10" velocity="2"/>' if limit is not None else ""
    return (f'<joint name="{name}" type="{jtype}"><parent link="{parent}"/>'
            f'<child link="{child}"/><origin xyz="{xyz}" rpy="0 0 0"/><axis xyz="{axis}"/>'
            f"{lim}{extra}</joint>")  # fmt: skip


def robot(*parts: str, links: str = "base l1 l2") -> str:
    body = "".join(f'<link name="{n}"/>' for n in links.split())
    return f'<robot name="r">{body}{"".join(parts)}</robot>'


#: base --j1 (z, 0.5 up)--> l1 --j2 (y, 0.5 up)--> l2 --fixed (0.2 along x)--> tip
GOOD = robot(
    joint("j1", "base", "l1"),
    joint("j2", "l1", "l2", axis="0 1 0"),
    '<joint name="tip_joint" type="fixed"><parent link="l2"/><child link="tip"/>'
    '<origin xyz="0.2 0 0"/></joint>',
    links="base l1 l2 tip",
)
SRDF = '<robot name="r"><disable_collisions link1="base" link2="l2" reason="Never"/></robot>'


def snapshot(root: Path) -> list[str]:
    return sorted(str(p.relative_to(root)) for p in root.rglob("*")) if root.exists() else []


def test_upload_then_fk_matches_hand_computation(client: TestClient) -> None:
    resp = client.post(
        "/robots/urdf",
        json={"name": "two-r", "urdf": GOOD, "srdf": SRDF, "description": "test"},
    )
    assert resp.status_code == 201, resp.text
    assert resp.headers["location"] == "/robots/two-r"
    body = resp.json()
    assert body == client.get("/robots/two-r").json()
    assert (body["source"], body["end_effector"], body["description"]) == ("upload", "tip", "test")
    assert [j["name"] for j in body["joints"]] == ["j1", "j2"]
    q1, q2 = 0.7, -0.4
    fk = client.post("/robots/two-r/fk", json={"q": [q1, q2], "frames": ["tip"]})
    assert fk.status_code == 200, fk.text
    # tip = Tz(0.5)·Rz(q1)·Tz(0.5)·Ry(q2)·Tx(0.2)
    x = 0.2 * math.cos(q2)
    expected = [x * math.cos(q1), x * math.sin(q1), 1.0 - 0.2 * math.sin(q2)]
    np.testing.assert_allclose(fk.json()["poses"]["tip"]["position"], expected, atol=1e-12)
    assert client.get("/robots/two-r/urdf").text == GOOD
    problem(client.get("/robots/two-r/dh"), 404, "robot_id")
    listed = {r["id"]: r for r in client.get("/robots").json()["robots"]}
    assert (listed["two-r"]["source"], listed["two-r"]["joints"]) == ("upload", 2)
    assert client.delete("/robots/two-r").status_code == 204
    problem(client.get("/robots/two-r"), 404, "robot_id")


def test_upload_with_ee_frame_and_persistence(tmp_path: Path) -> None:
    settings = Settings(data_dir=tmp_path / "data")
    with TestClient(create_app(settings)) as c:
        resp = c.post("/robots/urdf", json={"name": "arm", "urdf": GOOD, "ee_frame": "l1"})
        assert resp.status_code == 201 and resp.json()["end_effector"] == "l1"
        problem(c.post("/robots/urdf", json={"name": "arm", "urdf": GOOD}), 409, "name")
        problem(c.post("/robots/urdf", json={"name": "ur5", "urdf": GOOD}), 409, "name")
        problem(c.post("/robots/urdf", json={"name": "rrp", "urdf": GOOD}), 409, "name")
    with TestClient(create_app(settings)) as again:
        detail = again.get("/robots/arm").json()
        assert detail["end_effector"] == "l1" and detail["source"] == "upload"


BILLION_LAUGHS = (
    '<?xml version="1.0"?><!DOCTYPE lolz [<!ENTITY lol "lol">'
    '<!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">'
    '<!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">]>'
    '<robot name="&lol3;"><link name="a"/></robot>'
)
EXTERNAL_ENTITY = (
    '<?xml version="1.0"?><!DOCTYPE robot [<!ENTITY xxe SYSTEM "file:///etc/passwd">]>'
    '<robot name="r"><link name="&xxe;"/></robot>'
)
EXTERNAL_DTD = '<?xml version="1.0"?><!DOCTYPE robot SYSTEM "http://example.org/x.dtd">' + GOOD


def with_mesh(filename: str) -> str:
    mesh = (
        f'<link name="l2"><collision><geometry><mesh filename="{filename}"/></geometry>'
        "</collision></link>"
    )
    return robot(joint("j1", "base", "l1"), joint("j2", "l1", "l2"), links="base l1").replace(
        "</robot>", mesh + "</robot>"
    )


BAD_UPLOADS = {
    "not XML": ({"urdf": "<robot><link"}, 422, "urdf"),
    "not a robot": ({"urdf": "<sdf/>"}, 422, "urdf"),
    "billion laughs": ({"urdf": BILLION_LAUGHS}, 422, "urdf"),
    "external entity": ({"urdf": EXTERNAL_ENTITY}, 422, "urdf"),
    "external DTD": ({"urdf": EXTERNAL_DTD}, 422, "urdf"),
    "no links": ({"urdf": '<robot name="r"/>'}, 422, "urdf"),
    "only fixed joints": (
        {"urdf": robot(joint("j1", "base", "l1", "fixed"), links="base l1")},
        422,
        "urdf",
    ),
    "no joints at all": ({"urdf": robot(links="base")}, 422, "urdf"),
    "floating joint": (
        {"urdf": robot(joint("j1", "base", "l1", "floating", limit=None), links="base l1")},
        422,
        "urdf",
    ),
    "unknown joint type": (
        {"urdf": robot(joint("j1", "base", "l1", "hinge"), links="base l1")},
        422,
        "urdf",
    ),
    "undefined child link": ({"urdf": robot(joint("j1", "base", "ghost"))}, 422, "urdf"),
    "two roots": ({"urdf": robot(joint("j1", "base", "l1"))}, 422, "urdf"),
    "cycle": (
        {
            "urdf": robot(
                joint("j1", "base", "l1"), joint("j2", "l1", "l2"), joint("j3", "l2", "l1")
            )
        },
        422,
        "urdf",
    ),  # fmt: skip
    "duplicate joint": (
        {"urdf": robot(joint("j1", "base", "l1"), joint("j1", "l1", "l2"))},
        422,
        "urdf",
    ),
    "NaN origin": ({"urdf": GOOD.replace('xyz="0 0 0.5"', 'xyz="nan 0 0.5"', 1)}, 422, "urdf"),
    "text number": ({"urdf": GOOD.replace('xyz="0 0 0.5"', 'xyz="x 0 0.5"', 1)}, 422, "urdf"),
    "lower > upper": (
        {
            "urdf": robot(
                joint("j1", "base", "l1", limit='lower="1" upper="-1"'), joint("j2", "l1", "l2")
            )
        },
        422,
        "urdf",
    ),  # fmt: skip
    "revolute without limit": (
        {"urdf": robot(joint("j1", "base", "l1", limit=None), joint("j2", "l1", "l2"))},
        422,
        "urdf",
    ),
    "two-number axis": ({"urdf": GOOD.replace('axis xyz="0 0 1"', 'axis xyz="0 1"')}, 422, "urdf"),
    "two-number limit": (
        {"urdf": GOOD.replace('lower="-2"', 'lower="-2 -1"', 1)},
        422,
        "urdf",
    ),
    "mimic of nothing": (
        {
            "urdf": robot(
                joint("j1", "base", "l1"), joint("j2", "l1", "l2", extra='<mimic joint="ghost"/>')
            )
        },
        422,
        "urdf",
    ),  # fmt: skip
    "zero axis": ({"urdf": GOOD.replace('axis xyz="0 0 1"', 'axis xyz="0 0 0"')}, 422, "urdf"),
    "mesh package parent": ({"urdf": with_mesh("package://../../etc/passwd")}, 422, "urdf"),
    "mesh dotdot": ({"urdf": with_mesh("package://pkg/../../../etc/passwd")}, 422, "urdf"),
    "mesh file URI": ({"urdf": with_mesh("file:///etc/passwd")}, 422, "urdf"),
    "mesh absolute": ({"urdf": with_mesh("/etc/passwd")}, 422, "urdf"),
    "mesh relative dotdot": ({"urdf": with_mesh("../../secret.stl")}, 422, "urdf"),
    "mesh http": ({"urdf": with_mesh("http://169.254.169.254/x.stl")}, 422, "urdf"),
    "unknown ee_frame": ({"urdf": GOOD, "ee_frame": "hand"}, 422, "ee_frame"),
    "SRDF unknown link": (
        {"urdf": GOOD, "srdf": SRDF.replace('"l2"', '"nope"')},
        422,
        "srdf",
    ),
    "SRDF with entity": (
        {"urdf": GOOD, "srdf": EXTERNAL_ENTITY.replace("<link", "<group")},
        422,
        "srdf",
    ),
    "SRDF not XML": ({"urdf": GOOD, "srdf": "<robot"}, 422, "srdf"),
    "path in name": ({"name": "../../etc", "urdf": GOOD}, 422, "name"),
    "slash in name": ({"name": "a/b", "urdf": GOOD}, 422, "name"),
    "empty name": ({"name": "", "urdf": GOOD}, 422, "name"),
    "missing urdf": ({"urdf": None}, 422, "urdf"),
    "urdf not a string": ({"urdf": 42}, 422, "urdf"),
    "unknown field": ({"urdf": GOOD, "mesh_dir": "/"}, 422, "mesh_dir"),
}


@pytest.mark.parametrize("case", list(BAD_UPLOADS))
def test_bad_uploads_4xx_naming_the_field(client: TestClient, settings: Settings, case: str):
    changes, status, field = BAD_UPLOADS[case]
    body = {"name": "bad", **changes}
    body = {k: v for k, v in body.items() if v is not None}
    before = snapshot(settings.data_dir)
    problem(client.post("/robots/urdf", json=body), status, field)
    assert snapshot(settings.data_dir) == before
    problem(client.get("/robots/bad"), 404, "robot_id")


def test_safe_package_mesh_is_accepted(client: TestClient) -> None:
    urdf = with_mesh(
        "package://example-robot-data/robots/ur_description/meshes/ur5/collision/base.stl"
    )
    resp = client.post("/robots/urdf", json={"name": "meshy", "urdf": urdf})
    assert resp.status_code == 201, resp.text
    assert resp.json()["has_collision_geometry"]


def test_malformed_body_400(client: TestClient) -> None:
    resp = client.post(
        "/robots/urdf",
        content=b'{"name": "x", "urdf": ',
        headers={"content-type": "application/json"},
    )
    problem(resp, 400, "body")


def test_upload_limit_413(tmp_path: Path) -> None:
    settings = Settings(data_dir=tmp_path / "data", max_upload_bytes=4096)
    padded = GOOD.replace("</robot>", "<!--" + "x" * 5000 + "--></robot>")
    with TestClient(create_app(settings), raise_server_exceptions=False) as c:
        problem(c.post("/robots/urdf", json={"name": "big", "urdf": padded}), 413, "body")
        assert c.post("/robots/urdf", json={"name": "small", "urdf": GOOD}).status_code == 201
    assert not [p for p in snapshot(settings.data_dir) if "big" in p]


def test_upload_needs_the_token(tmp_path: Path) -> None:
    app = create_app(Settings(data_dir=tmp_path, api_token="tok"))
    with TestClient(app, raise_server_exceptions=False) as c:
        assert c.post("/robots/urdf", json={"name": "a", "urdf": GOOD}).status_code == 401
        ok = c.post(
            "/robots/urdf",
            json={"name": "a", "urdf": GOOD},
            headers={"authorization": "Bearer tok"},
        )
        assert ok.status_code == 201


@pytest.mark.parametrize("missing", ["effort", "velocity"])
def test_limit_without_effort_or_velocity_names_the_joint(client: TestClient, missing: str):
    """urdfdom refuses such a limit (Pinocchio then says only "not a valid URDF model")."""
    lim = 'lower="-2" upper="2" effort="10" velocity="2"'.replace(f'{missing}="', 'x="')
    urdf = robot(joint("j1", "base", "l1"), joint("j2", "l1", "l2").replace(
        '<limit lower="-2" upper="2" effort="10" velocity="2"/>', f"<limit {lim}/>"))  # fmt: skip
    detail = problem(client.post("/robots/urdf", json={"name": "bad", "urdf": urdf}), 422, "urdf")
    assert "'j2'" in detail["detail"] and f"{missing}=" in detail["detail"], detail
