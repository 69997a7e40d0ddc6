from http import HTTPStatus
from typing import Any
from urllib.parse import quote

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.problem import Problem
from ...models.query_request import QueryRequest
from ...models.query_response import QueryResponse
from ...types import Response


def _get_kwargs(
    robot_id: str,
    *,
    body: QueryRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/robots/{robot_id}/reachability/query".format(
            robot_id=quote(str(robot_id), safe=""),
        ),
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Problem | QueryResponse | None:
    if response.status_code == 200:
        response_200 = QueryResponse.from_dict(response.json())

        return response_200

    if response.status_code == 400:
        response_400 = Problem.from_dict(response.json())

        return response_400

    if response.status_code == 404:
        response_404 = Problem.from_dict(response.json())

        return response_404

    if response.status_code == 409:
        response_409 = Problem.from_dict(response.json())

        return response_409

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
) -> Response[Problem | QueryResponse]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    robot_id: str,
    *,
    client: AuthenticatedClient | Client,
    body: QueryRequest,
) -> Response[Problem | QueryResponse]:
    """Query Reachability

     Look poses up in a map: O(1) each. Outside the map's box → not reachable.

    Give ``poses`` (objects; orientation optional per pose) or the compact ``positions``
    (N×3) with optional ``orientations`` (N×4); a pose without orientation asks "reachable
    with any orientation" (the best over the voxel's bins).

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (QueryRequest): Poses to look up in a map: ``poses``, or the compact
            ``positions``/``orientations``.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Problem | QueryResponse]
    """

    kwargs = _get_kwargs(
        robot_id=robot_id,
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    robot_id: str,
    *,
    client: AuthenticatedClient | Client,
    body: QueryRequest,
) -> Problem | QueryResponse | None:
    """Query Reachability

     Look poses up in a map: O(1) each. Outside the map's box → not reachable.

    Give ``poses`` (objects; orientation optional per pose) or the compact ``positions``
    (N×3) with optional ``orientations`` (N×4); a pose without orientation asks "reachable
    with any orientation" (the best over the voxel's bins).

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (QueryRequest): Poses to look up in a map: ``poses``, or the compact
            ``positions``/``orientations``.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Problem | QueryResponse
    """

    return sync_detailed(
        robot_id=robot_id,
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    robot_id: str,
    *,
    client: AuthenticatedClient | Client,
    body: QueryRequest,
) -> Response[Problem | QueryResponse]:
    """Query Reachability

     Look poses up in a map: O(1) each. Outside the map's box → not reachable.

    Give ``poses`` (objects; orientation optional per pose) or the compact ``positions``
    (N×3) with optional ``orientations`` (N×4); a pose without orientation asks "reachable
    with any orientation" (the best over the voxel's bins).

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (QueryRequest): Poses to look up in a map: ``poses``, or the compact
            ``positions``/``orientations``.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Problem | QueryResponse]
    """

    kwargs = _get_kwargs(
        robot_id=robot_id,
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    robot_id: str,
    *,
    client: AuthenticatedClient | Client,
    body: QueryRequest,
) -> Problem | QueryResponse | None:
    """Query Reachability

     Look poses up in a map: O(1) each. Outside the map's box → not reachable.

    Give ``poses`` (objects; orientation optional per pose) or the compact ``positions``
    (N×3) with optional ``orientations`` (N×4); a pose without orientation asks "reachable
    with any orientation" (the best over the voxel's bins).

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (QueryRequest): Poses to look up in a map: ``poses``, or the compact
            ``positions``/``orientations``.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Problem | QueryResponse
    """

    return (
        await asyncio_detailed(
            robot_id=robot_id,
            client=client,
            body=body,
        )
    ).parsed
