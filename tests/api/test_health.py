"""GET /health (liveness) and GET /ready (readiness: data directory, catalog)."""

from __future__ import annotations

import shutil

from fastapi.testclient import TestClient

from app.main import create_app
from app.operations.settings import Settings


def test_health_is_ok(client) -> None:
    r = client.get("/health")
    assert r.status_code == 200
    assert r.json() == {"status": "ok"}


def test_ready_when_data_dir_and_catalog_are_fine(client, settings) -> None:
    r = client.get("/ready")
    assert r.status_code == 200, r.text
    assert r.json() == {"status": "ready", "checks": {"data_dir": "ok", "catalog": "ok"}}
    assert settings.data_dir.is_dir()
    assert not any(settings.data_dir.glob(".tmp-*"))  # the write probe cleans up


def test_ready_creates_a_missing_data_dir(tmp_path) -> None:
    app = create_app(Settings(data_dir=tmp_path / "later" / "data"))
    with TestClient(app) as c:
        shutil.rmtree(tmp_path / "later")
        assert c.get("/ready").status_code == 200
    assert (tmp_path / "later" / "data").is_dir()


def test_not_ready_when_the_data_dir_is_unusable(client, settings) -> None:
    shutil.rmtree(settings.data_dir)
    settings.data_dir.write_text("a file where the directory should be")
    r = client.get("/ready")
    assert r.status_code == 503
    assert r.headers["content-type"].startswith("application/problem+json")
    body = r.json()
    assert body["status"] == 503 and body["type"].endswith("/not-ready")
    assert body["checks"]["catalog"] == "ok"
    assert body["checks"]["data_dir"] != "ok"
    assert "data_dir" in body["detail"]
    assert client.get("/health").status_code == 200  # alive, just not ready


def test_not_ready_without_a_catalog(client, app) -> None:
    app.state.registry.catalog = {}
    r = client.get("/ready")
    assert r.status_code == 503
    assert r.json()["checks"] == {"data_dir": "ok", "catalog": "the robot catalog is empty"}


def test_not_ready_when_catalog_files_are_missing(client, app, tmp_path) -> None:
    entry = next(iter(app.state.registry.catalog.values()))
    broken = type(entry)(**{**entry.__dict__, "urdf": "../../nowhere/missing.urdf"})
    app.state.registry.catalog = {entry.id: broken}
    r = client.get("/ready")
    assert r.status_code == 503
    assert r.json()["checks"]["catalog"] == f"URDF files missing for {entry.id}"
