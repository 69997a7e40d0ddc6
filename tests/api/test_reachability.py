"""Routes under /robots/{id}/reachability: build jobs (progress, cancel), stored maps that
survive a restart, O(1) queries against the planar annulus, PNG slices, every bad input."""

from __future__ import annotations

import math
import struct
import time
import zlib

import httpx
import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.kinematics.models import RobotModel
from app.main import create_app
from app.operations.settings import Settings
from tests.helpers import poll_live, serve
from tests.kinematics.chains import L1, L2, planar2_urdf

ROBOT = "planar2_test"
BASE = f"/robots/{ROBOT}/reachability"
PLANAR_BUILD = {
    "voxel_size": 0.05,
    "bounds": {"min": [-1.6, -1.6, -0.025], "max": [1.6, 1.6, 0.025]},
    "orientation_divisions": 2,
    "rows": ["vx", "vy"],
    "samples": 60_000,
}


def add_planar(app, urdf: str | None = None) -> None:
    app.state.registry._cache[ROBOT] = RobotModel(ROBOT, urdf or planar2_urdf(), ee_frame="tip")


@pytest.fixture
def pc(client, app):
    add_planar(app)
    return client


def wait_job(client, job_id, timeout=60.0):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        j = client.get(f"{BASE}/jobs/{job_id}").json()
        if j["status"] not in ("queued", "running"):
            return j
        time.sleep(0.02)
    raise AssertionError(f"job {job_id} did not finish")


def build(client, body=None):
    r = client.post(BASE, json=body or PLANAR_BUILD)
    assert r.status_code == 202, r.text
    assert r.headers["location"].endswith(r.json()["job_id"])
    j = wait_job(client, r.json()["job_id"])
    assert j["status"] == "done", j
    return j


def annulus_points():
    """Points well inside (r from 0.45 to 1.35) and well outside the annulus 0.3 ≤ r ≤ 1.5."""
    rng = np.random.default_rng(0)
    ang = rng.uniform(-math.pi, math.pi, 200)
    r_in = rng.uniform(abs(L1 - L2) + 0.15, L1 + L2 - 0.15, 100)
    r_out = np.concatenate([rng.uniform(0, abs(L1 - L2) - 0.08, 50), rng.uniform(1.58, 2, 50)])
    r = np.concatenate([r_in, r_out])
    pts = np.stack([r * np.cos(ang), r * np.sin(ang), np.zeros(200)], 1)
    return pts, np.arange(200) < 100


def test_build_query_annulus(pc):
    j = build(pc)
    assert j["progress"]["percent"] == 100.0 and j["progress"]["samples_done"] == 60_000
    map_id = j["map_id"]
    pts, inside = annulus_points()
    r = pc.post(f"{BASE}/query", json={"map_id": map_id, "positions": pts.tolist()})
    assert r.status_code == 200, r.text
    b = r.json()
    reach = np.array(b["reachable"])
    assert reach[inside].all() and not reach[~inside].any()
    assert all(b["in_bounds"][i] for i in range(100))
    w = np.array([v if v is not None else np.nan for v in b["manipulability"]])
    assert np.all(w[inside] <= L1 * L2 + 1e-6)
    assert np.all(np.isnan(w[~inside]))
    # with orientations: the tip's orientation is Rz(θ1 + θ2), whose quaternion's largest
    # component is z or w; upside down (π about x: the x face of the bins) is never reached
    tilted = [1.0, 0.0, 0.0, 0.0]
    r = pc.post(
        f"{BASE}/query",
        json={
            "map_id": map_id,
            "poses": [
                {"position": [1.0, 0.3, 0.0]},
                {"position": [1.0, 0.3, 0.0], "orientation": tilted},
                {"position": [0.0, 0.0, 5.0], "orientation": [0, 0, 0, 1]},
            ],
        },
    )
    assert r.json()["reachable"] == [True, False, False]
    assert r.json()["in_bounds"] == [True, True, False]


