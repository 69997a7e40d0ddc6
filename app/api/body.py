"""Bodies that routes decode themselves: raw bytes → a validated request, fast for big batches.

Batch routes (FK, manipulability, reachability queries) and uploads read the raw body and
call :func:`decode_body`: orjson, then the request model, except that plain numeric
matrices (``configurations``, ``positions`` …) skip pydantic and become NumPy arrays
directly; anything off falls back to full validation, which names the offending element.
:func:`configurations` is the one check of a batch of configurations (count, widths, joint
bounds), :func:`group_configurations` its form for requests with a planning group. Such
routes document their body with :func:`body_schema`.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Mapping, Sequence
from typing import Any, TypeVar

import numpy as np
import orjson
from fastapi import Request
from fastapi.exceptions import RequestValidationError
from pydantic import BaseModel, ValidationError
from starlette.responses import Response

from app.api.errors import NESTED_TOO_DEEPLY, MalformedBodyError, problem
from app.api.limits import check_batch_size
from app.kinematics.errors import InvalidInputError
from app.kinematics.groups import Group, expand_rows, row_width
from app.kinematics.models import RobotModel, check_joint_values
from app.kinematics.text import SURROGATE_REASON, find_surrogate

S = TypeVar("S", bound=BaseModel)

#: A fast form of a body: from the decoded object, arrays keyed ``field`` or
#: ``field.part`` (the model's ``field`` is then validated empty), or ``None``.
FastForm = Callable[[dict[str, Any]], dict[str, np.ndarray] | None]


def decode_body(
    raw: bytes,
    model: type[S],
    matrices: Mapping[str, int | None] | None = None,
    fast: FastForm | None = None,
) -> tuple[S, dict[str, Any]]:
    """A raw JSON body as a validated ``model`` and its numeric matrices.

    Parameters
    ----------
    raw
        The body's bytes (decoded by :func:`parse_json`).
    model
        The request model; errors are FastAPI's 422 naming ``body.<field>``.
    matrices
        Fields holding N×width number matrices, name → width (``None``: any width, checked
        by the caller, e.g. :func:`configurations`). When every one present is a
        plain rectangular matrix of finite JSON numbers of its width (no ``true``/``false``
        anywhere in the body, which NumPy would turn into 1/0), it becomes a float array
        without pydantic, and the model validates the rest of the body with those fields
        empty (``[]``).
    fast
        Another fast form tried when no matrix field is present (e.g. a list of pose
        objects); see :data:`FastForm`.

    Returns
    -------
    (body, matrices)
        The validated model, and for each matrix field given in the body its rows: an
        ``(N, width)`` float array on the fast path, else the model's validated lists
        (their widths unchecked; see :func:`configurations`). On the fast path the model's
        own fields hold ``[]``: read the rows from the second item.
    """
    matrices = matrices or {}
    obj = parse_json(raw)
    if isinstance(obj, dict) and b"true" not in raw and b"false" not in raw:
        arrays = _fast_matrices(obj, matrices)
        if arrays == {} and fast is not None:
            arrays = fast(obj)
        if arrays:
            empty = {name.split(".")[0]: [] for name in arrays}
            return validate_body(model, {**obj, **empty}), arrays
    body = validate_body(model, obj)
    return body, {name: getattr(body, name) for name in matrices if getattr(body, name) is not None}


def _fast_matrices(
    obj: dict[str, Any], matrices: Mapping[str, int | None]
) -> dict[str, Any] | None:
    """The matrix fields present in ``obj`` as arrays; ``None`` if one is not plain."""
    arrays = {}
    for name, width in matrices.items():
        if name in obj:
            arr = finite_matrix(obj[name], width)
            if arr is None:
                return None
            arrays[name] = arr
    return arrays


def configurations(
    rows: np.ndarray | Sequence[Sequence[float]], n_joints: int, limit: int
) -> np.ndarray:
    """A batch of configurations as an (N, n_joints) array, checked (field ``configurations``).

    At least one and at most ``limit`` (``DENAVIT_MAX_BATCH``) rows, each one value per
    joint (rad or m), every value within the joint-value bound.
    """
    n = len(rows)
    check_batch_size(n, limit, "configurations", "configurations")
    if n == 0:
        raise InvalidInputError("give at least one configuration", "configurations")
    if not isinstance(rows, np.ndarray):
        for i, row in enumerate(rows):
            if len(row) != n_joints:
                raise InvalidInputError(
                    f"expected {n_joints} values (one per joint), got {len(row)}",
                    f"configurations.{i}",
                )
        rows = np.array(rows, dtype=float).reshape(n, n_joints)
    elif rows.shape[1] != n_joints:
        raise InvalidInputError(
            f"expected {n_joints} values (one per joint), got {rows.shape[1]}", "configurations.0"
        )
    check_joint_values(rows, "configurations")
    return rows


def group_configurations(
    robot: RobotModel,
    grp: Group | None,
    rows: np.ndarray | Sequence[Sequence[float]],
    limit: int,
) -> np.ndarray:
    """A batch of full configurations (N, n), checked by :func:`configurations`: rows of one
    value per joint, or with a group, of the group's joints only (the others neutral:
    :func:`~app.kinematics.groups.expand_rows`)."""
    return expand_rows(robot, grp, configurations(rows, row_width(robot, grp, rows), limit))


def parse_json(raw: bytes) -> Any:
    """Decode a JSON body: orjson, or the standard library for NaN/Infinity tokens.

    The standard library accepts NaN and ±Infinity (not JSON, but what many clients send);
    the request models then reject them with the field's name. It also decodes a lone
    UTF-16 surrogate escape (``"\ud800"``), which orjson refuses: that is a 422 naming the
    field holding it. Anything else that does not decode, including arrays and objects
    nested deeper than orjson's 1024 levels (where the standard library would exceed the
    recursion limit), raises :class:`MalformedBodyError` (a 400 naming the body).
    """
    try:
        return orjson.loads(raw)
    except orjson.JSONDecodeError:
        try:
            obj = json.loads(raw)
        except RecursionError:  # nested deeper than the interpreter's recursion limit
            raise MalformedBodyError(NESTED_TOO_DEEPLY) from None
        except (ValueError, UnicodeDecodeError) as exc:
            raise MalformedBodyError(f"body: malformed JSON ({exc})") from None
        where = find_surrogate(obj)
        if where is not None:
            raise InvalidInputError(SURROGATE_REASON, where) from None
        return obj


def validate_body(model: type[S], obj: Any) -> S:
    """Validate a decoded body against a request model, errors as FastAPI's (HTTP 422)."""
    try:
        return model.model_validate(obj)
    except ValidationError as exc:
        raise RequestValidationError(
            [{**e, "loc": ("body", *e["loc"])} for e in exc.errors(include_url=False)]
        ) from None


