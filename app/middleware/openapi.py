"""The served OpenAPI schema, with every error response documented as it is sent.

FastAPI documents validation errors as ``application/json`` ``HTTPValidationError``; this
service answers every error as RFC 9457 ``application/problem+json`` (:mod:`app.api.errors`).
:func:`install` post-processes the generated schema once so it tells the truth for every
operation, whichever router defined it:

- every 4xx/5xx response has exactly one media type, ``application/problem+json``, with the
  ``Problem`` schema (or the schema the route declared);
- the errors the middleware and the framework add are listed where they can happen:
  422 (any operation with parameters or a body), 400 (malformed body) and 413 (body over
  ``DENAVIT_MAX_BODY_BYTES``) for operations with a body, 404 for operations with path
  parameters (unknown robot, scene, map...), 401 and 403 for write operations guarded by
  :func:`app.api.security.require_token`;
- the bearer scheme is declared (``components.securitySchemes.bearerAuth``, HTTP bearer).

Then :func:`app.middleware.openapi_document.complete` adds the statuses the middleware
answers on any operation, the response headers, ``security`` (optional bearer on exactly
the guarded operations, ``[]`` on the others), ``servers``, the license and the tags, and
:func:`app.middleware.openapi_content.binary_responses` types binary answers (images,
files) as binary strings, and :func:`app.middleware.openapi_examples.add_examples` adds the
recorded examples.

Schemathesis (tests/test_schemathesis.py) checks the responses against this schema.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from fastapi import FastAPI
from fastapi.routing import APIRoute, iter_route_contexts
from pydantic import BaseModel

from app.api.body import EXTRA_SCHEMAS
from app.api.errors import Problem
from app.api.security import require_token
from app.middleware.methods import RouteTable
from app.middleware.openapi_content import binary_responses
from app.middleware.openapi_document import BEARER, complete
from app.middleware.openapi_examples import add_examples

PROBLEM = "application/problem+json"
_REF = "#/components/schemas/"
BEARER_SCHEME = {
    "type": "http",
    "scheme": "bearer",
    "description": "`Authorization: Bearer <token>` on write endpoints (robot import, "
    "upload and deletion, scenes, reachability builds) and the stream. Optional: enforced "
    "only when the service runs with DENAVIT_API_TOKEN set (401 without a token, 403 with "
    "a wrong one).",
}

GENERIC_ERRORS = {
    "400": "Malformed request body (not valid JSON or YAML).",
    "401": "A write endpoint without `Authorization: Bearer <token>` (DENAVIT_API_TOKEN set).",
    "403": "The bearer token is not valid, or the resource may not be changed.",
    "404": "Unknown robot, frame, joint or other named resource.",
    "413": "The request body exceeds DENAVIT_MAX_BODY_BYTES.",
    "422": "A field failed validation; `field` names it.",
}


def _uses(dependant: Any, fn: Any) -> bool:
    return any(d.call is fn or _uses(d, fn) for d in dependant.dependencies)


def guarded_operations(app: FastAPI) -> set[str]:
    """Operation ids of the routes that depend on :func:`require_token`."""
    out = set()
    for context in iter_route_contexts(app.routes):
        route = context.original_route
        if isinstance(route, APIRoute) and _uses(route.dependant, require_token):
            out.add(route.operation_id or route.unique_id)
    return out


def _model_schemas(model: type[BaseModel]) -> dict[str, Any]:
    """Component name → JSON schema for ``model`` and the models it refers to."""
    schema = model.model_json_schema(ref_template=_REF + "{model}")
    defs = schema.pop("$defs", {})
    return {model.__name__: schema, **defs}


def _without_null_defaults(schema: Any) -> Any:
    """``schema`` without its ``"default": null`` members (recursively)."""
    if isinstance(schema, dict):
        return {
            k: _without_null_defaults(v)
            for k, v in schema.items()
            if not (k == "default" and v is None)
        }
    if isinstance(schema, list):
        return [_without_null_defaults(v) for v in schema]
    return schema


def document_errors(
    schema: dict[str, Any], guarded: set[str], extra_models: Sequence[type[BaseModel]] = ()
) -> dict[str, Any]:
    """Rewrite ``schema`` in place (see the module docstring); returns it.

    ``extra_models`` are added to the components (see :data:`app.api.body.EXTRA_SCHEMAS`).
    """
    problem_ref = {"$ref": _REF + "Problem"}
    validation_ref = {"$ref": _REF + "HTTPValidationError"}
    for path, item in schema.get("paths", {}).items():
        for op in item.values():
            if not isinstance(op, dict) or "responses" not in op:
                continue
            responses: dict[str, Any] = op["responses"]
            wanted = set()
            if "requestBody" in op or op.get("parameters"):
                wanted.add("422")
            if "requestBody" in op:
                wanted |= {"400", "413"}
            if "{" in path:
                wanted.add("404")
            if op.get("operationId") in guarded:
                wanted |= {"401", "403"}
            for code in sorted(wanted):
                responses.setdefault(code, {"description": GENERIC_ERRORS[code]})
            for code, response in responses.items():
                if not code.startswith(("4", "5")):
                    continue
                content = response.get("content") or {}
                body = (content.get(PROBLEM) or {}).get("schema") or (
                    content.get("application/json") or {}
                ).get("schema")
                if body is None or body == validation_ref:
                    body = problem_ref
                response["content"] = {PROBLEM: {"schema": body}}
                if response.get("description") == "Validation Error":
                    response["description"] = GENERIC_ERRORS["422"]
    schema.setdefault("components", {}).setdefault("securitySchemes", {})[BEARER] = BEARER_SCHEME
    components = schema["components"].setdefault("schemas", {})
    # Problem, and the request models of routes that decode their own bodies (their
    # openapi_extra refers to them by name).
    for name, body in _model_schemas(Problem).items():
        components.setdefault(name, body)
    for model in extra_models:
        for name, body in _model_schemas(model).items():
            # FastAPI leaves out null defaults: a model both kinds of route use (a nested
            # PayloadIn) is the same schema but for them
            if _without_null_defaults(components.setdefault(name, body)) != (
                _without_null_defaults(body)
            ):
                raise RuntimeError(f"two different request schemas are named {name!r}")
    text = repr(schema.get("paths"))
    for name in ("HTTPValidationError", "ValidationError"):
        if _REF + name not in text:
            components.pop(name, None)
    return schema


def install(app: FastAPI) -> None:
    """Make ``app.openapi()`` serve the post-processed schema (built once, cached)."""
    generate = app.openapi

    def openapi() -> dict[str, Any]:
        if app.openapi_schema is None:
            guarded = guarded_operations(app)
            schema = document_errors(generate(), guarded, EXTRA_SCHEMAS)
            schema = complete(schema, RouteTable(app.routes), guarded)
            app.openapi_schema = add_examples(binary_responses(schema))
        return app.openapi_schema

    app.openapi = openapi  # type: ignore[method-assign]