def test_query_pose_orientation_in_plane(pc):
    """At r = l1 + l2 − ε the arm is stretched: tip yaw = atan2(y, x). That bin is reached."""
    j = build(pc)
    yaw = 0.7
    rr = L1 + L2 - 0.04
    pos = [rr * math.cos(yaw), rr * math.sin(yaw), 0.0]
    q_ok = [0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)]
    yaw_bad = yaw + math.pi / 2
    q_bad = [0.0, 0.0, math.sin(yaw_bad / 2), math.cos(yaw_bad / 2)]
    r = pc.post(
        f"{BASE}/query",
        json={
            "map_id": j["map_id"],
            "positions": [pos, pos],
            "orientations": [q_ok, q_bad],
        },
    )
    assert r.json()["reachable"] == [True, False]


def test_maps_survive_restart(pc, settings):
    j = build(pc)
    app2 = create_app(settings)  # a new process on the same data dir
    add_planar(app2)
    with TestClient(app2, raise_server_exceptions=False) as c2:
        maps = c2.get(f"{BASE}/maps").json()["maps"]
        assert [m["map_id"] for m in maps] == [j["map_id"]]
        m = maps[0]
        assert m["shape"] == [64, 64, 1] and m["orientation_bins"] == 32
        assert m["joints"] == ["j1", "j2"] and m["reachable_voxels"] > 1000
        one = c2.get(f"{BASE}/maps/{j['map_id']}").json()
        assert one == m
        r = c2.post(f"{BASE}/query", json={"map_id": j["map_id"], "positions": [[1.0, 0.3, 0.0]]})
        assert r.json()["reachable"] == [True]
    assert not list(settings.data_dir.rglob(".tmp-*"))


