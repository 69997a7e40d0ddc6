"""The Dockerfile: linted by hadolint, and its install and run steps executed outside a
container (no Docker engine here): a fresh virtualenv, the build stage's RUN commands, then
the final stage's CMD with its ENV, until /health answers.

The steps are parsed from the Dockerfile, not copied: change the Dockerfile incompatibly
and this test breaks. Container paths (/opt/venv, /src, /data, ...) are mapped under a
temporary directory. To stay fast, the new virtualenv sees the project venv's
site-packages through a ``.pth`` file (so ``pip install .`` finds the pinned dependencies
already there and only builds and installs the project itself).
"""

from __future__ import annotations

import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig
from dataclasses import dataclass, field
from pathlib import Path

import httpx
import pytest

from tests.test_production import free_port, start_server

ROOT = Path(__file__).resolve().parents[1]
DOCKERFILE = ROOT / "Dockerfile"
BIN = Path(sys.executable).parent


@dataclass
class Stage:
    base: str
    name: str | None
    instructions: list[tuple[str, str]] = field(default_factory=list)

    def all(self, keyword: str) -> list[str]:
        return [arg for k, arg in self.instructions if k == keyword]

    def env(self) -> dict[str, str]:
        out: dict[str, str] = {}
        for arg in self.all("ENV"):
            for token in shlex.split(arg):
                key, _, value = token.partition("=")
                out[key] = value
        return out


def parse(text: str) -> list[Stage]:
    """Stages of a Dockerfile: (keyword, argument) per instruction, continuations joined."""
    logical: list[str] = []
    current = ""
    for raw in text.splitlines():
        line = raw.strip()
        if not current and (not line or line.startswith("#")):
            continue
        if current and line.startswith("#"):
            continue
        if line.endswith("\\"):
            current += line[:-1] + " "
            continue
        logical.append(current + line)
        current = ""
    stages: list[Stage] = []
    for line in logical:
        keyword, _, arg = line.partition(" ")
        keyword, arg = keyword.upper(), arg.strip()
        if keyword == "FROM":
            parts = arg.split()
            name = parts[2] if len(parts) == 3 and parts[1].upper() == "AS" else None
            stages.append(Stage(parts[0], name))
        else:
            stages[-1].instructions.append((keyword, arg))
    return stages


STAGES = parse(DOCKERFILE.read_text())
BUILD, FINAL = STAGES[0], STAGES[-1]


def exec_form(arg: str) -> list[str]:
    value = json.loads(arg)
    assert isinstance(value, list), f"use the exec (JSON) form: {arg}"
    return value


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


def test_dependencies_come_from_the_pyproject_pins() -> None:
    installs = [cmd for cmd in BUILD.all("RUN") if "pip install" in cmd]
    assert installs, "the build stage installs the project"
    for cmd in installs:
        assert re.search(r"pip install (--no-cache-dir )?\.(\s|$)", cmd), cmd
    pins = re.findall(
        r'^\s+"([A-Za-z0-9_.\[\]-]+)([=<>!~]=?)', (ROOT / "pyproject.toml").read_text(), re.M
    )
    assert pins and all(op == "==" for _, op in pins), "every dependency is pinned with =="


def test_dockerignore_keeps_the_build_context_small() -> None:
    ignored = (ROOT / ".dockerignore").read_text().split()
    for entry in (".git", ".venv", "data", "tests"):
        assert entry in ignored
    copied = [arg.split()[:-1] for arg in BUILD.all("COPY")]
    for sources in copied:
        for src in sources:
            assert src not in ignored and (ROOT / src).exists(), src


class Mapper:
    """Container absolute paths → the same paths under ``root``."""

    def __init__(self, root: Path, prefixes: set[str]) -> None:
        self.root = root
        alternatives = "|".join(re.escape(p) for p in sorted(prefixes, key=len, reverse=True))
        self.pattern = re.compile(rf"(?<![\w./-])({alternatives})(?=/|\b|$)")

    def __call__(self, text: str) -> str:
        return self.pattern.sub(lambda m: str(self.root) + m[1], text)


def _prefixes() -> set[str]:
    """Top-level directories of every absolute container path the Dockerfile names."""
    out = set()
    for stage in STAGES:
        for keyword, arg in stage.instructions:
            if keyword in {"WORKDIR", "COPY", "RUN", "VOLUME", "ENV"}:
                for path in re.findall(r"(?<![\w.$-])(/[A-Za-z0-9_.-]+)(?:/[^\s:\"',]*)?", arg):
                    if path not in {"/bin", "/usr", "/etc", "/dev", "/tmp"}:
                        out.add(path)
    return out


def _copy(src: Path, dest: Path) -> None:
    ignore = shutil.ignore_patterns("__pycache__", "*.pyc", "*.egg-info")
    if src.is_dir():
        shutil.copytree(src, dest, dirs_exist_ok=True, ignore=ignore)
    else:
        dest.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(src, dest)


