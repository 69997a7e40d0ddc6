"""The OpenAPI document as a product: statuses, headers, security, servers, license, tags.

:func:`complete` runs after :func:`app.middleware.openapi.document_errors` (which gives every
error response the problem body) and makes the document say everything a generated client
needs to handle what the service really sends:

- **Statuses** the middleware answers on any operation: ``413`` (a body over
  ``DENAVIT_MAX_BODY_BYTES``, whatever the method: :mod:`app.middleware.body_limit`) and
  ``503`` (the service not started or its job table unwritable, ``UnavailableError``; a
  request cut off by the graceful-shutdown timeout, :mod:`app.middleware.guard`, with
  ``Retry-After``). ``405`` where the router can answer it on the operation's own method:
  a path the operation's template matches that the router resolves to another resource
  without that method (``GET /robots/dh`` is ``POST /robots/dh``'s, not the robot ``dh``:
  :mod:`app.middleware.methods`), found by unifying the route templates. The WebSocket
  stream's plain-HTTP face, ``GET /robots/{robot_id}/stream`` (``426`` naming the upgrade),
  is listed as an operation. ``499`` (client gone) is only logged and ``431`` is answered
  by ``python -m app``'s HTTP server before any route: both are described in
  ``info.description``, not listed as responses.
- **Headers**: ``X-Request-ID`` and ``X-Content-Type-Options`` on every response
  (:mod:`app.middleware.observability`), ``Allow`` on 405, ``Retry-After`` on 503,
  ``WWW-Authenticate`` on 401, ``Location`` on the 201 of robot writes and the 202 of a
  reachability build, ``Upgrade`` on 426, and the file headers of
  :mod:`app.api.untrusted` (:data:`OPERATION_HEADERS`).
- **Security**: the document's ``security`` is an *optional* bearer token,
  ``[{}, {bearerAuth: []}]``, which the write operations (guarded by
  :func:`app.api.security.require_token`) and the stream inherit: the token is only
  enforced when ``DENAVIT_API_TOKEN`` is set. Every other operation says ``security: []``.
  The write operations inherit it rather than repeat it because openapi-python-client
  makes any operation with its own non-empty ``security`` take an ``AuthenticatedClient``
  (a token); inherited, they accept a plain ``Client`` too, while Swagger UI and the other
  generators still offer the token there.
- ``servers`` (relative ``/`` first, so the docs page calls the server it is served by;
  then ``make run``'s address), ``info.license`` (the project's, from pyproject.toml) and
  the global ``tags`` list.

tests/test_openapi_statuses.py runs a request for every status and checks it is declared.
"""

from __future__ import annotations

from typing import Any

from app.middleware.methods import RouteTable

_REF = "#/components/schemas/"
#: Name of the bearer scheme in ``components.securitySchemes``.
BEARER = "bearerAuth"
_HEADERS = "#/components/headers/"

SERVERS = [
    {
        "url": "/",
        "description": "The server this document is served by (its docs page calls it).",
    },
    {
        "url": "http://127.0.0.1:8000",
        "description": "`make run` / `python -m app` on this machine (DENAVIT_HOST, "
        "DENAVIT_PORT); pass your server's address as a generated client's base URL.",
    },
]
LICENSE = {"name": "BSD-3-Clause", "identifier": "BSD-3-Clause"}

STATUS_NOTES = (
    "\n\nStatuses: every error is an RFC 9457 problem (`application/problem+json`). Any "
    "operation can answer 413 (a body over DENAVIT_MAX_BODY_BYTES, whatever the method) and "
    "503 (not started, storage unavailable, or cut off by the graceful-shutdown timeout: "
    "`Retry-After`). 499 is never received: it is the status the access log and metrics "
    "record for a request whose client disconnected before the answer (its work is "
    "cancelled). 431 (request head too large) is answered by `python -m app`'s HTTP server "
    "before any route, so without `X-Request-ID`. 500 means a bug. Every response carries "
    "`X-Request-ID` (the client's, when it sent a sane one)."
)

TAGS = {
    "kinematics": "Forward kinematics, Jacobians and velocities.",
    "inverse kinematics": "Inverse kinematics: single targets, batches and Cartesian paths.",
    "analysis": "Manipulability and statics.",
    "dynamics": "Joint torques from the URDF inertias: inverse dynamics, mass matrix, payloads.",
    "collisions": "Self- and environment collision checks, and named scenes of obstacles.",
    "robots": "The robot catalog, robot imports and uploads, and their files.",
    "reachability": "Reachability maps: background builds, queries and slices.",
    "service": "Health, readiness and metrics.",
    "stream": "The WebSocket stream (its plain-HTTP answer).",
}

