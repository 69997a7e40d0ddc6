"""Reachability build jobs in SQLite (app.storage.build_jobs): two BuildJobs instances on one data
directory stand for two uvicorn workers; each sees, lists and cancels the other's jobs. A
job whose owner's heartbeat stopped (a fake clock, no sleeps racing the threshold) reads
and is stored as failed; a corrupt or unusable database is a clear UnavailableError."""

from __future__ import annotations

import sqlite3
import time

import numpy as np
import pytest

from app.kinematics.errors import ConflictError, UnavailableError, UnknownNameError
from app.kinematics.models import RobotModel
from app.kinematics.reachability.map import ReachabilityMap, summarize
from app.storage.build_jobs import OWNER_GONE, STALE_SECONDS, BuildJobs, JobSnapshot
from app.storage.job_table import DB_FILE
from app.storage.maps import MapStore
from app.workers.map_build import build_map
from tests.kinematics.chains import planar_2link, planar_map_spec

ROBOT = "planar2_test"


@pytest.fixture(scope="module")
def planar() -> RobotModel:
    return RobotModel(ROBOT, planar_2link(0.9, 0.6, name=ROBOT), ee_frame="tip")


class FakeClock:
    """A wall clock that only moves when told to."""

    def __init__(self, t: float = 1_000_000.0) -> None:
        self.t = t

    def __call__(self) -> float:
        return self.t


def two_workers(root, **kw) -> tuple[BuildJobs, BuildJobs]:
    """Two job queues on one map store root, as two uvicorn workers have."""
    return BuildJobs(MapStore(root), processes=1, **kw), BuildJobs(
        MapStore(root), processes=1, **kw
    )


def wait_for(view, job_id, done=lambda j: j.status not in ("queued", "running")):
    """Poll ``view.get`` until ``done`` holds (60 s: a loaded machine is slow, never wrong)."""
    end = time.monotonic() + 60
    while not done(job := view.get(ROBOT, job_id)):
        assert time.monotonic() < end, job.to_json()
        time.sleep(0.02)
    return job


def rows(root) -> dict[str, sqlite3.Row]:
    """The job rows as stored, read with a connection of our own."""
    conn = sqlite3.connect(root / DB_FILE)
    conn.row_factory = sqlite3.Row
    try:
        return {r["job_id"]: r for r in conn.execute("SELECT * FROM jobs")}
    finally:
        conn.close()


def insert_row(root, job_id, status="running", heartbeat=None, created=None, robot=ROBOT):
    """A job row as an owner writes it (by hand: another process's job)."""
    BuildJobs(MapStore(root), processes=1).list(robot)  # creates the database
    now = time.time()
    conn = sqlite3.connect(root / DB_FILE)
    with conn:
        conn.execute(
            "INSERT INTO jobs (job_id, robot_id, frame, status, map_id, error, percent, "
            "samples_done, samples_total, samples_per_second, elapsed_seconds, eta_seconds, "
            "created_at, finished_at, owner, heartbeat, cancel) VALUES "
            "(?, ?, 'tip', ?, NULL, NULL, 10.0, 100, 1000, 50.0, 2.0, 18.0, ?, NULL, ?, ?, 0)",
            (job_id, robot, status, created or now, "f" * 32, heartbeat or now),
        )
    conn.close()


def test_jobs_of_one_worker_are_seen_by_another(tmp_path, planar):
    a, b = two_workers(tmp_path)
    job = a.submit(planar, planar_map_spec(planar))
    seen = b.get(ROBOT, job.job_id)
    assert isinstance(seen, JobSnapshot) and seen.job_id == job.job_id
    assert seen.status in ("queued", "running", "done")
    assert seen.to_json().keys() == job.to_json().keys()
    assert seen.to_json()["progress"].keys() == job.to_json()["progress"].keys()
    assert [j.job_id for j in b.list(ROBOT)] == [job.job_id]
    assert b.list("other_robot") == []
    with pytest.raises(UnknownNameError) as e:
        b.get("other_robot", job.job_id)
    assert e.value.field == "job_id"
    via_b = wait_for(b, job.job_id)
    via_a = wait_for(a, job.job_id)
    assert via_b.status == via_a.status == "done"
    assert via_a.map_id is not None and via_b.to_json()["map_id"] == via_a.map_id
    assert via_b.to_json()["progress"]["samples_done"] == 60_000
    assert via_b.to_json()["progress"]["percent"] == 100.0
    assert via_b.to_json()["progress"]["eta_seconds"] == 0.0
    loaded = b.store.get(ROBOT, via_a.map_id)
    assert np.array_equal(loaded.best, a.store.get(ROBOT, via_a.map_id).best)
    assert [j.job_id for j in a.list(ROBOT)] == [job.job_id]
    assert [j.job_id for j in b.list(ROBOT)] == [job.job_id]
    stored = rows(tmp_path)[job.job_id]
    assert stored["status"] == "done" and stored["owner"] == a.owner != b.owner
    assert not list(tmp_path.rglob(".tmp-*"))


