"""One error body for the whole API: RFC 9457 problem details.

Every 4xx/5xx answer is ``application/problem+json`` with ``type``, ``title``, ``status``,
``detail`` and, where one is to blame, the offending ``field`` (dotted path into the request,
e.g. ``q.3``, ``target.orientation``, ``robot_id``). Unknown names add ``suggestions``;
validation failures add every ``errors`` entry.
"""

from __future__ import annotations

import logging
from collections.abc import Sequence
from typing import Any

import orjson
from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from pydantic import BaseModel, Field
from starlette.exceptions import HTTPException as StarletteHTTPException
from starlette.responses import Response

from app.kinematics.errors import (
    ConflictError,
    ForbiddenError,
    InvalidInputError,
    KinematicsError,
    MissingInertiaError,
    UnavailableError,
    UnknownNameError,
)
from app.kinematics.text import printable

log = logging.getLogger("denavit")

PROBLEM_TYPES = "https://denavit.dev/problems/"
_TITLES = {
    400: "Bad Request",
    401: "Unauthorized",
    403: "Forbidden",
    404: "Not Found",
    405: "Method Not Allowed",
    409: "Conflict",
    413: "Content Too Large",
    415: "Unsupported Media Type",
    416: "Range Not Satisfiable",
    422: "Unprocessable Content",
    426: "Upgrade Required",
    431: "Request Header Fields Too Large",
    500: "Internal Server Error",
    503: "Service Unavailable",
}


#: Detail of a JSON body nested too deeply to decode (every route, fast path or not).
NESTED_TOO_DEEPLY = "body: malformed JSON (arrays and objects nested too deeply)"

#: The detail of the ``HTTPException`` FastAPI raises when decoding a body fails with anything
#: but a JSON syntax error (``RecursionError`` for deep nesting, ``UnicodeDecodeError``).
_FASTAPI_BODY_ERROR = "There was an error parsing the body"


class MalformedBodyError(Exception):
    """The request body is not JSON (HTTP 400); raised by routes that decode their own."""


def _body_error_detail(cause: BaseException | None) -> str:
    """The detail of a 400 for a body FastAPI could not decode, from the underlying error."""
    if isinstance(cause, RecursionError):
        return NESTED_TOO_DEEPLY
    if isinstance(cause, UnicodeDecodeError):
        return f"body: not UTF-8 text ({cause.reason})"
    return f"body: malformed JSON ({cause})" if cause else "body: malformed JSON"


class FieldError(BaseModel):
    """One validation failure."""

    field: str = Field(description="Dotted path of the offending value in the request.")
    message: str = Field(description="Why the value was rejected.")


class Problem(BaseModel):
    """RFC 9457 problem details, the body of every error response."""

    type: str = Field(description="URI identifying the problem type.")
    title: str = Field(description="Short summary of the problem type.")
    status: int = Field(description="HTTP status code.")
    detail: str = Field(description="Explanation specific to this occurrence.")
    instance: str | None = Field(None, description="The request path.")
    field: str | None = Field(None, description="The request field to blame, if any.")
    suggestions: list[str] | None = Field(None, description="Close matches for an unknown name.")
    errors: list[FieldError] | None = Field(None, description="All validation failures.")


def problem(
    status: int,
    detail: str,
    *,
    kind: str | None = None,
    field: str | None = None,
    instance: str | None = None,
    headers: dict[str, str] | None = None,
    **extra: Any,
) -> Response:
    """A problem-details response."""
    body = problem_body(status, detail, kind=kind, field=field, instance=instance, **extra)
    return Response(
        json_bytes(body),
        status_code=status,
        media_type="application/problem+json",
        headers=headers,
    )


def problem_body(
    status: int,
    detail: str,
    *,
    kind: str | None = None,
    field: str | None = None,
    instance: str | None = None,
    **extra: Any,
) -> dict[str, Any]:
    """The problem-details body of :func:`problem` (also sent in stream error messages)."""
    body: dict[str, Any] = {
        "type": PROBLEM_TYPES + (kind or str(status)),
        "title": _TITLES.get(status, "Error"),
        "status": status,
        "detail": detail,
    }
    if instance:
        body["instance"] = instance
    if field is not None:
        body["field"] = field
    body.update({k: v for k, v in extra.items() if v is not None})
    return body


def json_bytes(obj: Any) -> bytes:
    """``obj`` (plain JSON types) as JSON; a lone surrogate in echoed client text becomes
    U+FFFD."""
    try:
        return orjson.dumps(obj)
    except orjson.JSONEncodeError:
        return orjson.dumps(_printable(obj))


