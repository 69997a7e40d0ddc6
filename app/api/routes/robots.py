"""Robots: what exists, what each is made of, and adding or removing user robots.

Reads: GET /robots, GET /robots/{robot_id}, GET /robots/{robot_id}/urdf and
GET /robots/{robot_id}/dh. Writes (bearer token when ``DENAVIT_API_TOKEN`` is set):
POST /robots/dh (import a DH table, JSON or YAML), POST /robots/urdf (upload URDF text),
DELETE /robots/{robot_id} (user-added robots only). Write bodies are capped at
``DENAVIT_MAX_UPLOAD_BYTES`` (413 beyond), and a robot is stored atomically: it is served
(by every worker) once complete, or not at all.
"""

from __future__ import annotations

from typing import Any, Literal

import yaml
from fastapi import APIRouter, Depends, Request
from pydantic import BaseModel, Field
from starlette.responses import Response

from app.api.body import body_schema, decode_body, read_capped
from app.api.deps import RegistryDep
from app.api.errors import ERROR_RESPONSES, MalformedBodyError, Problem, problem
from app.api.offload import offload_upload
from app.api.responses import ORJSONResponse
from app.api.schemas.common import RobotId, Schema, Text, Vec3Out
from app.api.schemas.semantics import EndEffectorOut, GroupOut, NamedStateOut, semantics_detail
from app.api.security import require_token
from app.api.untrusted import OPENAPI_HEADERS, document_headers
from app.kinematics.collision_pairs import collision_link_pairs
from app.kinematics.models import RobotModel
from app.robots.documents.dh import MAX_DH_DOCUMENT_BYTES, MalformedDocumentError, parse_dh_document
from app.robots.registry import Registry
from app.storage.store import ID_PATTERN

router = APIRouter(prefix="/robots", tags=["robots"])


class RobotSummaryOut(BaseModel):
    """One robot in the list."""

    id: str = Field(description="Robot id, used in every /robots/{robot_id} URL.")
    name: str = Field(description="Human-readable name.")
    source: str = Field(description="example-robot-data | dh | upload | package.")
    joints: int = Field(description="Number of actuated joints (length of a configuration).")
    description: str = Field("", description="Short description.")


class RobotList(BaseModel):
    """All robots the service knows."""

    robots: list[RobotSummaryOut]


class JointLimits(BaseModel):
    """Joint limits, SI units; ``null`` where the URDF gives none (continuous joints)."""

    lower: float | None = Field(description="Lower position limit (rad or m).")
    upper: float | None = Field(description="Upper position limit (rad or m).")
    velocity: float | None = Field(description="Velocity limit (rad/s or m/s).")
    effort: float | None = Field(description="Effort limit (N·m or N).")


class JointOut(BaseModel):
    """An actuated joint, in configuration order."""

    name: str
    type: str = Field(description="revolute | prismatic | continuous.")
    parent: str = Field(description="Parent link.")
    child: str = Field(description="Child link.")
    axis: Vec3Out = Field(description="Joint axis in the joint frame (URDF <axis>).")
    limits: JointLimits
    continuous: bool = Field(description="Unbounded revolute joint (one angle on the wire).")


class MimicJointOut(BaseModel):
    """A mimic joint: it follows its leader and is not a configuration entry."""

    name: str
    type: str = Field(description="revolute | prismatic (the URDF type).")
    leader: str = Field(description="The actuated joint it follows.")
    multiplier: float = Field(description="value = multiplier × value(leader) + offset.")
    offset: float = Field(description="Offset (rad or m).")


class FrameOut(BaseModel):
    """A named frame."""

    name: str
    kind: str = Field(description="link | fixed (URDF fixed joint) | joint.")
    parent_joint: str | None = Field(description="The actuated joint that moves it, if any.")


class RobotFilesOut(BaseModel):
    """Where a viewer fetches the files (meshes, textures) a robot's URDF names."""

    uri_prefix: str = Field(
        description="Mesh URIs of the URDF that start with this prefix are files served here."
    )
    url: str = Field(
        description="Replace uri_prefix by this URL path (GET /robots/{robot_id}/files/{path})."
    )


