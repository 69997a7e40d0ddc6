"""Untrusted documents and stored records : nothing a client uploads may poison
the store, escape the package roots, crash a listing or stall a worker."""

from __future__ import annotations

import json
import math
import time
from pathlib import Path

import httpx
import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.kinematics.errors import InvalidInputError
from app.main import create_app
from app.operations.settings import Settings
from app.robots.catalog import erd_share_dir
from app.storage.scenes import SceneStore
from tests.helpers import problem, serve

SURROGATE = "\\ud800"  # the JSON escape of a lone UTF-16 surrogate


def urdf_doc(
    *,
    axis: str = "0 0 1",
    limit: str = 'lower="-1" upper="1"',
    geometry: str = "",
    root_attrs: str = "",
) -> str:
    """A 1-joint robot: base --j1 (revolute)--> l1, optional collision geometry on l1."""
    collision = f"<collision><geometry>{geometry}</geometry></collision>" if geometry else ""
    return (f'<robot name="r"{root_attrs}><link name="base"/><link name="l1">{collision}</link>'
            f'<joint name="j1" type="revolute"><parent link="base"/><child link="l1"/>'
            f'<origin xyz="0 0 0.5"/><axis xyz="{axis}"/>'
            f'<limit {limit} effort="1" velocity="1"/></joint></robot>')  # fmt: skip


def chain(n: int) -> str:
    """A serial chain of ``n`` revolute joints."""
    links = "".join(f'<link name="l{i}"/>' for i in range(n + 1))
    joints = "".join(
        f'<joint name="j{i}" type="revolute"><parent link="l{i}"/><child link="l{i + 1}"/>'
        f'<origin xyz="0 0 0.1"/><axis xyz="0 0 1"/>'
        f'<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        for i in range(n)
    )
    return f'<robot name="r">{links}{joints}</robot>'


def post_raw(client: TestClient, path: str, text: str, content_type: str = "application/json"):
    return client.post(path, content=text.encode(), headers={"content-type": content_type})


def user_ids(client: TestClient) -> list[str]:
    resp = client.get("/robots")
    assert resp.status_code == 200, resp.text
    reg = client.app.state.registry
    return [r["id"] for r in resp.json()["robots"] if not reg.is_builtin(r["id"])]


DH_ROW = '{"a": 0.1, "alpha": 0, "d": 0.2, "theta": 0}'


# ------------------------------------------------------------------ 1. lone surrogates
@pytest.mark.parametrize("field", ["description", "ee_frame", "name", "urdf", "srdf"])
def test_urdf_upload_with_a_lone_surrogate_is_422_naming_the_field(client, field) -> None:
    doc = {"name": "sur", "urdf": urdf_doc(), "description": "ok"}
    doc[field] = {
        "urdf": urdf_doc().replace("</robot>", "<!-- \ud800 --></robot>"),
        "srdf": "<robot name='r'><!-- \ud800 --></robot>",
    }.get(field, "a\ud800")
    text = json.dumps(doc)  # ensure_ascii: the surrogate travels as the escape \ud800
    assert SURROGATE in text
    body = problem(post_raw(client, "/robots/urdf", text), 422, field)
    assert "surrogate" in body["detail"]
    assert user_ids(client) == []


@pytest.mark.parametrize("fmt", ["json", "yaml"])
def test_dh_import_with_a_lone_surrogate_is_422_naming_the_field(client, fmt) -> None:
    if fmt == "json":
        text = (f'{{"name": "sur", "description": "x{SURROGATE}", "convention": "standard", '
                f'"joints": [{DH_ROW}]}}')  # fmt: skip
        ctype = "application/json"
    else:
        text = (f'name: sur\ndescription: "x{SURROGATE}"\nconvention: standard\n'
                "joints:\n  - {a: 0.1, alpha: 0, d: 0.2, theta: 0}\n")  # fmt: skip
        ctype = "application/yaml"
    body = problem(post_raw(client, "/robots/dh", text, ctype), 422, "description")
    assert "surrogate" in body["detail"]
    # A surrogate in a key (echoed in "unknown field" errors) is refused too, never a 500.
    key = text.replace('"description"', f'"d{SURROGATE}"') if fmt == "json" else None
    if key:
        assert post_raw(client, "/robots/dh", key, ctype).status_code == 422
    assert user_ids(client) == []


