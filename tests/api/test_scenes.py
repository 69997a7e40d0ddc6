"""POST/GET/DELETE /scenes: storage, persistence across restarts, auth, use in checks."""

from __future__ import annotations

import json

import pytest
from fastapi.testclient import TestClient

from app.main import create_app
from app.operations.settings import Settings

TABLE = {
    "name": "table",
    "shape": "box",
    "size": [0.6, 1.0, 0.05],
    "pose": {"position": [0.5, 0.0, 0.2], "orientation": [0, 0, 0, 1]},
}
POST = {"name": "post", "shape": "cylinder", "radius": 0.05, "length": 1.0}
SCENE = {"name": "bench-1", "description": "a table", "obstacles": [TABLE, POST]}


def _identity_pose(position: list[float]) -> dict:
    """The full answer pose (all four fields) of a translation ``position``."""
    matrix = [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0, 0, 0, 1.0]]
    for i in range(3):
        matrix[i][3] = position[i]
    return {
        "position": position,
        "orientation": [0.0, 0.0, 0.0, 1.0],
        "rpy": [0.0, 0.0, 0.0],
        "matrix": matrix,
    }


#: The table as answers show it: every pose field filled.
TABLE_OUT = {**TABLE, "pose": _identity_pose([0.5, 0.0, 0.2])}


def test_create_get_list_delete(client) -> None:
    r = client.post("/scenes", json=SCENE)
    assert r.status_code == 201, r.text
    stored = r.json()
    assert stored["name"] == "bench-1" and stored["description"] == "a table"
    assert stored["obstacles"][0] == TABLE_OUT
    assert stored["obstacles"][1]["pose"] == _identity_pose([0.0, 0.0, 0.0])
    assert client.get("/scenes/bench-1").json() == stored
    assert client.get("/scenes").json() == {
        "scenes": [{"name": "bench-1", "description": "a table", "obstacles": 2}]
    }
    r = client.delete("/scenes/bench-1")
    assert r.status_code == 204 and r.content == b""
    assert client.get("/scenes/bench-1").status_code == 404
    assert client.get("/scenes").json() == {"scenes": []}


def test_duplicate_name_is_409(client) -> None:
    assert client.post("/scenes", json=SCENE).status_code == 201
    r = client.post("/scenes", json={**SCENE, "obstacles": []})
    assert r.status_code == 409 and r.json()["field"] == "name"
    assert len(client.get("/scenes/bench-1").json()["obstacles"]) == 2


def test_file_on_disk_and_persisted_across_restart(settings) -> None:
    with TestClient(create_app(settings)) as c:
        assert c.post("/scenes", json=SCENE).status_code == 201
    path = settings.data_dir / "scenes" / "bench-1.json"
    assert json.loads(path.read_text())["obstacles"][0]["name"] == "table"
    with TestClient(create_app(settings)) as c:
        assert c.get("/scenes/bench-1").json()["obstacles"][0] == TABLE_OUT
        body = c.post("/robots/panda/collisions", json={"scene": "bench-1"}).json()
        assert body["environment_collision"] is True  # the post stands through the arm
        assert c.delete("/scenes/bench-1").status_code == 204
    with TestClient(create_app(settings)) as c:
        assert c.get("/scenes/bench-1").status_code == 404
    assert not path.exists()


def test_scene_in_collision_request_equals_inline(client) -> None:
    assert client.post("/scenes", json=SCENE).status_code == 201
    q = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785, 0.02]
    by_name = client.post(
        "/robots/panda/collisions", json={"q": q, "scene": "bench-1", "distances": True}
    ).json()
    inline = client.post(
        "/robots/panda/collisions",
        json={"q": q, "obstacles": SCENE["obstacles"], "distances": True},
    ).json()
    assert by_name == inline
    assert {p["b"] for p in by_name["pairs"] if p["kind"] == "environment"} == {"table", "post"}


@pytest.mark.parametrize(
    ("payload", "field"),
    [
        ({**SCENE, "name": "../etc"}, "name"),
        ({**SCENE, "name": ""}, "name"),
        ({**SCENE, "name": "x" * 65}, "name"),
        ({**SCENE, "obstacles": [TABLE, TABLE]}, "obstacles.1.name"),
        ({**SCENE, "obstacles": [{**TABLE, "size": [1, -1, 1]}]}, "obstacles.0.size.1"),
        ({**SCENE, "obstacles": [{**TABLE, "shape": "torus"}]}, "obstacles.0.shape"),
        ({"name": "a"}, "obstacles"),
        ({**SCENE, "extra": 1}, "extra"),
    ],
)
def test_bad_scenes_are_422_and_write_nothing(client, settings, payload, field) -> None:
    r = client.post("/scenes", json=payload)
    assert r.status_code == 422, r.text
    assert r.json()["field"] == field
    scenes = settings.data_dir / "scenes"
    assert not scenes.exists() or list(scenes.iterdir()) == []


def test_unknown_scene_is_404(client) -> None:
    for r in (client.get("/scenes/nope"), client.delete("/scenes/nope")):
        assert r.status_code == 404 and r.json()["field"] == "name"
    assert client.get("/scenes/..%2Fetc").status_code == 404


def test_write_routes_need_the_token(tmp_path) -> None:
    app = create_app(Settings(data_dir=tmp_path / "d", api_token="s3cret"))
    with TestClient(app) as c:
        assert c.post("/scenes", json=SCENE).status_code == 401
        bad = {"Authorization": "Bearer wrong"}
        assert c.post("/scenes", json=SCENE, headers=bad).status_code == 403
        ok = {"Authorization": "Bearer s3cret"}
        assert c.post("/scenes", json=SCENE, headers=ok).status_code == 201
        assert c.get("/scenes/bench-1").status_code == 200  # reads stay open
        assert c.delete("/scenes/bench-1").status_code == 401
        assert c.delete("/scenes/bench-1", headers=ok).status_code == 204


def test_corrupt_file_is_not_served(client, settings) -> None:
    assert client.post("/scenes", json=SCENE).status_code == 201
    (settings.data_dir / "scenes" / "bench-1.json").write_text("{not json")
    assert client.get("/scenes/bench-1").status_code == 404
    assert client.get("/scenes").json() == {"scenes": []}


def test_concurrent_creators_one_wins(tmp_path) -> None:
    """Threads on two stores sharing a directory (like two workers): exactly one create."""
    from concurrent.futures import ThreadPoolExecutor

    from app.kinematics.errors import ConflictError
    from app.storage.scenes import SceneStore

    stores = [SceneStore(tmp_path / "scenes") for _ in range(2)]

    def create(i: int) -> bool:
        try:
            stores[i % 2].create("race", [{**POST, "name": f"p{i}"}])
            return True
        except ConflictError:
            return False

    with ThreadPoolExecutor(8) as pool:
        wins = list(pool.map(create, range(16)))
    assert sum(wins) == 1
    winner = f"p{wins.index(True)}"
    assert [o.name for o in stores[0].get("race").obstacles] == [winner]
    assert [o.name for o in stores[1].get("race").obstacles] == [winner]
    assert sorted(p.name for p in (tmp_path / "scenes").iterdir()) == ["race.json"]
    stores[1].delete("race")
    assert stores[0].names() == []
