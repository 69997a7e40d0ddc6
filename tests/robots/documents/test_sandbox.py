"""The bounded child of untrusted parsing (app.robots.documents.sandbox), at its limits.

Valid meshes too big for the child's limits (here a 50 MB binary STL of a million random
triangles, which coal's loader takes seconds and ~700 MB to read): the child is killed at
its wall-clock limit, or runs out of its address space, and the upload gets a 422 naming
the file it was reading and the setting, with no child left behind.
"""

from __future__ import annotations

import os
import struct
from pathlib import Path

import numpy as np
import pytest

from app.kinematics.errors import InvalidInputError
from app.kinematics.meshes import MeshLimits
from app.robots.documents.mesh_check import check_meshes
from app.robots.documents.sandbox import PARSE_LIMITS, ChildLimits
from tests.helpers import descendants

UNBOUNDED_HEADERS = MeshLimits(10**9, 10**9)
URDF = (
    '<robot name="r"><link name="base"/><link name="l1"><visual><geometry>'
    '<mesh filename="package://p/m.stl"/></geometry></visual></link>'
    '<joint name="j" type="revolute"><parent link="base"/><child link="l1"/>'
    '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>'
)


@pytest.fixture(scope="module")
def big_stl(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A valid binary STL of a million random triangles (fixed seed), in package ``p``."""
    n = 1_000_000
    records = np.zeros(n, dtype=[("data", "<f4", (12,)), ("attr", "<u2")])
    records["data"] = np.random.default_rng(0).random((n, 12), dtype=np.float32)
    folder = tmp_path_factory.mktemp("sandbox") / "p"
    folder.mkdir()
    path = folder / "m.stl"
    path.write_bytes(b"\0" * 80 + struct.pack("<I", n) + records.tobytes())
    return path


def _children() -> set[int]:
    return {
        pid
        for pid in descendants(os.getpid())
        if b"sandbox_child" in Path(f"/proc/{pid}/cmdline").read_bytes()
    }


def _check(mesh: Path, limits: ChildLimits) -> InvalidInputError:
    dirs = [str(mesh.parent.parent)]
    with pytest.raises(InvalidInputError) as info:
        check_meshes(URDF, {"m.stl": mesh}, dirs, UNBOUNDED_HEADERS, limits, "archive")
    assert info.value.field == "archive"
    assert str(mesh.parent) not in info.value.message
    assert not _children(), "a child was left behind"
    return info.value


def test_a_long_read_is_killed_at_the_wall_clock_limit(big_stl: Path) -> None:
    limits = ChildLimits(2.5, 4 << 30, 1 << 20, "DENAVIT_PARSE_TIMEOUT_S", "M")
    message = _check(big_stl, limits).message
    assert "longer than 2.5 s while reading 'm.stl' (DENAVIT_PARSE_TIMEOUT_S)" in message


def test_a_read_beyond_the_memory_limit_ends_the_child(big_stl: Path) -> None:
    """The loader needs ~700 MB; the child may add 64 MiB to what it started with. The
    memory limit ends it, long before its (generous) clock."""
    limits = ChildLimits(600.0, 64 << 20, 1 << 20, "T", "DENAVIT_PARSE_MEMORY_BYTES")
    message = _check(big_stl, limits).message
    assert "while reading 'm.stl'" in message, message
    assert "DENAVIT_PARSE_MEMORY_BYTES" in message, message


def test_the_default_limits_name_their_settings() -> None:
    assert PARSE_LIMITS.timeout_setting == "DENAVIT_PARSE_TIMEOUT_S"
    assert PARSE_LIMITS.memory_setting == "DENAVIT_PARSE_MEMORY_BYTES"