def test_cancel_through_another_worker(tmp_path, planar):
    """B cancels A's queued job at once and A's running build within moments; both end
    cancelled on both views and nothing is stored."""
    a, b = two_workers(tmp_path)
    spec = planar_map_spec(planar, samples=200_000_000)
    running = a.submit(planar, spec)
    queued = a.submit(planar, spec)
    wait_for(b, running.job_id, lambda j: j.to_json()["progress"]["samples_done"])
    assert b.get(ROBOT, queued.job_id).status == "queued"
    assert b.cancel(ROBOT, queued.job_id).status == "queued"  # the owner acts on it
    assert rows(tmp_path)[queued.job_id]["cancel"] == 1
    assert wait_for(b, queued.job_id).status == "cancelled"
    assert wait_for(a, queued.job_id).status == "cancelled"
    assert b.get(ROBOT, running.job_id).status == "running"  # only the one cancelled
    assert b.cancel(ROBOT, running.job_id).status == "running"
    assert wait_for(b, running.job_id).status == "cancelled"
    assert wait_for(a, running.job_id).status == "cancelled"
    assert b.cancel(ROBOT, running.job_id).status == "cancelled"  # idempotent
    assert a.get(ROBOT, running.job_id).to_json()["map_id"] is None
    assert running.progress.done < spec.samples
    assert not list(tmp_path.rglob("*.npz"))


def test_own_cancel_and_a_finished_job_of_another_worker_conflicts(tmp_path, planar):
    a, b = two_workers(tmp_path)
    job = a.submit(planar, planar_map_spec(planar, samples=2048))
    wait_for(a, job.job_id)
    with pytest.raises(ConflictError) as e:
        b.cancel(ROBOT, job.job_id)
    assert e.value.field == "job_id"
    with pytest.raises(ConflictError):
        a.cancel(ROBOT, job.job_id)
    # A cancels its own running job; B reads the row
    long = a.submit(planar, planar_map_spec(planar, samples=200_000_000))
    wait_for(a, long.job_id, lambda j: j.status == "running")
    a.cancel(ROBOT, long.job_id)
    assert wait_for(b, long.job_id).status == "cancelled"


def test_stale_heartbeat_marks_the_job_failed(tmp_path, planar):
    """A's clock stands still, so its heartbeats stop advancing; B's clock moves past the
    stale threshold: B reports the job failed with OWNER_GONE and stores that; A, still
    alive, adopts the verdict and stops its build."""
    clock_a, clock_b = FakeClock(), FakeClock()
    a = BuildJobs(MapStore(tmp_path), processes=1, clock=clock_a)
    b = BuildJobs(MapStore(tmp_path), processes=1, clock=clock_b)
    job = a.submit(planar, planar_map_spec(planar, samples=200_000_000))
    wait_for(b, job.job_id, lambda j: j.to_json()["progress"]["samples_done"])
    clock_b.t += STALE_SECONDS  # at the threshold: still alive
    assert b.get(ROBOT, job.job_id).status == "running"
    clock_b.t += 1.0
    gone = b.get(ROBOT, job.job_id).to_json()
    assert gone["status"] == "failed" and gone["error"] == OWNER_GONE
    assert gone["progress"]["eta_seconds"] is None and gone["progress"]["samples_done"] > 0
    assert [j.status for j in b.list(ROBOT)] == ["failed"]
    stored = rows(tmp_path)[job.job_id]
    assert stored["status"] == "failed" and stored["error"] == OWNER_GONE
    # a third worker whose clock is A's (no staleness) reads the stored verdict
    c = BuildJobs(MapStore(tmp_path), processes=1, clock=FakeClock(clock_a.t))
    assert c.get(ROBOT, job.job_id).to_json()["error"] == OWNER_GONE
    with pytest.raises(ConflictError):
        c.cancel(ROBOT, job.job_id)
    # the owner finds its row failed at its next heartbeat and stops the build
    assert wait_for(a, job.job_id).status == "failed"
    assert job.error == OWNER_GONE and job.progress.cancel.is_set()
    # builds run one after another: the next one finishing proves the long one stopped
    nxt = a.submit(planar, planar_map_spec(planar, samples=2048))
    assert wait_for(a, nxt.job_id).status == "done"
    assert job.status == "failed" and rows(tmp_path)[job.job_id]["status"] == "failed"
    assert [m["map_id"] for m in a.store.list(ROBOT)] == [nxt.map_id]


