"""The registry: built-in DH robots, user robots from DH tables and URDF, several workers.

FK references are products of DH matrices written out here with NumPy (independent of
dh2urdf and Pinocchio).
"""

from __future__ import annotations

import math
import threading
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest
import yaml

import robots
from app.kinematics.errors import (
    ConflictError,
    ForbiddenError,
    InvalidInputError,
    UnknownNameError,
)
from app.kinematics.models import RobotModel
from app.robots.registry import Registry
from dh2urdf import DHTable


def dh_standard(a: float, alpha: float, d: float, theta: float) -> np.ndarray:
    """Rz(θ)·Tz(d)·Tx(a)·Rx(α), written out."""
    ct, st, ca, sa = math.cos(theta), math.sin(theta), math.cos(alpha), math.sin(alpha)
    return np.array(
        [
            [ct, -st * ca, st * sa, a * ct],
            [st, ct * ca, -ct * sa, a * st],
            [0, sa, ca, d],
            [0, 0, 0, 1],
        ]
    )


def dh_modified(a: float, alpha: float, d: float, theta: float) -> np.ndarray:
    """Rx(α)·Tx(a)·Rz(θ)·Tz(d) as the product of the four elementary transforms."""
    rx = np.eye(4)
    rx[1:3, 1:3] = [[math.cos(alpha), -math.sin(alpha)], [math.sin(alpha), math.cos(alpha)]]
    tx = np.eye(4)
    tx[0, 3] = a
    rz = np.eye(4)
    rz[0:2, 0:2] = [[math.cos(theta), -math.sin(theta)], [math.sin(theta), math.cos(theta)]]
    tz = np.eye(4)
    tz[2, 3] = d
    return rx @ tx @ rz @ tz


def frame_pose(robot: RobotModel, frame: str, q: np.ndarray) -> np.ndarray:
    data = robot.data
    pin.framesForwardKinematics(robot.model, data, robot.to_pin(q))
    return data.oMf[robot.frame_id(frame)].homogeneous


SMALL = {
    "name": "small",
    "convention": "standard",
    "joints": [
        {"a": 0.3, "alpha": -math.pi / 2, "d": 0.1, "theta": 0.2},
        {"type": "prismatic", "a": 0.05, "alpha": math.pi / 2, "d": 0.2, "theta": 0.0,
         "lower": 0.0, "upper": 0.5},
        {"a": 0.25, "alpha": 0.0, "d": 0.0, "theta": -0.4},
    ],
}  # fmt: skip


def small_reference(q: np.ndarray, rows: list[dict], fn=dh_standard) -> np.ndarray:
    T = np.eye(4)
    for row, value in zip(rows, q, strict=True):
        a, alpha, d, theta = row["a"], row["alpha"], row["d"], row["theta"]
        if row.get("type") == "prismatic":
            d += value
        else:
            theta += value
        T = T @ fn(a, alpha, d, theta)
    return T


# ------------------------------------------------------------------ built-in DH robots
def test_builtin_dh_robots_listed_without_building(tmp_path: Path) -> None:
    reg = Registry(tmp_path)
    tables = robots.dh_tables()
    assert tables, "robots/dh has tables"
    listed = {s.id: s for s in reg.summaries() if s.source == "dh"}
    assert set(listed) == set(tables)
    for rid, path in tables.items():
        rows = yaml.safe_load(path.read_text())["joints"]
        assert listed[rid].joints == len(rows)
        assert reg.cached(rid) is None  # nothing was built to list them
        assert reg.is_builtin(rid)


def test_builtin_planar2_tool_matches_closed_form(registry: Registry) -> None:
    robot = registry.get("planar2")
    assert robot.source == "dh" and robot.ee_frame == "tool"
    doc = yaml.safe_load(robots.dh_tables()["planar2"].read_text())
    l1, l2 = (row["a"] for row in doc["joints"])  # metres in this table
    for q in ([0.0, 0.0], [0.4, -1.2], [2.5, 3.0]):
        T = frame_pose(robot, "tool", np.array(q))
        x = l1 * math.cos(q[0]) + l2 * math.cos(q[0] + q[1])
        y = l1 * math.sin(q[0]) + l2 * math.sin(q[0] + q[1])
        np.testing.assert_allclose(T[:3, 3], [x, y, 0.0], atol=1e-12)


def test_registry_without_data_dir_serves_builtins_only() -> None:
    reg = Registry()
    assert "planar2" in reg.ids() and "panda" in reg.ids()
    with pytest.raises(ForbiddenError):
        reg.import_dh(DHTable.from_dict(SMALL))
    with pytest.raises(UnknownNameError):
        reg.get("small")


