"""POST /robots/dh, GET /robots/{id}/dh and /urdf, DELETE /robots/{id}, several app instances.

FK references are products of DH matrices written out here with NumPy.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import httpx
import numpy as np
import pytest
import yaml
from fastapi.testclient import TestClient
from hypothesis import HealthCheck, given
from hypothesis import settings as hsettings
from hypothesis import strategies as st

from app.main import create_app
from app.operations.settings import Settings
from tests.helpers import problem, serve

TABLE = {
    "name": "tiny",
    "description": "RRP test arm",
    "convention": "standard",
    "joints": [
        {"name": "base", "a": 0.0, "alpha": -math.pi / 2, "d": 0.3, "theta": 0.0},
        {"name": "shoulder", "a": 0.4, "alpha": 0.0, "d": 0.0, "theta": 0.3,
         "lower": -2.0, "upper": 2.0},
        {"name": "slide", "type": "prismatic", "a": 0.0, "alpha": math.pi / 2, "d": 0.1,
         "theta": 0.0, "lower": 0.0, "upper": 0.4},
    ],
}  # fmt: skip

#: The ARMAR-I arm of the course (mm, degrees, θ offsets), as YAML.
ARMAR_YAML = """\
name: armar_copy
convention: standard
units: {length: mm, angle: deg}
joints:
  - {a: 30, alpha: -90, d: 0, theta: 0}
  - {a: 0, alpha: -90, d: 0, theta: -90}
  - {a: 0, alpha: 90, d: 223.5, theta: 90}
  - {a: 0, alpha: -90, d: 0, theta: 0}
  - {a: 0, alpha: 90, d: 270, theta: 0}
  - {a: 0, alpha: -90, d: 0, theta: 90}
  - {a: 140, alpha: 90, d: 0, theta: 0}