class RobotDetail(BaseModel):
    """Everything a client needs to talk about a robot."""

    id: str
    name: str
    source: str
    description: str
    joints: list[JointOut] = Field(description="Actuated joints in configuration order.")
    mimic_joints: list[MimicJointOut] = Field(
        description="Mimic joints (URDF <mimic>): not in configurations, moved by their "
        "leader. A joint_positions or seed map may name them (a ROS JointState of the whole "
        "robot) when the value is multiplier × leader + offset within 1e-9 (the leader's "
        "value from the same map, else its default)."
    )
    frames: list[FrameOut] = Field(description="Every named frame (links and fixed frames).")
    end_effector: str = Field(
        description="Default frame of fk, jacobian and ik (the default tip): the ee_frame given "
        "at upload (or the catalog's choice), else the parent_link of the SRDF's first end "
        "effector, else the tip of the longest serial chain that is not a gripper finger (a "
        "finger: a link moved by one of at least two sibling branches made only of prismatic "
        "and mimic joints; among links held by the same joint, a link without geometry such "
        "as a TCP or tool0 first, then the farthest), else the deepest link."
    )
    groups: list[GroupOut] = Field(description="SRDF planning groups (`group` in requests).")
    end_effectors: list[EndEffectorOut] = Field(description="SRDF end effectors.")
    named_states: list[NamedStateOut] = Field(description="SRDF group states (IK seeds).")
    neutral: list[float] = Field(description="Neutral configuration (0, clipped to limits).")
    has_collision_geometry: bool = Field(description="Whether the URDF has <collision>.")
    collision_pairs: list[list[str]] = Field(
        description="Self-collision link pairs [a, b] that collision checks test (same-body, "
        "adjacent and SRDF-disabled pairs removed)."
    )
    files: RobotFilesOut | None = Field(
        None,
        description="How the URDF's mesh URIs map to GET /robots/{robot_id}/files/{path} "
        "(catalog and package robots; null for others).",
    )


# ---------------------------------------------------------------------- DH table documents
class DHUnitsDoc(Schema):
    """Units of the table's numbers (the service converts to SI on import)."""

    length: Literal["m", "cm", "mm"] = Field("m", description="Unit of a, d, xyz, limits.")
    angle: Literal["rad", "deg"] = Field("rad", description="Unit of alpha, theta, rpy, limits.")


class DHTransformDoc(Schema):
    """A fixed transform: translation ``xyz`` then rotation ``rpy`` (R = Rz·Ry·Rx)."""

    xyz: list[float] | None = Field([0.0, 0.0, 0.0], min_length=3, max_length=3)
    rpy: list[float] | None = Field([0.0, 0.0, 0.0], min_length=3, max_length=3)


class DHGeometryDoc(Schema):
    """Generated capsule geometry."""

    radius: float | None = Field(0.02, ge=0, description="Capsule radius in metres (0: none).")


class DHRowDoc(Schema):
    """One row: joint i's DH parameters."""

    name: Text | None = Field(None, description="Joint name (default j<i>, 1-based).")
    type: Literal["revolute", "prismatic", "continuous"] | None = Field(
        "revolute", description="Joint kind (null: revolute)."
    )
    a: float = Field(description="Link length (a_i; a_{i-1} in the modified convention).")
    alpha: float = Field(description="Link twist (α_i; α_{i-1} in the modified convention).")
    d: float = Field(description="Link offset; the constant part for a prismatic joint.")
    theta: float = Field(description="Joint angle offset (θ = q + theta for revolute joints).")
    lower: float | None = Field(None, description="Lower limit of q (table units).")
    upper: float | None = Field(None, description="Upper limit of q (table units).")
    velocity: float | None = Field(None, gt=0, description="Velocity limit (units per second).")
    effort: float | None = Field(None, gt=0, description="Effort limit (N·m or N).")


class DHTableDoc(Schema):
    """A Denavit–Hartenberg table (JSON, or YAML with ``Content-Type: application/yaml``).

    ``standard``: A_i = Rz(θ_i)·Tz(d_i)·Tx(a_i)·Rx(α_i); ``modified`` (Craig): A_i =
    Rx(α_{i-1})·Tx(a_{i-1})·Rz(θ_i)·Tz(d_i). The robot's frames ``dh_0`` … ``dh_n`` are the
    DH frames (world pose B·A_1⋯A_i) and ``tool`` (the default end effector) is
    dh_n·T_tool.
    """

    name: str = Field(
        pattern=ID_PATTERN.pattern, description="Robot id: 1-64 of a-z, 0-9, '_' and '-'."
    )
    description: Text | None = Field("", max_length=1000)
    convention: Literal["standard", "modified"]
    units: DHUnitsDoc | None = Field(default_factory=DHUnitsDoc)
    base: DHTransformDoc | None = Field(None, description="World → DH frame 0.")
    tool: DHTransformDoc | None = Field(None, description="DH frame n → tool (TCP).")
    geometry: DHGeometryDoc | None = None
    joints: list[DHRowDoc] = Field(min_length=1, max_length=64)


class UrdfUpload(Schema):
    """A robot given as URDF text (and optionally SRDF)."""

    name: Text = Field(
        max_length=256,
        json_schema_extra={"pattern": ID_PATTERN.pattern},
        description="Robot id: 1-64 of a-z, 0-9, '_' and '-' (used in /robots/{robot_id}).",
    )
    urdf: Text = Field(
        min_length=1,
        description="URDF document. No DTD or entities; mesh filenames must be "
        "package://<package>/<path> URIs; only revolute, continuous, prismatic and fixed "
        "joints.",
    )
    srdf: Text | None = Field(
        None,
        description="SRDF document: disabled collision pairs, planning groups (chain, joints, "
        "links, subgroups), end effectors and group states, checked against the URDF.",
    )
    ee_frame: Text | None = Field(
        None,
        max_length=256,
        description="Default end-effector frame (default: the parent_link of the SRDF's first "
        "end effector, else the tip of the longest serial chain that is not a gripper finger; "
        "see end_effector in GET /robots/{robot_id}).",
    )
    description: Text = Field("", max_length=1000, description="Short description.")


