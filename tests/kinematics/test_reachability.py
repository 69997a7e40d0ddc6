"""Reachability maps: vectorised FK/Jacobian vs Pinocchio, orientation bins, the planar
2-link annulus |l1 − l2| ≤ r ≤ l1 + l2 and its closed-form manipulability, process builds,
cancellation, storage, every bad input."""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
import time

import numpy as np
import pytest

from app.kinematics import reachability
from app.kinematics.analysis import compute_manipulability
from app.kinematics.errors import ConflictError, InvalidInputError, UnknownNameError
from app.kinematics.fk import forward_kinematics
from app.kinematics.jacobian import frame_jacobian
from app.kinematics.models import RobotModel
from app.kinematics.reachability import (
    OWNER_GONE,
    BuildJobs,
    Cancelled,
    ChainJacobian,
    JobSnapshot,
    MapBuilder,
    MapStore,
    PinocchioChain,
    Progress,
    ReachabilityMap,
    build_map,
    chunk_samples,
    default_bounds,
    make_spec,
    orientation_bin,
    orientation_bin_from_rotation,
    orientation_bins,
    summarize,
    yoshikawa_batch,
    yoshikawa_components,
)
from app.kinematics.rotations import matrix_to_quaternion, quaternion_to_matrix
from tests.kinematics.chains import COLLIDING_URDF, L1, L2, planar2_urdf

PRISMATIC_URDF = """<?xml version="1.0"?>
<robot name="rrp_test">
  <link name="base"/><link name="l1"/><link name="l2"/><link name="l3"/><link name="tip"/>
  <joint name="j1" type="continuous">
    <parent link="base"/><child link="l1"/>
    <origin xyz="0 0 0.4" rpy="0 0 0"/><axis xyz="0 0 1"/>
  </joint>
  <joint name="j2" type="revolute">
    <parent link="l1"/><child link="l2"/>
    <origin xyz="0.3 0 0.05" rpy="0.3 0 0"/><axis xyz="0 0.6 0.8"/>
    <limit lower="-3" upper="3" velocity="1" effort="1"/>
  </joint>
  <joint name="j3" type="prismatic">
    <parent link="l2"/><child link="l3"/>
    <origin xyz="0.1 0 0" rpy="0 0.4 0"/><axis xyz="1 0 0"/>
    <limit lower="0" upper="0.5" velocity="1" effort="1"/>
  </joint>
  <joint name="tip_joint" type="fixed">
    <parent link="l3"/><child link="tip"/>
    <origin xyz="0.05 0.02 0" rpy="0 0.2 -1.0"/>
  </joint>
</robot>"""


@pytest.fixture(scope="module")
def planar() -> RobotModel:
    return RobotModel("planar2_test", planar2_urdf(), ee_frame="tip")


def planar_spec(robot, **kw):
    args = dict(
        voxel_size=0.05,
        lower=[-1.6, -1.6, -0.025],
        upper=[1.6, 1.6, 0.025],
        orientation_divisions=0,
        rows=["vx", "vy"],
        samples=60_000,
    )
    args.update(kw)
    return make_spec(robot, "tip", **args)


# ------------------------------------------------------------------ FK and Jacobian
@pytest.mark.parametrize("robot_id", ["panda", "ur5", "kinova"])
def test_chain_matches_pinocchio(registry, robot_id):
    robot = registry.get(robot_id)
    chain = ChainJacobian.build(robot, robot.ee_frame)
    assert chain is not None
    rng = np.random.default_rng(7)
    Q = rng.uniform(-3, 3, size=(6, chain.wire.size))
    R, p, J = chain(Q)
    for i in range(len(Q)):
        q = robot.neutral()
        q[chain.wire] = Q[i]
        T = forward_kinematics(robot, q, [robot.ee_frame])[robot.ee_frame]
        np.testing.assert_allclose(R[i], T[:3, :3], atol=1e-12)
        np.testing.assert_allclose(p[i], T[:3, 3], atol=1e-12)
        Jr = frame_jacobian(robot, q, robot.ee_frame, "world")[:, chain.wire]
        np.testing.assert_allclose(J[i], Jr, atol=1e-12)


