"""Untrusted parsing in a bounded child process: xacro, MJCF, meshes.

Every parser that can stall or balloon on a client's document runs in a child process of
its own (:mod:`app.robots.documents.sandbox_child`), never in a server worker: a worker whose
native code holds the GIL for 5 s is killed by uvicorn's supervisor as hung, with every
request in flight. The child:

- is ``python -I -B`` with an empty environment, started in ``/``;
- dies with the thread that waits for it (``PR_SET_PDEATHSIG``, as
  :mod:`app.workers.procwatch` does for reachability builds);
- is bounded once its modules are imported: address space (``memory_bytes`` over what it
  uses then), CPU time, no file writes, no new processes, few open files;
- is killed after ``timeout_s`` of wall-clock time; its answer is read up to
  ``max_output_bytes``.

It reads one JSON request on stdin and writes one JSON answer on stdout: ``{"result":
...}`` or ``{"error": message, "field": field}``, after any number of progress lines
``{"at": what}`` (what it reads now). Any other end (a signal, a limit, no answer) is an
:class:`~app.kinematics.errors.InvalidInputError` naming the request field, the setting
that bounds the child and, when the task said, what it was reading. The waiting thread
holds no lock and no GIL while the child works.
"""

from __future__ import annotations

import json
import math
import os
import selectors
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import app
from app.kinematics.errors import InvalidInputError

_CHILD = "from app.robots.documents.sandbox_child import main; main({pid})"


@dataclass(frozen=True, slots=True)
class ChildLimits:
    """The bounds of one child: wall-clock time (s), address space it may add (bytes),
    longest answer (bytes), and the settings that set them (named in refusals)."""

    timeout_s: float
    memory_bytes: int
    max_output_bytes: int
    timeout_setting: str
    memory_setting: str


#: Default bounds of the child that reads a package's meshes or converts its MJCF
#: (``DENAVIT_PARSE_TIMEOUT_S``, ``DENAVIT_PARSE_MEMORY_BYTES``).
PARSE_LIMITS = ChildLimits(
    60.0, 1 << 30, 1 << 24, "DENAVIT_PARSE_TIMEOUT_S", "DENAVIT_PARSE_MEMORY_BYTES"
)


def run_child(
    task: str, args: dict[str, Any], limits: ChildLimits, *, field: str, what: str
) -> Any:
    """Run ``task`` (a name of :data:`app.robots.documents.sandbox_child.TASKS`) on ``args`` in a
    bounded child; its result.

    Parameters
    ----------
    task, args
        What the child does, and its JSON arguments.
    limits
        The child's bounds.
    field, what
        The request field a refusal names, and what the child does (``xacro expansion``)
        in the refusal's words.

    Raises
    ------
    InvalidInputError
        The child's own refusal (its message and field), or the limit it hit.
    """
    request = {
        "task": task,
        "args": args,
        "memory_bytes": int(limits.memory_bytes),
        "cpu_s": math.ceil(1.5 * limits.timeout_s) + 1,  # a backstop: the wall clock rules
    }
    path = str(Path(app.__file__).parent.parent)
    code = f"import sys; sys.path.insert(0, {path!r}); {_CHILD.format(pid=os.getpid())}"
    proc = subprocess.Popen(
        [sys.executable, "-I", "-B", "-c", code],  # isolated, writes no bytecode
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        env={"OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"},
        cwd="/",
        close_fds=True,
    )
    chunks: list[bytes] = []

    def reading() -> str:
        """`` while reading <what>`` from the last progress line, if any."""
        for line in reversed(b"".join(chunks).split(b"\n")[:-1]):
            try:
                at = json.loads(line).get("at")
            except (ValueError, AttributeError):
                continue
            if isinstance(at, str):
                return f" while reading {at[:200]!r}"
        return ""

    try:
        assert proc.stdin is not None and proc.stdout is not None
        proc.stdin.write(json.dumps(request).encode("utf-8", "surrogatepass"))
        proc.stdin.close()
        size = 0
        deadline = time.monotonic() + limits.timeout_s
        with selectors.DefaultSelector() as sel:
            sel.register(proc.stdout, selectors.EVENT_READ)
            while True:
                left = deadline - time.monotonic()
                if left <= 0:
                    raise InvalidInputError(
                        f"{what} took longer than {limits.timeout_s:g} s{reading()} "
                        f"({limits.timeout_setting})",
                        field,
                    )
                if not sel.select(left):
                    continue
                data = os.read(proc.stdout.fileno(), 1 << 16)
                if not data:
                    break
                chunks.append(data)
                size += len(data)
                if size > limits.max_output_bytes:
                    raise InvalidInputError(
                        f"{what} gave an answer larger than {limits.max_output_bytes} bytes",
                        field,
                    )
        proc.wait(timeout=max(1.0, deadline - time.monotonic()))
    except subprocess.TimeoutExpired:
        raise InvalidInputError(f"{what} did not finish", field) from None
    except BrokenPipeError:  # the child died before it read its request
        pass
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        if proc.stdout is not None:
            proc.stdout.close()
    try:
        answer = json.loads(b"".join(chunks).rsplit(b"\n", 1)[-1])
    except ValueError:
        answer = None
    if not isinstance(answer, dict) or not ({"result", "error"} & answer.keys()):
        raise InvalidInputError(
            f"{what} failed{reading()}: it exceeded its memory or CPU limits (exit status "
            f"{proc.returncode}; {limits.memory_setting})",
            field,
        )
    if "error" in answer:
        if answer.get("field") is None:  # not a refusal of the task's own: how it failed
            memory = f" ({limits.memory_setting})" if "memory" in str(answer["error"]) else ""
            raise InvalidInputError(f"{what} failed{reading()}: {answer['error']}{memory}", field)
        raise InvalidInputError(str(answer["error"]), str(answer["field"]))
    return answer["result"]
