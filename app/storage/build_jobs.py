"""Reachability build jobs: run in the process that accepted them, answered for by every
process on the data directory through one SQLite database.

State
-----
``<data_dir>/maps/jobs.sqlite3`` (:mod:`app.storage.job_table`: standard library ``sqlite3``, WAL
journal) holds one row per job: its public fields (status, map id, error, the progress
figures of :meth:`BuildJob.to_json`), ``created_at`` and ``finished_at`` (wall clock, s),
the ``owner`` (a random id of the :class:`BuildJobs` instance that runs it, one per
process), the owner's ``heartbeat`` (wall clock, s) and a ``cancel`` flag.

- The owner writes the row on submit and on every status change (a final state is
  committed before the job reads as finished in memory, so no process sees it finished
  while another still sees it run), and, from one heartbeat thread per instance, refreshes
  progress and heartbeat of its active jobs every :data:`PUBLISH_INTERVAL` s, reading their
  cancel flags in the same short transaction.
- :meth:`BuildJobs.get` and :meth:`BuildJobs.list` answer with the in-memory job when this
  process owns it, else with the row (:class:`JobSnapshot`). A row that says queued or
  running whose heartbeat is older than ``stale_seconds`` (default :data:`STALE_SECONDS`)
  belongs to an owner that stopped (killed, hung, its container gone): it is marked failed
  in the database with the error :data:`OWNER_GONE`. Should that owner still be alive, it
  finds its job no longer active on its next heartbeat and stops the build.
- :meth:`BuildJobs.cancel` of another process's job sets the row's cancel flag; the owner
  acts on it within :data:`PUBLISH_INTERVAL` s as on a local cancel.

A database that cannot be opened, read or written (corrupt, read-only, disk full) raises
:class:`~app.kinematics.errors.UnavailableError` (503 problem details) on the request that
needed it; the heartbeat thread logs such failures and keeps the build running.

A restart forgets nothing a client needs: finished maps are files (:mod:`app.storage.maps`), and
the jobs of a stopped process read as failed once their heartbeat is stale. At most
``max_active`` builds may be queued or running in one process (more is a conflict);
``max_jobs`` finished jobs are remembered in memory, and the database keeps the
``max_jobs`` newest finished jobs of all processes (older rows are deleted on submit; active
ones never are). Build processes die with the process that owns the build
(:mod:`app.kinematics.reachability.build`).
"""

from __future__ import annotations

import logging
import queue
import sqlite3
import threading
import time
import uuid
from collections.abc import Callable
from dataclasses import asdict, dataclass, field, replace
from datetime import UTC, datetime
from typing import Any

from app.kinematics.errors import Cancelled, ConflictError, UnavailableError, UnknownNameError
from app.kinematics.models import RobotModel
from app.kinematics.reachability.build import Progress
from app.kinematics.reachability.map import ReachabilityMap, robot_fingerprint, summarize
from app.kinematics.reachability.spec import MapSpec
from app.storage.job_table import ACTIVE, DB_FILE, PROGRESS_FIELDS, JobTable
from app.storage.maps import MapStore, valid_id
from app.workers import default_processes
from app.workers.map_build import build_map

#: Seconds between two heartbeats of an active job (and two looks at its cancel flag).
PUBLISH_INTERVAL = 0.25
#: A queued or running job whose heartbeat is older than this (s) has lost its owner.
STALE_SECONDS = 30.0
OWNER_GONE = "the worker process building it stopped"

log = logging.getLogger("denavit.reachability")


#: A build job's states: queued, then running, then one of the three ends.
JOB_STATUSES = ("queued", "running", "done", "failed", "cancelled")


@dataclass
class BuildJob:
    """A map build running (or queued) in the background, owned by this process."""

    job_id: str
    robot_id: str
    spec: MapSpec
    progress: Progress
    status: str = "queued"  # one of JOB_STATUSES
    created_at: float = field(default_factory=time.time)
    finished_at: float | None = None
    map_id: str | None = None
    error: str | None = None

    def to_json(self) -> dict[str, Any]:
        p = self.progress
        return {
            "job_id": self.job_id,
            "robot_id": self.robot_id,
            "frame": self.spec.frame,
            "status": self.status,
            "map_id": self.map_id,
            "error": self.error,
            "progress": {
                "percent": 100.0 * p.done / p.total if p.total else 100.0,
                "samples_done": p.done,
                "samples_total": p.total,
                "samples_per_second": p.rate(),
                "elapsed_seconds": p.elapsed(),
                "eta_seconds": 0.0
                if self.status == "done"
                else (p.eta() if self.status == "running" else None),
            },
        }


