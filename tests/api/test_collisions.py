"""POST /robots/{id}/collisions, /collisions/batch, GET /robots/{id}/collision_pairs."""

from __future__ import annotations

import math

import pytest

from tests.helpers import problem
from tests.kinematics.reference import planar2_elbows

READY = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785, 0.02]
FOLDED = [0.638, -1.713, -2.25, -2.588, -0.848, 0.027, 2.491, 0.01]
BALL = {"name": "ball", "shape": "sphere", "radius": 0.1, "pose": {"position": [0.5, 0, 0.5]}}


def test_panda_ready_is_free(client) -> None:
    r = client.post("/robots/panda/collisions", json={"q": READY})
    assert r.status_code == 200, r.text
    body = r.json()
    assert body["in_collision"] is False
    assert body["self_collision"] is False and body["environment_collision"] is False
    assert body["pairs"] == [] and body["min_distance"] is None
    assert body["checked_pairs"] == len(client.get("/robots/panda").json()["collision_pairs"])


def test_panda_folded_reports_hand_and_base(client) -> None:
    for geometry in ("mesh", "convex"):
        r = client.post("/robots/panda/collisions", json={"q": FOLDED, "geometry": geometry})
        body = r.json()
        assert body["in_collision"] and body["self_collision"], body
        pair = next(p for p in body["pairs"] if (p["a"], p["b"]) == ("panda_link0", "panda_hand"))
        assert pair["kind"] == "self" and pair["in_collision"] and pair["distance"] <= 0.0


def test_joint_positions_map(client) -> None:
    names = [j["name"] for j in client.get("/robots/panda").json()["joints"]]
    body = client.post(
        "/robots/panda/collisions", json={"joint_positions": dict(zip(names, FOLDED, strict=True))}
    ).json()
    assert body["q"] == FOLDED and body["in_collision"]


def test_obstacle_toggles_verdict_and_is_named(client) -> None:
    planar = {"q": [0.0, 0.0]}
    far = {**BALL, "name": "rock", "pose": {"position": [0.5, 0.0, 0.3]}}
    r = client.post("/robots/planar2/collisions", json={**planar, "obstacles": [far]})
    assert r.status_code == 200, r.text
    assert r.json()["in_collision"] is False
    near = {**far, "pose": {"position": [0.5, 0.0, 0.12]}}
    body = client.post("/robots/planar2/collisions", json={**planar, "obstacles": [near]}).json()
    assert body["in_collision"] and body["environment_collision"] and not body["self_collision"]
    assert [(p["a"], p["b"], p["kind"]) for p in body["pairs"]] == [
        ("link_1", "rock", "environment")
    ]
    assert body["pairs"][0]["distance"] == pytest.approx(0.12 - 0.1 - 0.03, abs=1e-6)


def test_distances_and_witness_points(client) -> None:
    """Sphere above link 1 of planar2 at height h: distance h − 0.03 − r, points on z."""
    ball = {**BALL, "pose": {"position": [0.4, 0.0, 0.5]}}
    body = client.post(
        "/robots/planar2/collisions",
        json={"q": [0.0, math.pi / 2], "obstacles": [ball], "distances": True},
    ).json()
    pair = next(p for p in body["pairs"] if p["a"] == "link_1")
    assert pair["distance"] == pytest.approx(0.5 - 0.03 - 0.1, abs=1e-6)
    assert pair["point_a"] == pytest.approx([0.4, 0.0, 0.03], abs=1e-6)
    assert pair["point_b"] == pytest.approx([0.4, 0.0, 0.4], abs=1e-6)
    assert body["min_distance"] == min(p["distance"] for p in body["pairs"])
    distances = [p["distance"] for p in body["pairs"]]
    assert distances == sorted(distances)


def test_margin(client) -> None:
    ball = {**BALL, "pose": {"position": [0.4, 0.0, 0.2]}}  # clearance 0.07 m to link 1
    base = {"q": [0.0, 0.0], "obstacles": [ball], "geometry": "convex"}
    free = client.post("/robots/planar2/collisions", json={**base, "margin": 0.06}).json()
    hit = client.post("/robots/planar2/collisions", json={**base, "margin": 0.08}).json()
    assert not free["in_collision"] and hit["in_collision"]
    assert hit["pairs"][0]["distance"] == pytest.approx(0.07, abs=1e-6)


