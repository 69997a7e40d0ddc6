from http import HTTPStatus
from typing import Any
from urllib.parse import quote

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.path_request import PathRequest
from ...models.path_response import PathResponse
from ...models.problem import Problem
from ...types import Response


def _get_kwargs(
    robot_id: str,
    *,
    body: PathRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/robots/{robot_id}/ik/path".format(
            robot_id=quote(str(robot_id), safe=""),
        ),
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> PathResponse | Problem | None:
    if response.status_code == 200:
        response_200 = PathResponse.from_dict(response.json())

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
) -> Response[PathResponse | Problem]:
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
    body: PathRequest,
) -> Response[PathResponse | Problem]:
    """Solve Ik Path

     A joint path that moves a frame along lines and arcs, on one branch.

    The path (position linear, orientation by slerp) is interpolated at `max_step`; each
    point is solved seeded by the previous solution and accepted only if no joint moves more
    than `max_joint_step`, the branch does not change and (with `avoid_collisions`) the
    configuration is collision-free. Between accepted points the path is densified until
    the joint-linear motion stays within `max_deviation` of the Cartesian path. A path that
    cannot be completed is not an error: 200 with `fraction` < 1, the points up to there,
    and `failure` (index, reason, detail) of the first point that failed. See docs/paths.md.
    The request's total budget, points × `timeout_ms`, may not exceed the server's
    `ik_max_request_s` (else 422 naming `max_step`), which is also the path's deadline (past
    it, the path stops with `failure.reason: timeout`); the work stops when the client leaves.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (PathRequest): A Cartesian path from a start configuration: waypoints or segments
            (exactly one).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[PathResponse | Problem]
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
    body: PathRequest,
) -> PathResponse | Problem | None:
    """Solve Ik Path

     A joint path that moves a frame along lines and arcs, on one branch.

    The path (position linear, orientation by slerp) is interpolated at `max_step`; each
    point is solved seeded by the previous solution and accepted only if no joint moves more
    than `max_joint_step`, the branch does not change and (with `avoid_collisions`) the
    configuration is collision-free. Between accepted points the path is densified until
    the joint-linear motion stays within `max_deviation` of the Cartesian path. A path that
    cannot be completed is not an error: 200 with `fraction` < 1, the points up to there,
    and `failure` (index, reason, detail) of the first point that failed. See docs/paths.md.
    The request's total budget, points × `timeout_ms`, may not exceed the server's
    `ik_max_request_s` (else 422 naming `max_step`), which is also the path's deadline (past
    it, the path stops with `failure.reason: timeout`); the work stops when the client leaves.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (PathRequest): A Cartesian path from a start configuration: waypoints or segments
            (exactly one).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        PathResponse | Problem
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
    body: PathRequest,
) -> Response[PathResponse | Problem]:
    """Solve Ik Path

     A joint path that moves a frame along lines and arcs, on one branch.

    The path (position linear, orientation by slerp) is interpolated at `max_step`; each
    point is solved seeded by the previous solution and accepted only if no joint moves more
    than `max_joint_step`, the branch does not change and (with `avoid_collisions`) the
    configuration is collision-free. Between accepted points the path is densified until
    the joint-linear motion stays within `max_deviation` of the Cartesian path. A path that
    cannot be completed is not an error: 200 with `fraction` < 1, the points up to there,
    and `failure` (index, reason, detail) of the first point that failed. See docs/paths.md.
    The request's total budget, points × `timeout_ms`, may not exceed the server's
    `ik_max_request_s` (else 422 naming `max_step`), which is also the path's deadline (past
    it, the path stops with `failure.reason: timeout`); the work stops when the client leaves.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (PathRequest): A Cartesian path from a start configuration: waypoints or segments
            (exactly one).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[PathResponse | Problem]
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
    body: PathRequest,
) -> PathResponse | Problem | None:
    """Solve Ik Path

     A joint path that moves a frame along lines and arcs, on one branch.

    The path (position linear, orientation by slerp) is interpolated at `max_step`; each
    point is solved seeded by the previous solution and accepted only if no joint moves more
    than `max_joint_step`, the branch does not change and (with `avoid_collisions`) the
    configuration is collision-free. Between accepted points the path is densified until
    the joint-linear motion stays within `max_deviation` of the Cartesian path. A path that
    cannot be completed is not an error: 200 with `fraction` < 1, the points up to there,
    and `failure` (index, reason, detail) of the first point that failed. See docs/paths.md.
    The request's total budget, points × `timeout_ms`, may not exceed the server's
    `ik_max_request_s` (else 422 naming `max_step`), which is also the path's deadline (past
    it, the path stops with `failure.reason: timeout`); the work stops when the client leaves.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (PathRequest): A Cartesian path from a start configuration: waypoints or segments
            (exactly one).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        PathResponse | Problem
    """

    return (
        await asyncio_detailed(
            robot_id=robot_id,
            client=client,
            body=body,
        )
    ).parsed