def test_chain_prismatic_and_unaligned_axes():
    robot = RobotModel("rrp_test", PRISMATIC_URDF, ee_frame="tip")
    chain = ChainJacobian.build(robot, "tip")
    slow = PinocchioChain(robot, "tip", chain.wire)
    Q = np.random.default_rng(2).uniform([-3, -3, 0], [3, 3, 0.5], size=(8, 3))
    for a, b in zip(chain(Q), slow(Q), strict=True):
        np.testing.assert_allclose(a, b, atol=1e-12)


def test_yoshikawa_components_against_svd():
    rng = np.random.default_rng(4)
    for m, k in ((6, 7), (6, 6), (3, 7), (2, 2), (6, 2)):
        J = rng.normal(size=(50, m, k))
        J[0, 0, :] = 0.0  # a rank-deficient one (rows and columns)
        J[0, :, 0] = J[0, :, 1]
        expected = np.prod(np.linalg.svd(J, compute_uv=False), axis=1)
        got = yoshikawa_components(J.transpose(1, 2, 0))
        np.testing.assert_allclose(got[1:], expected[1:], rtol=1e-9)
        assert got[0] == pytest.approx(0.0, abs=1e-6)
        np.testing.assert_allclose(yoshikawa_batch(J)[1:], expected[1:], rtol=1e-9)


# --------------------------------------------------------------------- orientation bins
def random_quaternions(n, seed=0):
    q = np.random.default_rng(seed).normal(size=(n, 4))
    return q / np.linalg.norm(q, axis=1, keepdims=True)


@pytest.mark.parametrize("d", [1, 2, 4, 7])
def test_orientation_bins_consistent_and_cover(d):
    q = random_quaternions(40_000)
    b = orientation_bin(q, d)
    assert np.array_equal(b, orientation_bin(-q, d))  # q and −q are one rotation
    R = quaternion_to_matrix(q)
    assert np.array_equal(b, orientation_bin_from_rotation(R.transpose(1, 2, 0), d))
    counts = np.bincount(b, minlength=orientation_bins(d))
    assert counts.size == 4 * d**3 and counts.min() > 0
    if d <= 2:  # uniform rotations: equal-angle cells differ in volume by at most ~2×
        assert counts.max() / counts.min() < 2.6


def test_orientation_bin_neighbours_are_close():
    """Rotations in one bin stay close (d = 4: a bin spans about 45° per axis)."""
    q = random_quaternions(20_000, seed=1)
    b = orientation_bin(q, 4)
    for cell in np.unique(b)[:40]:
        qs = q[b == cell]
        dots = np.abs(qs @ qs.T)
        angle = 2 * np.degrees(np.arccos(np.clip(dots.min(), -1, 1)))
        assert angle < 70.0


# ----------------------------------------------------------------- the planar annulus
def voxel_centres(spec):
    idx = np.stack(np.meshgrid(*[np.arange(n) for n in spec.shape], indexing="ij"), -1)
    return np.asarray(spec.lower) + (idx.reshape(-1, 3) + 0.5) * spec.voxel_size


def test_planar_map_is_the_annulus(planar):
    spec = planar_spec(planar)
    best = build_map(planar, spec)
    m = ReachabilityMap({"spec": spec.__dict__.copy(), **summarize(best)}, best)
    c = voxel_centres(spec)
    r = np.hypot(c[:, 0], c[:, 1])
    reach, val, ok = m.query(c, None)
    half_diag = spec.voxel_size * math.sqrt(2) / 2
    inner, outer = abs(L1 - L2), L1 + L2
    well_inside = (r > inner + half_diag + 0.03) & (r < outer - half_diag - 0.03)
    well_outside = (r < inner - half_diag) | (r > outer + half_diag)
    assert ok.all() and well_inside.sum() > 1000
    assert reach[well_inside].all()
    assert not reach[well_outside].any()
    # best manipulability in a voxel ≈ the closed form l1·l2·|sin θ2| at its radius
    c2 = (r**2 - L1**2 - L2**2) / (2 * L1 * L2)
    w = L1 * L2 * np.sqrt(np.clip(1 - c2**2, 0, 1))
    dw = L1 * L2 * half_diag * r / (L1 * L2) / np.sqrt(np.clip(1 - c2**2, 1e-3, 1)) + 1e-2
    sel = well_inside & (np.abs(c2) < 0.9)
    assert np.all(val[sel] <= w[sel] + dw[sel])
    assert np.all(val[sel] >= w[sel] - dw[sel] - 0.02)


