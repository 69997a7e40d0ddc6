"""The requests behind the OpenAPI examples: run them, record them, compare answers.

:data:`tests.openapi_scenario.EXCHANGES` is the scenario, in order: requests for every
operation of the document (its 2xx answers) and a table of error requests (one per status
the service answers, each on a named operation). ``scripts/record_examples.py`` (``make
examples``) runs it against fresh apps and writes :data:`EXAMPLES`
(``app/api/examples/exchanges.json``, which :mod:`app.middleware.openapi_examples` puts
into the document); tests/test_openapi_examples.py runs the recorded requests again and
compares the answers with :func:`differences`.

A request spec: ``name`` (unique; the example's key), ``operation`` (its operationId),
``method``, ``path``, and at most one body: ``json``, ``text`` (with ``content_type``),
``form`` + ``files`` (multipart; file contents base64) or ``filler`` (that many spaces).
``headers`` are sent as given. ``app`` picks the service: ``started`` (default), ``token``
(write protection on, token :data:`TOKEN`) or ``unstarted`` (lifespan not run). ``bind``
stores answer fields for later requests: ``{"job_id": "job_id"}`` sets ``{job_id}``
(substituted in paths and in JSON string values). ``until`` repeats a request (every 20 ms,
at most :data:`MAX_POLLS` times) until the answer's ``field`` equals ``value``. ``shared``
makes an error answer the document's shared example of its status. ``doc: false`` keeps a
request out of the document (a step the scenario needs, e.g. an extra build to cancel).

Volatile values: the JSON members named in :data:`VOLATILE_KEYS` (job and map ids, times,
durations, a running job's progress) and in a spec's ``volatile`` (a job answered while it
may be queued, running or done) are compared by type only (and not even that when one is
null); job and map ids (32 hex digits) inside strings are masked; the ``/metrics`` text is
compared by its ``# TYPE`` lines (its counts and latencies depend on what ran before).
Numbers elsewhere are compared within :data:`TOLERANCE` (absolute, or relative to the
recorded value); strings, booleans, nulls, keys and list lengths exactly. Binary answers
(the PNG slice) are compared by length and a SHA-256 prefix. ``X-Request-ID`` is sent by
every request (``example-<name>``), so its echo is exact.
"""

from __future__ import annotations

import base64
import hashlib
import json
import math
import re
import tempfile
import time
from collections.abc import Iterator
from contextlib import ExitStack, contextmanager
from pathlib import Path
from typing import Any

from fastapi.testclient import TestClient

from app.main import create_app
from app.operations.settings import Settings

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "app" / "api" / "examples" / "exchanges.json"
#: Binary answers (the PNG slice) as files, served at /static/examples/ (the document's
#: ``externalValue``).
STATIC_EXAMPLES = ROOT / "app" / "static" / "examples"

#: Absolute or relative tolerance of recorded numbers.
TOLERANCE = 1e-9
#: JSON members whose values change from run to run (compared by type only).
VOLATILE_KEYS = frozenset(
    {
        "job_id",
        "map_id",
        "created_at",
        "started_at",
        "finished_at",
        "updated_at",
        "elapsed_ms",
        "elapsed_s",
        "duration_ms",
        "duration_s",
        "build_s",
        "eta_s",
        "time_ms",
        "solve_ms",
        "compute_ms",
        "elapsed_seconds",
        "samples_per_second",
        "eta_seconds",
        "solve_time_ms",
        "total_time_ms",
        "build_seconds",
    }
)
#: A job or map id (in a URL or a message): masked where strings are compared.
_ID = re.compile(r"[0-9a-f]{32}")
#: The write token of the ``token`` app.
TOKEN = "example-token"
#: Polls of an ``until`` request before giving up.
MAX_POLLS = 3000
#: Response headers that are the transport's, not the service's (not compared, not declared).
TRANSPORT_HEADERS = frozenset({"content-length", "content-type", "date", "server", "connection"})


@contextmanager
def clients() -> Iterator[dict[str, TestClient]]:
    """The three services of the scenario, each on a fresh data directory."""
    with ExitStack() as stack:
        tmp = Path(stack.enter_context(tempfile.TemporaryDirectory()))
        started = TestClient(
            create_app(Settings(data_dir=tmp / "a")), raise_server_exceptions=False
        )
        token = TestClient(
            create_app(Settings(data_dir=tmp / "b", api_token=TOKEN)),
            raise_server_exceptions=False,
        )
        unstarted = TestClient(
            create_app(Settings(data_dir=tmp / "c")), raise_server_exceptions=False
        )
        stack.enter_context(started)
        stack.enter_context(token)
        yield {"started": started, "token": token, "unstarted": unstarted}