def test_many_obstacles_are_checked_off_the_loop(client) -> None:
    obstacles = [
        {"name": f"s{i}", "shape": "sphere", "radius": 0.05, "pose": {"position": [i, 5, 0]}}
        for i in range(20)
    ]
    obstacles.append({**BALL, "pose": {"position": [0.5, 0.0, 0.1]}})
    body = client.post(
        "/robots/planar2/collisions", json={"q": [0, 0], "obstacles": obstacles}
    ).json()
    assert [p["b"] for p in body["pairs"]] == ["ball"]


# ------------------------------------------------------------------------- bad obstacles
@pytest.mark.parametrize(
    ("obstacle", "field"),
    [
        ({"name": "x", "shape": "cone", "radius": 1}, "obstacles.0.shape"),
        ({"name": "x", "shape": "sphere", "radius": -0.1}, "obstacles.0.radius"),
        ({"name": "x", "shape": "sphere", "radius": 0}, "obstacles.0.radius"),
        ({"name": "x", "shape": "box", "size": [1, 0, 1]}, "obstacles.0.size.1"),
        ({"name": "x", "shape": "box", "size": [1, 1]}, "obstacles.0.size"),
        ({"name": "x", "shape": "box", "size": [1, 1, 1, 1]}, "obstacles.0.size"),
        ({"name": "x", "shape": "box"}, "obstacles.0.size"),
        ({"name": "x", "shape": "box", "size": [1, 1, 1], "radius": 1}, "obstacles.0.radius"),
        ({"name": "x", "shape": "cylinder", "radius": 1}, "obstacles.0.length"),
        ({"name": "x", "shape": "capsule", "radius": 1, "length": -2}, "obstacles.0.length"),
        ({"name": "x", "shape": "sphere"}, "obstacles.0.radius"),
        ({"name": "", "shape": "sphere", "radius": 1}, "obstacles.0.name"),
        ({"shape": "sphere", "radius": 1}, "obstacles.0.name"),
        ({"name": "x", "shape": "sphere", "radius": 1, "colour": "red"}, "obstacles.0.colour"),
        ({"name": "x", "shape": "sphere", "radius": "1"}, "obstacles.0.radius"),
        (
            {"name": "x", "shape": "sphere", "radius": 1, "pose": {"position": [0, 0]}},
            "obstacles.0.pose.position",
        ),
        (
            {"name": "x", "shape": "sphere", "radius": 1, "pose": {"orientation": [0, 0, 0, 2]}},
            "obstacles.0.pose.orientation",
        ),
        (
            {"name": "x", "shape": "sphere", "radius": 1, "pose": {"orientation": [0, 0, 0, 0]}},
            "obstacles.0.pose.orientation",
        ),
        ({"name": "x", "shape": "sphere", "radius": 1e300}, "obstacles.0.radius"),
        (
            {"name": "x", "shape": "sphere", "radius": 1, "pose": {"position": [0, -2e3, 0]}},
            "obstacles.0.pose.position.1",
        ),
    ],
)
def test_bad_obstacles_are_422_naming_the_field(client, obstacle: dict, field: str) -> None:
    r = client.post("/robots/panda/collisions", json={"obstacles": [obstacle]})
    problem(r, 422, field)


def test_nan_in_obstacle_is_rejected(client) -> None:
    raw = '{"obstacles": [{"name": "x", "shape": "box", "size": [1, NaN, 1]}]}'
    r = client.post(
        "/robots/panda/collisions", content=raw, headers={"content-type": "application/json"}
    )
    assert r.status_code in (400, 422), r.text
    assert r.json()["field"] in ("obstacles.0.size.1", "body")


def test_duplicate_obstacle_names(client) -> None:
    r = client.post("/robots/panda/collisions", json={"obstacles": [BALL, BALL]})
    body = problem(r, 422, "obstacles.1.name")
    assert "duplicate" in body["detail"]


@pytest.mark.parametrize(
    ("extra", "field"),
    [
        ({"margin": -0.1}, "margin"),
        ({"margin": "0.1"}, "margin"),
        ({"geometry": "voxels"}, "geometry"),
        ({"distances": "yes"}, "distances"),
        ({"q": [0.0] * 3}, "q"),
        ({"q": READY, "joint_positions": {}}, "q"),
        ({"joint_positions": {"nope": 1.0}}, "joint_positions.nope"),
        ({"scene": "s", "obstacles": [BALL]}, "scene"),
        ({"colour": 1}, "colour"),
        ({"q": READY[:7] + [1e300]}, "q.7"),
    ],
)
def test_bad_request_fields(client, extra: dict, field: str) -> None:
    r = client.post("/robots/panda/collisions", json=extra)
    assert r.status_code in (404, 422), r.text
    assert r.json()["field"] == field


