"""The robot store: atomic writes, crash recovery (kill -9), concurrent cleanup, change tokens."""

from __future__ import annotations

import fcntl
import os
import signal
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest

from app.kinematics.errors import ConflictError, InvalidInputError, UnknownNameError
from app.kinematics.models import RobotModel
from app.robots.registry import Registry
from app.storage.store import (
    GENERATION_FILE,
    META_FILE,
    PACKAGE_DIR,
    TMP_PREFIX,
    URDF_FILE,
    RobotStore,
    atomic_write_bytes,
    check_robot_id,
    remove_stale_temporaries,
)

ROOT = Path(__file__).resolve().parents[2]

URDF = b"""<robot name="r"><link name="a"/><link name="b"/>
<joint name="j" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>
<limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>"""

#: A subprocess importing the planar table below through the core registry.
IMPORT_SCRIPT = textwrap.dedent(
    """
    import sys, time
    from dh2urdf import DHTable
    from app.robots.registry import Registry
    import app.storage.store as store

    data_dir, mode = sys.argv[1], sys.argv[2]
    table = DHTable.from_dict({
        "name": "crashy", "convention": "standard",
        "joints": [{"a": 0.7, "alpha": 0, "d": 0, "theta": 0},
                   {"a": 0.4, "alpha": 0, "d": 0, "theta": 0}],
    })
    if mode != "complete":
        real = store._write_all
        def paused(fd, data):
            real(fd, data)
            print("mid-write", flush=True)
            if mode == "hang":
                time.sleep(600)
            sys.stdin.readline()  # mode "resume": wait for the parent's go
        store._write_all = paused
    Registry(data_dir).import_dh(table)
    print("imported", flush=True)
    time.sleep(600)
    """
)


def tree(root: Path) -> list[str]:
    """Every path under ``root`` (relative, sorted)."""
    return sorted(str(p.relative_to(root)) for p in root.rglob("*")) if root.exists() else []


def run_import(data_dir: Path, mode: str) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [sys.executable, "-c", IMPORT_SCRIPT, str(data_dir), mode],
        cwd=ROOT,
        env={**os.environ, "PYTHONPATH": str(ROOT)},
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        text=True,
    )


def wait_for(proc: subprocess.Popen[str], line: str) -> None:
    got = proc.stdout.readline().strip()
    assert got == line, f"subprocess said {got!r} (exit {proc.poll()})"


def kill9(proc: subprocess.Popen[str]) -> None:
    proc.send_signal(signal.SIGKILL)
    proc.wait(timeout=30)
    assert proc.returncode == -signal.SIGKILL


# ------------------------------------------------------------------ atomic files
def test_atomic_write_replaces_whole_file_and_leaves_no_temporary(tmp_path: Path) -> None:
    target = tmp_path / "sub" / "f.bin"
    atomic_write_bytes(target, b"old")
    atomic_write_bytes(target, b"new content")
    assert target.read_bytes() == b"new content"
    assert tree(tmp_path) == ["sub", "sub/f.bin"]


def test_stale_temporaries_removed_but_locked_ones_kept(tmp_path: Path) -> None:
    stale_file = tmp_path / f"{TMP_PREFIX}abc"
    stale_file.write_bytes(b"half")
    stale_dir = tmp_path / "robots" / f"{TMP_PREFIX}dir"
    stale_dir.mkdir(parents=True)
    (stale_dir / URDF_FILE).write_bytes(b"<robot")
    busy = tmp_path / f"{TMP_PREFIX}busy"
    busy.write_bytes(b"being written")
    keep = tmp_path / "scene.json"
    keep.write_bytes(b"{}")
    fd = os.open(busy, os.O_RDONLY)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)  # a writer (in this or another process) holds it
        assert remove_stale_temporaries(tmp_path) == 2
        assert tree(tmp_path) == [f"{TMP_PREFIX}busy", "robots", "scene.json"]
    finally:
        os.close(fd)
    assert remove_stale_temporaries(tmp_path) == 1
    assert tree(tmp_path) == ["robots", "scene.json"]


# ------------------------------------------------------------------ robot directories
def test_create_list_load_delete(tmp_path: Path) -> None:
    store = RobotStore(tmp_path / "robots")
    assert store.list() == {}
    t0 = store.token()
    made = store.create("arm-1", {"source": "upload", "joints": 1}, {URDF_FILE: URDF})
    assert made.meta["id"] == "arm-1" and len(made.revision) == 32
    t1 = store.token()
    assert t1 != t0
    loaded = store.load("arm-1")
    assert loaded is not None and loaded.meta == made.meta
    assert loaded.read_text(URDF_FILE) == URDF.decode()
    assert loaded.read_text("robot.srdf") is None
    assert list(store.list()) == ["arm-1"]
    assert tree(store.root) == [
        GENERATION_FILE,
        ".lock",
        "arm-1",
        f"arm-1/{META_FILE}",
        f"arm-1/{URDF_FILE}",
    ]
    store.delete("arm-1")
    assert store.token() not in (t0, t1)
    assert store.list() == {} and store.load("arm-1") is None
    assert tree(store.root) == [GENERATION_FILE, ".lock"]
    with pytest.raises(UnknownNameError):
        store.delete("arm-1")


