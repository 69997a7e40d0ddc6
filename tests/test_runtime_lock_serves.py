"""The runtime lock (requirements.lock, what `make run` and the image install) is enough to
serve: `python -m app` runs with every package that only the development lock holds made
unimportable, and answers the main operations.

The packages of requirements-dev.lock that requirements.lock lacks (pytest, Playwright,
schemathesis, httpx, …) are blocked by a ``sitecustomize`` on ``PYTHONPATH``, in the server
and the processes it starts with its environment (uvicorn workers, map-build workers):
importing one raises ``ModuleNotFoundError`` as it would in `make run`'s venv
(``.venv-run``), so a service module that needs a development-only package fails here. The
bounded children of uploads run ``python -I`` (no ``PYTHONPATH``) and are not covered; the
image build (`make container-check`) checks the same lock for real, without the source
tree.
"""

from __future__ import annotations

import importlib.metadata
import time
from pathlib import Path

import httpx

from tests.helpers import serve
from tests.locks import DEV, RUNTIME, canonical, parse_lock
from tests.packages import zip_bytes

BLOCKER = '''"""Test-only: make the development-only packages unimportable (see its test)."""
import importlib.abc
import sys

BLOCKED = frozenset({blocked!r})


class _DevelopmentOnly(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if name.partition(".")[0] in BLOCKED:
            raise ModuleNotFoundError(f"No module named {{name!r}} (development lock only)",
                                      name=name)
        return None


sys.meta_path.insert(0, _DevelopmentOnly())
'''

TINY_URDF = (
    '<robot name="tiny"><link name="base"/><link name="l1"><collision><geometry>'
    '<box size="0.1 0.1 0.1"/></geometry></collision></link>'
    '<joint name="j" type="revolute"><parent link="base"/><child link="l1"/>'
    '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>'
)


def development_only_modules() -> set[str]:
    """Top-level modules whose every installed distribution is in the development lock
    only."""
    dev_only = set(parse_lock(DEV)) - set(parse_lock(RUNTIME))
    blocked = set()
    for module, dists in importlib.metadata.packages_distributions().items():
        if all(canonical(d) in dev_only for d in dists):
            blocked.add(module)
    return blocked


def test_development_only_packages_are_found() -> None:
    blocked = development_only_modules()
    assert {"pytest", "playwright", "schemathesis", "httpx", "hypothesis"} <= blocked
    # What the runtime lock leaves out of the dependencies' own ([tool.denavit.runtime-lock]):
    # toppra's matplotlib and the rest, so the server below serves (timing included) without.
    assert {"matplotlib", "PIL", "fontTools", "kiwisolver", "defusedxml"} <= blocked
    assert not {"app", "fastapi", "pinocchio", "numpy", "numba", "uvicorn"} & blocked


def test_the_runtime_lock_is_enough_to_serve(tmp_path: Path) -> None:
    site = tmp_path / "site"
    site.mkdir()
    (site / "sitecustomize.py").write_text(
        BLOCKER.format(blocked=sorted(development_only_modules()))
    )
    env = {"PYTHONPATH": str(site)}
    # IK answers with random_seed and max_iterations, whatever the machine's load.
    settings = {"workers": "1", "ik_max_timeout_ms": "1000000", "ik_max_request_s": "10000"}
    with serve(tmp_path / "data", settings=settings, env=env) as server:
        with httpx.Client(base_url=server.url, timeout=60) as c:
            assert c.get("/ready").status_code == 200
            assert len(c.get("/robots").json()["robots"]) >= 10
            assert c.get("/openapi.json").status_code == 200
            assert c.get("/docs").status_code == 200 and c.get("/viewer").status_code == 200
            fk = c.post("/robots/panda/fk", json={}).json()
            pose = fk["poses"]["panda_hand_tcp"]
            target = {"position": pose["position"], "orientation": pose["orientation"]}
            options = {"random_seed": 0, "max_iterations": 100_000, "timeout_ms": 1e6}
            ik = c.post("/robots/panda/ik", json={"target": target, **options})
            assert ik.status_code == 200 and ik.json()["status"] == "converged", ik.text
            ball = {"name": "b", "shape": "sphere", "radius": 0.05}
            ball["pose"] = {"position": [0.1, 0.0, 0.8]}
            hit = c.post("/robots/panda/collisions", json={"obstacles": [ball]})
            assert hit.status_code == 200 and hit.json()["environment_collision"], hit.text
            assert c.post("/robots/ur5/jacobian", json={}).status_code == 200
            # Timing imports toppra, whose matplotlib the runtime lock leaves out.
            start = [0.3, -1.1, 1.4, -0.6, 1.2, 0.4]
            tip = c.post("/robots/ur5/fk", json={"q": start}).json()["poses"]["tool0"]
            x, y, z = tip["position"]
            moved = {"position": [x, y + 0.05, z - 0.05], "orientation": tip["orientation"]}
            body = {"start": start, "waypoints": [moved], "random_seed": 0, "timing": {}}
            path = c.post("/robots/ur5/ik/path", json=body)
            assert path.status_code == 200, path.text
            assert path.json()["fraction"] == 1.0 and path.json()["timing"], path.text
            dh = c.get("/robots/puma560/dh")
            assert dh.status_code == 200, dh.text
            archive = zip_bytes({"robot.urdf": TINY_URDF.encode()})
            up = c.post(
                "/robots/package",
                data={"name": "tiny", "description": "robot.urdf"},
                files={"archive": ("p.zip", archive)},
            )
            assert up.status_code == 201, up.text
            job = c.post("/robots/planar2/reachability", json={"samples": 2000})
            assert job.status_code == 202, job.text
            done = _poll(c, job.headers["location"])
            assert done["status"] == "done", done
            query = {"map_id": done["map_id"], "positions": [[0.5, 0.0, 0.0]]}
            assert c.post("/robots/planar2/reachability/query", json=query).status_code == 200
            png = c.get(f"/robots/planar2/reachability/maps/{done['map_id']}/slice.png?z=0")
            assert png.status_code == 200 and png.content.startswith(b"\x89PNG")
            assert c.get("/metrics").status_code == 200
        assert "development lock only" not in server.log.read_text()


def _poll(c: httpx.Client, url: str) -> dict:
    end = time.monotonic() + 60  # a guard against a hang, not a speed limit
    while True:
        job = c.get(url).json()
        if job["status"] not in ("queued", "running") or time.monotonic() > end:
            return job
        time.sleep(0.05)
