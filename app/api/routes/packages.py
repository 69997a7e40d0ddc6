"""Description packages: uploading a robot as an archive with its meshes, serving its files.

POST /robots/package (multipart/form-data, bearer token when ``DENAVIT_API_TOKEN`` is set)
adds a robot from a zip or tar.gz archive; GET (and HEAD) /robots/{robot_id}/files/{path}
serves the files of a package robot and of the catalog robots (their example-robot-data
folder), so a viewer can load the meshes the URDF names.
"""

from __future__ import annotations

from typing import Any

import orjson
from fastapi import APIRouter, Depends, Request
from starlette.datastructures import UploadFile
from starlette.responses import Response

from app.api.body import body_schema, read_capped, validate_body
from app.api.deps import RegistryDep, SettingsDep
from app.api.errors import ERROR_RESPONSES, problem
from app.api.offload import offload_upload
from app.api.robot_answers import WRITE_ERRORS, created, robot_detail
from app.api.schemas.common import RobotId
from app.api.schemas.packages import PackageForm, PackageUpload
from app.api.schemas.robots import RobotDetail
from app.api.security import require_token
from app.api.untrusted import OPENAPI_HEADERS, UntrustedFileResponse
from app.kinematics.errors import InvalidInputError
from app.robots.documents.xacro import check_xacro_args
from app.robots.registry import Registry

router = APIRouter(prefix="/robots", tags=["robots"])

#: Content types of the files a viewer loads (by extension); others are octet streams.
CONTENT_TYPES = {
    ".stl": "model/stl",
    ".dae": "model/vnd.collada+xml",
    ".obj": "model/obj",
    ".ply": "application/octet-stream",
    ".png": "image/png",
    ".jpg": "image/jpeg",
    ".jpeg": "image/jpeg",
    ".urdf": "application/xml",
    ".xacro": "application/xml",
    ".xml": "application/xml",
    ".srdf": "application/xml",
}
#: The longest file name (one path segment) a file system stores, in bytes (Linux NAME_MAX).
MAX_NAME_BYTES = 255
_TEXT_FIELDS = (
    "name",
    "description",
    "srdf",
    "xacro_args",
    "srdf_xacro_args",
    "ee_frame",
    "summary",
)


def _xacro_args(text: str | None, field: str = "xacro_args") -> dict[str, str]:
    """The ``xacro_args`` (or ``srdf_xacro_args``) form field: a JSON object of argument
    names to strings, numbers or booleans (:func:`app.robots.documents.xacro.check_xacro_args`)."""
    if text is None:
        return {}
    try:
        args = orjson.loads(text)
    except orjson.JSONDecodeError as exc:
        raise InvalidInputError(f"not a JSON object ({exc})", field) from None
    return check_xacro_args(args, field)


def _add_package(reg: Registry, form: PackageForm, archive: Any) -> dict[str, Any]:
    robot = reg.add_package(
        form.name,
        archive,
        form.description,
        srdf_path=form.srdf,
        xacro_args=_xacro_args(form.xacro_args),
        ee_frame=form.ee_frame,
        description=form.summary,
        srdf_xacro_args=(
            None
            if form.srdf_xacro_args is None
            else _xacro_args(form.srdf_xacro_args, "srdf_xacro_args")
        ),
    )
    return robot_detail(robot, reg.files_root(robot.id))