# ------------------------------------------------------------------ user-added robots
@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_imported_table_fk_is_product_of_dh_matrices(tmp_path: Path, convention: str) -> None:
    doc = {**SMALL, "convention": convention}
    reg = Registry(tmp_path)
    robot = reg.import_dh(DHTable.from_dict(doc))
    assert robot.source == "dh" and robot.ee_frame == "tool" and robot.n == 3
    fn = dh_standard if convention == "standard" else dh_modified
    rng = np.random.default_rng(7)
    for _ in range(20):
        q = np.array([rng.uniform(-3, 3), rng.uniform(0, 0.5), rng.uniform(-3, 3)])
        np.testing.assert_allclose(
            frame_pose(robot, "tool", q), small_reference(q, doc["joints"], fn), atol=1e-12
        )
        np.testing.assert_allclose(
            frame_pose(robot, "dh_2", q),
            small_reference(q[:2], doc["joints"][:2], fn),
            atol=1e-12,
        )


def test_user_robot_survives_restart_with_same_fk(tmp_path: Path) -> None:
    first = Registry(tmp_path)
    first.import_dh(DHTable.from_dict(SMALL))
    q = np.array([0.3, 0.2, -0.7])
    before = frame_pose(first.get("small"), "tool", q)
    again = Registry(tmp_path)
    summary = {s.id: s for s in again.summaries()}["small"]
    assert (summary.source, summary.joints) == ("dh", 3)
    assert again.cached("small") is None
    np.testing.assert_array_equal(frame_pose(again.get("small"), "tool", q), before)
    table = again.dh_table("small")
    assert table == DHTable.from_dict(SMALL)


def test_conflicts_and_deletes(tmp_path: Path) -> None:
    reg = Registry(tmp_path)
    for taken in ("panda", "planar2"):
        with pytest.raises(ConflictError):
            reg.import_dh(DHTable.from_dict({**SMALL, "name": taken}))
    reg.import_dh(DHTable.from_dict(SMALL))
    with pytest.raises(ConflictError):
        reg.import_dh(DHTable.from_dict(SMALL))
    for builtin in ("panda", "planar2"):
        with pytest.raises(ForbiddenError):
            reg.delete(builtin)
    reg.delete("small")
    with pytest.raises(UnknownNameError):
        reg.get("small")
    with pytest.raises(UnknownNameError):
        reg.delete("small")


def test_import_dh_refuses_more_than_64_rows_and_stores_nothing(tmp_path: Path) -> None:
    """A table built in Python (not through parse_dh_document) meets the same row limit."""
    reg = Registry(tmp_path)
    row = {"a": 0.1, "alpha": 0.0, "d": 0.0, "theta": 0.0}
    table = DHTable.from_dict({**SMALL, "joints": [dict(row) for _ in range(65)]})
    with pytest.raises(InvalidInputError) as err:
        reg.import_dh(table)
    assert err.value.field == "joints" and "at most 64 rows, got 65" in err.value.message
    assert not reg.exists("small")


def test_two_workers_share_the_data_directory(tmp_path: Path) -> None:
    a, b = Registry(tmp_path), Registry(tmp_path)
    assert "small" not in b.ids()  # b has looked at the (empty) directory
    a.import_dh(DHTable.from_dict(SMALL))
    q = np.array([0.1, 0.1, 0.1])
    assert frame_pose(b.get("small"), "tool", q) == pytest.approx(
        frame_pose(a.get("small"), "tool", q), abs=0
    )
    assert b.cached("small") is not None
    a.delete("small")
    assert b.cached("small") is None
    with pytest.raises(UnknownNameError):
        b.get("small")
    # same id again, different table: b serves the new robot, not its old cached model
    a.import_dh(DHTable.from_dict({**SMALL, "joints": SMALL["joints"][:2]}))
    assert b.get("small").n == 2
    assert [s.joints for s in b.summaries() if s.id == "small"] == [2]


def test_urdf_upload_checks_before_storing(tmp_path: Path) -> None:
    reg = Registry(tmp_path)
    urdf = reg.urdf_text("planar2")
    robot = reg.add_urdf("copy", urdf, ee_frame="tool", description="planar2 again")
    assert robot.source == "upload" and robot.n == 2
    assert reg.dh_table("copy") is None
    with pytest.raises(InvalidInputError) as err:
        reg.add_urdf("other", urdf, ee_frame="nope")
    assert err.value.field == "ee_frame"
    with pytest.raises(InvalidInputError) as err:
        reg.add_urdf("other", urdf.replace('type="revolute"', 'type="fixed"'))
    assert err.value.field == "urdf" and "no actuated joint" in err.value.message
    assert [r for r in reg.ids() if r in ("copy", "other")] == ["copy"]


#: Catalog SRDFs that fail the upload checks of SRDF groups and states (the catalog itself
#: resolves them leniently): the defect each upload's 422 names.
BAD_CATALOG_SRDFS = {
    "kinova": "<group_state name='arm_up'>: <joint name='j2s6s200_joint_3'>: value -1.5707 "
    "is beyond the joint's limits",
    "z1": "<group name='end_effector'>: <chain>: base_link 'base': no such link in the URDF",
}


