"""Robots: what exists, what each is made of, and adding or removing user robots.

Reads: GET /robots, GET /robots/{robot_id}, GET /robots/{robot_id}/urdf and
GET /robots/{robot_id}/dh. Writes (bearer token when ``DENAVIT_API_TOKEN`` is set):
POST /robots/dh (import a DH table, JSON or YAML), POST /robots/urdf (upload URDF text),
DELETE /robots/{robot_id} (user-added robots only). Write bodies are capped at
``DENAVIT_MAX_UPLOAD_BYTES`` (413 beyond), and a robot is stored atomically: it is served
(by every worker) once complete, or not at all. Wire models: :mod:`app.api.schemas.robots`;
a robot's description: :mod:`app.api.robot_answers`.
"""

from __future__ import annotations

from typing import Any, Literal

import yaml
from fastapi import APIRouter, Depends, Request
from starlette.responses import Response

from app.api.body import body_schema, decode_body, read_capped
from app.api.deps import RegistryDep, RobotDep, SettingsDep
from app.api.errors import ERROR_RESPONSES, MalformedBodyError, problem
from app.api.offload import offload_upload
from app.api.responses import ORJSONResponse
from app.api.robot_answers import WRITE_ERRORS, created, robot_detail
from app.api.schemas.common import RobotId
from app.api.schemas.robots import DHTableDoc, RobotDetail, RobotList, UrdfUpload
from app.api.security import require_token
from app.api.untrusted import OPENAPI_HEADERS, document_headers
from app.operations.settings import Settings
from app.robots.documents.dh import MAX_DH_DOCUMENT_BYTES, MalformedDocumentError, parse_dh_document
from app.robots.registry import Registry

router = APIRouter(prefix="/robots", tags=["robots"])

_JSON_TYPES = ("application/json", "")
_YAML_TYPES = ("application/yaml", "application/x-yaml", "text/yaml", "text/x-yaml")


async def _read_upload(
    request: Request, settings: Settings, cap: int | None = None
) -> bytes | Response:
    """The request body, or a 413 problem past ``DENAVIT_MAX_UPLOAD_BYTES`` (or ``cap``)."""
    limit = settings.max_upload_bytes
    if cap is not None:
        limit = min(limit, cap)
    return await read_capped(
        request,
        limit,
        f"body: larger than the {limit}-byte limit of this upload (DENAVIT_MAX_UPLOAD_BYTES; "
        f"DH tables at most {MAX_DH_DOCUMENT_BYTES})",
    )


def _import_dh(reg: Registry, text: str, fmt: Literal["json", "yaml"]) -> dict[str, Any]:
    try:
        table = parse_dh_document(text, fmt)
    except MalformedDocumentError as exc:
        raise MalformedBodyError(f"body: {exc.message}") from None
    return robot_detail(reg.import_dh(table))


def _add_urdf(reg: Registry, upload: UrdfUpload) -> dict[str, Any]:
    robot = reg.add_urdf(
        upload.name,
        upload.urdf,
        srdf=upload.srdf,
        ee_frame=upload.ee_frame,
        description=upload.description,
    )
    return robot_detail(robot)


# ---------------------------------------------------------------------- writes
@router.post(
    "/dh",
    operation_id="import_dh_robot",
    status_code=201,
    response_model=RobotDetail,
    dependencies=[Depends(require_token)],
    responses=WRITE_ERRORS,
    openapi_extra=body_schema(
        DHTableDoc, ("application/json", "application/yaml"), add_component=False
    ),
)
async def import_dh_robot(request: Request, reg: RegistryDep, settings: SettingsDep) -> Response:
    """Add a robot from a DH table; its id is the table's ``name``.

    The body is the table as JSON, or as YAML with ``Content-Type: application/yaml`` (or
    ``text/yaml``); lengths in m/cm/mm and angles in rad/deg as its ``units`` say. The
    service converts it to URDF (frames ``dh_0`` … ``dh_n`` and ``tool``, the default end
    effector) and answers 201 with the robot's description. 409 if the id is taken by any
    robot; 422 naming the field for a bad table (``joints.2.lower``); YAML aliases are
    refused; 413 past 256 KiB (or ``DENAVIT_MAX_UPLOAD_BYTES`` if smaller).
    """
    body = await _read_upload(request, settings, MAX_DH_DOCUMENT_BYTES)
    if isinstance(body, Response):
        return body
    media = request.headers.get("content-type", "").split(";")[0].strip().lower()
    if media in _JSON_TYPES or media.endswith("+json"):
        fmt: Literal["json", "yaml"] = "json"
    elif media in _YAML_TYPES:
        fmt = "yaml"
    else:
        return problem(
            415,
            f"content-type: {media!r} is not accepted; send application/json or application/yaml",
            kind="unsupported-media-type",
            field="content-type",
            instance=request.url.path,
        )
    try:
        text = body.decode("utf-8-sig")  # a leading BOM is dropped
    except UnicodeDecodeError as exc:
        raise MalformedBodyError(f"body: not UTF-8 text ({exc.reason})") from None
    return created(await offload_upload(request, _import_dh, reg, text, fmt))


