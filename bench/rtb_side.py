"""Driving the Robotics Toolbox's ``ik_LM`` in the bench-only venv from the bench.

The toolbox needs another NumPy than the service, so it lives in ``.venv-bench`` (made by
``make bench`` from ``requirements-bench.lock``) and runs in one child process
(:mod:`bench.rtb_ik_lm`) for the whole bench: targets and seed go to it as ``.npz`` files,
its q and per-target times come back the same way, and the caller judges its answers with
its own independent check. ``DENAVIT_BENCH_PYTHON`` names the bench venv's interpreter
(default ``.venv-bench/bin/python``).
"""

from __future__ import annotations

import os
import subprocess
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
CHILD = Path(__file__).with_name("rtb_ik_lm.py")


def bench_python() -> Path:
    """The bench venv's interpreter."""
    return Path(os.environ.get("DENAVIT_BENCH_PYTHON", ROOT / ".venv-bench" / "bin" / "python"))


def kinematic_urdf(urdf_text: str) -> str:
    """The URDF without ``<visual>`` and ``<collision>`` (the toolbox's loader fails on
    ``package://`` meshes; kinematics do not need them)."""
    root = ET.fromstring(urdf_text)
    for link in root.iter("link"):
        for child in list(link):
            if child.tag in ("visual", "collision"):
                link.remove(child)
    return ET.tostring(root, encoding="unicode")


class IkLM:
    """One child process running ``ik_LM``; ``unavailable`` says why when it cannot run."""

    def __init__(self) -> None:
        self.unavailable: str | None = None
        self._dir = tempfile.TemporaryDirectory(prefix="denavit-rtb-")
        self._proc: subprocess.Popen[str] | None = None
        python = bench_python()
        if not python.exists():
            self.unavailable = f"no bench venv ({python}): `make bench` could not build it"
            return
        self._proc = subprocess.Popen(
            [str(python), str(CHILD)],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
        )

    def _ask(self, line: str) -> str:
        assert self._proc is not None and self._proc.stdin and self._proc.stdout
        self._proc.stdin.write(line + "\n")
        self._proc.stdin.flush()
        answer = self._proc.stdout.readline().strip()
        if not answer.startswith("ok"):
            raise RuntimeError(f"ik_LM child: {answer or 'exited'}")
        return answer

    def load(self, rid: str, urdf_text: str, frame: str) -> int | None:
        """Build the toolbox's chain to ``frame``: its joint count (None: unavailable)."""
        if self.unavailable is not None:
            return None
        path = Path(self._dir.name) / f"{rid}.urdf"
        path.write_text(kinematic_urdf(urdf_text))
        try:
            return int(self._ask(f"load {rid} {path} {frame}").split()[1])
        except (RuntimeError, OSError) as exc:
            self.unavailable = f"the toolbox did not start: {exc}"
            return None

    def solve(
        self, rid: str, T: np.ndarray, seed: np.ndarray, setting: str
    ) -> dict[str, np.ndarray]:
        """ik_LM on targets ``T`` (n × 4 × 4) from ``seed`` (the chain's joints): ``q``,
        ``success`` (its own claim), ``wall`` and ``cpu`` (s per target)."""
        src = Path(self._dir.name) / "in.npz"
        dst = Path(self._dir.name) / "out.npz"
        np.savez(src, T=T, seed=seed)
        self._ask(f"solve {rid} {src} {dst} {setting}")
        with np.load(dst) as out:
            return {k: out[k] for k in ("q", "success", "wall", "cpu")}

    def close(self) -> None:
        if self._proc is not None:
            self._proc.stdin.close()  # type: ignore[union-attr]
            try:
                self._proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self._proc.kill()
                self._proc.wait()
        self._dir.cleanup()