_WRITE_ERRORS: dict[int | str, dict[str, Any]] = {
    code: {"model": Problem, "content": {"application/problem+json": {}}, "description": text}
    for code, text in {
        400: "The body is not JSON (or YAML).",
        401: "A bearer token is required.",
        403: "Wrong token, or a built-in robot.",
        409: "The robot id is taken.",
        413: "The body exceeds DENAVIT_MAX_UPLOAD_BYTES.",
        415: "Unsupported Content-Type.",
        422: "A field failed validation; `field` names it.",
    }.items()
}
_JSON_TYPES = ("application/json", "")
_YAML_TYPES = ("application/yaml", "application/x-yaml", "text/yaml", "text/x-yaml")


def robot_detail(robot: RobotModel, files: tuple[Any, str] | None = None) -> dict[str, Any]:
    """The wire description of a robot (GET /robots/{robot_id}); ``files`` as returned by
    :meth:`Registry.files_root`."""
    return {
        "id": robot.id,
        "name": robot.name,
        "source": robot.source,
        "description": robot.description,
        "joints": [robot.describe_joint(j) for j in robot.joints],
        "mimic_joints": [m.describe() for m in robot.mimic_joints],
        "frames": [
            {"name": f.name, "kind": f.kind, "parent_joint": f.parent_joint} for f in robot.frames
        ],
        "end_effector": robot.ee_frame,
        **semantics_detail(robot),
        "neutral": robot.neutral().tolist(),
        "has_collision_geometry": robot.has_collision_geometry,
        "collision_pairs": [list(p) for p in collision_link_pairs(robot)],
        "files": ({"uri_prefix": files[1], "url": f"/robots/{robot.id}/files/"} if files else None),
    }


def _created(detail: dict[str, Any]) -> ORJSONResponse:
    """201 with the new robot's description (built in the pool, like the robot itself)."""
    return ORJSONResponse(detail, status_code=201, headers={"Location": f"/robots/{detail['id']}"})


async def _read_upload(request: Request, cap: int | None = None) -> bytes | Response:
    """The request body, or a 413 problem past ``DENAVIT_MAX_UPLOAD_BYTES`` (or ``cap``)."""
    limit = request.app.state.settings.max_upload_bytes
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
    responses=_WRITE_ERRORS,
    openapi_extra=body_schema(
        DHTableDoc, ("application/json", "application/yaml"), add_component=False
    ),
)
async def import_dh_robot(request: Request, reg: RegistryDep) -> Response:
    """Add a robot from a DH table; its id is the table's ``name``.

    The body is the table as JSON, or as YAML with ``Content-Type: application/yaml`` (or
    ``text/yaml``); lengths in m/cm/mm and angles in rad/deg as its ``units`` say. The
    service converts it to URDF (frames ``dh_0`` … ``dh_n`` and ``tool``, the default end
    effector) and answers 201 with the robot's description. 409 if the id is taken by any
    robot; 422 naming the field for a bad table (``joints.2.lower``); YAML aliases are
    refused; 413 past 256 KiB (or ``DENAVIT_MAX_UPLOAD_BYTES`` if smaller).
    """
    body = await _read_upload(request, MAX_DH_DOCUMENT_BYTES)
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
    return _created(await offload_upload(request, _import_dh, reg, text, fmt))


@router.post(
    "/urdf",
    operation_id="upload_urdf_robot",
    status_code=201,
    response_model=RobotDetail,
    dependencies=[Depends(require_token)],
    responses=_WRITE_ERRORS,
    openapi_extra=body_schema(UrdfUpload),
)
async def upload_urdf_robot(request: Request, reg: RegistryDep) -> Response:
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
    body = await _read_upload(request)
    if isinstance(body, Response):
        return body
    upload, _ = decode_body(body, UrdfUpload)
    return _created(await offload_upload(request, _add_urdf, reg, upload))


@router.delete(
    "/{robot_id}",
    operation_id="delete_robot",
    status_code=204,
    dependencies=[Depends(require_token)],
    responses={k: _WRITE_ERRORS[k] for k in (401, 403, 422)} | {404: ERROR_RESPONSES[404]},
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
def get_robot(robot_id: RobotId, reg: RegistryDep) -> ORJSONResponse:
    """Describe a robot: joints in order, frames, default end effector, neutral configuration.

    ``files`` tells a viewer where the meshes are: a mesh URI of GET /robots/{robot_id}/urdf
    that starts with ``files.uri_prefix`` is served at ``files.url`` + the rest of the URI
    (``package://files/meshes/a.stl`` → ``/robots/{robot_id}/files/meshes/a.stl``).

    Runs in the thread pool: the first request for a robot parses its URDF.
    """
    return ORJSONResponse(robot_detail(reg.get(robot_id), reg.files_root(robot_id)))


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