"""


def dh(a: float, alpha: float, d: float, theta: float) -> np.ndarray:
    """Standard DH matrix Rz(θ)·Tz(d)·Tx(a)·Rx(α)."""
    ct, st, ca, sa = math.cos(theta), math.sin(theta), math.cos(alpha), math.sin(alpha)
    return np.array(
        [
            [ct, -st * ca, st * sa, a * ct],
            [st, ct * ca, -ct * sa, a * st],
            [0, sa, ca, d],
            [0, 0, 0, 1],
        ]
    )


def reference(rows: list[dict], q: list[float], length: float = 1.0, angle: float = 1.0):
    T = np.eye(4)
    for row, value in zip(rows, q, strict=True):
        a, d = row["a"] * length, row["d"] * length
        alpha, theta = row["alpha"] * angle, row["theta"] * angle
        if row.get("type") == "prismatic":
            d += value
        else:
            theta += value
        T = T @ dh(a, alpha, d, theta)
    return T


def snapshot(root: Path) -> list[str]:
    return sorted(str(p.relative_to(root)) for p in root.rglob("*")) if root.exists() else []


def tool_matrix(client: TestClient, robot_id: str, q: list[float]) -> np.ndarray:
    resp = client.post(f"/robots/{robot_id}/fk", json={"q": q})
    assert resp.status_code == 200, resp.text
    return np.array(resp.json()["poses"]["tool"]["matrix"])


def yaml_post(client: TestClient, text: str, media: str = "application/yaml"):
    return client.post("/robots/dh", content=text.encode(), headers={"content-type": media})


# ------------------------------------------------------------------ import and read back
def test_import_json_answers_detail_and_fk_matches_dh_product(client: TestClient) -> None:
    resp = client.post("/robots/dh", json=TABLE)
    assert resp.status_code == 201, resp.text
    assert resp.headers["location"] == "/robots/tiny"
    body = resp.json()
    assert body == client.get("/robots/tiny").json()
    assert (body["id"], body["source"], body["end_effector"]) == ("tiny", "dh", "tool")
    assert [j["name"] for j in body["joints"]] == ["base", "shoulder", "slide"]
    assert [j["type"] for j in body["joints"]] == ["revolute", "revolute", "prismatic"]
    assert body["joints"][1]["limits"]["lower"] == -2.0
    assert {f"dh_{i}" for i in range(4)} | {"tool"} <= {f["name"] for f in body["frames"]}
    listed = {r["id"]: r for r in client.get("/robots").json()["robots"]}
    assert listed["tiny"] == {
        "id": "tiny",
        "name": "tiny",
        "source": "dh",
        "joints": 3,
        "description": "RRP test arm",
    }
    for q in ([0.0, 0.0, 0.0], [0.7, -1.3, 0.25], [-2.9, 1.9, 0.4]):
        np.testing.assert_allclose(
            tool_matrix(client, "tiny", q), reference(TABLE["joints"], q), atol=1e-12
        )


@pytest.mark.parametrize("media", ["application/yaml", "text/yaml", "application/x-yaml"])
def test_import_yaml_in_mm_and_degrees(client: TestClient, media: str) -> None:
    resp = yaml_post(client, ARMAR_YAML, media)
    assert resp.status_code == 201, resp.text
    rows = yaml.safe_load(ARMAR_YAML)["joints"]
    q = [0.1, -0.2, 0.3, -0.4, 0.5, -0.6, 0.7]
    np.testing.assert_allclose(
        tool_matrix(client, "armar_copy", q),
        reference(rows, q, length=1e-3, angle=math.pi / 180),
        atol=1e-12,
    )


def test_get_dh_and_urdf(client: TestClient) -> None:
    client.post("/robots/dh", json=TABLE)
    table = client.get("/robots/tiny/dh")
    assert table.status_code == 200
    doc = table.json()
    assert doc["name"] == "tiny" and doc["units"] == {"length": "m", "angle": "rad"}
    assert [(j["a"], j["alpha"], j["d"], j["theta"]) for j in doc["joints"]] == [
        (j["a"], j["alpha"], j["d"], j["theta"]) for j in TABLE["joints"]
    ]
    as_yaml = client.get("/robots/tiny/dh", headers={"accept": "application/yaml"})
    assert as_yaml.headers["content-type"].startswith("application/yaml")
    assert yaml.safe_load(as_yaml.text) == doc
    # the document served is importable as is (under another name)
    assert client.post("/robots/dh", json={**doc, "name": "tiny2"}).status_code == 201
    urdf = client.get("/robots/tiny/urdf")
    assert urdf.status_code == 200 and urdf.headers["content-type"].startswith("application/xml")
    assert '<robot name="tiny">' in urdf.text and 'name="slide"' in urdf.text
    builtin = client.get("/robots/planar2/dh").json()
    assert builtin["name"] == "planar2" and len(builtin["joints"]) == 2
    assert "<robot" in client.get("/robots/planar2/urdf").text
    catalog = client.get("/robots/ur5/urdf")
    assert catalog.status_code == 200 and "shoulder_pan_joint" in catalog.text
    body = problem(client.get("/robots/ur5/dh"), 404, "robot_id")
    assert "not built from a DH table" in body["detail"] and "/robots/ur5/urdf" in body["detail"]
    problem(client.get("/robots/nope/dh"), 404, "robot_id")
    problem(client.get("/robots/nope/urdf"), 404, "robot_id")


# ------------------------------------------------------------------ conflicts and deletes
@pytest.mark.parametrize("taken", ["panda", "planar2"])
def test_builtin_ids_conflict(client: TestClient, settings: Settings, taken: str) -> None:
    before = snapshot(settings.data_dir)
    body = problem(client.post("/robots/dh", json={**TABLE, "name": taken}), 409, "name")
    assert "built-in" in body["detail"]
    assert snapshot(settings.data_dir) == before


def test_user_id_conflict_then_delete(client: TestClient, settings: Settings) -> None:
    assert client.post("/robots/dh", json=TABLE).status_code == 201
    problem(client.post("/robots/dh", json=TABLE), 409, "name")
    resp = client.delete("/robots/tiny")
    assert resp.status_code == 204 and resp.content == b""
    problem(client.get("/robots/tiny"), 404, "robot_id")
    problem(client.post("/robots/tiny/fk", json={"q": [0, 0, 0]}), 404, "robot_id")
    problem(client.delete("/robots/tiny"), 404, "robot_id")
    assert "tiny" not in {r["id"] for r in client.get("/robots").json()["robots"]}
    assert not [p for p in snapshot(settings.data_dir) if "tiny" in p]
    assert client.post("/robots/dh", json=TABLE).status_code == 201  # the id is free again


@pytest.mark.parametrize("builtin", ["panda", "planar2"])
def test_builtin_robots_cannot_be_deleted(client: TestClient, builtin: str) -> None:
    problem(client.delete(f"/robots/{builtin}"), 403, "robot_id")
    assert client.get(f"/robots/{builtin}").status_code == 200


def test_write_routes_need_the_token(tmp_path: Path) -> None:
    app = create_app(Settings(data_dir=tmp_path, api_token="s3cret"))
    with TestClient(app, raise_server_exceptions=False) as c:
        assert c.post("/robots/dh", json=TABLE).status_code == 401
        wrong = {"authorization": "Bearer nope"}
        assert c.post("/robots/dh", json=TABLE, headers=wrong).status_code == 403
        good = {"authorization": "Bearer s3cret"}
        assert c.post("/robots/dh", json=TABLE, headers=good).status_code == 201
        assert c.delete("/robots/tiny").status_code == 401
        assert c.delete("/robots/tiny", headers=wrong).status_code == 403
        assert c.get("/robots/tiny").status_code == 200  # reads stay open
        assert c.delete("/robots/tiny", headers=good).status_code == 204


# ------------------------------------------------------------------ restart, several workers
def test_robot_survives_restart(tmp_path: Path) -> None:
    settings = Settings(data_dir=tmp_path / "data")
    q = [0.4, 0.9, 0.12]
    with TestClient(create_app(settings)) as first:
        assert first.post("/robots/dh", json=TABLE).status_code == 201
        detail = first.get("/robots/tiny").json()
        pose = tool_matrix(first, "tiny", q)
    with TestClient(create_app(settings)) as second:
        assert second.get("/robots/tiny").json() == detail
        np.testing.assert_array_equal(tool_matrix(second, "tiny", q), pose)


def test_two_app_instances_share_the_data_dir(tmp_path: Path) -> None:
    settings = Settings(data_dir=tmp_path / "data")
    with (
        TestClient(create_app(settings), raise_server_exceptions=False) as a,
        TestClient(create_app(settings), raise_server_exceptions=False) as b,
    ):
        problem(b.get("/robots/tiny"), 404, "robot_id")  # b caches what it saw
        assert a.post("/robots/dh", json=TABLE).status_code == 201
        assert b.get("/robots/tiny").status_code == 200
        q = [0.1, 0.2, 0.3]
        np.testing.assert_array_equal(tool_matrix(b, "tiny", q), tool_matrix(a, "tiny", q))
        assert a.delete("/robots/tiny").status_code == 204
        problem(b.get("/robots/tiny"), 404, "robot_id")
        problem(b.post("/robots/tiny/fk", json={"q": q}), 404, "robot_id")
        assert "tiny" not in {r["id"] for r in b.get("/robots").json()["robots"]}
        # re-created through b with other rows: a serves the new robot
        two = {**TABLE, "joints": TABLE["joints"][:2]}
        assert b.post("/robots/dh", json=two).status_code == 201
        assert len(a.get("/robots/tiny").json()["joints"]) == 2
        problem(a.post("/robots/dh", json=TABLE), 409, "name")


# ------------------------------------------------------------------ bad and hostile input
def _row(**changes) -> dict:
    return {**TABLE, "joints": [{**TABLE["joints"][0], **changes}]}


def _without(key: str) -> dict:
    row = {k: v for k, v in TABLE["joints"][0].items() if k != key}
    return {**TABLE, "joints": [row]}


BAD_TABLES = {
    "unknown convention": ({**TABLE, "convention": "craig"}, "convention"),
    "unknown joint type": (_row(type="spherical"), "joints.0.type"),
    "unknown length unit": ({**TABLE, "units": {"length": "inch"}}, "units.length"),
    "unknown angle unit": ({**TABLE, "units": {"angle": "grad"}}, "units.angle"),
    "missing a": (_without("a"), "joints.0.a"),
    "missing alpha": (_without("alpha"), "joints.0.alpha"),
    "missing d": (_without("d"), "joints.0.d"),
    "missing theta": (_without("theta"), "joints.0.theta"),
    "lower > upper": (_row(lower=1.0, upper=-1.0), "joints.0.lower"),
    "no joints": ({**TABLE, "joints": []}, "joints"),
    "joints not a list": ({**TABLE, "joints": {"a": 1}}, "joints"),
    "string number": (_row(a="0,5"), "joints.0.a"),
    "boolean number": (_row(d=True), "joints.0.d"),
    "unknown field": ({**TABLE, "colour": "red"}, "colour"),
    "missing name": ({k: v for k, v in TABLE.items() if k != "name"}, "name"),
    "path in name": ({**TABLE, "name": "../../etc"}, "name"),
    "slash in name": ({**TABLE, "name": "a/b"}, "name"),
    "upper-case name": ({**TABLE, "name": "Tiny"}, "name"),
    "long name": ({**TABLE, "name": "x" * 65}, "name"),
    "base not 3 numbers": ({**TABLE, "base": {"xyz": [0, 0]}}, "base.xyz"),
    "too many rows": (
        {**TABLE, "joints": [{"a": 1, "alpha": 0, "d": 0, "theta": 0}] * 65},
        "joints",
    ),
}


@pytest.mark.parametrize("case", list(BAD_TABLES))
def test_bad_tables_422_naming_the_field(client: TestClient, settings: Settings, case: str) -> None:
    doc, field = BAD_TABLES[case]
    before = snapshot(settings.data_dir)
    problem(client.post("/robots/dh", json=doc), 422, field)
    assert snapshot(settings.data_dir) == before


@pytest.mark.parametrize(
    ("raw", "field"),
    [
        (json.dumps(_row(a=1.0)).replace("1.0", "NaN"), "joints.0.a"),
        (json.dumps(_row(alpha=1.0)).replace("1.0", "Infinity"), "joints.0.alpha"),
        (json.dumps(_row(d=1e308)).replace("1e+308", "1e999"), "joints.0.d"),
    ],
)
def test_non_finite_json_numbers(client: TestClient, settings: Settings, raw: str, field) -> None:
    before = snapshot(settings.data_dir)
    resp = client.post("/robots/dh", content=raw, headers={"content-type": "application/json"})
    problem(resp, 422, field)
    assert snapshot(settings.data_dir) == before


YAML_ROWS = "name: y1\nconvention: standard\njoints:\n"
BAD_YAML = {
    "nan": (YAML_ROWS + "  - {a: .nan, alpha: 0, d: 0, theta: 0}\n", 422, "joints.0.a"),
    "inf": (YAML_ROWS + "  - {a: 0, alpha: .inf, d: 0, theta: 0}\n", 422, "joints.0.alpha"),
    "deg unit typo": (
        "name: y1\nconvention: standard\nunits: {angle: degree}\njoints:\n"
        "  - {a: 0, alpha: 0, d: 0, theta: 0}\n",
        422,
        "units.angle",
    ),
    "alias bomb": (
        'a: &a ["x","x","x","x","x","x","x","x","x","x"]\nb: &b [*a,*a,*a,*a,*a,*a,*a,*a]\n'
        "c: &c [*b,*b,*b,*b,*b,*b,*b,*b]\nd: [*c,*c,*c,*c,*c,*c,*c,*c]\n",
        422,
        "body",
    ),
    "python tag": ("!!python/object/apply:os.system ['echo hi']\n", 400, "body"),
    "not yaml": ("name: [unclosed\n", 400, "body"),
    "duplicate key": (YAML_ROWS + "  - {a: 1, a: 2, alpha: 0, d: 0, theta: 0}\n", 400, "body"),
    "scalar document": ("just a string\n", 422, "body"),
    "deep nesting": ("[" * 20000 + "]" * 20000, 400, "body"),
    "deep block nesting": ("".join(" " * i + "k:\n" for i in range(40)), 400, "body"),
    "too many values": (YAML_ROWS + "  - {a: 1, alpha: 0, d: 0, theta: 0}\n" * 3000, 422, "body"),
}


@pytest.mark.parametrize("case", list(BAD_YAML))
def test_bad_yaml(client: TestClient, settings: Settings, case: str) -> None:
    text, status, field = BAD_YAML[case]
    before = snapshot(settings.data_dir)
    problem(yaml_post(client, text), status, field)
    assert snapshot(settings.data_dir) == before


@pytest.mark.parametrize(
    "raw",
    ["{not json", "[1, 2", "\xff\xfe", "[" * 100000 + "]" * 100000, '{"name": "a", "name": "b"}'],
)
def test_malformed_json_is_400(client: TestClient, settings: Settings, raw: str) -> None:
    before = snapshot(settings.data_dir)
    resp = client.post(
        "/robots/dh",
        content=raw.encode("latin-1"),
        headers={"content-type": "application/json"},
    )
    problem(resp, 400, "body")
    assert snapshot(settings.data_dir) == before


@pytest.mark.parametrize(
    "units", [{"length": {}}, {"angle": []}, {"length": ["mm"]}, {"length": 1}, {"angle": None}]
)
def test_odd_unit_values_are_422(client: TestClient, settings: Settings, units: dict) -> None:
    resp = client.post("/robots/dh", json={**TABLE, "units": units})
    assert resp.status_code == 422, resp.text
    assert resp.json()["field"] == f"units.{next(iter(units))}"
    assert snapshot(settings.data_dir / "robots") == []


def test_unsupported_media_type(client: TestClient) -> None:
    resp = client.post("/robots/dh", content=b"<x/>", headers={"content-type": "text/xml"})
    problem(resp, 415, "content-type")


def test_dh_documents_capped_at_256_kib(client: TestClient, settings: Settings) -> None:
    text = "# " + "x" * (256 * 1024) + "\n" + ARMAR_YAML
    problem(yaml_post(client, text), 413, "body")
    assert snapshot(settings.data_dir / "robots") == []


def test_upload_limit_413(tmp_path: Path) -> None:
    settings = Settings(data_dir=tmp_path / "data", max_upload_bytes=2048)
    big = {**TABLE, "description": "x" * 900, "joints": TABLE["joints"] * 10}
    with TestClient(create_app(settings), raise_server_exceptions=False) as c:
        problem(c.post("/robots/dh", json=big), 413, "body")

        def chunks():  # no Content-Length: the body is counted as it streams
            data = json.dumps(big).encode()
            for i in range(0, len(data), 512):
                yield data[i : i + 512]

        resp = c.post("/robots/dh", content=chunks(), headers={"content-type": "application/json"})
        problem(resp, 413, "body")
        assert c.post("/robots/dh", json=TABLE).status_code == 201  # small bodies pass
    assert snapshot(settings.data_dir / "robots")[-1].startswith("tiny")


def test_two_server_processes_share_the_data_dir(tmp_path: Path) -> None:
    """Two uvicorn processes (as two workers are): import via A, GET via B; delete, 404."""
    data = tmp_path / "data"
    with serve(data) as server_a, serve(data) as server_b:
        a, b = server_a.url, server_b.url
        assert httpx.get(f"{b}/robots/tiny").status_code == 404  # B looked before
        assert httpx.post(f"{a}/robots/dh", json=TABLE).status_code == 201
        q = {"q": [0.3, -0.2, 0.1]}
        via_b = httpx.post(f"{b}/robots/tiny/fk", json=q)
        assert via_b.status_code == 200
        assert via_b.json() == httpx.post(f"{a}/robots/tiny/fk", json=q).json()
        assert httpx.delete(f"{a}/robots/tiny").status_code == 204
        assert httpx.post(f"{b}/robots/tiny/fk", json=q).status_code == 404
        assert httpx.get(f"{b}/robots/tiny").status_code == 404


_json_values = st.recursive(
    st.none() | st.booleans() | st.integers() | st.floats() | st.text(max_size=8),
    lambda inner: (
        st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=6), inner, max_size=3)
    ),
    max_leaves=6,
)
_numbers = st.floats(allow_nan=False, allow_infinity=False, width=64) | st.integers(-1000, 1000)
_row = st.fixed_dictionaries(
    {"a": _numbers, "alpha": _numbers, "d": _numbers, "theta": _numbers},
    optional={
        "type": st.sampled_from(["revolute", "prismatic", "continuous", "ball", 3]),
        "lower": _numbers | _json_values,
        "upper": _numbers | _json_values,
        "name": st.text(max_size=10) | _json_values,
        "velocity": _numbers,
    },
)
_doc = st.fixed_dictionaries(
    {
        "name": st.just("fuzz"),
        "convention": st.sampled_from(["standard", "modified", "dh"]),
        "joints": st.lists(_row | _json_values, max_size=4),
    },
    optional={
        "units": st.fixed_dictionaries(
            {}, optional={"length": st.sampled_from(["m", "mm", "ft"]), "angle": _json_values}
        ),
        "base": _json_values,
        "tool": st.fixed_dictionaries({"xyz": st.lists(_numbers, max_size=4)}),
    },
)


_FUZZ: dict[str, tuple[TestClient, Path]] = {}


def _fuzz_client(factory: pytest.TempPathFactory) -> tuple[TestClient, Path]:
    """One app for every example (building an app per example is slow)."""
    if "client" not in _FUZZ:
        data = factory.mktemp("fuzz")
        app = create_app(Settings(data_dir=data))
        client = TestClient(app, raise_server_exceptions=False)
        client.__enter__()  # the lifespan runs (its stores and pools) until the process ends
        _FUZZ["client"] = (client, data)
    return _FUZZ["client"]


@hsettings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(doc=_doc)
def test_fuzzed_tables_never_500(tmp_path_factory: pytest.TempPathFactory, doc: dict) -> None:
    c, data = _fuzz_client(tmp_path_factory)
    raw = json.dumps(doc)
    resp = c.post("/robots/dh", content=raw, headers={"content-type": "application/json"})
    assert resp.status_code in (201, 400, 422), resp.text
    if resp.status_code == 201:
        assert c.get("/robots/fuzz/dh").status_code == 200
        assert c.delete("/robots/fuzz").status_code == 204
    assert not (data / "robots" / "fuzz").exists()


@pytest.mark.parametrize("reserved", ["dh", "urdf", "package"])
def test_import_route_names_are_reserved(client: TestClient, reserved: str) -> None:
    body = problem(client.post("/robots/dh", json={**TABLE, "name": reserved}), 422, "name")
    assert "reserved" in body["detail"]
    assert client.get(f"/robots/{reserved}").status_code == 405


def test_allow_headers(client: TestClient) -> None:
    for path in ("/robots/dh", "/robots/urdf"):
        for method in ("GET", "PUT", "DELETE", "OPTIONS"):
            resp = client.request(method, path)
            assert (resp.status_code, resp.headers["allow"]) == (405, "POST"), (method, path)
    for method in ("POST", "PUT", "PATCH", "OPTIONS"):
        resp = client.request(method, "/robots/planar2")
        assert resp.status_code == 405 and resp.headers["allow"] == "GET, HEAD, DELETE"


@pytest.mark.parametrize("media", ["application/json", "application/yaml"])
def test_byte_order_mark_is_accepted(client: TestClient, media: str) -> None:
    text = json.dumps(TABLE) if media == "application/json" else yaml.safe_dump(TABLE)
    resp = client.post(
        "/robots/dh", content=b"\xef\xbb\xbf" + text.encode(), headers={"content-type": media}
    )
    assert resp.status_code == 201, resp.text


def test_start_after_a_crash_serves_no_half_robot(tmp_path: Path) -> None:
    """Leftovers of a crash mid-write are cleaned when the app starts; complete robots stay."""
    settings = Settings(data_dir=tmp_path / "data")
    with TestClient(create_app(settings)) as first:
        assert first.post("/robots/dh", json=TABLE).status_code == 201
    robots_dir = settings.data_dir / "robots"
    half = robots_dir / ".tmp-3f9a2c"  # files being written when the process died
    half.mkdir()
    (half / "robot.urdf").write_text("<robot name='half'><link")
    orphan = robots_dir / "orphan"  # a robot directory without its metadata
    orphan.mkdir()
    (orphan / "robot.urdf").write_text("<robot/>")
    (robots_dir / ".tmp-gen123").write_bytes(b"4")  # an interrupted counter update
    with TestClient(create_app(settings), raise_server_exceptions=False) as again:
        ids = {r["id"] for r in again.get("/robots").json()["robots"]}
        assert "tiny" in ids and "orphan" not in ids
        problem(again.get("/robots/orphan"), 404, "robot_id")
        assert again.get("/robots/tiny").status_code == 200
    left = snapshot(robots_dir)
    assert not [p for p in left if p.startswith((".tmp-", "orphan"))], left