def test_planar_exact_manipulability_at_sampled_cells(planar):
    """Map values are the Yoshikawa index of samples: check samples against the analysis."""
    spec = planar_spec(planar, samples=4096)
    builder = MapBuilder(planar, spec)
    cells, vals = builder.cells(0, 4096)
    Q = chunk_samples(spec, 0, 4096)
    for i in range(0, 4096, 512):
        exact = compute_manipulability(planar, Q[i], "tip", rows=["vx", "vy"]).yoshikawa
        assert exact == pytest.approx(L1 * L2 * abs(math.sin(Q[i, 1])), abs=1e-12)
    assert vals.max() <= L1 * L2 + 1e-6 and vals.size == 4096  # all in the box


def test_grid_sampling_lattice(planar):
    spec = planar_spec(planar, sampling="grid", samples=100)
    assert spec.grid_per_joint == 10 and spec.samples == 100
    Q = chunk_samples(spec, 0, spec.samples)
    # a full turn (±π) has no duplicate end point
    grid = np.linspace(-math.pi, math.pi, 10, endpoint=False)
    np.testing.assert_allclose(np.unique(Q[:, 0]), grid)
    np.testing.assert_allclose(np.unique(Q[:, 1]), grid)
    short = RobotModel("p2", planar2_urdf(limit=2.0), ee_frame="tip")
    Q = chunk_samples(planar_spec(short, sampling="grid", samples=36), 0, 36)
    np.testing.assert_allclose(np.unique(Q[:, 1]), np.linspace(-2.0, 2.0, 6))


def test_processes_give_the_same_map(planar):
    spec = planar_spec(planar, samples=3 * 32_768, orientation_divisions=2)
    one = build_map(planar, spec)
    two = build_map(planar, spec, processes=2, min_samples_per_process=1)
    assert np.array_equal(one, two)


def test_cancel(planar):
    spec = planar_spec(planar, samples=10_000_000)
    progress = Progress(spec.samples)
    progress.cancel.set()
    with pytest.raises(Cancelled):
        build_map(planar, spec, progress)


def test_default_bounds_contain_the_workspace(registry):
    robot = registry.get("ur5")
    lo, hi = default_bounds(robot, robot.ee_frame)
    chain = ChainJacobian.build(robot, robot.ee_frame)
    Q = np.random.default_rng(0).uniform(-2 * math.pi, 2 * math.pi, (5000, 6))
    _, p, _ = chain(Q)
    assert np.all(p >= lo) and np.all(p <= hi)


def test_store_roundtrip(tmp_path, planar):
    spec = planar_spec(planar, samples=2048)
    best = build_map(planar, spec)
    meta = {
        "map_id": "0" * 32,
        "created_at": "2026-01-01T00:00:00+00:00",
        "spec": spec.__dict__.copy(),
        "joints": ["j1", "j2"],
        "robot_fingerprint": "x",
        **summarize(best),
    }
    store = MapStore(tmp_path)
    store.save(ReachabilityMap(meta, best))
    assert [m["map_id"] for m in store.list("planar2_test")] == ["0" * 32]
    again = MapStore(tmp_path).get("planar2_test", "0" * 32)
    assert np.array_equal(again.best, best)
    with pytest.raises(UnknownNameError) as e:
        store.get("planar2_test", "../../etc/passwd")
    assert e.value.field == "map_id"
    assert not list(tmp_path.rglob(".tmp-*"))


# ---------------------------------------------------------------------- bad inputs
@pytest.mark.parametrize(
    ("kw", "field"),
    [
        ({"voxel_size": 0.0}, "voxel_size"),
        ({"voxel_size": -0.1}, "voxel_size"),
        ({"lower": [0, 0, 0], "upper": [1, -1, 1]}, "bounds.max.1"),
        ({"lower": [0, 0, 0], "upper": [0, 1, 1]}, "bounds.max.0"),
        ({"voxel_size": 1e-4}, "voxel_size"),  # too many cells
        ({"orientation_divisions": 13}, "orientation_divisions"),
        ({"samples": 0}, "samples"),
        ({"sampling": "sobol"}, "sampling"),
        ({"self_collision": "maybe"}, "self_collision"),
        ({"rows": ["vq"]}, "rows.0"),
    ],
)
def test_bad_specs(planar, kw, field):
    with pytest.raises(InvalidInputError) as e:
        planar_spec(planar, **kw)
    assert e.value.field == field


