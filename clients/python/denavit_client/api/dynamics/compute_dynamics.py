from http import HTTPStatus
from typing import Any
from urllib.parse import quote

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.dynamics_request import DynamicsRequest
from ...models.dynamics_response import DynamicsResponse
from ...models.problem import Problem
from ...types import Response


def _get_kwargs(
    robot_id: str,
    *,
    body: DynamicsRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/robots/{robot_id}/dynamics".format(
            robot_id=quote(str(robot_id), safe=""),
        ),
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> DynamicsResponse | Problem | None:
    if response.status_code == 200:
        response_200 = DynamicsResponse.from_dict(response.json())

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
) -> Response[DynamicsResponse | Problem]:
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
    body: DynamicsRequest,
) -> Response[DynamicsResponse | Problem]:
    """Compute Dynamics

     Joint torques τ = M(q)·q̈ + C(q, q̇)·q̇ + g(q) + Jᵀ·F at one state, each term, the mass
    and Coriolis matrices, the centre of mass and the effort ratios.

    Velocities and accelerations are zeros when absent; a payload is a rigid body fixed to a
    frame; the wrench is the one the frame exerts on its environment (as in statics). With
    `group`, every vector and matrix is over the group's joints.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (DynamicsRequest): A state (q, q̇, q̈), an optional payload and an optional wrench.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[DynamicsResponse | Problem]
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
    body: DynamicsRequest,
) -> DynamicsResponse | Problem | None:
    """Compute Dynamics

     Joint torques τ = M(q)·q̈ + C(q, q̇)·q̇ + g(q) + Jᵀ·F at one state, each term, the mass
    and Coriolis matrices, the centre of mass and the effort ratios.

    Velocities and accelerations are zeros when absent; a payload is a rigid body fixed to a
    frame; the wrench is the one the frame exerts on its environment (as in statics). With
    `group`, every vector and matrix is over the group's joints.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (DynamicsRequest): A state (q, q̇, q̈), an optional payload and an optional wrench.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        DynamicsResponse | Problem
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
    body: DynamicsRequest,
) -> Response[DynamicsResponse | Problem]:
    """Compute Dynamics

     Joint torques τ = M(q)·q̈ + C(q, q̇)·q̇ + g(q) + Jᵀ·F at one state, each term, the mass
    and Coriolis matrices, the centre of mass and the effort ratios.

    Velocities and accelerations are zeros when absent; a payload is a rigid body fixed to a
    frame; the wrench is the one the frame exerts on its environment (as in statics). With
    `group`, every vector and matrix is over the group's joints.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (DynamicsRequest): A state (q, q̇, q̈), an optional payload and an optional wrench.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[DynamicsResponse | Problem]
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
    body: DynamicsRequest,
) -> DynamicsResponse | Problem | None:
    """Compute Dynamics

     Joint torques τ = M(q)·q̈ + C(q, q̇)·q̇ + g(q) + Jᵀ·F at one state, each term, the mass
    and Coriolis matrices, the centre of mass and the effort ratios.

    Velocities and accelerations are zeros when absent; a payload is a rigid body fixed to a
    frame; the wrench is the one the frame exerts on its environment (as in statics). With
    `group`, every vector and matrix is over the group's joints.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (DynamicsRequest): A state (q, q̇, q̈), an optional payload and an optional wrench.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        DynamicsResponse | Problem
    """

    return (
        await asyncio_detailed(
            robot_id=robot_id,
            client=client,
            body=body,
        )
    ).parsed
