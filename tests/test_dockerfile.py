"""The Dockerfile's shape, parsed from the file: linted by hadolint, the locked install,
the kernel cache built for the installed copy, the user, the entry shared with `make run`.

Building and running it for real is CI's container check (.ci/run → `make
container-check`: podman build, run, health, FK, uid, HEALTHCHECK, first IK from the
cache, DH import to /data, graceful stop, /data across restarts).
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from tests.dockerfile import BUILD, DOCKERFILE, FINAL, STAGES, exec_form, parse

ROOT = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent


def test_hadolint_passes() -> None:
    done = subprocess.run(
        [str(BIN / "hadolint"), str(DOCKERFILE)], capture_output=True, text=True, timeout=60
    )
    assert done.returncode == 0, done.stdout + done.stderr


def test_image_shape() -> None:
    assert len(STAGES) >= 2, "multi-stage build"
    for stage in STAGES:
        assert re.fullmatch(r"python:3\.11-slim(-\w+)?", stage.base), stage.base
    assert any(a.startswith("--from=") for a in FINAL.all("COPY")), "final stage copies a build"
    user = FINAL.all("USER")
    assert user and user[-1].split(":")[0] not in {"root", "0"}, "runs as a non-root user"
    assert FINAL.all("EXPOSE") == ["8000"]
    env = FINAL.env()
    assert env["DENAVIT_HOST"] == "0.0.0.0" and env["DENAVIT_PORT"] == "8000"
    assert int(env["DENAVIT_WORKERS"]) >= 1
    volumes = [v for arg in FINAL.all("VOLUME") for v in exec_form(arg)]
    assert env["DENAVIT_DATA_DIR"] in volumes, "the data directory is a volume"
    health = FINAL.all("HEALTHCHECK")
    assert len(health) == 1
    assert exec_form(health[0].split(" CMD ", 1)[1]) == ["python", "-m", "app", "healthcheck"]


def test_image_and_make_run_share_the_entry() -> None:
    assert exec_form(FINAL.all("CMD")[-1]) == ["python", "-m", "app"]
    makefile = (ROOT / "Makefile").read_text()
    run = re.search(r"^run:.*\n((?:\t.*\n)+)", makefile, re.M)
    assert run and "-m app" in run[1]
    assert "DENAVIT_HOST=$(HOST)" in run[1] and "DENAVIT_PORT=$(PORT)" in run[1]


def test_dependencies_come_from_the_runtime_lock() -> None:
    installs = [cmd for cmd in BUILD.all("RUN") if "pip install" in cmd]
    assert len(installs) == 2, installs
    locked, project = installs
    # Exactly the hash-checked lock, nothing resolved; then the project alone.
    assert re.search(r"pip install --no-deps --require-hashes -r /src/requirements\.lock$", locked)
    assert re.search(r"pip install --no-deps --no-build-isolation /src(\s|$)", project)
    copied = [arg.split()[0] for arg in BUILD.all("COPY")]
    assert copied[0] == "requirements.lock", "the lock layer comes first (cached)"
    pins = re.findall(
        r'^\s+"([A-Za-z0-9_.\[\]-]+)([=<>!~]=?)', (ROOT / "pyproject.toml").read_text(), re.M
    )
    assert pins and all(op == "==" for _, op in pins), "every dependency is pinned with =="


def test_both_stages_have_the_openmp_runtime() -> None:
    for stage in (BUILD, FINAL):
        assert any(
            "apt-get install" in cmd and "libgomp1" in cmd.split() for cmd in stage.all("RUN")
        ), f"libgomp1 missing in the stage FROM {stage.base}"


def test_kernel_cache_is_built_for_the_installed_package() -> None:
    """The warm-up imports the site-packages copy (no /src left, not run from it) and a
    second process must load every kernel from the cache; the runtime reads that cache."""
    runs = BUILD.all("RUN")
    project = next(i for i, cmd in enumerate(runs) if "pip install --no-deps --no-build" in cmd)
    assert "rm -rf /src" in runs[project]
    warm = [cmd for cmd in runs if "-m app warm-up" in cmd]
    assert warm and "--require-cache" in warm[-1]
    workdirs = BUILD.all("WORKDIR")
    assert workdirs and not workdirs[-1].startswith("/src")
    cache = BUILD.env()["NUMBA_CACHE_DIR"]
    assert FINAL.env()["NUMBA_CACHE_DIR"] == cache
    assert BUILD.env()["NUMBA_CPU_NAME"] == FINAL.env()["NUMBA_CPU_NAME"] == "generic"
    assert any(a.startswith("--from=build") and f" {cache} " in a for a in FINAL.all("COPY"))


def test_user_and_group_10001_are_named() -> None:
    setup = " ".join(FINAL.all("RUN"))
    assert re.search(r"groupadd [^&]*--gid 10001 denavit", setup)
    assert re.search(r"useradd [^&]*--uid 10001 --gid denavit", setup)
    assert FINAL.all("USER")[-1] == "10001:10001"


def test_dockerignore_keeps_the_build_context_small() -> None:
    ignored = (ROOT / ".dockerignore").read_text().split()
    for entry in (".git", ".venv", "data", "tests"):
        assert entry in ignored
    copied = [arg.split()[:-1] for arg in BUILD.all("COPY")]
    for sources in copied:
        for src in sources:
            assert src not in ignored and (ROOT / src).exists(), src


@pytest.mark.parametrize(
    ("text", "stages", "cmd"),
    [
        ('FROM a AS b\nRUN x \\\n  && y\n# c\nFROM d\nCMD ["p"]\n', 2, ["p"]),
        ('FROM a\nENV A=1 \\\n    B="two words"\nCMD ["q", "r"]\n', 1, ["q", "r"]),
    ],
)
def test_parser(text, stages, cmd) -> None:
    parsed = parse(text)
    assert len(parsed) == stages
    assert exec_form(parsed[-1].all("CMD")[0]) == cmd
    if stages == 2:
        assert parsed[0].all("RUN") == ["x  && y"] and parsed[0].name == "b"
    else:
        assert parsed[0].env() == {"A": "1", "B": "two words"}