def test_scene_with_a_lone_surrogate_is_422_naming_the_field(client, tmp_path) -> None:
    box = '{"name": "b%s", "shape": "box", "size": [1, 1, 1]}'
    text = f'{{"name": "s1", "description": "d{SURROGATE}", "obstacles": [{box % ""}]}}'
    problem(post_raw(client, "/scenes", text), 422, "description")
    text = f'{{"name": "s1", "obstacles": [{box % SURROGATE}]}}'
    problem(post_raw(client, "/scenes", text), 422, "obstacles.0.name")
    assert client.get("/scenes").json()["scenes"] == []
    # The store refuses it too, whoever calls it (it used to fail writing the file).
    store = SceneStore(tmp_path / "scenes")
    box_doc = {"name": "b", "shape": "box", "size": [1.0, 1.0, 1.0]}
    with pytest.raises(InvalidInputError) as err:
        store.create("s2", [box_doc], "d\ud800")
    assert err.value.field == "description"
    with pytest.raises(InvalidInputError) as err:
        store.create("s2", [{**box_doc, "name": "b\ud800"}])
    assert err.value.field == "obstacles.0.name"
    assert store.names() == []


def test_echoed_surrogate_is_a_422_not_a_500(client) -> None:
    """A surrogate in a name the service echoes (an unknown joint, as a map key)."""
    text = f'{{"joint_positions": {{"x{SURROGATE}": 1.0}}}}'
    resp = post_raw(client, "/robots/panda/fk", text)
    assert resp.status_code in (404, 422), resp.text
    body = problem(resp, resp.status_code)
    assert body["field"].startswith("joint_positions")
    resp.content.decode("utf-8")  # strict: the echo is valid UTF-8


def _store_robot(settings: Settings, rid: str) -> Path:
    with TestClient(create_app(settings)) as c:
        resp = c.post("/robots/urdf", json={"name": rid, "urdf": urdf_doc(), "description": "d"})
        assert resp.status_code == 201, resp.text
    return settings.data_dir / "robots" / rid


def test_poisoned_record_on_disk_is_skipped_and_listing_survives(settings) -> None:
    """A robot.json holding a lone surrogate (written before this fix, or by hand)."""
    _store_robot(settings, "good")
    bad = _store_robot(settings, "bad")
    meta = json.loads((bad / "robot.json").read_text())
    meta["description"] = "\ud800"  # json.dumps writes it as the escape \ud800
    (bad / "robot.json").write_text(json.dumps(meta))
    broken_joints = _store_robot(settings, "bad-joints")
    meta = json.loads((broken_joints / "robot.json").read_text())
    meta["joints"] = "many"
    (broken_joints / "robot.json").write_text(json.dumps(meta))
    with TestClient(create_app(settings), raise_server_exceptions=False) as c:  # a restart
        assert user_ids(c) == ["good"]
        assert c.get("/robots/good").status_code == 200
        problem(c.get("/robots/bad"), 404, "robot_id")
        # The damaged record can still be deleted.
        assert c.delete("/robots/bad").status_code == 204
        assert not bad.exists()


def test_damaged_urdf_on_disk_is_a_409_not_a_500(settings) -> None:
    path = _store_robot(settings, "torn")
    (path / "robot.urdf").write_bytes(b"<robot name='r'>\xed\xa0\x80</robot>")  # not UTF-8
    with TestClient(create_app(settings), raise_server_exceptions=False) as c:
        assert user_ids(c) == ["torn"]
        problem(c.get("/robots/torn"), 409, "robot_id")
        problem(c.post("/robots/torn/fk", json={"q": [0.0]}), 409, "robot_id")
        assert c.delete("/robots/torn").status_code == 204


