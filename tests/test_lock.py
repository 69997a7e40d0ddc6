"""The lock files (`make lock`): every package pinned with hashes, in step with pyproject.toml,
and the runtime lock a subset of the development lock at the same versions.

Whether they are up to date with PyPI is not tested (that needs the network); that they
agree with pyproject.toml's == pins and with each other is.
"""

from __future__ import annotations

import os
import re
import subprocess
import tomllib
from pathlib import Path

import pytest

from tests.locks import DEV, RUNTIME, canonical, parse_lock

ROOT = Path(__file__).resolve().parents[1]
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text())


def pins(requirements: list[str]) -> dict[str, str]:
    """{name: version} of == requirements (extras dropped); fails on any other operator."""
    out = {}
    for req in requirements:
        m = re.fullmatch(r"([A-Za-z0-9_.-]+)(\[[^\]]*\])?==([^\s;]+)", req.strip())
        assert m, f"not an == pin: {req!r}"
        out[canonical(m[1])] = m[3]
    return out


LOCKS = {path.name: parse_lock(path) for path in (RUNTIME, DEV)}


@pytest.mark.parametrize("name", sorted(LOCKS))
def test_every_entry_has_hashes(name) -> None:
    lock = LOCKS[name]
    assert len(lock) > 40
    for package, (_, hashes) in lock.items():
        assert hashes, f"{name}: {package} has no hash"


def test_runtime_lock_holds_the_runtime_pins_and_the_build_backend() -> None:
    lock = LOCKS[RUNTIME.name]
    wanted = pins(PYPROJECT["project"]["dependencies"])
    wanted |= pins(PYPROJECT["build-system"]["requires"])
    for package, version in wanted.items():
        assert package in lock, f"{package} missing from {RUNTIME.name}"
        assert lock[package][0] == version, f"{package}: lock {lock[package][0]} != {version}"


def test_dev_lock_holds_every_pin() -> None:
    lock = LOCKS[DEV.name]
    wanted = pins(PYPROJECT["project"]["dependencies"])
    wanted |= pins(PYPROJECT["project"]["optional-dependencies"]["test"])
    wanted |= pins(PYPROJECT["build-system"]["requires"])
    for package, version in wanted.items():
        assert package in lock and lock[package][0] == version, package


def test_runtime_lock_is_the_dev_lock_restricted() -> None:
    runtime, dev = LOCKS[RUNTIME.name], LOCKS[DEV.name]
    for package, (version, hashes) in runtime.items():
        assert package in dev, f"{package} is in the runtime lock only"
        assert dev[package][0] == version, f"{package}: {version} vs dev {dev[package][0]}"
        assert set(hashes) == set(dev[package][1]), package


def test_runtime_lock_leaves_out_test_tools_and_trimesh_extras() -> None:
    runtime = LOCKS[RUNTIME.name]
    for package in ("pytest", "hypothesis", "schemathesis", "uv", "ruff", "embreex", "shapely"):
        assert package not in runtime, package
    overrides = PYPROJECT["tool"]["uv"]["override-dependencies"]
    assert pins(overrides)["trimesh"] == runtime["trimesh"][0]


def test_make_install_uses_the_dev_lock() -> None:
    makefile = (ROOT / "Makefile").read_text()
    assert "LOCK     := requirements-dev.lock" in makefile
    recipe = re.search(r"^\$\(STAMP\):.*\n((?:\t.*\n)+)", makefile, re.M)
    assert recipe, "the install recipe"
    assert "pip install --quiet --no-deps --require-hashes -r $(LOCK)" in recipe[1]
    assert "--no-deps --no-build-isolation -e ." in recipe[1]


def test_make_run_installs_the_runtime_lock_only_in_its_own_venv() -> None:
    """What `make run` would do from scratch (``make -n -B``: printed, not run): the runtime
    lock and the project into ``.venv-run``, then ``python -m app`` from there; never the
    development lock or ``.venv`` (so `make run` and `make test` work in either order).
    tests/test_runtime_lock_serves.py checks that this lock is enough to serve."""
    # Not as a sub-make of `make test` (which would add "Entering directory" lines).
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MAKELEVEL", "MFLAGS")}
    out = subprocess.run(
        ["make", "-n", "-B", "run"], cwd=ROOT, capture_output=True, text=True, check=True, env=env
    ).stdout
    lines = out.splitlines()
    assert "requirements-dev.lock" not in out and ".venv/" not in out, out
    assert any(
        ".venv-run/bin/python -m pip install --quiet --no-deps --require-hashes "
        "-r requirements.lock" in line
        for line in lines
    ), out
    assert lines[-1].endswith(".venv-run/bin/python -m app"), out
