"""compose.yaml and its companions agree with the image and the app: the healthcheck is the
image's, /data is a named volume, the token comes from an env file kept out of git and of
the build context, and the Prometheus example scrapes a route the app serves.

Starting it for real is CI's `make compose-check` (podman-compose, deploy/compose-check.sh).
"""

from __future__ import annotations

import json
from pathlib import Path

import yaml

from app.operations.settings import Settings
from tests.dockerfile import FINAL, exec_form

ROOT = Path(__file__).resolve().parents[1]
COMPOSE = yaml.safe_load((ROOT / "compose.yaml").read_text())
SERVICE = COMPOSE["services"]["denavit"]


def test_service_runs_the_image_with_its_healthcheck() -> None:
    assert SERVICE["build"] == "." and SERVICE["image"] == "denavit"
    image_check = exec_form(FINAL.all("HEALTHCHECK")[0].split(" CMD ", 1)[1])
    assert SERVICE["healthcheck"]["test"] == ["CMD", *image_check]
    published = SERVICE["ports"][0].rsplit(":", 1)[1]
    assert published == FINAL.all("EXPOSE")[0] == FINAL.env()["DENAVIT_PORT"]


def test_data_is_a_named_volume() -> None:
    mounts = {m.split(":")[1]: m.split(":")[0] for m in SERVICE["volumes"]}
    data = FINAL.env()["DENAVIT_DATA_DIR"]
    assert mounts[data] in COMPOSE["volumes"], "a named volume, not a host path"


def test_token_comes_from_an_env_file_that_stays_private() -> None:
    assert SERVICE["env_file"] == ["${DENAVIT_ENV_FILE:-denavit.env}"]
    assert "DENAVIT_API_TOKEN" not in json.dumps(SERVICE.get("environment", {}))
    assert "denavit.env" in (ROOT / ".gitignore").read_text().split()
    assert "*.env" in (ROOT / ".dockerignore").read_text().split()
    example = (ROOT / "deploy" / "denavit.env.example").read_text().splitlines()
    keys = [line.split("=", 1)[0] for line in example if line and not line.startswith("#")]
    assert "DENAVIT_API_TOKEN" in keys
    fields = {f"DENAVIT_{name.upper()}" for name in Settings.model_fields}
    assert set(keys) <= fields, set(keys) - fields


def test_prometheus_example_scrapes_the_metrics_route() -> None:
    prometheus = COMPOSE["services"]["prometheus"]
    assert prometheus["profiles"] == ["metrics"], "not started unless asked for"
    config_mount = prometheus["volumes"][0].split(":")
    config = yaml.safe_load((ROOT / config_mount[0]).read_text())
    assert config_mount[1] in prometheus["command"][0]
    (job,) = config["scrape_configs"]
    (target,) = job["static_configs"][0]["targets"]
    host, port = target.split(":")
    assert host == "denavit" and port == FINAL.env()["DENAVIT_PORT"]
    openapi = json.loads((ROOT / "docs" / "openapi.json").read_text())
    assert "get" in openapi["paths"][job["metrics_path"]]