# ------------------------------------------------------------------ 2. huge numbers in DH
@pytest.mark.parametrize("fmt", ["json", "yaml"])
def test_dh_integer_of_thousands_of_digits_is_422_naming_the_field(client, fmt) -> None:
    big = "7" * 5000
    if fmt == "json":
        text = (f'{{"name": "big", "convention": "standard", "joints": '
                f'[{DH_ROW}, {{"a": 0, "alpha": 0, "d": {big}, "theta": 0}}]}}')  # fmt: skip
        ctype = "application/json"
    else:
        text = (f"name: big\nconvention: standard\njoints:\n"
                f"  - {{a: 0.1, alpha: 0, d: 0.2, theta: 0}}\n"
                f"  - {{a: 0, alpha: 0, d: {big}, theta: 0}}\n")  # fmt: skip
        ctype = "application/yaml"
    problem(post_raw(client, "/robots/dh", text, ctype), 422, "joints.1.d")
    assert user_ids(client) == []


@pytest.mark.parametrize(
    ("row", "units", "field"),
    [
        ({"a": 1e308, "d": 1e308}, "m", "joints.0.a"),
        ({"a": 0.0, "d": -2e6}, "m", "joints.0.d"),
        ({"a": 2e9, "d": 0.0}, "mm", "joints.0.a"),  # 2e6 m after conversion
        ({"a": 0.0, "d": 0.0, "theta": 1e300}, "m", "joints.0.theta"),
    ],
)
def test_dh_lengths_and_angles_are_bounded(client, row, units, field) -> None:
    joint = {"a": 0.0, "alpha": 0.0, "d": 0.0, "theta": 0.0, **row}
    doc = {"name": "huge", "convention": "standard", "units": {"length": units}, "joints": [joint]}
    problem(client.post("/robots/dh", json=doc), 422, field)
    assert user_ids(client) == []
    # At the bound itself the table is accepted.
    edge = {"a": 1e6, "alpha": 0.0, "d": -1e6, "theta": 1e6}
    doc = {"name": "edge", "convention": "standard", "joints": [edge]}
    assert client.post("/robots/dh", json=doc).status_code == 201


# ------------------------------------------------------------------ 3. namespaces and URIs
PASSWD_MESH = '<mesh filename="/etc/passwd"/>'


def hidden_joint(joint_attrs: str) -> str:
    """A second joint (and its child link) in a default namespace, invisible to a check that
    reads tags namespace-aware, plain to urdfdom."""
    return urdf_doc().replace(
        "</robot>",
        '<link xmlns="urn:x" name="l2"/>'
        '<joint xmlns="urn:x" name="j2" type="revolute"><parent link="l1"/><child link="l2"/>'
        f"{joint_attrs}</joint></robot>",
    )


@pytest.mark.parametrize(
    "doc",
    [
        urdf_doc(geometry='<mesh xmlns="urn:x" filename="/etc/passwd"/>'),
        urdf_doc(geometry='<mesh xmlns="urn:x" filename="/etc/passwd" scale="1 1 1"/>'),
        # a default namespace on an ancestor hides every descendant from a namespace-aware check
        urdf_doc(geometry=PASSWD_MESH).replace("<collision>", '<collision xmlns="urn:x">'),
        urdf_doc(geometry=PASSWD_MESH).replace('<link name="l1">', '<link name="l1" xmlns="u:x">'),
        urdf_doc(geometry='<mesh xmlns:x="urn:x" x:scale="1 1 1" filename="/etc/passwd"/>'),
        urdf_doc(geometry='<mesh filename="&#x2F;etc/passwd"/>'),
        urdf_doc(axis="0 0 0").replace("<axis ", '<axis xmlns="urn:x" '),
        urdf_doc(limit='lower="2" upper="1"').replace("<limit ", '<limit xmlns="urn:x" '),
        urdf_doc(axis="0 0 1e308").replace("<axis ", '<axis xmlns="urn:x" '),
        hidden_joint('<axis xyz="0 0 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/>'),
        hidden_joint('<axis xyz="0 0 1"/><limit lower="2" upper="1" effort="1" velocity="1"/>'),
    ],
)
def test_namespace_tricks_do_not_bypass_the_checks(client, doc) -> None:
    body = problem(client.post("/robots/urdf", json={"name": "ns", "urdf": doc}), 422, "urdf")
    assert "passwd" not in body["detail"] or "refused" in body["detail"]
    assert user_ids(client) == []