def test_row_of_another_owner_and_bad_job_ids(tmp_path):
    """Rows of another owner are answered for; a stale one is failed; ids that are not 32
    hex digits are unknown without a look at the database."""
    jobs = BuildJobs(MapStore(tmp_path), processes=1)
    alive, dead = "a" * 32, "b" * 32
    insert_row(tmp_path, alive)
    insert_row(tmp_path, dead, heartbeat=time.time() - 10 * STALE_SECONDS)
    assert jobs.get(ROBOT, alive).status == "running"
    failed = jobs.get(ROBOT, dead).to_json()
    assert failed["status"] == "failed" and failed["error"] == OWNER_GONE
    assert failed["progress"]["samples_done"] == 100
    listed = {j.job_id: j.status for j in jobs.list(ROBOT)}
    assert listed == {alive: "running", dead: "failed"}
    jobs.cancel(ROBOT, alive)  # an active job of another owner: its flag is set
    assert rows(tmp_path)[alive]["cancel"] == 1
    for bad in ("../evil", "A" * 32, "a" * 31, "a" * 33, "", "a" * 31 + "/", "nope"):
        with pytest.raises(UnknownNameError) as e:
            jobs.get(ROBOT, bad)
        assert e.value.field == "job_id"
        with pytest.raises(UnknownNameError):
            jobs.cancel(ROBOT, bad)


def test_old_finished_rows_are_deleted(tmp_path, planar):
    """Submitting keeps the max_jobs newest finished rows; active ones always stay."""
    a, b = two_workers(tmp_path, max_jobs=2)
    active = "a" * 32
    insert_row(tmp_path, active, created=1.0)  # oldest of all, but running
    ids = []
    for _ in range(4):
        job = a.submit(planar, planar_map_spec(planar, samples=2048))
        ids.append(job.job_id)
        wait_for(a, job.job_id)
    # at the 4th submit, 3 were finished: the oldest went; the 4th finished since
    assert set(rows(tmp_path)) == {active, *ids[1:]}
    assert b.get(ROBOT, ids[1]).status == "done"
    with pytest.raises(UnknownNameError):  # forgotten: A's memory keeps max_jobs too
        a.get(ROBOT, ids[0])
    with pytest.raises(UnknownNameError):
        b.get(ROBOT, ids[0])


@pytest.mark.parametrize("damage", ["corrupt", "directory"])
def test_unusable_database_is_a_clear_error(tmp_path, planar, damage):
    """A database file that is not a database, or cannot be opened: every call that needs
    it raises UnavailableError naming the file; once repaired, jobs work again."""
    path = tmp_path / DB_FILE
    if damage == "corrupt":
        path.write_bytes(b"this is not an SQLite database\n" * 100)
    else:
        path.mkdir()
    jobs = BuildJobs(MapStore(tmp_path), processes=1)
    for call in (
        lambda: jobs.list(ROBOT),
        lambda: jobs.get(ROBOT, "a" * 32),
        lambda: jobs.cancel(ROBOT, "a" * 32),
        lambda: jobs.submit(planar, planar_map_spec(planar, samples=2048)),
    ):
        with pytest.raises(UnavailableError) as e:
            call()
        assert DB_FILE in e.value.message
    assert jobs.jobs == {}  # nothing half-submitted
    if damage == "corrupt":
        path.unlink()
    else:
        path.rmdir()
    job = jobs.submit(planar, planar_map_spec(planar, samples=2048))
    assert wait_for(jobs, job.job_id).status == "done"


def test_store_roundtrip(tmp_path, planar):
    spec = planar_map_spec(planar, samples=2048)
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
    assert [m["map_id"] for m in store.list(ROBOT)] == ["0" * 32]
    again = MapStore(tmp_path).get(ROBOT, "0" * 32)
    assert np.array_equal(again.best, best)
    with pytest.raises(UnknownNameError) as e:
        store.get(ROBOT, "../../etc/passwd")
    assert e.value.field == "map_id"
    assert not list(tmp_path.rglob(".tmp-*"))


def test_a_failed_build_is_logged_with_its_traceback(tmp_path, planar, monkeypatch, caplog):
    """The job reports the failure and the log carries the traceback (before: the job's
    error string only, nothing in the log to find the bug by)."""

    def broken_build(*args, **kwargs):
        raise ZeroDivisionError("a bug in the build")

    monkeypatch.setattr("app.storage.build_jobs.build_map", broken_build)
    jobs = BuildJobs(MapStore(tmp_path), processes=1)
    with caplog.at_level("ERROR", logger="denavit.reachability"):
        job = wait_for(jobs, jobs.submit(planar, planar_map_spec(planar)).job_id)
    assert job.status == "failed" and "ZeroDivisionError" in job.to_json()["error"]
    [record] = [r for r in caplog.records if r.exc_info is not None]
    assert job.job_id in record.getMessage()
    assert record.exc_info[0] is ZeroDivisionError
    assert "broken_build" in caplog.text  # the traceback's frame
