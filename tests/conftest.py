"""Shared fixtures: an app on a temporary data directory, its client, the registry."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from fastapi.testclient import TestClient
from hypothesis import settings as hypothesis_settings

from app.main import create_app
from app.operations.settings import Settings
from app.robots.registry import Registry

# Property tests draw the same examples on every run (a fixed seed per test) and keep no
# example database: a run never depends on what an earlier run found.
hypothesis_settings.register_profile("deterministic", derandomize=True, database=None)
hypothesis_settings.load_profile("deterministic")


@pytest.fixture
def settings(tmp_path: Path) -> Settings:
    """Settings with a fresh, empty data directory."""
    return Settings(data_dir=tmp_path / "data")


@pytest.fixture
def app(settings: Settings):
    return create_app(settings)


@pytest.fixture
def client(app) -> Iterator[TestClient]:
    """A client that returns 500s as responses (so tests can assert there are none)."""
    with TestClient(app, raise_server_exceptions=False) as c:
        yield c


@pytest.fixture(scope="session")
def registry() -> Registry:
    """A registry for in-process (no HTTP) tests of the core."""
    return Registry()
