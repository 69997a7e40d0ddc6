"""What the app holds while it serves: stores, build jobs and work pools, made by the lifespan.

:func:`app.main.lifespan` opens one :class:`Services` at start-up (``app.state.services``)
and closes it at shutdown; routes reach its parts through the typed dependencies of
:mod:`app.api.deps` (or :func:`services` where they hold a connection, as the stream and the
work-pool helpers of :mod:`app.api.offload` do). Nothing here is made on first use: an app
whose lifespan has not run answers 503 (``UnavailableError``) where it would need them.
"""

from __future__ import annotations

import os
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass

from starlette.requests import HTTPConnection

from app.kinematics.errors import UnavailableError
from app.operations.settings import Settings
from app.storage.build_jobs import BuildJobs
from app.storage.maps import MapStore
from app.storage.scenes import SceneStore
from app.workers import default_processes
from app.workers.ik_batch import BatchPool

#: The error of a request that needs the services of an app whose lifespan has not run.
NOT_STARTED = "the service is not started (its lifespan has not run, or has ended)"


@dataclass(frozen=True, slots=True)
class Services:
    """The app's long-lived parts (one per app, :func:`open_services`).

    Attributes
    ----------
    scenes
        The scene store, ``<data_dir>/scenes``.
    maps
        The reachability map store, ``<data_dir>/maps``.
    jobs
        The reachability build queue on ``maps`` (its job table in the same directory).
    compute
        The bounded pool of long work (IK with big budgets, batches, reachability queries):
        one thread per core (Pinocchio work holds the GIL for short stretches only).
    uploads
        The pool of robot uploads, ``DENAVIT_UPLOAD_WORKERS`` threads: never the compute
        pool, so slow uploads never hold a compute request.
    ik_batch
        The worker processes of independent IK batches (``DENAVIT_IK_BATCH_PROCESSES``,
        default every core); its processes start with its first batch.
    """

    scenes: SceneStore
    maps: MapStore
    jobs: BuildJobs
    compute: ThreadPoolExecutor
    uploads: ThreadPoolExecutor
    ik_batch: BatchPool

    def close(self) -> None:
        """Stop what runs: queued builds and the builds running are cancelled, pooled work
        not yet started is dropped, and the batch IK workers are joined (their running
        chunks finish first). Threads already running a request's work finish it."""
        self.jobs.close()
        self.ik_batch.shutdown()
        self.compute.shutdown(wait=False, cancel_futures=True)
        self.uploads.shutdown(wait=False, cancel_futures=True)


def open_services(settings: Settings) -> Services:
    """The :class:`Services` of an app with ``settings`` (no thread or process starts yet)."""
    maps = MapStore(settings.data_dir / "maps")
    return Services(
        scenes=SceneStore(settings.data_dir / "scenes"),
        maps=maps,
        jobs=BuildJobs(maps),
        compute=ThreadPoolExecutor(max_workers=os.cpu_count() or 2, thread_name_prefix="work"),
        uploads=ThreadPoolExecutor(
            max_workers=settings.upload_workers, thread_name_prefix="upload"
        ),
        ik_batch=BatchPool(settings.ik_batch_processes or default_processes()),
    )


def services(conn: HTTPConnection) -> Services:
    """The services of the app serving ``conn`` (a request or a WebSocket).

    Raises
    ------
    UnavailableError
        The app's lifespan has not run (503).
    """
    found = getattr(conn.app.state, "services", None)
    if found is None:
        raise UnavailableError(NOT_STARTED)
    return found
