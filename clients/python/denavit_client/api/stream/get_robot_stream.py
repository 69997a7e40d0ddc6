from http import HTTPStatus
from typing import Any, cast
from urllib.parse import quote

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.problem import Problem
from ...types import Response


def _get_kwargs(
    robot_id: str,
) -> dict[str, Any]:

    _kwargs: dict[str, Any] = {
        "method": "get",
        "url": "/robots/{robot_id}/stream".format(
            robot_id=quote(str(robot_id), safe=""),
        ),
    }

    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Any | Problem | None:
    if response.status_code == 101:
        response_101 = cast(Any, None)
        return response_101

    if response.status_code == 413:
        response_413 = Problem.from_dict(response.json())

        return response_413

    if response.status_code == 426:
        response_426 = Problem.from_dict(response.json())

        return response_426

    if response.status_code == 503:
        response_503 = Problem.from_dict(response.json())

        return response_503

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[Any | Problem]:
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
) -> Response[Any | Problem]:
    """Robot stream (WebSocket)

     FK, Jacobian, IK and dynamics of one robot over a WebSocket (docs/stream.md): connect with `ws://`
    (an HTTP/1.1 `Upgrade: websocket` request). OpenAPI cannot describe the messages; a plain HTTP
    request is answered 426 naming the upgrade. With DENAVIT_API_TOKEN set, the upgrade request carries
    the bearer token (or the first message is `{"token": ...}`).

    Args:
        robot_id (str):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Any | Problem]
    """

    kwargs = _get_kwargs(
        robot_id=robot_id,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    robot_id: str,
    *,
    client: AuthenticatedClient | Client,
) -> Any | Problem | None:
    """Robot stream (WebSocket)

     FK, Jacobian, IK and dynamics of one robot over a WebSocket (docs/stream.md): connect with `ws://`
    (an HTTP/1.1 `Upgrade: websocket` request). OpenAPI cannot describe the messages; a plain HTTP
    request is answered 426 naming the upgrade. With DENAVIT_API_TOKEN set, the upgrade request carries
    the bearer token (or the first message is `{"token": ...}`).

    Args:
        robot_id (str):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Any | Problem
    """

    return sync_detailed(
        robot_id=robot_id,
        client=client,
    ).parsed


async def asyncio_detailed(
    robot_id: str,
    *,
    client: AuthenticatedClient | Client,
) -> Response[Any | Problem]:
    """Robot stream (WebSocket)

     FK, Jacobian, IK and dynamics of one robot over a WebSocket (docs/stream.md): connect with `ws://`
    (an HTTP/1.1 `Upgrade: websocket` request). OpenAPI cannot describe the messages; a plain HTTP
    request is answered 426 naming the upgrade. With DENAVIT_API_TOKEN set, the upgrade request carries
    the bearer token (or the first message is `{"token": ...}`).

    Args:
        robot_id (str):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[Any | Problem]
    """

    kwargs = _get_kwargs(
        robot_id=robot_id,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    robot_id: str,
    *,
    client: AuthenticatedClient | Client,
) -> Any | Problem | None:
    """Robot stream (WebSocket)

     FK, Jacobian, IK and dynamics of one robot over a WebSocket (docs/stream.md): connect with `ws://`
    (an HTTP/1.1 `Upgrade: websocket` request). OpenAPI cannot describe the messages; a plain HTTP
    request is answered 426 naming the upgrade. With DENAVIT_API_TOKEN set, the upgrade request carries
    the bearer token (or the first message is `{"token": ...}`).

    Args:
        robot_id (str):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Any | Problem
    """

    return (
        await asyncio_detailed(
            robot_id=robot_id,
            client=client,
        )
    ).parsed