def png_pixels(data: bytes) -> np.ndarray:
    """Decode an 8-bit RGB PNG with filter 0 (what the service writes)."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, w, h = 8, b"", 0, 0
    while pos < len(data):
        (n,) = struct.unpack(">I", data[pos : pos + 4])
        kind = data[pos + 4 : pos + 8]
        body = data[pos + 8 : pos + 8 + n]
        (crc,) = struct.unpack(">I", data[pos + 8 + n : pos + 12 + n])
        assert crc == zlib.crc32(kind + body) & 0xFFFFFFFF
        if kind == b"IHDR":
            w, h, depth, colour = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and colour == 2
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    rows = [raw[r * (3 * w + 1) : (r + 1) * (3 * w + 1)] for r in range(h)]
    assert all(row[0] == 0 for row in rows)
    return np.array([list(row[1:]) for row in rows], dtype=np.uint8).reshape(h, w, 3)


def pixel(lower: float, upper: float, value: float, scale: int, flip: bool = False) -> int:
    """Pixel index (column, or row with ``flip``: row 0 is the top, the largest value) of the
    centre of the voxel holding ``value``, voxels of 0.05 m from ``lower`` to ``upper``."""
    n = round((upper - lower) / 0.05)
    i = math.floor((value - lower) / 0.05)
    return ((n - 1 - i) if flip else i) * scale + scale // 2


def test_slice_png(pc, app):
    """Orientation of the image against the geometry: the planar arm's base is moved to
    (0.625, 0.325), so the unreachable hole of its annulus (r < |l1 − l2| = 0.2) lies off
    every axis of symmetry of the image. Columns: x (z slice) or y (x slice) increasing to
    the right; rows: y (z slice) or z (x slice) increasing upwards (row 0 at the top)."""
    cx, cy = 0.625, 0.325
    add_planar(app, planar2_urdf(base_xyz=(cx, cy, 0.0)))
    j = build(pc)
    grey = (235, 235, 235)
    r = pc.get(f"{BASE}/maps/{j['map_id']}/slice.png", params={"z": 0.0, "scale": 2})
    assert r.status_code == 200 and r.headers["content-type"] == "image/png"
    img = png_pixels(r.content)
    assert img.shape == (128, 128, 3)

    def at(x: float, y: float) -> tuple[int, ...]:
        return tuple(img[pixel(-1.6, 1.6, y, 2, flip=True), pixel(-1.6, 1.6, x, 2)])

    assert at(cx, cy) == grey  # the hole
    # its mirror images (left-right, up-down, both, transposed) are well inside the annulus
    for x, y in ((-cx, cy), (cx, -cy), (-cx, -cy), (cy, cx)):
        assert math.hypot(x - cx, y - cy) > 0.4 and at(x, y) != grey, (x, y)
    assert at(cx - 1.0, cy) != grey and at(cx - 1.9, cy) == grey  # r = 1.0; r = 1.9 > 1.8
    # an x slice through the hole: columns are y, one row (z)
    r = pc.get(f"{BASE}/maps/{j['map_id']}/slice.png", params={"x": cx, "scale": 2})
    img = png_pixels(r.content)
    assert img.shape == (2, 128, 3)
    assert tuple(img[1, pixel(-1.6, 1.6, cy, 2)]) == grey
    assert tuple(img[1, pixel(-1.6, 1.6, -cy, 2)]) != grey
    r = pc.get(f"{BASE}/maps/{j['map_id']}/slice.png", params={"x": 0.5})
    assert r.status_code == 200 and png_pixels(r.content).shape[1] == 512


def test_progress_and_cancel(pc, settings):
    body = dict(PLANAR_BUILD, samples=200_000_000, orientation_divisions=0)
    r = pc.post(BASE, json=body)
    assert r.status_code == 202
    job_id = r.json()["job_id"]
    end = time.monotonic() + 60
    while True:
        j = pc.get(f"{BASE}/jobs/{job_id}").json()
        if j["progress"]["samples_done"] > 0 or time.monotonic() > end:
            break
        time.sleep(0.05)
    assert j["status"] == "running"
    p = j["progress"]
    assert 0 < p["percent"] < 100 and p["samples_per_second"] > 0 and p["eta_seconds"] > 0
    assert p["samples_total"] == 200_000_000
    listed = pc.get(f"{BASE}/jobs").json()["jobs"]
    assert [x["job_id"] for x in listed] == [job_id]
    r = pc.delete(f"{BASE}/jobs/{job_id}")
    assert r.status_code == 200
    j = wait_job(pc, job_id)
    assert j["status"] == "cancelled" and j["map_id"] is None
    assert pc.delete(f"{BASE}/jobs/{job_id}").status_code == 200  # idempotent
    assert pc.get(f"{BASE}/maps").json()["maps"] == []
    assert not list(settings.data_dir.rglob("*.npz"))


def test_corrupt_job_database_is_a_clear_503(pc, settings):
    """A job database that is not a database: every job route answers 503 problem details
    naming the file (no 500, no traceback); maps still answer; once it is gone, jobs work."""
    db = settings.data_dir / "maps" / "jobs.sqlite3"
    db.parent.mkdir(parents=True, exist_ok=True)
    db.write_bytes(b"garbage, not SQLite\n" * 100)
    for method, url in (
        ("POST", BASE),
        ("GET", f"{BASE}/jobs"),
        ("GET", f"{BASE}/jobs/{'a' * 32}"),
        ("DELETE", f"{BASE}/jobs/{'a' * 32}"),
    ):
        r = pc.request(method, url, json=PLANAR_BUILD if method == "POST" else None)
        assert r.status_code == 503, (method, url, r.text)
        assert r.headers["content-type"] == "application/problem+json"
        body = r.json()
        assert body["status"] == 503 and "jobs.sqlite3" in body["detail"]
        assert "Traceback" not in r.text
    assert pc.get(f"{BASE}/maps").status_code == 200
    db.unlink()
    build(pc, dict(PLANAR_BUILD, samples=2000))


def test_cancel_finished_job_conflicts_and_map_delete(pc):
    j = build(pc, dict(PLANAR_BUILD, samples=2000))
    r = pc.delete(f"{BASE}/jobs/{j['job_id']}")
    assert r.status_code == 409 and r.json()["field"] == "job_id"
    assert pc.delete(f"{BASE}/maps/{j['map_id']}").status_code == 204
    r = pc.get(f"{BASE}/maps/{j['map_id']}")
    assert r.status_code == 404 and r.json()["field"] == "map_id"


def test_changed_robot_model_conflicts(pc, app):
    j = build(pc, dict(PLANAR_BUILD, samples=2000))
    add_planar(app, planar2_urdf(l1=1.1))
    r = pc.post(f"{BASE}/query", json={"map_id": j["map_id"], "positions": [[1, 0, 0]]})
    assert r.status_code == 409 and r.json()["field"] == "map_id"


def test_write_routes_need_the_token(tmp_path):
    app = create_app(Settings(data_dir=tmp_path / "d", api_token="s3cret"))
    add_planar(app)
    with TestClient(app, raise_server_exceptions=False) as c:
        assert c.post(BASE, json=PLANAR_BUILD).status_code == 401
        bad = {"Authorization": "Bearer nope"}
        assert c.post(BASE, json=PLANAR_BUILD, headers=bad).status_code == 403
        ok = {"Authorization": "Bearer s3cret"}
        r = c.post(BASE, json=dict(PLANAR_BUILD, samples=1000), headers=ok)
        assert r.status_code == 202
        assert c.delete(f"{BASE}/jobs/{r.json()['job_id']}").status_code == 401
        wait_job(c, r.json()["job_id"])


@pytest.mark.parametrize(
    ("change", "field"),
    [
        ({"voxel_size": 0}, "voxel_size"),
        ({"voxel_size": -0.05}, "voxel_size"),
        ({"voxel_size": "big"}, "voxel_size"),
        ({"voxel_size": 0.0002}, "voxel_size"),  # too many cells
        ({"bounds": {"min": [0, 0, 0], "max": [1, 1, -1]}}, "bounds.max.2"),
        ({"bounds": {"min": [0, 0], "max": [1, 1, 1]}}, "bounds.min"),
        ({"bounds": {"min": [-1e308, 0, 0], "max": [1e308, 1, 1]}}, "voxel_size"),
        ({"orientation_divisions": 13}, "orientation_divisions"),
        ({"orientation_divisions": -1}, "orientation_divisions"),
        ({"samples": 0}, "samples"),
        ({"sampling": "halton"}, "sampling"),
        ({"self_collision": "yes"}, "self_collision"),
        ({"rows": ["vz", "vz"]}, "rows.1"),
        ({"part": "full"}, "rows"),
        ({"frame": "nope"}, "frame"),
        ({"frame": "base"}, "frame"),
        ({"colour": "red"}, "colour"),
    ],
)
def test_bad_build_requests(pc, change, field):
    r = pc.post(BASE, json=dict(PLANAR_BUILD, **change))
    assert 400 <= r.status_code < 500, r.text
    assert r.json()["field"] == field
    assert pc.get(f"{BASE}/jobs").json()["jobs"] == []


def test_bad_queries_and_unknown_ids(pc, app):
    j = build(pc, dict(PLANAR_BUILD, samples=2000))
    mid = j["map_id"]
    cases = [
        ({"map_id": "f" * 32, "positions": [[0, 0, 0]]}, 404, "map_id"),
        ({"map_id": "../x", "positions": [[0, 0, 0]]}, 404, "map_id"),
        ({"map_id": mid}, 422, "poses"),
        ({"map_id": mid, "poses": [], "positions": [[0, 0, 0]]}, 422, "poses"),
        ({"map_id": mid, "positions": []}, 422, "positions"),
        ({"map_id": mid, "positions": [[0, 0]]}, 422, "positions.0"),
        ({"map_id": mid, "positions": [[0, 0, 0]], "orientations": []}, 422, "orientations"),
        (
            {"map_id": mid, "positions": [[0, 0, 0]], "orientations": [[0, 0, 0, 2]]},
            422,
            "orientations.0",
        ),
        (
            {
                "map_id": mid,
                "poses": [
                    {"position": [0, 0, 0]},
                    {"position": [0, 0, 0], "orientation": [0, 0, 0, 0]},
                ],
            },
            422,
            "poses.1.orientation",
        ),
        ({"map_id": mid, "poses": [{"position": [0, 0, "x"]}]}, 422, "poses.0.position.2"),
    ]
    for body, status, field in cases:
        r = pc.post(f"{BASE}/query", json=body)
        assert r.status_code == status, (body, r.text)
        assert r.json()["field"] == field, (body, r.json())
    app.state.settings.max_batch = 2
    r = pc.post(f"{BASE}/query", json={"map_id": mid, "positions": [[0, 0, 0]] * 3})
    assert r.status_code == 422 and r.json()["field"] == "positions"
    for path, field in (
        (f"{BASE}/jobs/nope", "job_id"),
        (f"{BASE}/maps/{'a' * 32}", "map_id"),
        (f"{BASE}/maps/{'a' * 32}/slice.png?z=0", "map_id"),
        ("/robots/nope/reachability/maps", "robot_id"),
    ):
        r = pc.get(path)
        assert r.status_code == 404 and r.json()["field"] == field, path
    assert pc.delete(f"{BASE}/jobs/nope").json()["field"] == "job_id"
    for params, field in (
        ({}, "z"),
        ({"x": 0, "z": 0}, "z"),
        ({"z": 3.0}, "z"),
        ({"y": 9}, "y"),
        ({"x": 1e308}, "x"),
        ({"z": -1e308}, "z"),
        ({"y": "inf"}, "y"),
    ):
        r = pc.get(f"{BASE}/maps/{mid}/slice.png", params=params)
        assert r.status_code == 422 and r.json()["field"] == field, params
    r = pc.get(f"{BASE}/maps/{mid}/slice.png", params={"z": 0, "scale": 0})
    assert r.status_code == 422 and r.json()["field"] == "scale"


def test_query_body_errors(pc):
    j = build(pc, dict(PLANAR_BUILD, samples=2000))
    url = f"{BASE}/query"
    r = pc.post(url, content=b"{oops", headers={"content-type": "application/json"})
    assert r.status_code == 400 and r.json()["field"] == "body"
    r = pc.post(url, json={"map_id": j["map_id"], "positions": [[0, 0, True]]})
    assert r.status_code == 422 and r.json()["field"] == "positions.0.2"
    r = pc.post(url, json={"positions": [[0, 0, 0]]})
    assert r.status_code == 422 and r.json()["field"] == "map_id"
    r = pc.post(url, json={"map_id": j["map_id"], "positions": [[0, 0, 0]], "extra": 1})
    assert r.status_code == 422 and r.json()["field"] == "extra"


def test_registry_planar2_annulus(client):
    """The DH built-in planar2 (l1 = 1.0, l2 = 0.8): reachable iff 0.2 ≤ r ≤ 1.8."""
    body = {
        "voxel_size": 0.05,
        "bounds": {"min": [-2, -2, -0.025], "max": [2, 2, 0.025]},
        "orientation_divisions": 0,
        "samples": 60_000,
    }
    r = client.post("/robots/planar2/reachability", json=body)
    assert r.status_code == 202, r.text
    job_id = r.json()["job_id"]
    end = time.monotonic() + 60
    while (j := client.get(f"/robots/planar2/reachability/jobs/{job_id}").json())["status"] in (
        "queued",
        "running",
    ) and time.monotonic() < end:
        time.sleep(0.02)
    assert j["status"] == "done"
    ang = np.linspace(-math.pi, math.pi, 40, endpoint=False)
    pts = []
    for rr in (0.35, 1.0, 1.65, 0.08, 1.92):
        pts += [[rr * math.cos(a), rr * math.sin(a), 0.0] for a in ang]
    out = client.post(
        "/robots/planar2/reachability/query", json={"map_id": j["map_id"], "positions": pts}
    ).json()["reachable"]
    assert all(out[:120]) and not any(out[120:])


def test_too_many_active_builds(pc, app):
    app.state.services.jobs.max_active = 1
    first = pc.post(BASE, json=dict(PLANAR_BUILD, samples=200_000_000)).json()["job_id"]
    r = pc.post(BASE, json=PLANAR_BUILD)
    assert r.status_code == 409 and r.json()["field"] == "robot_id"
    pc.delete(f"{BASE}/jobs/{first}")
    assert wait_job(pc, first)["status"] == "cancelled"
    assert pc.post(BASE, json=dict(PLANAR_BUILD, samples=1000)).status_code == 202


def test_query_forms_agree(pc):
    j = build(pc)
    pts, _ = annulus_points()
    rng = np.random.default_rng(3)
    yaw = rng.uniform(-math.pi, math.pi, len(pts))
    quats = np.stack([0 * yaw, 0 * yaw, np.sin(yaw / 2), np.cos(yaw / 2)], 1)
    compact = pc.post(
        f"{BASE}/query",
        json={"map_id": j["map_id"], "positions": pts.tolist(), "orientations": quats.tolist()},
    ).json()
    poses = [
        {"position": p.tolist(), "orientation": q.tolist()} for p, q in zip(pts, quats, strict=True)
    ]
    fast = pc.post(f"{BASE}/query", json={"map_id": j["map_id"], "poses": poses}).json()
    poses[0] = {"position": pts[0].tolist()}  # mixed keys: forces full validation
    slow = pc.post(f"{BASE}/query", json={"map_id": j["map_id"], "poses": poses}).json()
    assert compact == fast
    assert slow["reachable"][1:] == fast["reachable"][1:]
    # The full pose an answer gives (rpy and matrix of the same yaw, written out here)
    full = []
    for p, y in zip(pts.tolist(), yaw.tolist(), strict=True):
        c, s = math.cos(y), math.sin(y)
        matrix = [[c, -s, 0.0, p[0]], [s, c, 0.0, p[1]], [0.0, 0.0, 1.0, p[2]], [0, 0, 0, 1.0]]
        quat = [0.0, 0.0, math.sin(y / 2), math.cos(y / 2)]
        full.append({"position": p, "orientation": quat, "rpy": [0.0, 0.0, y], "matrix": matrix})
    same = pc.post(f"{BASE}/query", json={"map_id": j["map_id"], "poses": full}).json()
    assert same == fast
    no_rotation = [{"matrix": f["matrix"]} for f in full[:1]] + [{"position": pts[1].tolist()}]
    r = pc.post(f"{BASE}/query", json={"map_id": j["map_id"], "poses": no_rotation})
    assert r.status_code == 200 and r.json()["reachable"][0] == fast["reachable"][0], r.text
    r = pc.post(f"{BASE}/query", json={"map_id": j["map_id"], "poses": [{"rpy": [0, 0, 0]}]})
    assert r.status_code == 422 and r.json()["field"] == "poses.0.position", r.text
    assert slow["manipulability"][1:] == fast["manipulability"][1:]
    poses = [{"position": [0, 0, 0], "orientation": [0, 0, 0, 1]}] * 2
    poses[1] = {"position": [0, 0, 0], "orientation": [0, 0, 0, 0]}
    r = pc.post(f"{BASE}/query", json={"map_id": j["map_id"], "poses": poses})
    assert r.status_code == 422 and r.json()["field"] == "poses.1.orientation"


def test_self_collision_build_over_http(client, app):
    """The self-collision hook through the API: folded configurations of a boxed planar arm
    are dropped (see the core test); a robot without collision geometry builds normally."""
    from tests.kinematics.chains import COLLIDING_URDF

    app.state.registry._cache["boxes"] = RobotModel("boxes", COLLIDING_URDF, ee_frame="tip")
    body = {
        "voxel_size": 0.1,
        "bounds": {"min": [-1.6, -1.6, -0.05], "max": [1.6, 1.6, 0.05]},
        "orientation_divisions": 0,
        "samples": 4000,
        "sampling": "grid",
    }
    maps = {}
    for mode in ("ignore", "convex"):
        r = client.post("/robots/boxes/reachability", json=dict(body, self_collision=mode))
        assert r.status_code == 202, r.text
        job_id = r.json()["job_id"]
        end = time.monotonic() + 60
        while (j := client.get(f"/robots/boxes/reachability/jobs/{job_id}").json())["status"] in (
            "queued",
            "running",
        ) and time.monotonic() < end:
            time.sleep(0.02)
        assert j["status"] == "done", j
        maps[mode] = j["map_id"]
    near = [[0.35 * math.cos(a), 0.35 * math.sin(a), 0.0] for a in np.linspace(0, 6, 12)]
    got = {
        mode: client.post(
            "/robots/boxes/reachability/query", json={"map_id": mid, "positions": near}
        ).json()["reachable"]
        for mode, mid in maps.items()
    }
    assert all(got["ignore"]) and not any(got["convex"])
    listed = client.get("/robots/boxes/reachability/maps").json()["maps"]
    assert sorted(m["self_collision"] for m in listed) == ["convex", "ignore"]


def finished(job: dict) -> bool:
    return job["status"] not in ("queued", "running")


def test_two_server_processes_share_build_jobs(tmp_path):
    """Two uvicorn processes (as two workers are) on one data dir: a build posted to A is
    polled, listed and queried through B; a long build on A is cancelled through B."""
    body = {
        "voxel_size": 0.05,
        "bounds": {"min": [-2, -2, -0.025], "max": [2, 2, 0.025]},
        "orientation_divisions": 0,
        "samples": 60_000,
    }
    base = "/robots/planar2/reachability"
    with serve(tmp_path / "data") as server_a, serve(tmp_path / "data") as server_b:
        a, b = server_a.url, server_b.url
        r = httpx.post(a + base, json=body, timeout=30)
        assert r.status_code == 202, r.text
        job_id = r.json()["job_id"]
        j = poll_live(f"{b}{base}/jobs/{job_id}", finished)
        assert j["status"] == "done" and j["progress"]["samples_done"] == 60_000, j
        assert poll_live(f"{a}{base}/jobs/{job_id}", finished) == j
        listed = httpx.get(f"{b}{base}/jobs", timeout=10).json()["jobs"]
        assert [x["job_id"] for x in listed] == [job_id]
        assert httpx.get(f"{b}{base}/maps/{j['map_id']}", timeout=10).status_code == 200
        # planar2 (l1 = 1.0, l2 = 0.8) reaches 0.2 ≤ r ≤ 1.8
        pts = [[1.0, 0.0, 0.0], [0.0, 1.5, 0.0], [0.05, 0.0, 0.0], [1.95, 0.0, 0.0]]
        q = httpx.post(
            f"{b}{base}/query", json={"map_id": j["map_id"], "positions": pts}, timeout=10
        )
        assert q.status_code == 200 and q.json()["reachable"] == [True, True, False, False]
        r = httpx.delete(f"{b}{base}/jobs/{job_id}", timeout=10)
        assert r.status_code == 409 and r.json()["field"] == "job_id"  # already done

        r = httpx.post(a + base, json=dict(body, samples=500_000_000), timeout=30)
        assert r.status_code == 202, r.text
        long_id = r.json()["job_id"]
        poll_live(f"{b}{base}/jobs/{long_id}", lambda j: j["status"] == "running")
        r = httpx.delete(f"{b}{base}/jobs/{long_id}", timeout=10)
        assert r.status_code == 200 and r.json()["job_id"] == long_id
        for server in (b, a):
            j = poll_live(f"{server}{base}/jobs/{long_id}", finished)
            assert j["status"] == "cancelled" and j["map_id"] is None, j
        assert httpx.delete(f"{b}{base}/jobs/{long_id}", timeout=10).status_code == 200
        maps = httpx.get(f"{b}{base}/maps", timeout=10).json()["maps"]
        assert [m["map_id"] for m in maps] == [j["map_id"] for j in listed]
        assert httpx.get(f"{b}{base}/jobs/{'0' * 32}", timeout=10).status_code == 404