def test_unknown_scene_is_422_and_unknown_robot_404(client) -> None:
    problem(client.post("/robots/panda/collisions", json={"scene": "nowhere"}), 422, "scene")
    problem(client.post("/robots/pandaa/collisions", json={}), 404, "robot_id")


# ---------------------------------------------------------------------------------- batch
def test_batch_per_configuration(client) -> None:
    r = client.post(
        "/robots/panda/collisions/batch",
        json={"configurations": [READY, FOLDED, READY], "obstacles": [BALL]},
    )
    assert r.status_code == 200, r.text
    body = r.json()
    assert body["count"] == 3
    assert body["self_collision"] == [False, True, False]
    singles = [
        client.post("/robots/panda/collisions", json={"q": q, "obstacles": [BALL]}).json()
        for q in (READY, FOLDED, READY)
    ]
    assert body["in_collision"] == [s["in_collision"] for s in singles]
    assert body["environment_collision"] == [s["environment_collision"] for s in singles]
    for got, single in zip(body["pairs"], singles, strict=True):
        assert sorted(map(tuple, got)) == sorted((p["a"], p["b"]) for p in single["pairs"])
    assert body["num_in_collision"] == sum(body["in_collision"])
    assert body["first_collision"] == body["in_collision"].index(True)
    assert "min_distance" not in body


def test_batch_with_distances(client) -> None:
    body = client.post(
        "/robots/panda/collisions/batch",
        json={"configurations": [READY, FOLDED], "distances": True, "geometry": "convex"},
    ).json()
    assert body["min_distance"][0] > 0 > body["min_distance"][1]
    assert body["first_collision"] == 1


@pytest.mark.parametrize(
    ("payload", "field"),
    [
        ({"configurations": []}, "configurations"),
        ({"configurations": [READY, [0.0]]}, "configurations.1"),
        ({"configurations": [READY], "margin": -1}, "margin"),
        (
            {"configurations": [READY], "obstacles": [{"name": "a", "shape": "x"}]},
            "obstacles.0.shape",
        ),
        ({}, "configurations"),
        ({"configurations": [READY, READY[:7] + [-2e4]]}, "configurations.1.7"),
    ],
)
def test_batch_bad_input(client, payload: dict, field: str) -> None:
    problem(client.post("/robots/panda/collisions/batch", json=payload), 422, field)


# ----------------------------------------------------------------------------- pair lists
def test_collision_pairs_route_and_robot_detail(client) -> None:
    r = client.get("/robots/panda/collision_pairs")
    assert r.status_code == 200
    body = r.json()
    detail = client.get("/robots/panda").json()
    assert body["pairs"] == detail["collision_pairs"]
    pairs = {frozenset(p) for p in body["pairs"]}
    # SRDF-disabled, adjacent and same-body pairs are absent; hand-base is checked.
    assert frozenset(("panda_link0", "panda_hand")) in pairs
    assert frozenset(("panda_leftfinger", "panda_rightfinger")) not in pairs
    assert frozenset(("panda_link6", "panda_link7")) not in pairs
    assert frozenset(("panda_link7", "panda_hand")) not in pairs
    assert body["srdf"] is True and "panda_hand" in body["links"]
    problem(client.get("/robots/nope/collision_pairs"), 404, "robot_id")


# ----------------------------------------------------------------- collision-aware IK
L1, L2 = 1.0, 0.8  # planar2


def _elbows(x: float, y: float) -> list[tuple[float, float]]:
    """Closed-form planar 2-link IK of planar2 (both elbows)."""
    return planar2_elbows(x, y, L1, L2)


def _segment_distance(p, a, b) -> float:
    ap, ab = [p[0] - a[0], p[1] - a[1]], [b[0] - a[0], b[1] - a[1]]
    t = max(0.0, min(1.0, (ap[0] * ab[0] + ap[1] * ab[1]) / (ab[0] ** 2 + ab[1] ** 2)))
    return math.hypot(ap[0] - t * ab[0], ap[1] - t * ab[1])