@dataclass(frozen=True)
class JobSnapshot:
    """A job of another process, as its row reads: ``record`` is the owner's
    :meth:`BuildJob.to_json` (``to_json`` and ``status`` read as on a :class:`BuildJob`)."""

    record: dict[str, Any]
    created_at: float
    finished_at: float | None
    heartbeat: float
    owner: str

    @property
    def job_id(self) -> str:
        return self.record["job_id"]

    @property
    def robot_id(self) -> str:
        return self.record["robot_id"]

    @property
    def status(self) -> str:
        return self.record["status"]

    def to_json(self) -> dict[str, Any]:
        return {**self.record, "progress": dict(self.record["progress"])}

    @classmethod
    def from_row(cls, row: sqlite3.Row) -> JobSnapshot:
        record = {k: row[k] for k in ("job_id", "robot_id", "frame", "status", "map_id", "error")}
        record["progress"] = {k: row[k] for k in PROGRESS_FIELDS}
        return cls(record, row["created_at"], row["finished_at"], row["heartbeat"], row["owner"])

    def failed(self, error: str) -> JobSnapshot:
        """This job as failed with ``error`` (finished at its last heartbeat)."""
        progress = {**self.record["progress"], "eta_seconds": None}
        record = {**self.record, "status": "failed", "error": error, "progress": progress}
        return replace(self, record=record, finished_at=self.heartbeat)


