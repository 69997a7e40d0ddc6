"""The committed docs/openapi.json is what the app serves, and the schema follows the API
conventions (snake_case operation ids, problem+json errors)."""

from __future__ import annotations

import json
import re
from pathlib import Path

COMMITTED = Path(__file__).resolve().parents[1] / "docs" / "openapi.json"


def _operations(schema: dict) -> list[tuple[str, str, dict]]:
    return [
        (method, path, op)
        for path, item in schema["paths"].items()
        for method, op in item.items()
        if isinstance(op, dict)
    ]


def test_committed_schema_matches_the_app(client) -> None:
    served = client.get("/openapi.json").json()
    committed = json.loads(COMMITTED.read_text())
    if served != committed:
        ours = {(m, p) for m, p, _ in _operations(served)}
        theirs = {(m, p) for m, p, _ in _operations(committed)}
        added = sorted(ours - theirs)
        removed = sorted(theirs - ours)
        raise AssertionError(
            "docs/openapi.json is out of date: run `make openapi` and commit it "
            f"(operations added: {added}, removed: {removed}, or models/docs changed)"
        )


def test_operation_ids_are_unique_snake_case(client) -> None:
    ops = _operations(client.get("/openapi.json").json())
    ids = [op.get("operationId") for _, _, op in ops]
    assert all(i and re.fullmatch(r"[a-z][a-z0-9_]*", i) for i in ids), ids
    assert len(ids) == len(set(ids))
    assert all(op.get("tags") for _, _, op in ops)


def test_every_error_response_is_problem_json(client) -> None:
    schema = client.get("/openapi.json").json()
    assert "HTTPValidationError" not in schema["components"]["schemas"]
    for method, path, op in _operations(schema):
        for code, response in op["responses"].items():
            if code.startswith(("4", "5")):
                assert list(response["content"]) == ["application/problem+json"], (
                    method,
                    path,
                    code,
                )
                assert response["content"]["application/problem+json"]["schema"]


def test_errors_the_middleware_can_send_are_documented(client) -> None:
    schema = client.get("/openapi.json").json()
    for method, path, op in _operations(schema):
        codes = set(op["responses"])
        if "requestBody" in op:
            assert {"400", "413", "422"} <= codes, (method, path)
        if "{" in path:
            assert "404" in codes, (method, path)
    guarded = schema["paths"]["/scenes"]["post"]["responses"]
    assert {"401", "403"} <= set(guarded)
