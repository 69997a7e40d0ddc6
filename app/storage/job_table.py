"""The SQLite table of reachability build jobs (``<data_dir>/maps/jobs.sqlite3``).

One row per job: its public fields (status, map id, error, the progress figures of
:meth:`app.storage.build_jobs.BuildJob.to_json`), ``created_at`` and ``finished_at`` (wall clock,
s),
the ``owner`` (the random id of the :class:`app.storage.build_jobs.BuildJobs` instance that runs
it), the owner's ``heartbeat`` (wall clock, s) and a ``cancel`` flag. What the rows mean and
who writes them is :mod:`app.storage.build_jobs`; this module is the storage: the schema, one
connection per thread (``sqlite3`` connections are not shared across threads), WAL journal
(readers never wait for the writer), ``busy_timeout`` for writers of other processes and
short transactions. Any database or file-system failure (a corrupt file, a read-only
directory, a full disk) raises :class:`~app.kinematics.errors.UnavailableError` naming the
file; the connection is dropped, so the next use opens it again.
"""

from __future__ import annotations

import sqlite3
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from app.kinematics.errors import UnavailableError

#: Statuses of a job that is not finished yet.
ACTIVE = ("queued", "running")
STATUSES = (*ACTIVE, "done", "failed", "cancelled")
#: The database file, in the map store's root (a name no robot directory can take).
DB_FILE = "jobs.sqlite3"
#: How long (ms) a connection waits for another process's write transaction.
BUSY_TIMEOUT_MS = 10_000

_SCHEMA = """
CREATE TABLE IF NOT EXISTS jobs (
    job_id TEXT PRIMARY KEY,
    robot_id TEXT NOT NULL,
    frame TEXT NOT NULL,
    status TEXT NOT NULL,
    map_id TEXT,
    error TEXT,
    percent REAL NOT NULL,
    samples_done INTEGER NOT NULL,
    samples_total INTEGER NOT NULL,
    samples_per_second REAL,
    elapsed_seconds REAL NOT NULL,
    eta_seconds REAL,
    created_at REAL NOT NULL,
    finished_at REAL,
    owner TEXT NOT NULL,
    heartbeat REAL NOT NULL,
    cancel INTEGER NOT NULL DEFAULT 0
);
CREATE INDEX IF NOT EXISTS jobs_robot ON jobs (robot_id, created_at);
"""
#: The progress figures of a job, one column each.
PROGRESS_FIELDS = (
    "percent",
    "samples_done",
    "samples_total",
    "samples_per_second",
    "elapsed_seconds",
    "eta_seconds",
)
COLUMNS = (
    "job_id", "robot_id", "frame", "status", "map_id", "error", *PROGRESS_FIELDS,
    "created_at", "finished_at", "owner", "heartbeat", "cancel",
)  # fmt: skip
#: Columns an owner rewrites on every update (not the identity, creation or cancel flag).
_UPDATED = [c for c in COLUMNS if c not in ("job_id", "created_at", "owner", "cancel")]
_ACTIVE_SQL = "('queued', 'running')"


