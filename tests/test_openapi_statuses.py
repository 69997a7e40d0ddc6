"""The document declares every status and header the service answers, and says how to call it.

- Every recorded exchange (tests/openapi_examples.py: one request per 2xx of every
  operation, and a table of error requests, one per status the service answers; their
  answers are checked against the service by tests/test_openapi_examples.py) is answered
  with a status its operation declares, and the headers the service sent are the ones the
  document declares for that status (every required one sent, nothing undeclared).
- 405: every (operation, path of another resource) pair the router resolves elsewhere is
  sent; a 405 answer is declared on the operation, and a declared 405 happens.
- ``security: []`` on open operations, an optional bearer on the guarded ones; a 4xx on
  every operation; ``servers``; the license of pyproject.toml.
"""

from __future__ import annotations

import re
import tomllib

from tests.helpers import ROOT, write_routes
from tests.openapi_examples import TRANSPORT_HEADERS, load

#: Every status the service answers through its routes and middleware (431 is the HTTP
#: server's, before the app; 499 is only logged; 500 is a bug).
STATUSES = {200, 201, 202, 204, 206, 400, 401, 403, 404, 405, 409, 413, 415, 416, 422, 426, 503}


def _operations(schema: dict) -> dict[str, tuple[str, str, dict]]:
    return {
        op["operationId"]: (method.upper(), path, op)
        for path, item in schema["paths"].items()
        for method, op in item.items()
    }


def _template_regex(template: str) -> re.Pattern[str]:
    parts = re.split(r"(\{[^}]+\})", template)
    return re.compile(
        "".join(
            ("(.+)" if p.endswith(":path}") or "{path}" in p else "([^/]+)")
            if p.startswith("{")
            else re.escape(p)
            for p in parts
        )
    )


def _declared_headers(schema: dict, response: dict) -> dict[str, bool]:
    """Header name (lower case) → required, of a response."""
    out = {}
    for name, header in response.get("headers", {}).items():
        if "$ref" in header:
            header = schema["components"]["headers"][header["$ref"].rsplit("/", 1)[1]]
        out[name.lower()] = bool(header.get("required"))
    return out


def test_every_answered_status_and_header_is_declared(app) -> None:
    schema = app.openapi()
    operations = _operations(schema)
    wrong = []
    seen = set()
    for exchange in load():
        spec, answer = exchange["request"], exchange["response"]
        method, template, op = operations[spec["operation"]]
        path = spec["path"].split("?")[0]
        assert method == spec["method"], spec["name"]
        assert _template_regex(template).fullmatch(path), (spec["name"], template)
        status = str(answer["status"])
        seen.add(answer["status"])
        response = op["responses"].get(status)
        if response is None:
            wrong.append(f"{spec['name']}: {status} not declared on {spec['operation']}")
            continue
        declared = _declared_headers(schema, response)
        sent = set(answer["headers"]) - TRANSPORT_HEADERS
        undeclared = sent - set(declared)
        missing = {name for name, required in declared.items() if required} - sent
        if undeclared or missing:
            wrong.append(f"{spec['name']} {status}: undeclared {undeclared}, missing {missing}")
    assert not wrong, "\n".join(wrong)
    assert seen == STATUSES, sorted(seen ^ STATUSES)


def _unify(a: str, b: str) -> str | None:
    """A concrete path both templates match (independent of the document's own code)."""
    sa, sb = a.split("/"), b.split("/")
    if len(sa) != len(sb):
        return None
    out = []
    for x, y in zip(sa, sb, strict=True):
        if x.startswith("{") and y.startswith("{"):
            out.append("p")
        elif x.startswith("{") or y.startswith("{"):
            out.append(y if x.startswith("{") else x)
        elif x == y:
            out.append(x)
        else:
            return None
    return "/".join(out)


def test_405_is_declared_exactly_where_the_router_answers_it(app, client) -> None:
    schema = app.openapi()
    templates = list(schema["paths"])
    answered: dict[str, list[str]] = {}
    for template, item in schema["paths"].items():
        for method, op in item.items():
            for other in templates:
                path = _unify(template, other)
                if path is None or path == template:
                    continue
                r = client.request(method.upper(), path)
                if r.status_code == 405:
                    answered.setdefault(op["operationId"], []).append(path)
                    assert "405" in op["responses"], (method, path, op["operationId"])
                    assert set(r.headers["allow"].split(", ")) <= {
                        m.upper() for m in schema["paths"][other]
                    } | {"HEAD"}
    declared = {
        op["operationId"]
        for item in schema["paths"].values()
        for op in item.values()
        if "405" in op["responses"]
    }
    assert declared == set(answered), sorted(declared ^ set(answered))
    assert "get_robot" in declared  # GET /robots/dh: the path of POST /robots/dh


def test_security_is_open_or_optional_bearer(app) -> None:
    """Derived from the routes' dependencies, not a list: an open operation says
    ``security: []``; a guarded one takes the bearer token but also works without it (the
    token is only enforced when DENAVIT_API_TOKEN is set), inherited from the document (see
    tests/test_openapi.py for the client that this lets take a plain ``Client``)."""
    schema = app.openapi()
    guarded = {(m.lower(), p) for m, p, _ in write_routes(app)} | {
        ("get", "/robots/{robot_id}/stream")
    }
    (name,) = schema["components"]["securitySchemes"]
    for path, item in schema["paths"].items():
        for method, op in item.items():
            expected = [{}, {name: []}] if (method, path) in guarded else []
            effective = op.get("security", schema["security"])
            assert effective == expected, (method, path, effective)


def test_every_operation_has_a_4xx_servers_and_the_license(app) -> None:
    schema = app.openapi()
    for method, path, op in _operations(schema).values():
        assert any(code.startswith("4") for code in op["responses"]), (method, path)
    assert schema["servers"][0]["url"] == "/"
    assert all(s.get("description") for s in schema["servers"])
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert schema["info"]["license"]["identifier"] == project["license"]
    assert "499" in schema["info"]["description"]