HEADERS: dict[str, dict[str, Any]] = {
    "X-Request-ID": {
        "description": "The request's id: the client's `X-Request-ID` when it is 1–128 "
        "characters of `[A-Za-z0-9._:/+=@-]`, else 24 random hex digits. Also in every log "
        "line of the request.",
        "required": True,
        "schema": {"type": "string", "pattern": "^[A-Za-z0-9._:/+=@-]{1,128}$"},
    },
    "X-Content-Type-Options": {
        "description": "Always `nosniff`: browsers keep to the declared content type.",
        "required": True,
        "schema": {"type": "string", "enum": ["nosniff"]},
    },
    "Allow": {
        "description": "The methods the path supports, e.g. `GET, HEAD, DELETE`.",
        "required": True,
        "schema": {"type": "string"},
    },
    "Retry-After": {
        "description": "Seconds to wait before sending the request again: sent when the "
        "service is shutting down (the request was cut off), not when it is not started.",
        "required": False,
        "schema": {"type": "integer", "minimum": 0},
    },
    "WWW-Authenticate": {
        "description": "`Bearer`: the scheme the write endpoints expect.",
        "required": True,
        "schema": {"type": "string"},
    },
    "Location": {
        "description": "The URL of what was created (the robot, or the reachability job).",
        "required": True,
        "schema": {"type": "string", "format": "uri-reference"},
    },
    "Upgrade": {
        "description": "`websocket`: the protocol this endpoint speaks.",
        "required": True,
        "schema": {"type": "string"},
    },
    "Content-Security-Policy": {
        "description": "`default-src 'none'; sandbox`: a client-supplied document is never "
        "run as a page.",
        "required": True,
        "schema": {"type": "string"},
    },
    "Content-Disposition": {
        "description": "`attachment; filename=...` for a file not shown inline.",
        "required": False,
        "schema": {"type": "string"},
    },
    "Content-Range": {
        "description": "The byte range sent (`bytes 0-9/124`), or on 416 the file size "
        "(`bytes */124`).",
        "required": True,
        "schema": {"type": "string"},
    },
    "Accept-Ranges": {
        "description": "`bytes`: a `Range` request is served.",
        "required": True,
        "schema": {"type": "string"},
    },
    "ETag": {
        "description": "The file's version (from its size and modification time), for `If-Range`.",
        "required": True,
        "schema": {"type": "string"},
    },
    "Last-Modified": {
        "description": "When the file was stored (HTTP date).",
        "required": True,
        "schema": {"type": "string"},
    },
}

#: Headers on every response of every operation.
EVERY_RESPONSE = ("X-Request-ID", "X-Content-Type-Options")
#: Headers by status, on every operation that declares the status.
STATUS_HEADERS = {
    "405": ("Allow",),
    "503": ("Retry-After",),
    "401": ("WWW-Authenticate",),
    "426": ("Upgrade",),
}
_FILE = ("Content-Security-Policy", "Content-Disposition", "Accept-Ranges", "ETag", "Last-Modified")
#: Headers that routes set, by operation id and status (``?``: sent on some answers only).
OPERATION_HEADERS: dict[str, dict[str, tuple[str, ...]]] = {
    "import_dh_robot": {"201": ("Location",)},
    "upload_urdf_robot": {"201": ("Location",)},
    "upload_robot_package": {"201": ("Location",)},
    "build_reachability_map": {"202": ("Location",)},
    "get_robot_urdf": {"200": ("Content-Security-Policy", "Content-Disposition")},
    # The YAML answer is a download; the JSON one has neither header.
    "get_robot_dh": {"200": ("Content-Security-Policy?", "Content-Disposition")},
    "get_robot_file": {
        "200": _FILE,
        "206": (*_FILE, "Content-Range"),
        "400": ("Content-Security-Policy",),
        "416": ("Content-Security-Policy", "Content-Range"),
    },
}

ANY_OPERATION = {
    "413": "The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method).",
    "503": "The service cannot serve this now: not started, storage unavailable, or "
    "shutting down (the request was cut off by the graceful-shutdown timeout; "
    "`Retry-After`). Send it again later.",
}
METHOD_NOT_ALLOWED = (
    "The path belongs to another resource that does not support this method (e.g. {example} "
    "is the path of another operation); `Allow` lists the methods it supports."
)

#: The plain-HTTP face of the WebSocket stream (``GET /robots/{robot_id}/stream``).
STREAM_PATH = "/robots/{robot_id}/stream"
STREAM_OPERATION: dict[str, Any] = {
    "tags": ["stream"],
    "summary": "Robot stream (WebSocket)",
    "description": "FK, Jacobian, IK and dynamics of one robot over a WebSocket (docs/stream.md): "
    "connect with `ws://` (an HTTP/1.1 `Upgrade: websocket` request). OpenAPI cannot "
    "describe the messages; a plain HTTP request is answered 426 naming the upgrade. With "
    "DENAVIT_API_TOKEN set, the upgrade request carries the bearer token (or the first "
    'message is `{"token": ...}`).',
    "operationId": "get_robot_stream",
    "parameters": [
        {
            "name": "robot_id",
            "in": "path",
            "required": True,
            "schema": {"type": "string", "title": "Robot Id"},
        }
    ],
    "responses": {
        "101": {"description": "Switching Protocols: the WebSocket is open."},
        "426": {"description": "A plain HTTP request: this endpoint needs the WebSocket upgrade."},
    },
}