def finite_matrix(obj: Any, width: int | None = None) -> np.ndarray | None:
    """A list of lists of JSON numbers as an (N, width) float array, or ``None``.

    The fast path for big batches: ``None`` whenever anything is off (ragged rows,
    non-numbers, booleans, non-finite values, wrong width), so the caller can fall back to
    full validation, which names the offending element.
    """
    if not isinstance(obj, list) or not obj:
        return None
    try:
        arr = np.array(obj)
    except (ValueError, TypeError, OverflowError):
        return None
    if arr.ndim != 2 or arr.dtype.kind not in "if" or (width is not None and arr.shape[1] != width):
        return None
    arr = arr.astype(float, copy=False)
    if not np.isfinite(arr).all():
        return None
    return arr


async def read_capped(request: Request, limit: int, detail: str) -> bytes | Response:
    """The request body, or a 413 problem (``detail``, field ``body``) past ``limit`` bytes.

    The body is counted as it streams, so an oversized one is never held whole.
    """
    too_large = problem(413, detail, kind="body-too-large", field="body", instance=request.url.path)
    length = request.headers.get("content-length", "")
    if length.isdigit() and int(length) > limit:
        return too_large
    chunks: list[bytes] = []
    total = 0
    async for chunk in request.stream():
        total += len(chunk)
        if total > limit:
            return too_large
        chunks.append(chunk)
    return b"".join(chunks)


def body_schema(
    model: type[BaseModel],
    media_types: tuple[str, ...] = ("application/json",),
    *,
    add_component: bool = True,
) -> dict[str, Any]:
    """``openapi_extra`` documenting a body that a route decodes itself (fast paths, YAML).

    The body is required and refers to ``model``'s schema under each media type. The model
    is added to the OpenAPI components (:data:`EXTRA_SCHEMAS`) unless ``add_component`` is
    false: for a model already there as a response model (its output schema is the one
    listed).
    """
    if add_component:
        EXTRA_SCHEMAS.append(model)
    ref = {"$ref": f"#/components/schemas/{model.__name__}"}
    content = {media: {"schema": ref} for media in media_types}
    return {"requestBody": {"required": True, "content": content}}


#: Request models of routes that decode their own bodies; added to the OpenAPI components.
EXTRA_SCHEMAS: list[type[BaseModel]] = []
