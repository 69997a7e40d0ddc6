"""The committed docs/openapi.json is what the app serves, and the schema follows the API
conventions (snake_case operation ids, problem+json errors) and generates usable clients
(the bearer scheme on write routes, named request bodies, fixed-size pose arrays)."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

from tests.helpers import write_routes

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
        if "{" in path and op["operationId"] != "get_robot_stream":  # 426 whatever the id
            assert "404" in codes, (method, path)
    guarded = schema["paths"]["/scenes"]["post"]["responses"]
    assert {"401", "403"} <= set(guarded)


# ---------------------------------------------------------------------------------------------
# Generated clients: the bearer scheme, named request bodies, fixed-size pose arrays


def _resolve(schema: dict, node: dict) -> dict:
    """``node`` with a top-level ``$ref`` followed."""
    while "$ref" in node:
        node = schema["components"]["schemas"][node["$ref"].rsplit("/", 1)[1]]
    return node


def _refs(node) -> Iterator[str]:
    """Names of every component ``node`` refers to (directly)."""
    if isinstance(node, dict):
        if isinstance(node.get("$ref"), str):
            yield node["$ref"].rsplit("/", 1)[1]
        for value in node.values():
            yield from _refs(value)
    elif isinstance(node, list):
        for value in node:
            yield from _refs(value)


def _reachable(schema: dict, roots) -> set[str]:
    """Component names reachable from ``roots`` by $ref (transitively)."""
    seen: set[str] = set()
    todo = list(_refs(roots))
    while todo:
        name = todo.pop()
        if name not in seen:
            seen.add(name)
            todo.extend(_refs(schema["components"]["schemas"][name]))
    return seen


def _camel(operation_id: str) -> str:
    return "".join(part.capitalize() for part in operation_id.split("_"))


def test_bearer_scheme_is_declared_on_exactly_the_guarded_operations(app) -> None:
    """Derived from the routes' dependencies (as tests/test_production.py does), not a list.
    The bearer is optional there (the document's ``[{}, {bearerAuth: []}]``, inherited: the
    token is enforced only with DENAVIT_API_TOKEN set); open operations say ``security: []``
    (tests/test_openapi_statuses.py checks every operation)."""
    schema = app.openapi()
    scheme = schema["components"]["securitySchemes"]
    assert len(scheme) == 1
    (name, declared), *_ = scheme.items()
    assert declared["type"] == "http" and declared["scheme"].lower() == "bearer"
    guarded = {(m.lower(), p) for m, p, _ in write_routes(app)}
    assert guarded
    assert schema["security"] == [{}, {name: []}]  # optional: reads stay open
    for method, path, op in _operations(schema):
        if (method, path) in guarded:
            assert "security" not in op, (method, path)  # the document's optional bearer
        elif path != "/robots/{robot_id}/stream":
            assert op.get("security") == [], (method, path)


def test_request_bodies_are_named_schemas(client) -> None:
    schema = client.get("/openapi.json").json()
    names = set(schema["components"]["schemas"])
    camel_ids = {_camel(op["operationId"]) for _, _, op in _operations(schema)}
    for name in names:
        assert not name.startswith("Body_"), name
        assert not any(c in name for c in camel_ids), f"{name}: named after its operation"
    for method, path, op in _operations(schema):
        if "requestBody" not in op:
            continue
        for media, content in op["requestBody"]["content"].items():
            ref = content["schema"].get("$ref", "")
            assert ref.startswith("#/components/schemas/"), (method, path, media)
            assert ref.rsplit("/", 1)[1] in names, (method, path, media)


def _array_shape(node: dict, schema: dict) -> list[tuple[int | None, int | None]]:
    """(minItems, maxItems) per nesting level of an array property (``null`` variant dropped)."""
    node = _resolve(schema, node)
    variants = [v for v in node.get("anyOf", [node]) if v.get("type") != "null"]
    assert len(variants) == 1, node
    node = _resolve(schema, variants[0])
    assert node.get("type") == "array", node
    shape = [(node.get("minItems"), node.get("maxItems"))]
    items = _resolve(schema, node["items"])
    if items.get("type") == "array":
        shape += _array_shape(items, schema)
    return shape


def test_response_poses_have_the_request_array_lengths(client) -> None:
    """Every position/orientation/rpy/matrix in a response is as fixed as in a request, so an
    FK pose can be sent back as an IK target without a cast."""
    schema = client.get("/openapi.json").json()
    components = schema["components"]["schemas"]
    expected = {  # the request side: IK targets and DH fixed transforms
        "position": _array_shape(components["Pose"]["properties"]["position"], schema),
        "orientation": _array_shape(components["Pose"]["properties"]["orientation"], schema),
        "matrix": _array_shape(components["Pose"]["properties"]["matrix"], schema),
        "rpy": _array_shape(components["DHTransformDoc"]["properties"]["rpy"], schema),
    }
    assert expected == {
        "position": [(3, 3)],
        "orientation": [(4, 4)],
        "matrix": [(4, 4), (4, 4)],
        "rpy": [(3, 3)],
    }
    responses = [
        response.get("content", {})
        for _, _, op in _operations(schema)
        for code, response in op["responses"].items()
        if code.startswith("2")
    ]
    checked = []
    for name in sorted(_reachable(schema, responses)):
        for prop, node in (components[name].get("properties") or {}).items():
            if prop in expected:
                assert _array_shape(node, schema) == expected[prop], (name, prop)
                checked.append((name, prop))
            elif prop in ("positions", "orientations"):  # compact batch forms: N rows
                row = expected[prop[:-1]]
                assert _array_shape(node, schema)[1:] == row, (name, prop)
                checked.append((name, prop))
    assert ("Pose", "matrix") in checked and ("FKBatchResponse", "positions") in checked


def test_a_python_client_generates_from_the_served_schema(client, tmp_path) -> None:
    """openapi-python-client accepts the schema (its only warnings: media types it cannot
    generate, YAML bodies, XML and PNG answers), names the request bodies after their
    models, and lets write operations be called without a token."""
    spec = tmp_path / "openapi.json"
    spec.write_text(json.dumps(client.get("/openapi.json").json()))
    bin_dir = Path(sys.executable).parent
    done = subprocess.run(
        [
            str(bin_dir / "openapi-python-client"),
            "generate",
            "--path",
            str(spec),
            "--meta",
            "none",
            "--output-path",
            str(tmp_path / "gen"),
        ],
        env={**os.environ, "PATH": f"{bin_dir}:{os.environ.get('PATH', '')}"},
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    for warning in (done.stdout + done.stderr).split("WARNING parsing")[1:]:
        assert "Unsupported content" in warning, warning
    models = {p.stem for p in (tmp_path / "gen" / "models").glob("*.py")}
    for body in ("urdf_upload", "manipulability_batch_request", "query_request"):
        assert body in models, sorted(models)
    # The write operations take a plain Client (the token is optional), not only an
    # AuthenticatedClient.
    write = (tmp_path / "gen" / "api" / "collisions" / "create_scene.py").read_text()
    signature = re.search(r"def sync\((.*?)\)", write, re.S)
    assert signature and "client: AuthenticatedClient | Client," in signature.group(1), write
    op_ids = {op["operationId"] for _, _, op in _operations(json.loads(spec.read_text()))}
    assert not [m for m in models if m.startswith(tuple(i + "_" for i in op_ids))], sorted(models)
