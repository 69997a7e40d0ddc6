"""The child process of :mod:`app.robots.documents.sandbox`: one task on one untrusted document.

Run as ``python -I -c 'from app.robots.documents.sandbox_child import main; main(<parent pid>)'``
with an empty environment. It makes itself die with its parent (``PR_SET_PDEATHSIG``),
reads one JSON request from stdin, imports the task's module (trusted code, before any
limit), bounds itself (address space, CPU time, no file writes, no new processes, few open
files), runs the task on the request's arguments and writes one JSON answer to stdout:
``{"result": ...}`` or ``{"error": message, "field": field}``.

A task is a function of its JSON arguments returning a JSON value; it raises
:class:`~app.kinematics.errors.InvalidInputError` to refuse the document (its message and
field are the answer). Any other exception is the document's too: its type is named,
never its text (which may hold paths of this host). A task may say what it is reading
(:func:`progress`) so that a limit hit while reading it names it.
"""

from __future__ import annotations

import importlib
import json
import os
import resource
import sys
from typing import Any

from app.kinematics.errors import InvalidInputError
from app.workers.procwatch import set_parent_death_signal

#: Task name → ``module:function``.
TASKS = {
    "xacro": "app.robots.documents.xacro_child:run",
    "mjcf": "app.robots.documents.mjcf_urdf:convert_in_child",
    "meshes": "app.robots.documents.mesh_check:check_in_child",
}


def progress(what: str) -> None:
    """Tell the parent what this task reads now (one line on stdout, before the answer)."""
    sys.stdout.buffer.write(json.dumps({"at": what}).encode("utf-8", "surrogatepass") + b"\n")
    sys.stdout.buffer.flush()


def limit_self(memory_bytes: int, cpu_s: int) -> None:
    """Bound this process: address space, CPU time, no file writes or new processes."""
    try:
        with open("/proc/self/statm") as f:
            used = int(f.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
    except OSError:  # pragma: no cover - not Linux
        used = 256 * 1024 * 1024
    limits = {
        resource.RLIMIT_AS: used + memory_bytes,
        resource.RLIMIT_CPU: cpu_s,
        resource.RLIMIT_FSIZE: 0,
        resource.RLIMIT_NOFILE: 32,
        resource.RLIMIT_NPROC: 0,
        resource.RLIMIT_CORE: 0,
    }
    for which, value in limits.items():
        try:
            resource.setrlimit(which, (value, value))
        except (ValueError, OSError):  # pragma: no cover - already lower, or not allowed
            pass


def _answer(request: dict[str, Any]) -> dict[str, Any]:
    try:
        module, name = TASKS[request["task"]].split(":")
        run = getattr(importlib.import_module(module), name)
    except (KeyError, ImportError, AttributeError) as exc:  # pragma: no cover - our bug
        return {"error": f"no such task ({type(exc).__name__})", "field": None}
    limit_self(int(request["memory_bytes"]), int(request["cpu_s"]))
    try:
        return {"result": run(request["args"])}
    except InvalidInputError as exc:
        return {"error": exc.message, "field": exc.field}
    except MemoryError:
        return {"error": "it ran out of memory", "field": None}
    except RecursionError:
        return {"error": "it is nested too deeply (recursion)", "field": None}
    except Exception as exc:  # noqa: BLE001 - every failure is the client's document
        return {"error": f"it cannot be read ({type(exc).__name__})", "field": None}


def main(parent: int | None = None) -> None:
    """Read the request from stdin, run its task, write the answer to stdout.

    ``parent`` is the PID of the process that started this one: if it is already gone
    (this process was re-parented before it could ask for the death signal), this process
    is killed at once (see :func:`app.workers.procwatch.set_parent_death_signal`).
    """
    set_parent_death_signal(parent=parent)
    request = json.loads(sys.stdin.buffer.read())
    answer = _answer(request)
    sys.stdout.buffer.write(json.dumps(answer).encode("utf-8", "surrogatepass"))
    sys.stdout.buffer.flush()