class JobTable:
    """The ``jobs`` table of the database at ``path`` (created on first use)."""

    def __init__(self, path: Path) -> None:
        self.path = Path(path)
        self._local = threading.local()  # one connection per thread

    def _connect(self) -> sqlite3.Connection:
        """This thread's connection, opened (and the schema created) on first use."""
        conn = getattr(self._local, "conn", None)
        if conn is not None:
            return conn
        self.path.parent.mkdir(parents=True, exist_ok=True)
        conn = sqlite3.connect(self.path, timeout=BUSY_TIMEOUT_MS / 1000, isolation_level=None)
        try:
            conn.row_factory = sqlite3.Row
            conn.execute(f"PRAGMA busy_timeout = {BUSY_TIMEOUT_MS}")
            conn.execute("PRAGMA journal_mode = WAL")
            conn.execute("PRAGMA synchronous = NORMAL")  # job state is ephemeral
            conn.executescript(_SCHEMA)
        except BaseException:
            conn.close()
            raise
        self._local.conn = conn
        return conn

    @contextmanager
    def transaction(self, write: bool = False) -> Iterator[sqlite3.Connection]:
        """A short transaction on this thread's connection (``write``: take the write lock
        at once, so it never fails half-way on a lock)."""
        try:
            conn = self._connect()
            conn.execute("BEGIN IMMEDIATE" if write else "BEGIN")
            try:
                yield conn
            except BaseException:
                conn.rollback()
                raise
            conn.commit()
        except (sqlite3.Error, OSError) as exc:
            conn = getattr(self._local, "conn", None)
            self._local.conn = None
            if conn is not None:
                conn.close()
            raise UnavailableError(
                f"the build job database {self.path.name} is unusable: {exc}"
            ) from exc

    @staticmethod
    def insert(conn: sqlite3.Connection, values: dict[str, Any]) -> None:
        """Add a row (``values``: every column of :data:`COLUMNS`)."""
        names = ", ".join(COLUMNS)
        marks = ", ".join(f":{c}" for c in COLUMNS)
        conn.execute(f"INSERT INTO jobs ({names}) VALUES ({marks})", values)

    @staticmethod
    def update(conn: sqlite3.Connection, values: dict[str, Any]) -> bool:
        """Rewrite the row of ``values["job_id"]`` if ``values["owner"]`` owns it and it is
        still active; whether it was."""
        sets = ", ".join(f"{c} = :{c}" for c in _UPDATED)
        cur = conn.execute(
            f"UPDATE jobs SET {sets} WHERE job_id = :job_id AND owner = :owner "
            f"AND status IN {_ACTIVE_SQL}",
            values,
        )
        return cur.rowcount == 1

    @staticmethod
    def row(conn: sqlite3.Connection, job_id: str) -> sqlite3.Row | None:
        return conn.execute("SELECT * FROM jobs WHERE job_id = ?", (job_id,)).fetchone()

    def read(self, job_id: str) -> sqlite3.Row | None:
        """The row of ``job_id``, if any."""
        with self.transaction() as conn:
            return self.row(conn, job_id)

    def rows(self, robot_id: str) -> list[sqlite3.Row]:
        """The rows of the robot's jobs."""
        with self.transaction() as conn:
            return conn.execute("SELECT * FROM jobs WHERE robot_id = ?", (robot_id,)).fetchall()

    def fail(self, jobs: list[tuple[str, float]], error: str) -> None:
        """Mark failed with ``error`` the (job id, heartbeat) rows that are still active with
        that heartbeat (finished at it): an owner that came back in between keeps its job."""
        with self.transaction(write=True) as conn:
            conn.executemany(
                "UPDATE jobs SET status = 'failed', error = ?, eta_seconds = NULL, "
                f"finished_at = heartbeat WHERE job_id = ? AND status IN {_ACTIVE_SQL} "
                "AND heartbeat = ?",
                [(error, job_id, heartbeat) for job_id, heartbeat in jobs],
            )

    def request_cancel(self, job_id: str) -> None:
        """Set the cancel flag of the job's row (its owner acts on it)."""
        with self.transaction(write=True) as conn:
            conn.execute("UPDATE jobs SET cancel = 1 WHERE job_id = ?", (job_id,))

    @staticmethod
    def housekeep(conn: sqlite3.Connection, keep: int) -> None:
        """Delete the oldest finished rows beyond the ``keep`` newest."""
        conn.execute(
            f"DELETE FROM jobs WHERE status NOT IN {_ACTIVE_SQL} AND job_id NOT IN "
            f"(SELECT job_id FROM jobs WHERE status NOT IN {_ACTIVE_SQL} "
            "ORDER BY created_at DESC LIMIT ?)",
            (keep,),
        )