def _unify(template: str, other: str) -> str | None:
    """A concrete path both ``template`` and ``other`` match, segment by segment, or
    ``None`` (a parameter takes the other's literal, two parameters take ``x``)."""
    a, b = template.split("/"), other.split("/")
    if len(a) != len(b):
        return None
    out = []
    for s, t in zip(a, b, strict=True):
        s_param, t_param = s.startswith("{"), t.startswith("{")
        if not s_param and not t_param and s != t:
            return None
        out.append(t if s_param and not t_param else s if not s_param else "x")
    return "/".join(out)


def method_not_allowed(table: RouteTable, method: str, template: str) -> str | None:
    """A path of ``template`` on which ``method`` is answered 405, or ``None``."""
    for other in table.resources:
        path = _unify(template, other)
        resource = table.match(path) if path is not None else None
        if resource is not None and resource.path != template and method not in resource.native:
            return path
    return None


def _header_refs(names: tuple[str, ...]) -> dict[str, Any]:
    """The ``headers`` of a response: references to the components, an optional copy for a
    name ending with ``?``."""
    out: dict[str, Any] = {}
    for name in names:
        if name.endswith("?"):
            out[name[:-1]] = {**HEADERS[name[:-1]], "required": False}
        else:
            out[name] = {"$ref": _HEADERS + name}
    return out


def complete(schema: dict[str, Any], table: RouteTable, guarded: set[str]) -> dict[str, Any]:
    """Rewrite ``schema`` in place (see the module docstring); returns it.

    ``table`` is the application's route table (for 405s), ``guarded`` the operation ids
    of the write routes.
    """
    problem = {"application/problem+json": {"schema": {"$ref": _REF + "Problem"}}}
    paths = schema.setdefault("paths", {})
    paths[STREAM_PATH] = {"get": _copy(STREAM_OPERATION)}
    guarded = guarded | {STREAM_OPERATION["operationId"]}
    for template, item in paths.items():
        for method, op in item.items():
            if not isinstance(op, dict) or "responses" not in op:
                continue
            responses = op["responses"]
            for code, text in ANY_OPERATION.items():
                responses.setdefault(code, {"description": text})
            example = method_not_allowed(table, method.upper(), template)
            if example is not None:
                description = METHOD_NOT_ALLOWED.format(example=f"`{method.upper()} {example}`")
                responses.setdefault("405", {"description": description})
            own = OPERATION_HEADERS.get(op.get("operationId", ""), {})
            if "206" in responses and "content" in responses.get("200", {}):  # a byte range
                responses["206"].setdefault("content", _copy(responses["200"]["content"]))
            for code, response in responses.items():
                _fill_schemas(response.get("content") or {})
                if code.startswith(("4", "5")):
                    response.setdefault("content", _copy(problem))
                if code.startswith("1"):  # the WebSocket upgrade: no HTTP middleware
                    continue
                names = EVERY_RESPONSE + STATUS_HEADERS.get(code, ()) + own.get(code, ())
                response["headers"] = _header_refs(names)
            op["responses"] = dict(sorted(responses.items()))
            if op.get("operationId") in guarded:
                op.pop("security", None)  # inherits the document's optional bearer
            else:
                op["security"] = []
    components = schema.setdefault("components", {})
    components["headers"] = {name: dict(body) for name, body in HEADERS.items()}
    info = schema.setdefault("info", {})
    info["license"] = dict(LICENSE)
    if STATUS_NOTES not in info.get("description", ""):
        info["description"] = info.get("description", "").rstrip("\n") + STATUS_NOTES
    schema["servers"] = [dict(s) for s in SERVERS]
    schema["security"] = [{}, {BEARER: []}]
    used = [t for item in paths.values() for op in item.values() for t in op.get("tags", ())]
    schema["tags"] = [
        {"name": name, **({"description": TAGS[name]} if name in TAGS else {})}
        for name in dict.fromkeys(used)
    ]
    return schema


def _fill_schemas(content: dict[str, Any]) -> None:
    """Give a YAML answer without a schema its JSON sibling's (the same document); binary
    answers are typed by :func:`app.middleware.openapi_content.binary_responses`."""
    for media, entry in content.items():
        if entry.get("schema"):
            continue
        if "yaml" in media and "schema" in content.get("application/json", {}):
            entry["schema"] = _copy(content["application/json"]["schema"])


def _copy(value: Any) -> Any:
    """A deep copy of plain JSON data."""
    if isinstance(value, dict):
        return {k: _copy(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_copy(v) for v in value]
    return value
