from http import HTTPStatus
from io import BytesIO
from typing import Any
from urllib.parse import quote

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.problem import Problem
from ...types import File, Response


def _get_kwargs(
    robot_id: str,
    path: str,
) -> dict[str, Any]:

    _kwargs: dict[str, Any] = {
        "method": "get",
        "url": "/robots/{robot_id}/files/{path}".format(
            robot_id=quote(str(robot_id), safe=""),
            path=quote(str(path), safe=""),
        ),
    }

    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> File | Problem | None:
    if response.status_code == 200:
        response_200 = File(payload=BytesIO(response.content))

        return response_200

    if response.status_code == 206:
        response_206 = File(payload=BytesIO(response.content))

        return response_206

    if response.status_code == 400:
        response_400 = Problem.from_dict(response.json())

        return response_400

    if response.status_code == 404:
        response_404 = Problem.from_dict(response.json())

        return response_404

    if response.status_code == 413:
        response_413 = Problem.from_dict(response.json())

        return response_413

    if response.status_code == 416:
        response_416 = Problem.from_dict(response.json())

        return response_416

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
) -> Response[File | Problem]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    robot_id: str,
    path: str,
    *,
    client: AuthenticatedClient | Client,
) -> Response[File | Problem]:
    """Get Robot File

     A file of a robot's package: what its URDF's mesh URIs name, for viewers.

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

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        path (str):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[File | Problem]
    """

    kwargs = _get_kwargs(
        robot_id=robot_id,
        path=path,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    robot_id: str,
    path: str,
    *,
    client: AuthenticatedClient | Client,
) -> File | Problem | None:
    """Get Robot File

     A file of a robot's package: what its URDF's mesh URIs name, for viewers.

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

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        path (str):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        File | Problem
    """

    return sync_detailed(
        robot_id=robot_id,
        path=path,
        client=client,
    ).parsed


async def asyncio_detailed(
    robot_id: str,
    path: str,
    *,
    client: AuthenticatedClient | Client,
) -> Response[File | Problem]:
    """Get Robot File

     A file of a robot's package: what its URDF's mesh URIs name, for viewers.

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

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        path (str):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[File | Problem]
    """

    kwargs = _get_kwargs(
        robot_id=robot_id,
        path=path,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    robot_id: str,
    path: str,
    *,
    client: AuthenticatedClient | Client,
) -> File | Problem | None:
    """Get Robot File

     A file of a robot's package: what its URDF's mesh URIs name, for viewers.

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

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        path (str):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        File | Problem
    """

    return (
        await asyncio_detailed(
            robot_id=robot_id,
            path=path,
            client=client,
        )
    ).parsed