def _fill(value: Any, bound: dict[str, str]) -> Any:
    if isinstance(value, str):
        return re.sub(r"\{(\w+)\}", lambda m: bound.get(m.group(1), m.group(0)), value)
    if isinstance(value, dict):
        return {k: _fill(v, bound) for k, v in value.items()}
    if isinstance(value, list):
        return [_fill(v, bound) for v in value]
    return value


def send(client: TestClient, spec: dict[str, Any], bound: dict[str, str]):
    """Send the request of ``spec`` (its ``{name}`` placeholders filled from ``bound``)."""
    headers = {"X-Request-ID": f"example-{spec['name']}", **spec.get("headers", {})}
    kw: dict[str, Any] = {}
    if "json" in spec:
        kw["json"] = _fill(spec["json"], bound)
    elif "text" in spec:
        kw["content"] = spec["text"].encode()
        headers["Content-Type"] = spec["content_type"]
    elif "files" in spec:
        kw["data"] = spec["form"]
        kw["files"] = {
            field: (name, base64.b64decode(data), media)
            for field, (name, media, data) in spec["files"].items()
        }
    elif "filler" in spec:
        kw["content"] = b" " * spec["filler"]
    path = _fill(spec["path"], bound)
    return client.request(spec["method"], path, headers=headers, **kw)


def answer(resp) -> dict[str, Any]:
    """The recorded form of a response: status, media type, service headers, body."""
    media = resp.headers.get("content-type", "").split(";")[0].strip()
    out: dict[str, Any] = {
        "status": resp.status_code,
        "content_type": media or None,
        "headers": {
            k.lower(): v
            for k, v in sorted(resp.headers.items())
            if k.lower() not in TRANSPORT_HEADERS
        },
    }
    if not resp.content:
        return out
    if media.endswith("json"):
        out["json"] = resp.json()
    else:
        try:
            out["text"] = resp.content.decode()
        except UnicodeDecodeError:
            out["bytes"] = len(resp.content)
            out["sha256"] = hashlib.sha256(resp.content).hexdigest()[:16]
            out["_content"] = resp.content  # the recorder stores it (STATIC_EXAMPLES)
    return out


def run(specs: list[dict[str, Any]]) -> Iterator[tuple[dict[str, Any], dict[str, Any]]]:
    """Send ``specs`` in order; yields (spec, recorded answer)."""
    bound: dict[str, str] = {}
    with clients() as services:
        for spec in specs:
            client = services[spec.get("app", "started")]
            resp = send(client, spec, bound)
            until = spec.get("until")
            polls = 0
            while until and resp.json().get(until["field"]) != until["value"]:
                polls += 1
                if polls > MAX_POLLS or resp.status_code >= 400:
                    raise AssertionError(f"{spec['name']}: never {until}: {resp.text}")
                time.sleep(0.02)
                resp = send(client, spec, bound)
            recorded = answer(resp)
            for var, key in spec.get("bind", {}).items():
                bound[var] = str(recorded["json"][key])
            yield spec, recorded


def differences(
    expected: Any, got: Any, where: str = "", volatile: frozenset[str] = VOLATILE_KEYS
) -> list[str]:
    """Where ``got`` differs from the recorded ``expected`` (see the module docstring);
    members named in ``volatile`` are compared by type only."""
    key = where.rsplit(".", 1)[-1]
    if key in volatile:
        same = expected is None or got is None or type(expected) is type(got)
        return [] if same else [f"{where}: {got!r} (type changed)"]
    if isinstance(expected, dict) and isinstance(got, dict):
        out = [f"{where}.{k}: missing" for k in expected if k not in got]
        out += [f"{where}.{k}: unexpected" for k in got if k not in expected]
        for k in expected.keys() & got.keys():
            out += differences(expected[k], got[k], f"{where}.{k}", volatile)
        return out
    if isinstance(expected, list) and isinstance(got, list):
        if len(expected) != len(got):
            return [f"{where}: {len(got)} items, recorded {len(expected)}"]
        return [
            d
            for i, (e, g) in enumerate(zip(expected, got, strict=True))
            for d in differences(e, g, f"{where}.{i}", volatile)
        ]
    numbers = (int, float)
    if (
        isinstance(expected, numbers)
        and isinstance(got, numbers)
        and not isinstance(expected, bool)
        and not isinstance(got, bool)
    ):
        if math.isclose(expected, got, rel_tol=TOLERANCE, abs_tol=TOLERANCE):
            return []
        return [f"{where}: {got!r}, recorded {expected!r} (tolerance {TOLERANCE})"]
    if isinstance(expected, str) and isinstance(got, str):  # ids in URLs and messages
        expected, got = _ID.sub("<id>", expected), _ID.sub("<id>", got)
    return [] if expected == got else [f"{where}: {got!r}, recorded {expected!r}"]


def load() -> list[dict[str, Any]]:
    """The recorded exchanges (``request`` spec and ``response``), in scenario order."""
    return json.loads(EXAMPLES.read_text())["exchanges"]
