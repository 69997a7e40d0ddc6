"""The examples of the OpenAPI document are answers the service really gives.

Every recorded request (app/api/examples/exchanges.json, from the scenario of
tests/openapi_examples.py) is sent again to fresh apps and its answer compared with the
recording: status, media type, the service's headers, the body (numbers within
``TOLERANCE``; the volatile members, the metrics text and binary bodies as the helper's
docstring says). Every request body and response of the document has an example, and every
example is valid against its schema. A mismatch names the example; ``make examples``
records them again.
"""

from __future__ import annotations

import hashlib
import re
from typing import Any

from jsonschema_rs import Draft202012Validator

from tests.openapi_examples import VOLATILE_KEYS, differences, load, run
from tests.openapi_scenario import EXCHANGES

_ID = re.compile(r"[0-9a-f]{32}")
#: Header values that change from run to run (a file's time, ids in URLs): compared as
#: present only, or with their ids masked.
_VOLATILE_HEADERS = frozenset({"etag", "last-modified"})


def _types(text: str) -> list[str]:
    return sorted(line for line in text.splitlines() if line.startswith("# TYPE"))


def _answer_differences(
    spec: dict[str, Any], recorded: dict[str, Any], got: dict[str, Any]
) -> list[str]:
    out = [
        f"{key}: {got.get(key)!r}, recorded {recorded.get(key)!r}"
        for key in ("status", "content_type")
        if got.get(key) != recorded.get(key)
    ]
    if set(got["headers"]) != set(recorded["headers"]):
        out.append(f"headers: {sorted(got['headers'])}, recorded {sorted(recorded['headers'])}")
    for name in got["headers"].keys() & recorded["headers"].keys() - _VOLATILE_HEADERS:
        a, b = (_ID.sub("<id>", h["headers"][name]) for h in (got, recorded))
        if a != b:
            out.append(f"header {name}: {a!r}, recorded {b!r}")
    if spec["operation"] == "get_metrics":  # counts and latencies depend on what ran before
        if _types(got.get("text", "")) != _types(recorded["text"]):
            out.append("metrics: other `# TYPE` lines")
        return out
    volatile = frozenset(spec.get("volatile", ()))
    for kind in ("json", "text", "bytes", "sha256"):
        if (kind in got) != (kind in recorded):
            out.append(f"body: {kind} {'unexpected' if kind in got else 'missing'}")
        elif kind == "json" and kind in got:
            out += differences(recorded["json"], got["json"], "body", VOLATILE_KEYS | volatile)
        elif kind in got and got[kind] != recorded[kind]:
            out.append(f"body {kind}: differs from the recording")
    return out


def test_the_recording_is_of_the_current_scenario() -> None:
    """The scenario changed since the examples were recorded: run `make examples`."""
    recorded = [e["request"] for e in load()]
    names = [s["name"] for s in EXCHANGES]
    assert len(set(names)) == len(names)
    stale = [s["name"] for s, r in zip(EXCHANGES, recorded, strict=False) if s != r]
    assert len(recorded) == len(EXCHANGES) and not stale, (
        f"run `make examples`: requests changed since recording: {stale or 'count'}"
    )


def test_every_example_answer_is_what_the_service_answers() -> None:
    recorded = {e["request"]["name"]: e["response"] for e in load()}
    wrong = {}
    for spec, got in run(EXCHANGES):
        found = _answer_differences(spec, recorded[spec["name"]], got)
        if found:
            wrong[spec["name"]] = found[:5]
    assert not wrong, "examples that no longer match (`make examples` re-records them):\n" + (
        "\n".join(f"  {name}: {'; '.join(d)}" for name, d in wrong.items())
    )


def test_binary_examples_are_the_recorded_files(client) -> None:
    """The PNG the document links to is served, and is the recorded answer."""
    linked = [e["response"] for e in load() if "static" in e["response"]]
    assert linked
    for answer in linked:
        r = client.get(answer["static"])
        assert r.status_code == 200 and r.headers["content-type"] == answer["content_type"]
        assert hashlib.sha256(r.content).hexdigest()[:16] == answer["sha256"]


def _examples(schema: dict, content: dict) -> list[tuple[str, Any]]:
    out = []
    for name, example in content.get("examples", {}).items():
        if "$ref" in example:
            example = schema["components"]["examples"][example["$ref"].rsplit("/", 1)[1]]
        if "value" in example:
            out.append((name, example["value"]))
    return out


def _media(schema: dict):
    """(where, media content, is a request) of every body of every operation."""
    for path, item in schema["paths"].items():
        for method, op in item.items():
            for media, content in op.get("requestBody", {}).get("content", {}).items():
                yield f"{method.upper()} {path} request {media}", content, True
            for code, response in op["responses"].items():
                for media, content in (response.get("content") or {}).items():
                    yield f"{method.upper()} {path} {code} {media}", content, False


def test_every_request_body_and_response_has_an_example(app) -> None:
    schema = app.openapi()
    missing = [where for where, content, _ in _media(schema) if not content.get("examples")]
    assert not missing, missing
    responses = [
        (f"{m} {p} {code}", r)
        for p, item in schema["paths"].items()
        for m, op in item.items()
        for code, r in op["responses"].items()
    ]
    no_body = [
        w for w, r in responses if not r.get("content") and w.split()[-1] not in {"101", "204"}
    ]
    assert not no_body, no_body


def test_every_example_is_valid_against_its_schema(app) -> None:
    schema = app.openapi()
    invalid = []
    checked = 0
    for where, content, _ in _media(schema):
        body_schema = {**content["schema"], "components": schema["components"]}
        validator = Draft202012Validator(body_schema)
        for name, value in _examples(schema, content):
            checked += 1
            errors = [e.message for e in validator.iter_errors(value)]
            if errors:
                invalid.append(f"{where} example {name}: {errors[:2]}")
    assert not invalid, "\n".join(invalid)
    assert checked >= 100, checked