def _run_stage(stage: Stage, mapper: Mapper, env: dict[str, str], venv_hook) -> Path:
    """Execute ``stage``'s WORKDIR/ENV/COPY/RUN steps outside a container; its workdir."""
    workdir = mapper.root
    for keyword, arg in stage.instructions:
        if keyword == "WORKDIR":
            workdir = Path(mapper(arg))
            workdir.mkdir(parents=True, exist_ok=True)
        elif keyword == "ENV":
            for token in shlex.split(arg):
                key, _, value = token.partition("=")
                env[key] = mapper(value).replace("$PATH", env["PATH"])
        elif keyword == "COPY" and not arg.startswith("--from="):
            *sources, dest = arg.split()
            target = Path(mapper(dest)) if dest.startswith("/") else workdir / dest
            for src in sources:
                name = Path(src).name
                _copy(ROOT / src, target / name if dest.endswith("/") else target)
        elif keyword == "RUN":
            done = subprocess.run(
                ["/bin/sh", "-c", mapper(arg)],
                cwd=workdir,
                env=env,
                capture_output=True,
                text=True,
                timeout=600,
            )
            assert done.returncode == 0, f"RUN {arg}\n{done.stdout[-3000:]}{done.stderr[-3000:]}"
            venv_hook()
    return workdir


def test_build_and_run_steps_outside_a_container(tmp_path) -> None:
    root = tmp_path / "root"
    mapper = Mapper(root, _prefixes())
    # `python` in the image is CPython 3.11: the same interpreter as this venv's.
    shims = tmp_path / "shims"
    shims.mkdir()
    base_python = Path(sys._base_executable)  # type: ignore[attr-defined]
    (shims / "python").symlink_to(base_python)
    env = {k: v for k, v in os.environ.items() if not k.upper().startswith(("DENAVIT_", "VIRTUAL"))}
    env["PATH"] = f"{shims}:/usr/local/bin:/usr/bin:/bin"
    env.pop("PYTHONPATH", None)
    main_site = sysconfig.get_paths()["purelib"]

    # One .pth line: add this venv's site-packages and run its .pth files (pin and coal
    # need theirs), except the editable install's, which would import the source tree.
    pth = (
        f"import sys; sys.path.append({main_site!r}); "
        f"[__import__('site').addpackage({main_site!r}, n, None) "
        f"for n in sorted(__import__('os').listdir({main_site!r})) "
        "if n.endswith('.pth') and not n.startswith('__editable__')]\n"
    )

    def link_dependencies() -> None:
        """Let each new venv see this venv's installed wheels (not its editable project)."""
        for site in root.glob("**/lib/python3*/site-packages"):
            (site / "_denavit_test_deps.pth").write_text(pth)

    _run_stage(BUILD, mapper, env, link_dependencies)
    # The IK kernels were compiled at build time into the cache the image ships.
    cache = Path(mapper(BUILD.env()["NUMBA_CACHE_DIR"]))
    assert cache.is_relative_to(root) and list(cache.rglob("*.nbi")), "no compiled IK kernels"

    final_env = {k: v for k, v in env.items() if k == "HOME" or k == "LANG"}
    final_env["PATH"] = "/usr/local/bin:/usr/bin:/bin"
    for stage_run in FINAL.all("RUN"):  # image set-up as root: the user and its data dir
        words = set(re.findall(r"[a-z]+", stage_run))
        assert words & {"useradd", "mkdir", "chown"}, (
            f"unexpected RUN in the final stage: {stage_run}"
        )
        assert "pip" not in words
    workdir = _run_stage(
        Stage(FINAL.base, None, [(k, a) for k, a in FINAL.instructions if k != "RUN"]),
        mapper,
        final_env,
        lambda: None,
    )
    # The installed project, not the source tree, is what runs.
    where = subprocess.run(
        ["python", "-c", "import app, pinocchio; print(app.__file__)"],
        cwd=workdir,
        env=final_env,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert where.returncode == 0, where.stderr
    assert where.stdout.strip().startswith(str(root)), where.stdout
    assert "site-packages" in where.stdout

    port = free_port()
    final_env |= {"DENAVIT_HOST": "127.0.0.1", "DENAVIT_PORT": str(port)}  # loopback only
    data_dir = Path(final_env["DENAVIT_DATA_DIR"])
    assert data_dir.is_relative_to(root)
    cmd = exec_form(FINAL.all("CMD")[-1])
    with start_server(cmd, final_env, port, cwd=workdir) as server:
        assert httpx.get(server.url + "/health").json() == {"status": "ok"}
        assert httpx.get(server.url + "/ready").status_code == 200
        fk = httpx.post(server.url + "/robots/ur5/fk", json={"q": [0.0] * 6}, timeout=60)
        assert fk.status_code == 200, fk.text
        health_cmd = exec_form(FINAL.all("HEALTHCHECK")[0].split(" CMD ", 1)[1])
        check = subprocess.run(
            health_cmd, cwd=workdir, env=final_env, capture_output=True, text=True, timeout=60
        )
        assert check.returncode == 0, check.stderr
        workers = {d.get("message") for d in server.log_lines()}
    assert (
        any(str(m).startswith("Started parent process") for m in workers)
        or int(final_env["DENAVIT_WORKERS"]) == 1
    )
    assert data_dir.is_dir()
    # And the health check fails once the server is gone.
    check = subprocess.run(
        health_cmd, cwd=workdir, env=final_env, capture_output=True, text=True, timeout=60
    )
    assert check.returncode == 1


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