def test_quaternion_bins_from_matrices_roundtrip():
    q = random_quaternions(100, seed=5)
    back = matrix_to_quaternion(quaternion_to_matrix(q))
    assert np.array_equal(orientation_bin(q, 3), orientation_bin(back, 3))


def test_self_collision_hook_drops_folded_samples():
    """Folded back (|θ2| ≈ π) link 2 enters the base box (|x|, |y| ≤ 0.4): with the hook
    those tip positions (r ≈ 0.3) disappear; without it they are reachable."""
    robot = RobotModel("planar_boxes", COLLIDING_URDF, ee_frame="tip")
    kw = dict(
        voxel_size=0.1,
        lower=[-1.6, -1.6, -0.05],
        upper=[1.6, 1.6, 0.05],
        orientation_divisions=0,
        samples=4000,
        sampling="grid",
    )
    plain = build_map(robot, make_spec(robot, "tip", **kw))
    checked = build_map(robot, make_spec(robot, "tip", self_collision="convex", **kw))
    spec = make_spec(robot, "tip", **kw)
    c = voxel_centres(spec)
    r = np.hypot(c[:, 0], c[:, 1])
    near = (r > 0.32) & (r < 0.4)
    assert (plain.reshape(-1)[near] >= 0).all()
    assert not (checked.reshape(-1)[near] >= 0).any()
    far = (r > 1.0) & (r < 1.4)
    assert (checked.reshape(-1)[far] >= 0).all()


def test_worker_failure_is_reported(planar):
    """A worker that cannot build its model fails the build with the worker's error."""
    broken = RobotModel("planar2_test", planar2_urdf(), ee_frame="tip")
    broken.urdf_text = "<robot name='x'><link name='a'/></robot>"  # no frame 'tip' there
    spec = planar_spec(broken, samples=4 * 32_768)
    with pytest.raises(RuntimeError, match="build process failed"):
        build_map(broken, spec, processes=2, min_samples_per_process=1)


def test_pinocchio_fallback_gives_the_same_map(planar, monkeypatch):
    """Chains the vectorised path cannot take (mimic, multi-DoF joints) use Pinocchio per
    sample: forcing that path must give the same map."""
    spec = planar_spec(planar, samples=8192, orientation_divisions=3)
    fast = build_map(planar, spec)
    monkeypatch.setattr(ChainJacobian, "build", classmethod(lambda cls, robot, frame: None))
    assert isinstance(MapBuilder(planar, spec).chain, PinocchioChain)
    slow = build_map(planar, spec)
    assert np.array_equal(fast >= 0, slow >= 0)
    np.testing.assert_allclose(fast, slow, rtol=1e-6, atol=1e-7)


def test_sampled_poses_are_in_the_map(registry):
    """Every sampled configuration's pose (Pinocchio FK) is reachable in the map, with a
    cell value at least its Yoshikawa index (from the analysis module's SVD)."""
    robot = registry.get("ur5")
    spec = make_spec(robot, robot.ee_frame, voxel_size=0.1, samples=4096, orientation_divisions=3)
    best = build_map(robot, spec)
    m = ReachabilityMap({"spec": spec.__dict__.copy(), **summarize(best)}, best)
    Q = chunk_samples(spec, 0, 4096)
    pos, quat, w = [], [], []
    for q in Q[::97]:
        T = forward_kinematics(robot, q, [robot.ee_frame])[robot.ee_frame]
        pos.append(T[:3, 3])
        quat.append(matrix_to_quaternion(T[:3, :3]))
        w.append(compute_manipulability(robot, q, robot.ee_frame).yoshikawa)
    reach, val, ok = m.query(np.array(pos), np.array(quat))
    assert ok.all() and reach.all()
    assert np.all(val >= np.array(w) * (1 - 1e-6) - 1e-9)


# ------------------------------------------------------------ jobs seen by every worker
def two_workers(root, **kw) -> tuple[BuildJobs, BuildJobs]:
    """Two job queues on one map store root, as two uvicorn workers have."""
    return BuildJobs(MapStore(root), processes=1, **kw), BuildJobs(
        MapStore(root), processes=1, **kw
    )