@pytest.mark.parametrize(
    "uri",
    [
        "Package://example-robot-data/robots/ur_description/meshes/ur5/collision/base.stl",
        "PACKAGE://example-robot-data/robots/ur_description/meshes/ur5/collision/base.stl",
        "File:///etc/passwd",
        "file:///etc/passwd",
        "model://example-robot-data/robots/ur_description/meshes/ur5/collision/base.stl",
        " package://example-robot-data/robots/ur_description/meshes/ur5/collision/base.stl",
        "package://example-robot-data/robots/ur_description/meshes/ur5/collision/base.stl ",
        "package://example-robot-data/robots/ur_description/meshes/ur5/collision/b se.stl",
        "package:///etc/passwd",
        "package://pkg/a.stl?x=1",
    ],
)
def test_mesh_uris_pinocchio_resolves_differently_are_refused(client, uri) -> None:
    doc = urdf_doc(geometry=f'<mesh filename="{uri}"/>')
    body = problem(client.post("/robots/urdf", json={"name": "uri", "urdf": doc}), 422, "urdf")
    assert "mesh" in body["detail"]
    assert user_ids(client) == []


def test_mesh_loading_errors_leak_no_host_or_source_path(client) -> None:
    """A file inside the package roots that is no mesh: refused at upload, naming the URI
    only."""
    uri = "package://example-robot-data/robots/ur_description/urdf/ur5_robot.urdf"
    doc = urdf_doc(geometry=f'<mesh filename="{uri}"/>')
    body = problem(client.post("/robots/urdf", json={"name": "nomesh", "urdf": doc}), 422, "urdf")
    detail = body["detail"]
    assert uri in detail
    for leak in (str(erd_share_dir()), ".cpp", "From file", "line:", "/project/"):
        assert leak not in detail, detail
    # A plain package:// mesh is accepted and loads.
    uri = "package://example-robot-data/robots/ur_description/meshes/ur5/collision/base.stl"
    doc = urdf_doc(geometry=f'<mesh filename="{uri}"/>')
    assert client.post("/robots/urdf", json={"name": "ok", "urdf": doc}).status_code == 201
    assert client.post("/robots/ok/collisions", json={"q": [0.0]}).status_code == 200
    # <x:mesh> is no mesh to urdfdom either: whatever happens, /etc/passwd is not read.
    doc = urdf_doc(geometry='<x:mesh xmlns:x="urn:x" filename="/etc/passwd"/>')
    resp = client.post("/robots/urdf", json={"name": "prefixed", "urdf": doc})
    assert resp.status_code in (201, 422), resp.text
    if resp.status_code == 201:
        coll = client.post("/robots/prefixed/collisions", json={"q": [0.0]})
        assert coll.status_code in (200, 422), coll.text
        assert "passwd" not in coll.text and "root:" not in coll.text


@pytest.mark.parametrize(
    "limit", ['lower="2e4" upper="3e4"', 'lower="-1" upper="10000.5"', 'lower="-2e5" upper="0"']
)
def test_joint_limits_beyond_the_joint_value_bound_are_422(client, limit) -> None:
    """A range beyond ±1e4 would have configurations (its neutral one) FK refuses."""
    doc = urdf_doc(limit=limit)
    body = problem(client.post("/robots/urdf", json={"name": "wide", "urdf": doc}), 422, "urdf")
    assert "'j1'" in body["detail"] and "limit" in body["detail"]
    assert user_ids(client) == []
    ok = urdf_doc(limit='lower="-10000" upper="10000"')
    assert client.post("/robots/urdf", json={"name": "edge", "urdf": ok}).status_code == 201


