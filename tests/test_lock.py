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

from tests.locks import DEV, RUNTIME, canonical, parse_lock, parse_via

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
OMITTED = PYPROJECT["tool"]["denavit"]["runtime-lock"]


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


def test_the_omitted_packages_are_in_the_dev_lock_only() -> None:
    """[tool.denavit.runtime-lock]: each name a locked development package, none in the
    runtime lock, and the runtime lock's own header says `make lock` left each out."""
    runtime, dev = LOCKS[RUNTIME.name], LOCKS[DEV.name]
    header = RUNTIME.read_text().split("\n", 2)[1]
    for package in OMITTED["cut"] + OMITTED["with-cut"]:
        assert canonical(package) == package, package
        assert package in dev, f"{package} is not in {DEV.name}: nothing to omit"
        assert package not in runtime, f"{package} is still in {RUNTIME.name}"
        assert f"--no-emit-package={package}" in header, f"`make lock` does not omit {package}"
    assert "matplotlib" in OMITTED["cut"]


def test_each_cut_is_a_declared_dependency_of_a_runtime_package() -> None:
    """A `cut` package is required by a package the runtime lock keeps (toppra declares
    matplotlib): the lock leaves out a real dependency, on purpose."""
    runtime, via = LOCKS[RUNTIME.name], parse_via(DEV)
    for package in OMITTED["cut"]:
        assert via[package] & set(runtime), f"{package}: no runtime package requires it"


def test_omitted_with_the_cut_means_needed_by_nothing_kept() -> None:
    """A `with-cut` package is required only by omitted or development-only packages, and by
    at least one omitted one: nothing the runtime lock keeps declares it (else leaving it
    out would break that package)."""
    runtime, via = LOCKS[RUNTIME.name], parse_via(DEV)
    omitted = set(OMITTED["cut"]) | set(OMITTED["with-cut"])
    for package in OMITTED["with-cut"]:
        kept = via[package] & set(runtime)
        assert not kept, f"{package} is required by {sorted(kept)}, which the runtime lock keeps"
        assert via[package] & omitted, f"{package}: required by no omitted package"


def test_the_runtime_lock_holds_nothing_only_the_omitted_need() -> None:
    """Every runtime-lock entry is a direct runtime requirement (pyproject.toml's dependencies
    or the build backend) or required by another entry it keeps: leaving out a `cut` package
    leaves none of its own dependencies behind unlisted."""
    runtime, via = LOCKS[RUNTIME.name], parse_via(RUNTIME)
    direct = set(pins(PYPROJECT["project"]["dependencies"]))
    direct |= set(pins(PYPROJECT["build-system"]["requires"]))
    for package in runtime:
        assert package in direct or via[package] & set(runtime), (
            f"{package} is in {RUNTIME.name} for omitted packages only: add it to with-cut"
        )


def test_the_image_allowlist_names_runtime_packages_each_with_a_reason() -> None:
    """.ci/image-allowlist.txt (what the image keeps unimported; the container check fails on
    any other never-imported distribution): each line a runtime-lock package and a reason,
    none of them one the runtime lock omits."""
    runtime = LOCKS[RUNTIME.name]
    omitted = set(OMITTED["cut"]) | set(OMITTED["with-cut"])
    lines = (ROOT / ".ci" / "image-allowlist.txt").read_text().splitlines()
    entries = [line for line in lines if line.strip() and not line.startswith("#")]
    assert entries
    for line in entries:
        name, _, reason = line.partition("#")
        package = canonical(name.strip())
        assert package in runtime and package not in omitted, line
        assert len(reason.strip()) > 20, f"{package}: give the reason it stays"