class BuildJobs:
    """Runs builds one after another in a background thread; each build uses ``processes``.

    Job state lives in the SQLite database ``<store.root>/jobs.sqlite3`` (module doc), so
    every process on the data directory answers for every job. ``clock`` (wall clock, s) is
    injectable for tests of staleness.
    """

    def __init__(
        self,
        store: MapStore,
        processes: int | None = None,
        max_jobs: int = 64,
        max_active: int = 8,
        publish_interval: float = PUBLISH_INTERVAL,
        stale_seconds: float = STALE_SECONDS,
        clock: Callable[[], float] = time.time,
    ):
        self.store = store
        self.processes = processes or default_processes()
        self.max_jobs = max_jobs
        self.max_active = max_active
        self.publish_interval = publish_interval
        self.stale_seconds = stale_seconds
        self.clock = clock
        self.jobs: dict[str, BuildJob] = {}
        self.table = JobTable(store.root / DB_FILE)
        #: This instance's owner id in the database (one instance per process).
        self.owner = uuid.uuid4().hex
        self._lock = threading.Lock()  # jobs and their statuses
        self._queue: queue.Queue[tuple[RobotModel, BuildJob]] = queue.Queue()
        self._thread: threading.Thread | None = None
        self._publisher: threading.Thread | None = None
        self._publish_failing = False

    def _values(self, job: BuildJob) -> dict[str, Any]:
        data = job.to_json()
        return {
            **{k: data[k] for k in ("job_id", "robot_id", "frame", "status", "map_id", "error")},
            **data["progress"],
            "created_at": job.created_at,
            "finished_at": job.finished_at,
            "owner": self.owner,
            "heartbeat": self.clock(),
            "cancel": 0,
        }

    def _update(self, conn: sqlite3.Connection, job: BuildJob) -> bool:
        """Write the job's state to its row if the row is still active; whether it was."""
        return self.table.update(conn, self._values(job))

    def _stale(self, snap: JobSnapshot) -> bool:
        """Whether the row says queued/running but its owner's heartbeat stopped."""
        return snap.status in ACTIVE and self.clock() - snap.heartbeat > self.stale_seconds

    def _resolved(self, snaps: list[JobSnapshot]) -> list[JobSnapshot]:
        """The snapshots, those whose owner is gone marked failed (in the database too:
        nobody will ever finish them)."""
        gone = [s for s in snaps if self._stale(s)]
        ids = {s.job_id for s in gone}
        if gone:
            self.table.fail([(s.job_id, s.heartbeat) for s in gone], OWNER_GONE)
        return [s.failed(OWNER_GONE) if s.job_id in ids else s for s in snaps]

    def _read(self, job_id: str) -> JobSnapshot | None:
        """The row of ``job_id`` (a valid id), resolved; ``None`` if there is none."""
        row = self.table.read(job_id)
        return None if row is None else self._resolved([JobSnapshot.from_row(row)])[0]

    def _rows(self, robot_id: str, skip: set[str]) -> list[JobSnapshot]:
        """The robot's rows but those of ``skip`` (job ids), resolved."""
        rows = self.table.rows(robot_id)
        return self._resolved([JobSnapshot.from_row(r) for r in rows if r["job_id"] not in skip])

    # ------------------------------------------------------------------- jobs
    def submit(self, robot: RobotModel, spec: MapSpec) -> BuildJob:
        with self._lock:
            active = {j.job_id for j in self.jobs.values() if j.status in ACTIVE}
            if len(active) >= self.max_active:
                raise ConflictError(
                    f"{len(active)} builds are already queued or running; cancel one or wait",
                    "robot_id",
                )
            job = BuildJob(
                uuid.uuid4().hex, robot.id, spec, Progress(spec.samples), created_at=self.clock()
            )
            with self.table.transaction(write=True) as conn:
                self.table.insert(conn, self._values(job))
                self.table.housekeep(conn, self.max_jobs)
            for old in [i for i in self.jobs if i not in active]:
                if len(self.jobs) < self.max_jobs:
                    break
                del self.jobs[old]
            self.jobs[job.job_id] = job
            # daemon threads: a build in progress never holds up the process's exit
            if self._thread is None:
                self._thread = threading.Thread(
                    target=self._loop, name="reachability-builds", daemon=True
                )
                self._thread.start()
            if self._publisher is None:
                self._publisher = threading.Thread(
                    target=self._publish_loop, name="reachability-jobs", daemon=True
                )
                self._publisher.start()
        self._queue.put((robot, job))
        return job

    def _loop(self) -> None:
        while True:
            robot, job = self._queue.get()
            self._run(robot, job)

    def _publish_loop(self) -> None:
        """Heartbeat: refresh the rows of active jobs and act on their cancel flags; ends
        when no job is active (:meth:`submit` starts it again)."""
        while True:
            time.sleep(self.publish_interval)
            with self._lock:
                active = [j for j in self.jobs.values() if j.status in ACTIVE]
                if not active:
                    self._publisher = None
                    return
            try:
                self._heartbeat(active)
            except UnavailableError as exc:
                if not self._publish_failing:
                    log.warning("cannot publish build jobs: %s", exc.message)
                self._publish_failing = True
            except Exception:  # never let the thread die while jobs depend on it
                log.exception("publishing build jobs failed")
            else:
                self._publish_failing = False

    def _heartbeat(self, active: list[BuildJob]) -> None:
        with self._lock, self.table.transaction(write=True) as conn:
            for job in active:
                if job.status not in ACTIVE:
                    continue
                if not self._update(conn, job):  # failed by another process (stale owner)
                    self._adopt(conn, job)
                    continue
                if self.table.row(conn, job.job_id)["cancel"]:
                    self._cancel(job, conn)

    def _adopt(self, conn: sqlite3.Connection, job: BuildJob) -> None:
        """Take over the final state another process gave the row of an own job (lock
        held), and stop the build."""
        row = self.table.row(conn, job.job_id)
        job.progress.cancel.set()
        if job.progress.finished is None:
            job.progress.finished = time.monotonic()
        if row is None:
            job.status, job.error = "failed", OWNER_GONE
        else:
            job.map_id, job.error, job.finished_at = row["map_id"], row["error"], row["finished_at"]
            job.status = row["status"]

    def get(self, robot_id: str, job_id: str) -> BuildJob | JobSnapshot:
        """The job: this process's own, else another process's row."""
        job = self.jobs.get(job_id)
        if job is not None and job.robot_id == robot_id:
            return job
        snap = self._read(job_id) if job is None and valid_id(job_id) else None
        if snap is not None and snap.robot_id == robot_id:
            return snap
        known = [j.job_id for j in self.list(robot_id)]
        raise UnknownNameError("job", job_id, "job_id", known)

    def list(self, robot_id: str) -> list[BuildJob | JobSnapshot]:
        """The robot's jobs, this process's and the others', oldest first."""
        with self._lock:
            own = [j for j in self.jobs.values() if j.robot_id == robot_id]
            ids = set(self.jobs)
        others = self._rows(robot_id, ids)
        return sorted([*own, *others], key=lambda j: j.created_at)

    def cancel(self, robot_id: str, job_id: str) -> BuildJob | JobSnapshot:
        """Cancel a queued or running build (idempotent); a finished one is a conflict.

        Another process's job gets its cancel flag set, which its owner acts on within
        :data:`PUBLISH_INTERVAL` s; the snapshot returned is the job before that.
        """
        job = self.get(robot_id, job_id)
        if isinstance(job, JobSnapshot):
            if job.status in ("done", "failed"):
                raise ConflictError(f"the job has already {job.status}", "job_id")
            if job.status in ACTIVE:
                self.table.request_cancel(job_id)
            return job
        with self._lock:
            if job.status in ("done", "failed"):
                raise ConflictError(f"the job has already {job.status}", "job_id")
            if job.status in ACTIVE:
                self._cancel(job)
        return job

    def close(self) -> None:
        """Cancel this instance's queued and running builds (at application shutdown): a
        queued one ends ``cancelled`` at once, a running one's build processes stop within
        a moment and it ends ``cancelled``; other processes' jobs are left alone."""
        with self._lock:
            for job in [j for j in self.jobs.values() if j.status in ACTIVE]:
                self._cancel(job)

    def _cancel(self, job: BuildJob, conn: sqlite3.Connection | None = None) -> None:
        """Cancel an own job (lock held): a queued one at once (in transaction ``conn``, else
        its own), a running one when :func:`build_map` next looks at ``progress.cancel``."""
        job.progress.cancel.set()
        if job.status == "queued":
            if conn is None:
                self._end(job, "cancelled")
            else:
                self._finish(job, conn, "cancelled")

    def _finish(
        self,
        job: BuildJob,
        conn: sqlite3.Connection,
        status: str,
        map_id: str | None = None,
        error: str | None = None,
    ) -> None:
        """Write the job's final state, then make it final in memory (lock held). A row
        another process has already failed (stale heartbeat) keeps its state."""
        if job.progress.finished is None:
            job.progress.finished = time.monotonic()
        final = replace(job, status=status, map_id=map_id, error=error, finished_at=self.clock())
        if not self._update(conn, final):
            self._adopt(conn, job)
            return
        job.map_id, job.error, job.finished_at = map_id, error, final.finished_at
        job.status = status

    def _end(
        self, job: BuildJob, status: str, map_id: str | None = None, error: str | None = None
    ) -> None:
        """:meth:`_finish` in its own transaction (lock held); if the database fails, the
        job still ends in memory (this process answers for it) and the failure is logged."""
        try:
            with self.table.transaction(write=True) as conn:
                self._finish(job, conn, status, map_id, error)
        except UnavailableError as exc:
            log.warning("cannot record the end of build job %s: %s", job.job_id, exc.message)
            if job.progress.finished is None:
                job.progress.finished = time.monotonic()
            job.map_id, job.error, job.finished_at = map_id, error, self.clock()
            job.status = status

    def _run(self, robot: RobotModel, job: BuildJob) -> None:
        with self._lock:
            if job.status != "queued":  # cancelled while queued
                return
            try:
                with self.table.transaction(write=True) as conn:
                    if not self._update(conn, replace(job, status="running")):
                        self._adopt(conn, job)
                        return
            except UnavailableError as exc:
                log.warning("cannot record the start of build job %s: %s", job.job_id, exc.message)
            job.status = "running"
        try:
            best = build_map(robot, job.spec, job.progress, self.processes)
            job.progress.finished = time.monotonic()
            took = job.progress.elapsed()
            meta = {
                "map_id": uuid.uuid4().hex,
                "created_at": datetime.now(UTC).isoformat(),
                "spec": asdict(job.spec),
                "joints": [robot.joint_names[i] for i in job.spec.chain_wire],
                "robot_fingerprint": robot_fingerprint(robot),
                "build_seconds": took,
                "samples_per_second": job.spec.samples / took if took > 0 else None,
                **summarize(best),
            }
            self.store.save(ReachabilityMap(meta, best))
        except Cancelled:
            outcome: tuple[str, str | None, str | None] = ("cancelled", None, None)
        except Exception as exc:  # reported on the job (and logged), not raised into the void
            log.exception("reachability build job %s failed", job.job_id)
            outcome = ("failed", None, f"{type(exc).__name__}: {exc}")
        else:
            outcome = ("done", meta["map_id"], None)
        with self._lock:
            self._end(job, *outcome)
