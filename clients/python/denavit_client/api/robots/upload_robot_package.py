from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.package_upload import PackageUpload
from ...models.problem import Problem
from ...models.robot_detail import RobotDetail
from ...types import Response


def _get_kwargs(
    *,
    body: PackageUpload,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/robots/package",
    }

    _kwargs["files"] = body.to_multipart()

    headers["Content-Type"] = "multipart/form-data; boundary=+++"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Problem | RobotDetail | None:
    if response.status_code == 201:
        response_201 = RobotDetail.from_dict(response.json())

        return response_201

    if response.status_code == 400:
        response_400 = Problem.from_dict(response.json())

        return response_400

    if response.status_code == 401:
        response_401 = Problem.from_dict(response.json())

        return response_401

    if response.status_code == 403:
        response_403 = Problem.from_dict(response.json())

        return response_403

    if response.status_code == 409:
        response_409 = Problem.from_dict(response.json())

        return response_409

    if response.status_code == 413:
        response_413 = Problem.from_dict(response.json())

        return response_413

    if response.status_code == 415:
        response_415 = Problem.from_dict(response.json())

        return response_415

    if response.status_code == 422:
        response_422 = Problem.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = Problem.from_dict(response.json())

        return response_503

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[Problem | RobotDetail]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PackageUpload,
) -> Response[Problem | RobotDetail]:
    """Upload Robot Package

     Add a robot from a description package (zip or tar.gz with its meshes); id ``name``.

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

    Args:
        body (PackageUpload): A robot as a description package: an archive with its description
            and meshes.

            Sent as ``multipart/form-data``; every field but ``archive`` is a text part.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Problem | RobotDetail]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: PackageUpload,
) -> Problem | RobotDetail | None:
    """Upload Robot Package

     Add a robot from a description package (zip or tar.gz with its meshes); id ``name``.

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

    Args:
        body (PackageUpload): A robot as a description package: an archive with its description
            and meshes.

            Sent as ``multipart/form-data``; every field but ``archive`` is a text part.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Problem | RobotDetail
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PackageUpload,
) -> Response[Problem | RobotDetail]:
    """Upload Robot Package

     Add a robot from a description package (zip or tar.gz with its meshes); id ``name``.

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

    Args:
        body (PackageUpload): A robot as a description package: an archive with its description
            and meshes.

            Sent as ``multipart/form-data``; every field but ``archive`` is a text part.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Problem | RobotDetail]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: PackageUpload,
) -> Problem | RobotDetail | None:
    """Upload Robot Package

     Add a robot from a description package (zip or tar.gz with its meshes); id ``name``.

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

    Args:
        body (PackageUpload): A robot as a description package: an archive with its description
            and meshes.

            Sent as ``multipart/form-data``; every field but ``archive`` is a text part.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Problem | RobotDetail
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