def test_collision_aware_ik_returns_the_other_elbow(client) -> None:
    x, y = 1.2, 0.6
    (blocked, free) = _elbows(x, y)
    elbow = [L1 * math.cos(blocked[0]), L1 * math.sin(blocked[0]), 0.0]
    rock = {"name": "rock", "shape": "sphere", "radius": 0.1, "pose": {"position": elbow}}
    # Precondition (closed form): the free elbow's links stay clear of the rock.
    free_elbow = (L1 * math.cos(free[0]), L1 * math.sin(free[0]))
    for a, b in (((0.0, 0.0), free_elbow), (free_elbow, (x, y))):
        assert _segment_distance(elbow, a, b) > 0.1 + 0.03 + 0.05
    request = {"target": {"position": [x, y, 0.0]}, "mode": "position", "num_solutions": 2}

    both = client.post("/robots/planar2/ik", json=request).json()
    assert both["success"] and len(both["solutions"]) == 2

    r = client.post(
        "/robots/planar2/ik",
        json={**request, "avoid_collisions": True, "obstacles": [rock], "timeout_ms": 500},
    )
    assert r.status_code == 200, r.text
    body = r.json()
    assert body["success"] and len(body["solutions"]) == 1
    q = body["solutions"][0]["q"]
    assert q == pytest.approx(list(free), abs=1e-6)
    check = client.post("/robots/planar2/collisions", json={"q": q, "obstacles": [rock]}).json()
    assert not check["in_collision"]


def test_collision_aware_ik_with_scene_and_no_free_solution(client) -> None:
    x, y = 1.2, 0.6
    walls = [
        {"name": f"w{i}", "shape": "sphere", "radius": 0.1, "pose": {"position": [ex, ey, 0]}}
        for i, (ex, ey) in enumerate(
            (L1 * math.cos(t1), L1 * math.sin(t1)) for t1, _ in _elbows(x, y)
        )
    ]
    assert client.post("/scenes", json={"name": "elbows", "obstacles": walls}).status_code == 201
    body = client.post(
        "/robots/planar2/ik",
        json={
            "target": {"position": [x, y, 0.0]},
            "mode": "position",
            "avoid_collisions": True,
            "scene": "elbows",
            "timeout_ms": 20,
        },
    ).json()
    assert body["success"] is False and body["solutions"] == []


def test_collision_aware_ik_batch(client) -> None:
    x, y = 1.2, 0.6
    blocked, free = _elbows(x, y)
    elbow = [L1 * math.cos(blocked[0]), L1 * math.sin(blocked[0]), 0.0]
    rock = {"name": "rock", "shape": "sphere", "radius": 0.1, "pose": {"position": elbow}}
    body = client.post(
        "/robots/planar2/ik/batch",
        json={
            "targets": [{"position": [x, y, 0.0]}],
            "mode": "position",
            "avoid_collisions": True,
            "obstacles": [rock],
            "timeout_ms": 500,
        },
    ).json()
    assert body["solved"] == 1
    assert body["results"][0]["q"] == pytest.approx(list(free), abs=1e-6)


@pytest.mark.parametrize(
    ("extra", "field"),
    [
        ({"obstacles": [BALL]}, "obstacles"),
        ({"scene": "x"}, "scene"),
        ({"avoid_collisions": True, "scene": "missing"}, "scene"),
        ({"avoid_collisions": True, "obstacles": [{**BALL, "radius": 0}]}, "obstacles.0.radius"),
        ({"avoid_collisions": True, "margin": -1}, "margin"),
        ({"avoid_collisions": "yes"}, "avoid_collisions"),
        ({"avoid_collisions": True, "collision_geometry": "voxel"}, "collision_geometry"),
    ],
)
def test_collision_aware_ik_bad_input(client, extra: dict, field: str) -> None:
    r = client.post(
        "/robots/planar2/ik",
        json={"target": {"position": [1.2, 0.6, 0]}, "mode": "position", **extra},
    )
    assert r.status_code in (404, 422), r.text
    assert r.json()["field"] == field


def test_robot_with_unloadable_meshes_is_422_not_500(client) -> None:
    """An uploaded URDF whose collision mesh is not available: refused at upload (a 201
    means collisions work), naming the mesh."""
    urdf = (
        '<robot name="m"><link name="a"><collision><geometry>'
        '<mesh filename="package://nowhere/a.stl"/></geometry></collision></link>'
        '<link name="b"/><joint name="j" type="revolute"><parent link="a"/><child link="b"/>'
        '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        "</robot>"
    )
    r = client.post("/robots/urdf", json={"name": "meshless", "urdf": urdf})
    body = problem(r, 422, "urdf")
    assert "nowhere/a.stl" in body["detail"]
    problem(client.get("/robots/meshless"), 404, "robot_id")