# ------------------------------------------------------------------ 4. axes
@pytest.mark.parametrize("axis", ["1e-320 0 0", "0 0 1e-7", "0 0 0", "-0 0 -0"])
def test_axis_of_tiny_norm_is_422_naming_the_joint(client, axis) -> None:
    doc = urdf_doc(axis=axis)
    body = problem(client.post("/robots/urdf", json={"name": "tiny", "urdf": doc}), 422, "urdf")
    assert "'j1'" in body["detail"] and "axis" in body["detail"]
    assert user_ids(client) == []


@pytest.mark.parametrize("axis", [(0.0, 0.0, 2.0), (0.0, 3.0, -4.0), (1e-5, 0.0, 0.0), (1, 1, 1)])
def test_reported_axis_is_the_normalised_one_fk_uses(client, axis) -> None:
    doc = urdf_doc(axis=" ".join(repr(float(v)) for v in axis))
    resp = client.post("/robots/urdf", json={"name": "ax", "urdf": doc})
    assert resp.status_code == 201, resp.text
    expected = np.asarray(axis, dtype=float) / math.sqrt(sum(float(v) ** 2 for v in axis))
    reported = client.get("/robots/ax").json()["joints"][0]["axis"]
    np.testing.assert_allclose(reported, expected, rtol=0, atol=1e-15)
    # FK about that axis (Rodrigues, independent of Pinocchio): an orthonormal rotation.
    q = 0.7
    k = expected
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    R = np.eye(3) + math.sin(q) * K + (1 - math.cos(q)) * K @ K
    fk = client.post("/robots/ax/fk", json={"q": [q], "frames": ["l1"]}).json()
    M = np.asarray(fk["poses"]["l1"]["matrix"])
    np.testing.assert_allclose(M[:3, :3], R, atol=1e-12)


# ------------------------------------------------------------------ 5. bounded work
def test_urdf_beyond_the_movable_joint_limit_is_refused(client) -> None:
    """65 movable joints: per-thread Data would grow as dof³ (4.5 GB at the old 512)."""
    body = problem(client.post("/robots/urdf", json={"name": "long", "urdf": chain(65)}), 422)
    assert body["field"] == "urdf" and "DENAVIT_MAX_ROBOT_DOF" in body["detail"]
    assert client.post("/robots/urdf", json={"name": "ok64", "urdf": chain(64)}).status_code == 201


def test_the_limits_are_settings(tmp_path) -> None:
    settings = Settings(
        data_dir=tmp_path / "data",
        max_robot_dof=70,
        max_urdf_joints=70,
        max_xml_elements=600,
        max_xml_depth=8,
        max_xml_attributes_per_element=8,
        max_xml_attributes=1000,
    )
    with TestClient(create_app(settings), raise_server_exceptions=False) as c:
        assert c.post("/robots/urdf", json={"name": "c65", "urdf": chain(65)}).status_code == 201
        body = problem(c.post("/robots/urdf", json={"name": "c71", "urdf": chain(71)}), 422)
        assert "DENAVIT_MAX_URDF_JOINTS" in body["detail"]
        many = urdf_doc().replace("</robot>", "<x/>" * 600 + "</robot>")
        body = problem(c.post("/robots/urdf", json={"name": "m", "urdf": many}), 422, "urdf")
        assert "DENAVIT_MAX_XML_ELEMENTS" in body["detail"]
        deep = urdf_doc().replace("</robot>", "<x>" * 9 + "</x>" * 9 + "</robot>")
        body = problem(c.post("/robots/urdf", json={"name": "d", "urdf": deep}), 422, "urdf")
        assert "DENAVIT_MAX_XML_DEPTH" in body["detail"]
        attrs = " " + " ".join(f'a{i}="1"' for i in range(9))
        wide = urdf_doc(root_attrs=attrs)
        body = problem(c.post("/robots/urdf", json={"name": "w", "urdf": wide}), 422, "urdf")
        assert "DENAVIT_MAX_XML_ATTRIBUTES_PER_ELEMENT" in body["detail"]
        total = urdf_doc().replace("</robot>", '<x a="1" b="2" c="3"/>' * 400 + "</robot>")
        body = problem(c.post("/robots/urdf", json={"name": "t", "urdf": total}), 422, "urdf")
        assert "(DENAVIT_MAX_XML_ATTRIBUTES)" in body["detail"]
        srdf = "<robot>" + "<x/>" * 600 + "</robot>"
        upload = {"name": "s", "urdf": urdf_doc(), "srdf": srdf}
        problem(c.post("/robots/urdf", json=upload), 422, "srdf")
        assert user_ids(c) == ["c65"]


