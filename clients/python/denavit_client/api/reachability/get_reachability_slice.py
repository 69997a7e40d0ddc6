from http import HTTPStatus
from io import BytesIO
from typing import Any
from urllib.parse import quote

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.problem import Problem
from ...types import UNSET, File, Response, Unset


def _get_kwargs(
    robot_id: str,
    map_id: str,
    *,
    x: float | None | Unset = UNSET,
    y: float | None | Unset = UNSET,
    z: float | None | Unset = UNSET,
    scale: int | None | Unset = UNSET,
) -> dict[str, Any]:

    params: dict[str, Any] = {}

    json_x: float | None | Unset
    if isinstance(x, Unset):
        json_x = UNSET
    else:
        json_x = x
    params["x"] = json_x

    json_y: float | None | Unset
    if isinstance(y, Unset):
        json_y = UNSET
    else:
        json_y = y
    params["y"] = json_y

    json_z: float | None | Unset
    if isinstance(z, Unset):
        json_z = UNSET
    else:
        json_z = z
    params["z"] = json_z

    json_scale: int | None | Unset
    if isinstance(scale, Unset):
        json_scale = UNSET
    else:
        json_scale = scale
    params["scale"] = json_scale

    params = {k: v for k, v in params.items() if v is not UNSET and v is not None}

    _kwargs: dict[str, Any] = {
        "method": "get",
        "url": "/robots/{robot_id}/reachability/maps/{map_id}/slice.png".format(
            robot_id=quote(str(robot_id), safe=""),
            map_id=quote(str(map_id), safe=""),
        ),
        "params": params,
    }

    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> File | Problem | None:
    if response.status_code == 200:
        response_200 = File(payload=BytesIO(response.content))

        return response_200

    if response.status_code == 400:
        response_400 = Problem.from_dict(response.json())

        return response_400

    if response.status_code == 404:
        response_404 = Problem.from_dict(response.json())

        return response_404

    if response.status_code == 413:
        response_413 = Problem.from_dict(response.json())

        return response_413

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
    map_id: str,
    *,
    client: AuthenticatedClient | Client,
    x: float | None | Unset = UNSET,
    y: float | None | Unset = UNSET,
    z: float | None | Unset = UNSET,
    scale: int | None | Unset = UNSET,
) -> Response[File | Problem]:
    """Get Reachability Slice

     Heat map of one voxel layer: colour = best manipulability over orientations (viridis,
    scaled to the map's maximum), light grey = unreached. Give exactly one of x, y, z.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        map_id (str): Map id, as listed by …/reachability/maps.
        x (float | None | Unset): Slice at this x (m).
        y (float | None | Unset): Slice at this y (m).
        z (float | None | Unset): Slice at this z (m).
        scale (int | None | Unset): Pixels per voxel (default: ~512 px).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[File | Problem]
    """

    kwargs = _get_kwargs(
        robot_id=robot_id,
        map_id=map_id,
        x=x,
        y=y,
        z=z,
        scale=scale,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    robot_id: str,
    map_id: str,
    *,
    client: AuthenticatedClient | Client,
    x: float | None | Unset = UNSET,
    y: float | None | Unset = UNSET,
    z: float | None | Unset = UNSET,
    scale: int | None | Unset = UNSET,
) -> File | Problem | None:
    """Get Reachability Slice

     Heat map of one voxel layer: colour = best manipulability over orientations (viridis,
    scaled to the map's maximum), light grey = unreached. Give exactly one of x, y, z.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        map_id (str): Map id, as listed by …/reachability/maps.
        x (float | None | Unset): Slice at this x (m).
        y (float | None | Unset): Slice at this y (m).
        z (float | None | Unset): Slice at this z (m).
        scale (int | None | Unset): Pixels per voxel (default: ~512 px).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        File | Problem
    """

    return sync_detailed(
        robot_id=robot_id,
        map_id=map_id,
        client=client,
        x=x,
        y=y,
        z=z,
        scale=scale,
    ).parsed


async def asyncio_detailed(
    robot_id: str,
    map_id: str,
    *,
    client: AuthenticatedClient | Client,
    x: float | None | Unset = UNSET,
    y: float | None | Unset = UNSET,
    z: float | None | Unset = UNSET,
    scale: int | None | Unset = UNSET,
) -> Response[File | Problem]:
    """Get Reachability Slice

     Heat map of one voxel layer: colour = best manipulability over orientations (viridis,
    scaled to the map's maximum), light grey = unreached. Give exactly one of x, y, z.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        map_id (str): Map id, as listed by …/reachability/maps.
        x (float | None | Unset): Slice at this x (m).
        y (float | None | Unset): Slice at this y (m).
        z (float | None | Unset): Slice at this z (m).
        scale (int | None | Unset): Pixels per voxel (default: ~512 px).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[File | Problem]
    """

    kwargs = _get_kwargs(
        robot_id=robot_id,
        map_id=map_id,
        x=x,
        y=y,
        z=z,
        scale=scale,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    robot_id: str,
    map_id: str,
    *,
    client: AuthenticatedClient | Client,
    x: float | None | Unset = UNSET,
    y: float | None | Unset = UNSET,
    z: float | None | Unset = UNSET,
    scale: int | None | Unset = UNSET,
) -> File | Problem | None:
    """Get Reachability Slice

     Heat map of one voxel layer: colour = best manipulability over orientations (viridis,
    scaled to the map's maximum), light grey = unreached. Give exactly one of x, y, z.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        map_id (str): Map id, as listed by …/reachability/maps.
        x (float | None | Unset): Slice at this x (m).
        y (float | None | Unset): Slice at this y (m).
        z (float | None | Unset): Slice at this z (m).
        scale (int | None | Unset): Pixels per voxel (default: ~512 px).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        File | Problem
    """

    return (
        await asyncio_detailed(
            robot_id=robot_id,
            map_id=map_id,
            client=client,
            x=x,
            y=y,
            z=z,
            scale=scale,
        )
    ).parsed