@router.post(
    "/urdf",
    operation_id="upload_urdf_robot",
    status_code=201,
    response_model=RobotDetail,
    dependencies=[Depends(require_token)],
    responses=WRITE_ERRORS,
    openapi_extra=body_schema(UrdfUpload),
)
async def upload_urdf_robot(request: Request, reg: RegistryDep, settings: SettingsDep) -> Response:
    """Add a robot from URDF text (and optional SRDF); its id is ``name``.

    The XML is checked first, read as Pinocchio reads it (names taken literally, namespaces
    ignored): DTDs and entity declarations are refused, mesh filenames must be exactly
    ``package://<package>/<path>`` URIs without ``..`` or whitespace, joint axes need a norm
    of at least 1e-6, lengths and angles at most 1e6, and the links must form one tree with
    at least one actuated joint; then Pinocchio builds the model. The work a document may
    cause is bounded (422 naming the limit): XML elements, attributes (in total and per
    element), nesting depth, joints and movable joints (``DENAVIT_MAX_XML_*``,
    ``DENAVIT_MAX_URDF_JOINTS``, ``DENAVIT_MAX_ROBOT_DOF``). Text must be valid Unicode
    (no lone surrogates). 201 with the robot's description; 409 if the id is taken; 413
    past the upload limit.
    """
    body = await _read_upload(request, settings)
    if isinstance(body, Response):
        return body
    upload, _ = decode_body(body, UrdfUpload)
    return created(await offload_upload(request, _add_urdf, reg, upload))


@router.delete(
    "/{robot_id}",
    operation_id="delete_robot",
    status_code=204,
    dependencies=[Depends(require_token)],
    responses={k: WRITE_ERRORS[k] for k in (401, 403, 422)} | {404: ERROR_RESPONSES[404]},
)
def delete_robot(robot_id: RobotId, reg: RegistryDep) -> Response:
    """Remove a user-added robot (every worker stops serving it); built-in robots: 403."""
    reg.delete(robot_id)
    return Response(status_code=204)


# ---------------------------------------------------------------------- reads
@router.get("", operation_id="list_robots", response_model=RobotList)
def list_robots(reg: RegistryDep) -> ORJSONResponse:
    """List every robot: catalog robots, DH robots and user-added ones."""
    return ORJSONResponse(
        {
            "robots": [
                {
                    "id": s.id,
                    "name": s.name,
                    "source": s.source,
                    "joints": s.joints,
                    "description": s.description,
                }
                for s in reg.summaries()
            ]
        }
    )


@router.get(
    "/{robot_id}",
    operation_id="get_robot",
    response_model=RobotDetail,
    responses={404: ERROR_RESPONSES[404], 422: ERROR_RESPONSES[422]},
)
def get_robot(robot: RobotDep, reg: RegistryDep) -> ORJSONResponse:
    """Describe a robot: joints in order, frames, default end effector, neutral configuration.

    ``files`` tells a viewer where the meshes are: a mesh URI of GET /robots/{robot_id}/urdf
    that starts with ``files.uri_prefix`` is served at ``files.url`` + the rest of the URI
    (``package://files/meshes/a.stl`` → ``/robots/{robot_id}/files/meshes/a.stl``).

    Runs in the thread pool: the first request for a robot parses its URDF.
    """
    return ORJSONResponse(robot_detail(robot, reg.files_root(robot.id)))


@router.get(
    "/{robot_id}/urdf",
    operation_id="get_robot_urdf",
    response_class=Response,
    responses={
        200: {
            "content": {"application/xml": {"schema": {"type": "string"}}},
            "description": "URDF, as a download (`<robot_id>.urdf`).",
            "headers": OPENAPI_HEADERS,
        },
        404: ERROR_RESPONSES[404],
        422: ERROR_RESPONSES[422],
    },
)
def get_robot_urdf(robot_id: RobotId, reg: RegistryDep) -> Response:
    """The robot's URDF: the catalog file, the uploaded text, or the one generated from a
    DH table (links ``dh_0`` … ``dh_n`` and ``tool``; SI units).

    The uploaded text is served as it was sent, so the answer is a download that a browser
    never runs: ``Content-Disposition: attachment; filename="<robot_id>.urdf"`` and
    ``Content-Security-Policy: default-src 'none'; sandbox``."""
    return Response(
        reg.urdf_text(robot_id),
        media_type="application/xml",
        headers=document_headers(f"{robot_id}.urdf", "application/xml"),
    )


@router.get(
    "/{robot_id}/dh",
    operation_id="get_robot_dh",
    response_model=DHTableDoc,
    responses={
        200: {"content": {"application/yaml": {}}},
        404: {**ERROR_RESPONSES[404], "description": "Unknown robot, or not a DH robot."},
        422: ERROR_RESPONSES[422],
    },
)
def get_robot_dh(robot_id: RobotId, request: Request, reg: RegistryDep) -> Response:
    """The DH table a robot was built from, in SI units (m, rad) as validated on import.

    JSON by default; YAML when the ``Accept`` header asks for ``application/yaml``, as a
    download (``<robot_id>.yaml``, the headers of GET /robots/{robot_id}/urdf). 404 for
    robots that were not built from a DH table (their URDF is at /robots/{robot_id}/urdf).
    """
    table = reg.dh_table(robot_id)
    if table is None:
        return problem(
            404,
            f"robot_id: robot {robot_id!r} ({reg.source(robot_id)}) was not built from a DH "
            f"table; its URDF is at /robots/{robot_id}/urdf",
            kind="not-a-dh-robot",
            field="robot_id",
            instance=request.url.path,
        )
    doc = table.to_dict()
    accept = request.headers.get("accept", "")
    if any(t in accept for t in _YAML_TYPES):
        return Response(
            yaml.safe_dump(doc, sort_keys=False, allow_unicode=True),
            media_type="application/yaml",
            headers=document_headers(f"{robot_id}.yaml", "application/yaml"),
        )
    return ORJSONResponse(doc)