def killer_urdf(attributes: int = 100_000) -> str:
    """About 1 MB: every attribute on one element (urdfdom's parser is quadratic in them)."""
    attrs = " " + " ".join(f'a{i}="{i}"' for i in range(attributes))
    return urdf_doc(root_attrs=attrs)


def test_killer_document_gets_a_quick_4xx_on_a_live_two_worker_server(tmp_path) -> None:
    """Before: ~100 s of GIL in the model build (the worker starved). Now: refused at parse."""
    doc = killer_urdf()
    assert len(doc) > 1_000_000
    with serve(tmp_path / "data", "--workers", "2") as server, httpx.Client(timeout=60) as http:
        url = server.url
        start = time.monotonic()
        resp = http.post(url + "/robots/urdf", json={"name": "killer", "urdf": doc})
        elapsed = time.monotonic() - start
        assert resp.status_code == 422, resp.text[:500]
        assert "DENAVIT_MAX_XML_ATTRIBUTES_PER_ELEMENT" in resp.json()["detail"]
        assert elapsed < 60
        # The other worker killer: 512 movable joints (the old maximum), whose per-thread
        # Data (~4.5 GB) the first FK would have built. Refused before any model exists.
        for n, limit in ((512, "DENAVIT_MAX_URDF_JOINTS"), (200, "DENAVIT_MAX_ROBOT_DOF")):
            long = http.post(url + "/robots/urdf", json={"name": "long", "urdf": chain(n)})
            assert long.status_code == 422, long.text[:500]
            assert long.json()["field"] == "urdf" and limit in long.json()["detail"]
        # Both workers stay healthy and serve writes and reads.
        for _ in range(6):
            assert http.get(url + "/health").status_code == 200
        ok = http.post(url + "/robots/urdf", json={"name": "fine", "urdf": urdf_doc()})
        assert ok.status_code == 201, ok.text
        listing = http.get(url + "/robots").json()["robots"]
        assert [r["id"] for r in listing if r["source"] == "upload"] == ["fine"]


def test_records_stored_before_the_checks_are_not_served(settings) -> None:
    """A URDF stored before this fix with a namespace-hidden host path, or too many joints:
    re-checked when first loaded, a 409 naming the robot, and no host file is read."""
    hidden = _store_robot(settings, "hidden")
    doc = urdf_doc(geometry='<mesh xmlns="urn:x" filename="/etc/passwd"/>')
    (hidden / "robot.urdf").write_text(doc)
    big = _store_robot(settings, "big")
    (big / "robot.urdf").write_text(chain(200))
    with TestClient(create_app(settings), raise_server_exceptions=False) as c:
        for rid, reason in (("hidden", "refused"), ("big", "DENAVIT_MAX_ROBOT_DOF")):
            body = problem(c.get(f"/robots/{rid}"), 409, "robot_id")
            assert reason in body["detail"], body
            coll = c.post(f"/robots/{rid}/collisions", json={"q": [0.0]})
            assert coll.status_code == 409, coll.text
            assert "root:" not in coll.text
        assert c.delete("/robots/hidden").status_code == 204