def wait_for(view, robot_id, job_id, done=lambda j: j.status not in ("queued", "running")):
    """Poll ``view.get`` until ``done`` holds (60 s: a loaded machine is slow, never wrong)."""
    end = time.monotonic() + 60
    while not done(job := view.get(robot_id, job_id)):
        assert time.monotonic() < end, job.to_json()
        time.sleep(0.02)
    return job


def test_jobs_of_one_worker_are_seen_by_another(tmp_path, planar):
    a, b = two_workers(tmp_path)
    job = a.submit(planar, planar_spec(planar))
    seen = b.get("planar2_test", job.job_id)
    assert isinstance(seen, JobSnapshot) and seen.job_id == job.job_id
    assert seen.status in ("queued", "running", "done")
    assert seen.to_json().keys() == job.to_json().keys()
    assert [j.job_id for j in b.list("planar2_test")] == [job.job_id]
    assert b.list("other_robot") == []
    with pytest.raises(UnknownNameError) as e:
        b.get("other_robot", job.job_id)
    assert e.value.field == "job_id"
    via_b = wait_for(b, "planar2_test", job.job_id)
    via_a = wait_for(a, "planar2_test", job.job_id)
    assert via_b.status == via_a.status == "done"
    assert via_a.map_id is not None and via_b.to_json()["map_id"] == via_a.map_id
    assert via_b.to_json()["progress"]["samples_done"] == 60_000
    assert via_b.to_json()["progress"]["percent"] == 100.0
    loaded = b.store.get("planar2_test", via_a.map_id)
    assert np.array_equal(loaded.best, a.store.get("planar2_test", via_a.map_id).best)
    # both list the job once, and the job files are whole (no temporaries left behind)
    assert [j.job_id for j in a.list("planar2_test")] == [job.job_id]
    assert [j.job_id for j in b.list("planar2_test")] == [job.job_id]
    assert not list(tmp_path.rglob(".tmp-*"))


def test_cancel_through_another_worker(tmp_path, planar):
    """B cancels A's queued job at once and A's running build within moments; both end
    cancelled on both views, nothing is stored and the cancel markers are gone."""
    a, b = two_workers(tmp_path)
    spec = planar_spec(planar, samples=200_000_000)
    running = a.submit(planar, spec)
    queued = a.submit(planar, spec)
    wait_for(b, "planar2_test", running.job_id, lambda j: j.to_json()["progress"]["samples_done"])
    assert b.get("planar2_test", queued.job_id).status == "queued"
    assert b.cancel("planar2_test", queued.job_id).status == "queued"  # the owner acts on it
    assert wait_for(b, "planar2_test", queued.job_id).status == "cancelled"
    assert wait_for(a, "planar2_test", queued.job_id).status == "cancelled"
    assert b.get("planar2_test", running.job_id).status == "running"  # only the one cancelled
    assert b.cancel("planar2_test", running.job_id).status == "running"
    assert wait_for(b, "planar2_test", running.job_id).status == "cancelled"
    assert wait_for(a, "planar2_test", running.job_id).status == "cancelled"
    assert b.cancel("planar2_test", running.job_id).status == "cancelled"  # idempotent
    assert a.get("planar2_test", running.job_id).to_json()["map_id"] is None
    assert running.progress.done < spec.samples
    assert not list(tmp_path.rglob("*.npz"))
    assert not list(tmp_path.rglob("*.cancel"))


def test_cancel_of_a_finished_job_of_another_worker_conflicts(tmp_path, planar):
    a, b = two_workers(tmp_path)
    job = a.submit(planar, planar_spec(planar, samples=2048))
    wait_for(a, "planar2_test", job.job_id)
    with pytest.raises(ConflictError) as e:
        b.cancel("planar2_test", job.job_id)
    assert e.value.field == "job_id"
    assert not list(tmp_path.rglob("*.cancel"))