def _printable(obj: Any) -> Any:
    """``obj`` with every string made encodable (lone surrogates become U+FFFD)."""
    if isinstance(obj, str):
        return printable(obj)
    if isinstance(obj, dict):
        return {printable(str(k)): _printable(v) for k, v in obj.items()}
    if isinstance(obj, list | tuple):
        return [_printable(v) for v in obj]
    return obj


def _loc(loc: tuple[Any, ...] | list[Any]) -> str:
    parts = [str(p) for p in loc]
    if parts and parts[0] in {"body", "query", "path", "header"}:
        parts = parts[1:]
    return ".".join(parts) or "body"


#: Fields that are path parameters: an unknown name there is a missing resource (404);
#: an unknown name anywhere in a body (a frame, a joint, a group, a scene) is a 422.
PATH_FIELDS = frozenset({"robot_id", "job_id", "map_id", "name", "path"})

_STATUS = {
    UnknownNameError: (404, "unknown-name"),
    ConflictError: (409, "conflict"),
    ForbiddenError: (403, "forbidden"),
    InvalidInputError: (422, "invalid-input"),
    MissingInertiaError: (422, "missing-inertia"),
    UnavailableError: (503, "unavailable"),
}


def kinematics_problem(exc: KinematicsError, instance: str) -> dict[str, Any]:
    """The problem body of a core error (its status from the error's type)."""
    status, kind = _STATUS.get(type(exc), (422, "invalid-input"))
    if isinstance(exc, UnknownNameError) and exc.field not in PATH_FIELDS:
        status = 422  # a name in the body (frame, joint, group, scene): invalid input
    detail = f"{exc.field}: {exc.message}" if exc.field else exc.message
    return problem_body(
        status,
        detail,
        kind=kind,
        field=exc.field,
        instance=instance,
        suggestions=getattr(exc, "suggestions", None),
    )


def validation_problem(errs: Sequence[Any], instance: str) -> dict[str, Any]:
    """The problem body of failed request validation (pydantic's ``errors()``): 400 for
    malformed JSON, else 422 naming the first field and listing every failure."""
    if any(e.get("type") == "json_invalid" for e in errs):
        e = next(e for e in errs if e.get("type") == "json_invalid")
        ctx = e.get("ctx") or {}
        return problem_body(
            400,
            f"body: malformed JSON ({ctx.get('error', e.get('msg'))})",
            kind="malformed-json",
            field="body",
            instance=instance,
        )
    items = [{"field": _loc(e["loc"]), "message": e["msg"]} for e in errs]
    first = items[0] if items else {"field": "body", "message": "invalid request"}
    more = f" (and {len(items) - 1} more)" if len(items) > 1 else ""
    return problem_body(
        422,
        f"{first['field']}: {first['message']}{more}",
        kind="validation-error",
        field=first["field"],
        instance=instance,
        errors=items[:50],
    )


def _response(body: dict[str, Any]) -> Response:
    return Response(
        json_bytes(body), status_code=body["status"], media_type="application/problem+json"
    )


def install(app: FastAPI) -> None:
    """Register the handlers that turn every error into a problem response."""

    @app.exception_handler(KinematicsError)
    async def _kinematics(request: Request, exc: KinematicsError) -> Response:
        return _response(kinematics_problem(exc, request.url.path))

    @app.exception_handler(MalformedBodyError)
    async def _malformed(request: Request, exc: MalformedBodyError) -> Response:
        return problem(
            400, str(exc), kind="malformed-json", field="body", instance=request.url.path
        )

    @app.exception_handler(RequestValidationError)
    async def _validation(request: Request, exc: RequestValidationError) -> Response:
        return _response(validation_problem(exc.errors(), request.url.path))

    @app.exception_handler(StarletteHTTPException)
    async def _http(request: Request, exc: StarletteHTTPException) -> Response:
        if exc.status_code == 400 and exc.detail == _FASTAPI_BODY_ERROR:
            return problem(
                400,
                _body_error_detail(exc.__cause__),
                kind="malformed-json",
                field="body",
                instance=request.url.path,
            )
        return problem(
            exc.status_code,
            str(exc.detail),
            instance=request.url.path,
            headers=getattr(exc, "headers", None),
        )

    @app.exception_handler(Exception)
    async def _unexpected(request: Request, exc: Exception) -> Response:  # pragma: no cover
        log.exception("unhandled error on %s", request.url.path)
        return problem(500, "internal error", instance=request.url.path)


#: OpenAPI description of the error responses, for ``responses=`` on routes.
ERROR_RESPONSES: dict[int | str, dict[str, Any]] = {
    code: {"model": Problem, "content": {"application/problem+json": {}}, "description": text}
    for code, text in {
        400: "Malformed request body.",
        404: "Unknown robot, frame or joint.",
        422: "A field failed validation; `field` names it.",
    }.items()
}