def test_create_with_a_package_tree_and_staging_cleanup(tmp_path: Path) -> None:
    """A staged tree moves into the robot as files/; a failed write or a refused upload
    leaves no staging directory, and a staging directory a crash left is recovered."""
    store = RobotStore(tmp_path)
    with store.staging() as staging:
        (staging / "files" / "meshes").mkdir(parents=True)
        (staging / "files" / "meshes" / "a.stl").write_bytes(b"solid a")
        made = store.create("pkg", {"source": "package"}, {URDF_FILE: URDF}, staging / "files")
    assert (made.path / PACKAGE_DIR / "meshes" / "a.stl").read_bytes() == b"solid a"
    with pytest.raises(ValueError), store.staging() as staging:
        (staging / "x").write_bytes(b"partial")
        raise ValueError("refused")
    with store.staging() as staging:
        (staging / "files").mkdir()
        with pytest.raises(ConflictError):
            store.create("pkg", {"source": "package"}, {URDF_FILE: URDF}, staging / "files")
    assert not [p for p in tree(tmp_path) if TMP_PREFIX in p]
    (tmp_path / f"{TMP_PREFIX}crashed" / "files").mkdir(parents=True)  # unlocked: a crash
    assert store.recover() == 1
    assert not [p for p in tree(tmp_path) if TMP_PREFIX in p]
    store.delete("pkg")
    assert tree(tmp_path) == [GENERATION_FILE, ".lock"]


def test_create_conflict_keeps_first_and_leaves_no_temporary(tmp_path: Path) -> None:
    store = RobotStore(tmp_path)
    first = store.create("a", {"source": "upload"}, {URDF_FILE: URDF})
    with pytest.raises(ConflictError):
        store.create("a", {"source": "dh"}, {URDF_FILE: b"<robot/>"})
    assert store.load("a").meta == first.meta
    assert not [p for p in tree(tmp_path) if TMP_PREFIX in p]


@pytest.mark.parametrize("bad", ["", "A", "../x", "a/b", "a b", ".tmp-x", "x" * 65, "é", 3])
def test_robot_ids_are_checked(tmp_path: Path, bad: object) -> None:
    with pytest.raises(InvalidInputError) as err:
        check_robot_id(bad, "name")
    assert err.value.field == "name"
    with pytest.raises(InvalidInputError):
        RobotStore(tmp_path).create(bad, {}, {URDF_FILE: URDF})  # type: ignore[arg-type]
    assert tree(tmp_path) == []


def test_recover_removes_temporaries_and_incomplete_directories(tmp_path: Path) -> None:
    store = RobotStore(tmp_path)
    store.create("good", {"source": "upload"}, {URDF_FILE: URDF})
    half = tmp_path / f"{TMP_PREFIX}k2j3h4"  # a crash while the files were being written
    half.mkdir()
    (half / URDF_FILE).write_bytes(URDF[:40])
    (tmp_path / "nometa").mkdir()  # a robot directory without its metadata
    (tmp_path / "nometa" / URDF_FILE).write_bytes(URDF)
    (tmp_path / "nourdf").mkdir()
    (tmp_path / "nourdf" / META_FILE).write_text('{"id": "nourdf"}')
    (tmp_path / f"{TMP_PREFIX}deleted-old-123").mkdir()  # a crash in the middle of a delete
    token = store.token()
    assert store.recover() == 4
    assert store.token() != token  # other workers notice
    assert list(store.list()) == ["good"]
    assert not [p for p in tree(tmp_path) if TMP_PREFIX in p or "meta" in p or "nourdf" in p]


# ------------------------------------------------------------------ crashes of a real process
def test_robot_acknowledged_then_kill9_is_complete_on_restart(tmp_path: Path) -> None:
    proc = run_import(tmp_path, "complete")
    try:
        wait_for(proc, "imported")  # import_dh returned: the 201 would have gone out now
    finally:
        kill9(proc)
    reg = Registry(tmp_path)
    robot = reg.get("crashy")
    assert robot.source == "dh" and robot.joint_names == ["j1", "j2"]
    q = np.array([0.3, -1.1])
    pin_pose = _tool(robot, q)
    expected = [0.7 * np.cos(0.3) + 0.4 * np.cos(0.3 - 1.1), 0.7 * np.sin(0.3) + 0.4 * np.sin(-0.8)]
    np.testing.assert_allclose(pin_pose[:2, 3], expected, atol=1e-12)
    assert not [p for p in tree(tmp_path) if TMP_PREFIX in p]


def test_kill9_mid_write_leaves_no_half_robot(tmp_path: Path) -> None:
    proc = run_import(tmp_path, "hang")
    try:
        wait_for(proc, "mid-write")
        assert [p for p in tree(tmp_path / "robots") if p.startswith(TMP_PREFIX)]
    finally:
        kill9(proc)
    reg = Registry(tmp_path)  # start-up cleanup
    assert "crashy" not in reg.ids()
    assert set(tree(tmp_path / "robots")) <= {".lock", GENERATION_FILE}
    with pytest.raises(UnknownNameError):
        reg.get("crashy")


def test_start_up_cleanup_spares_a_write_in_progress(tmp_path: Path) -> None:
    proc = run_import(tmp_path, "resume")
    try:
        wait_for(proc, "mid-write")
        Registry(tmp_path)  # another worker starts while the write is under way
        assert remove_stale_temporaries(tmp_path) == 0
        assert [p for p in tree(tmp_path / "robots") if p.startswith(TMP_PREFIX)]
        while True:  # let every remaining write go (robot files, metadata, generation)
            proc.stdin.write("go\n")
            proc.stdin.flush()
            said = proc.stdout.readline().strip()
            if said != "mid-write":
                assert said == "imported"
                break
    finally:
        kill9(proc)
    assert Registry(tmp_path).get("crashy").n == 2
    assert not [p for p in tree(tmp_path) if TMP_PREFIX in p]


def _tool(robot: RobotModel, q: np.ndarray) -> np.ndarray:
    data = robot.data
    pin.framesForwardKinematics(robot.model, data, robot.to_pin(q))
    return data.oMf[robot.frame_id("tool")].homogeneous
