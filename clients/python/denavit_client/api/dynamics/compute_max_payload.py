from http import HTTPStatus
from typing import Any
from urllib.parse import quote

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.max_payload_request import MaxPayloadRequest
from ...models.max_payload_response import MaxPayloadResponse
from ...models.problem import Problem
from ...types import Response


def _get_kwargs(
    robot_id: str,
    *,
    body: MaxPayloadRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/robots/{robot_id}/dynamics/max_payload".format(
            robot_id=quote(str(robot_id), safe=""),
        ),
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> MaxPayloadResponse | Problem | None:
    if response.status_code == 200:
        response_200 = MaxPayloadResponse.from_dict(response.json())

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
) -> Response[MaxPayloadResponse | Problem]:
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
    body: MaxPayloadRequest,
) -> Response[MaxPayloadResponse | Problem]:
    """Compute Max Payload

     The largest payload mass the joints' effort limits hold at rest, at one configuration
    or along a path (its minimum and the sample it occurs at), the limiting joint and each
    joint's bound. A payload that loads no joint with a limit is unbounded (null).

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (MaxPayloadRequest): One configuration (`q` or `joint_positions`) or a `path` of
            configurations, the point
            the payload hangs from, and a tool already attached.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[MaxPayloadResponse | Problem]
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
    body: MaxPayloadRequest,
) -> MaxPayloadResponse | Problem | None:
    """Compute Max Payload

     The largest payload mass the joints' effort limits hold at rest, at one configuration
    or along a path (its minimum and the sample it occurs at), the limiting joint and each
    joint's bound. A payload that loads no joint with a limit is unbounded (null).

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (MaxPayloadRequest): One configuration (`q` or `joint_positions`) or a `path` of
            configurations, the point
            the payload hangs from, and a tool already attached.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        MaxPayloadResponse | Problem
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
    body: MaxPayloadRequest,
) -> Response[MaxPayloadResponse | Problem]:
    """Compute Max Payload

     The largest payload mass the joints' effort limits hold at rest, at one configuration
    or along a path (its minimum and the sample it occurs at), the limiting joint and each
    joint's bound. A payload that loads no joint with a limit is unbounded (null).

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (MaxPayloadRequest): One configuration (`q` or `joint_positions`) or a `path` of
            configurations, the point
            the payload hangs from, and a tool already attached.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[MaxPayloadResponse | Problem]
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
    body: MaxPayloadRequest,
) -> MaxPayloadResponse | Problem | None:
    """Compute Max Payload

     The largest payload mass the joints' effort limits hold at rest, at one configuration
    or along a path (its minimum and the sample it occurs at), the limiting joint and each
    joint's bound. A payload that loads no joint with a limit is unbounded (null).

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        body (MaxPayloadRequest): One configuration (`q` or `joint_positions`) or a `path` of
            configurations, the point
            the payload hangs from, and a tool already attached.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        MaxPayloadResponse | Problem
    """

    return (
        await asyncio_detailed(
            robot_id=robot_id,
            client=client,
            body=body,
        )
    ).parsed
