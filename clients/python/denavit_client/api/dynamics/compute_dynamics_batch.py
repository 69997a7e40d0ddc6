from http import HTTPStatus
from typing import Any
from urllib.parse import quote

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.dynamics_batch_request import DynamicsBatchRequest
from ...models.dynamics_batch_response import DynamicsBatchResponse
from ...models.problem import Problem
from ...types import Response


def _get_kwargs(
    robot_id: str,
    *,
    body: DynamicsBatchRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/robots/{robot_id}/dynamics/batch".format(
            robot_id=quote(str(robot_id), safe=""),
        ),
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> DynamicsBatchResponse | Problem | None:
    if response.status_code == 200:
        response_200 = DynamicsBatchResponse.from_dict(response.json())

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
) -> Response[DynamicsBatchResponse | Problem]:
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
    body: DynamicsBatchRequest,
) -> Response[DynamicsBatchResponse | Problem]:
    """Compute Dynamics Batch

     Joint torques τ (RNEA) and gravity torques g(q) for many states (q, q̇, q̈), with an
    optional payload, computed off the event loop; up to ``DENAVIT_MAX_BATCH`` states.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (DynamicsBatchRequest): Many states (q, q̇, q̈), one optional payload.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[DynamicsBatchResponse | Problem]
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
    body: DynamicsBatchRequest,
) -> DynamicsBatchResponse | Problem | None:
    """Compute Dynamics Batch

     Joint torques τ (RNEA) and gravity torques g(q) for many states (q, q̇, q̈), with an
    optional payload, computed off the event loop; up to ``DENAVIT_MAX_BATCH`` states.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (DynamicsBatchRequest): Many states (q, q̇, q̈), one optional payload.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        DynamicsBatchResponse | Problem
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
    body: DynamicsBatchRequest,
) -> Response[DynamicsBatchResponse | Problem]:
    """Compute Dynamics Batch

     Joint torques τ (RNEA) and gravity torques g(q) for many states (q, q̇, q̈), with an
    optional payload, computed off the event loop; up to ``DENAVIT_MAX_BATCH`` states.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (DynamicsBatchRequest): Many states (q, q̇, q̈), one optional payload.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[DynamicsBatchResponse | Problem]
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
    body: DynamicsBatchRequest,
) -> DynamicsBatchResponse | Problem | None:
    """Compute Dynamics Batch

     Joint torques τ (RNEA) and gravity torques g(q) for many states (q, q̇, q̈), with an
    optional payload, computed off the event loop; up to ``DENAVIT_MAX_BATCH`` states.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (DynamicsBatchRequest): Many states (q, q̇, q̈), one optional payload.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        DynamicsBatchResponse | Problem
    """

    return (
        await asyncio_detailed(
            robot_id=robot_id,
            client=client,
            body=body,
        )
    ).parsed