@router.post(
    "/package",
    operation_id="upload_robot_package",
    status_code=201,
    response_model=RobotDetail,
    dependencies=[Depends(require_token)],
    responses={
        **WRITE_ERRORS,
        413: {**WRITE_ERRORS[413], "description": "The body exceeds DENAVIT_MAX_PACKAGE_BYTES."},
    },
    openapi_extra=body_schema(PackageUpload, ("multipart/form-data",)),
)
async def upload_robot_package(
    request: Request, reg: RegistryDep, settings: SettingsDep
) -> Response:
    """Add a robot from a description package (zip or tar.gz with its meshes); id ``name``.

    Form fields: ``name``, ``archive`` (the file), ``description`` (path inside the archive
    of a ``.urdf``, ``.xacro`` or MJCF ``.xml``), optional ``srdf`` (path; a ``.xacro`` one
    is expanded like the description), ``xacro_args`` (JSON object of strings, numbers or
    booleans), ``srdf_xacro_args`` (the same, for a ``.xacro`` SRDF whose arguments
    differ), ``ee_frame`` and ``summary`` (short description).

    The archive is unpacked safely (422 naming ``archive`` and the member otherwise): no
    absolute names, ``..``, drive letters or backslashes, no links, devices or duplicate
    names, at most ``DENAVIT_MAX_PACKAGE_FILES`` entries and
    ``DENAVIT_MAX_PACKAGE_UNPACKED_BYTES`` once unpacked (counted while decompressing).
    Mesh and texture references resolve inside the package: relative paths and
    ``file://<relative path>`` against the description's folder, ``package://<pkg>/…``
    against the package named ``<pkg>`` by a ``package.xml`` (or a top-level folder of the
    archive); ``package://example-robot-data/robots/<folder>/<path>`` names the archive's
    own copy when it has one (``<path>``, ``<folder>/<path>`` or ``robots/<folder>/<path>``
    under the description's folder or its nearest parent with one), else the catalog's file.
    A reference that leaves the package, an absolute path, another scheme or a missing file
    is a 422 naming it; every mesh is loaded (STL, COLLADA, OBJ or PLY) and one that cannot
    be read is a 422 naming it, so a 201 means collisions work. The stored URDF (GET
    /robots/{robot_id}/urdf) names every file ``package://files/<path in the archive>``,
    served at GET /robots/{robot_id}/files/<path in the archive>. Then the URDF is checked
    as in POST /robots/urdf. 413 past ``DENAVIT_MAX_PACKAGE_BYTES`` (the whole
    form); 409 if the id is taken. Nothing is stored on any refusal.
    """
    limit = settings.max_package_bytes
    body = await read_capped(
        request,
        limit,
        f"body: larger than the {limit}-byte limit of a package upload (DENAVIT_MAX_PACKAGE_BYTES)",
    )
    if isinstance(body, Response):
        return body
    media = request.headers.get("content-type", "").split(";")[0].strip().lower()
    if media != "multipart/form-data":
        return problem(
            415,
            f"content-type: {media!r} is not accepted; send multipart/form-data",
            kind="unsupported-media-type",
            field="content-type",
            instance=request.url.path,
        )
    request._body = body  # the form parser reads the body already counted
    try:
        form = await request.form(max_files=8, max_fields=len(_TEXT_FIELDS) + 8)
    except Exception as exc:  # python-multipart's and Starlette's parse errors
        return problem(
            400,
            f"body: not a valid multipart form ({getattr(exc, 'detail', exc)})",
            kind="malformed-body",
            field="body",
            instance=request.url.path,
        )
    try:
        fields: dict[str, Any] = {}
        archive = None
        for key, value in form.multi_items():
            if key in fields or (key == "archive" and archive is not None):
                raise InvalidInputError("given twice", key)
            if key == "archive":
                if not isinstance(value, UploadFile):
                    raise InvalidInputError("must be a file part", "archive")
                archive = value
            elif isinstance(value, UploadFile):
                raise InvalidInputError("must be a text field, not a file", key)
            else:
                fields[key] = value
        parsed = validate_body(PackageForm, fields)
        if archive is None:
            raise InvalidInputError("the archive file is required", "archive")
        return created(await offload_upload(request, _add_package, reg, parsed, archive.file))
    finally:
        await form.close()


@router.get(
    "/{robot_id}/files/{path:path}",
    operation_id="get_robot_file",
    response_class=Response,
    responses={
        200: {
            "content": {"application/octet-stream": {"schema": {"type": "string"}}},
            "description": "The file (model/stl, model/vnd.collada+xml, model/obj, image/png, "
            "image/jpeg, application/xml, or application/octet-stream), as a download.",
            "headers": OPENAPI_HEADERS,
        },
        206: {"description": "The byte ranges asked for by `Range`, with the same headers."},
        400: {**ERROR_RESPONSES[400], "description": "A malformed `Range` header."},
        404: {**ERROR_RESPONSES[404], "description": "Unknown robot, or no such file."},
        416: {**ERROR_RESPONSES[400], "description": "A `Range` outside the file."},
        422: ERROR_RESPONSES[422],
    },
)
def get_robot_file(robot_id: RobotId, path: str, request: Request, reg: RegistryDep) -> Response:
    """A file of a robot's package: what its URDF's mesh URIs name, for viewers.

    For a package robot, ``path`` is the file's path inside the uploaded archive (the URDF
    names it ``package://files/<path>``); for a catalog robot, the path inside its
    example-robot-data folder (``package://example-robot-data/robots/<folder>/<path>``).
    GET /robots/{robot_id} gives this mapping in ``files``. 404 for a missing file, a robot
    without files, or a path the file system cannot hold (a segment over 255 bytes); 422
    for a path with ``..``, ``.``, empty segments or backslashes.

    The files are the client's, served as it sent them: every answer carries
    ``Content-Security-Policy: default-src 'none'; sandbox`` and ``X-Content-Type-Options:
    nosniff``, and every type but image/png and image/jpeg ``Content-Disposition:
    attachment``, so that a browser never runs a script a file holds (an XHTML, SVG or
    HTML document) in the service's origin. Viewers load them with fetch/XHR or ``<img>``,
    which ignore the disposition. ``Range`` is honoured (206); a malformed one is a 400, one
    outside the file a 416, both naming ``range``.
    """
    located = reg.files_root(robot_id)
    parts = path.split("/")
    if any(p in ("", ".", "..") for p in parts) or any(c in path for c in "\\\x00"):
        raise InvalidInputError("must be a relative path without '..', '.' or '//'", "path")
    missing = problem(
        404,
        f"path: robot {robot_id!r} has no file {path[:200]!r}",
        kind="unknown-name",
        field="path",
        instance=request.url.path,
    )
    if located is None:
        return missing
    if any(len(p.encode("utf-8", "replace")) > MAX_NAME_BYTES for p in parts):
        return missing  # no file system stores such a name
    root = located[0].resolve()
    file = root.joinpath(*parts)
    try:
        if not file.resolve().is_relative_to(root) or file.is_symlink() or not file.is_file():
            return missing
        stat_result = file.stat()
    except OSError:  # a path the OS refuses (too long, too deep, unreadable): not a file here
        return missing
    media = CONTENT_TYPES.get(file.suffix.lower(), "application/octet-stream")
    return UntrustedFileResponse(file, stat_result, media)