def write_snapshot(root, job_id, status="running", pid=None, started=None, robot="planar2_test"):
    """A job file as an owner publishes it (by hand)."""
    record = {
        "job_id": job_id,
        "robot_id": robot,
        "frame": "tip",
        "status": status,
        "map_id": None,
        "error": None,
        "progress": {
            "percent": 10.0,
            "samples_done": 100,
            "samples_total": 1000,
            "samples_per_second": 50.0,
            "elapsed_seconds": 2.0,
            "eta_seconds": 18.0,
        },
        "created_at": time.time(),
        "finished_at": None,
        "updated_at": time.time(),
        "owner_pid": os.getpid() if pid is None else pid,
        "owner_token": "f" * 32,
        "owner_space": reachability._PID_SPACE,
        "owner_started": started,
    }
    path = root / reachability.JOBS_DIR / f"{job_id}.json"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(record))
    return path


def test_job_of_a_stopped_worker_reads_failed(tmp_path):
    child = subprocess.Popen([sys.executable, "-c", "import sys; sys.stdin.read()"],
                             stdin=subprocess.PIPE)  # fmt: skip
    stat = reachability._process_stat(child.pid)
    child.communicate(b"")  # it exits and is reaped: its pid is gone
    _, jobs = two_workers(tmp_path)
    alive, dead, reused = "a" * 32, "b" * 32, "c" * 32
    write_snapshot(tmp_path, alive)  # this process: alive
    write_snapshot(tmp_path, dead, pid=child.pid, started=stat[1] if stat else None)
    own = reachability._process_stat(os.getpid())
    if own is not None:  # our pid, but another start time: a pid reused after a restart
        write_snapshot(tmp_path, reused, started=own[1] + 1)
    assert jobs.get("planar2_test", alive).status == "running"
    gone = jobs.get("planar2_test", dead).to_json()
    assert gone["status"] == "failed" and gone["error"] == OWNER_GONE
    assert gone["progress"]["eta_seconds"] is None and gone["progress"]["samples_done"] == 100
    if own is not None:
        assert jobs.get("planar2_test", reused).status == "failed"
    listed = {j.job_id: j.status for j in jobs.list("planar2_test")}
    assert listed[alive] == "running" and listed[dead] == "failed"
    with pytest.raises(ConflictError):
        jobs.cancel("planar2_test", dead)
    jobs.cancel("planar2_test", alive)  # an active job of another owner: a marker
    assert (tmp_path / reachability.JOBS_DIR / f"{alive}.cancel").exists()


def test_bad_job_ids_are_unknown(tmp_path):
    """Ids that are not 32 hex digits never reach the file system (no path traversal)."""
    _, jobs = two_workers(tmp_path)
    write_snapshot(tmp_path, "d" * 32)
    # a well-formed job file outside the jobs directory, named so that a path built from
    # the id "../evil" would find it
    evil = write_snapshot(tmp_path, "../evil")
    evil.rename(tmp_path / "evil.json")
    for bad in ("../evil", "D" * 32, "d" * 31, "d" * 33, "", "d" * 31 + "/", "nope"):
        with pytest.raises(UnknownNameError) as e:
            jobs.get("planar2_test", bad)
        assert e.value.field == "job_id"
        with pytest.raises(UnknownNameError):
            jobs.cancel("planar2_test", bad)
    assert jobs.get("planar2_test", "d" * 32).status == "running"
    (tmp_path / reachability.JOBS_DIR / f"{'e' * 32}.json").write_text("{not json")
    with pytest.raises(UnknownNameError):
        jobs.get("planar2_test", "e" * 32)
    assert [j.job_id for j in jobs.list("planar2_test")] == ["d" * 32]


def test_old_finished_job_files_are_deleted(tmp_path, planar):
    """Submitting keeps the max_jobs newest finished job files; active ones always stay."""
    a, b = two_workers(tmp_path, max_jobs=2)
    active = "a" * 32
    write_snapshot(tmp_path, active)  # oldest of all, but running (this process is alive)
    ids = []
    for _ in range(4):
        job = a.submit(planar, planar_spec(planar, samples=2048))
        ids.append(job.job_id)
        wait_for(a, "planar2_test", job.job_id)
    files = {p.stem for p in (tmp_path / reachability.JOBS_DIR).glob("*.json")}
    # at the 4th submit, 3 were finished: the oldest went; the 4th finished since
    assert files == {active, *ids[1:]}
    assert b.get("planar2_test", ids[1]).status == "done"
    with pytest.raises(UnknownNameError):  # forgotten: A's memory keeps max_jobs too
        a.get("planar2_test", ids[0])
    with pytest.raises(UnknownNameError):
        b.get("planar2_test", ids[0])