def test_every_catalog_urdf_is_a_valid_upload(tmp_path: Path, registry: Registry) -> None:
    """Real-world URDFs (Gazebo plugins, meshes, fixed joints without axes) pass the checks,
    and so do the catalog's SRDFs, but for two whose groups or states are wrong."""
    reg = Registry(tmp_path)
    for rid in registry.catalog:
        builtin = registry.get(rid)
        srdf = builtin.srdf_text
        if rid in BAD_CATALOG_SRDFS:
            with pytest.raises(InvalidInputError) as exc:
                reg.add_urdf(f"bad-{rid}", reg.urdf_text(rid), srdf=srdf)
            assert exc.value.field == "srdf"
            assert exc.value.message.startswith(BAD_CATALOG_SRDFS[rid])
            srdf = None
        robot = reg.add_urdf(
            f"copy-{rid}", reg.urdf_text(rid), srdf=srdf, ee_frame=builtin.ee_frame
        )
        assert robot.joint_names == builtin.joint_names
        q = builtin.mid_range()
        np.testing.assert_array_equal(
            frame_pose(robot, builtin.ee_frame, q), frame_pose(builtin, builtin.ee_frame, q)
        )


# ------------------------------------------------------------------ builds and failures
#: Generous bound on waits that succeed at once when the code is right (no timing budget).
WAIT_S = 60.0


def _blocking(build, started: threading.Event, release: threading.Event):
    """``build`` that first says it started, then waits for ``release``."""

    def slow(*args, **kwargs):
        started.set()
        assert release.wait(WAIT_S), "the test never released the slow build"
        return build(*args, **kwargs)

    return slow


def _get_in_thread(reg: Registry, rid: str, out: dict) -> threading.Thread:
    def run() -> None:
        try:
            out[rid] = reg.get(rid)
        except BaseException as exc:  # noqa: BLE001 - reported by the test
            out[rid] = exc

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    return thread


@pytest.mark.parametrize("kind", ["stored", "builtin"])
def test_a_slow_build_does_not_block_other_robots(
    tmp_path: Path, kind: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Robot A's build waits on an event; robot B is served meanwhile (before: one global
    lock held across every build, so B waited for A). A second get of A waits for the one
    build of A."""
    Registry(tmp_path).import_dh(DHTable.from_dict(SMALL))
    Registry(tmp_path).import_dh(DHTable.from_dict({**SMALL, "name": "other"}))
    reg = Registry(tmp_path)
    started, release = threading.Event(), threading.Event()
    builds: list[str] = []
    if kind == "stored":
        slow_id, quick_id = "small", "other"
        real = reg._build_stored

        def build_stored(stored):
            builds.append(stored.id)
            if stored.id == slow_id:
                return _blocking(real, started, release)(stored)
            return real(stored)

        monkeypatch.setattr(reg, "_build_stored", build_stored)
    else:
        slow_id, quick_id = "planar2", "panda"
        entry = reg.dh_builtin[slow_id]

        class SlowEntry:
            def build(self) -> RobotModel:
                builds.append(slow_id)
                return _blocking(entry.build, started, release)()

        reg.dh_builtin = {**reg.dh_builtin, slow_id: SlowEntry()}
    out: dict = {}
    first = _get_in_thread(reg, slow_id, out)
    assert started.wait(WAIT_S)
    second_out: dict = {}
    second = _get_in_thread(reg, slow_id, second_out)
    quick = _get_in_thread(reg, quick_id, out)
    quick.join(WAIT_S)
    try:
        assert not quick.is_alive(), f"{quick_id} waited for the build of {slow_id}"
        assert isinstance(out[quick_id], RobotModel)
        assert slow_id not in out and slow_id not in second_out
    finally:
        release.set()
    first.join(WAIT_S)
    second.join(WAIT_S)
    assert out[slow_id] is second_out[slow_id]
    assert builds.count(slow_id) == 1


def test_a_bug_while_loading_a_stored_robot_is_not_a_conflict(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A TypeError/KeyError/IndexError is a bug in the loading code: it propagates (the
    HTTP guard answers 500 with its traceback) instead of a 409 "delete it and add it
    again". A record that no longer reads (bytes that are not UTF-8) stays a 409."""
    Registry(tmp_path).import_dh(DHTable.from_dict(SMALL))
    for bug in (TypeError("bug"), KeyError("bug"), IndexError("bug")):
        reg = Registry(tmp_path)

        def broken(*args, exc=bug, **kwargs):
            raise exc

        monkeypatch.setattr("app.robots.registry.check_stored_meshes", broken)
        with pytest.raises(type(bug)):
            reg.get("small")
    monkeypatch.undo()
    (tmp_path / "robots" / "small" / "robot.urdf").write_bytes(b"<robot name='r'>\xed</robot>")
    with pytest.raises(ConflictError) as err:
        Registry(tmp_path).get("small")
    assert err.value.field == "robot_id" and "delete it and add it again" in err.value.message
