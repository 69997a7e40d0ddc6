from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.dh_table_doc import DHTableDoc
from ...models.problem import Problem
from ...models.robot_detail import RobotDetail
from ...types import Response


def _get_kwargs(
    *,
    body: DHTableDoc,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/robots/dh",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

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
    body: DHTableDoc,
) -> Response[Problem | RobotDetail]:
    """Import Dh Robot

     Add a robot from a DH table; its id is the table's ``name``.

    The body is the table as JSON, or as YAML with ``Content-Type: application/yaml`` (or
    ``text/yaml``); lengths in m/cm/mm and angles in rad/deg as its ``units`` say. The
    service converts it to URDF (frames ``dh_0`` … ``dh_n`` and ``tool``, the default end
    effector) and answers 201 with the robot's description. 409 if the id is taken by any
    robot; 422 naming the field for a bad table (``joints.2.lower``); YAML aliases are
    refused; 413 past 256 KiB (or ``DENAVIT_MAX_UPLOAD_BYTES`` if smaller).

    Args:
        body (DHTableDoc): A Denavit–Hartenberg table (JSON, or YAML with ``Content-Type:
            application/yaml``).

            ``standard``: A_i = Rz(θ_i)·Tz(d_i)·Tx(a_i)·Rx(α_i); ``modified`` (Craig): A_i =
            Rx(α_{i-1})·Tx(a_{i-1})·Rz(θ_i)·Tz(d_i). The robot's frames ``dh_0`` … ``dh_n`` are the
            DH frames (world pose B·A_1⋯A_i) and ``tool`` (the default end effector) is
            dh_n·T_tool.

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
    body: DHTableDoc,
) -> Problem | RobotDetail | None:
    """Import Dh Robot

     Add a robot from a DH table; its id is the table's ``name``.

    The body is the table as JSON, or as YAML with ``Content-Type: application/yaml`` (or
    ``text/yaml``); lengths in m/cm/mm and angles in rad/deg as its ``units`` say. The
    service converts it to URDF (frames ``dh_0`` … ``dh_n`` and ``tool``, the default end
    effector) and answers 201 with the robot's description. 409 if the id is taken by any
    robot; 422 naming the field for a bad table (``joints.2.lower``); YAML aliases are
    refused; 413 past 256 KiB (or ``DENAVIT_MAX_UPLOAD_BYTES`` if smaller).

    Args:
        body (DHTableDoc): A Denavit–Hartenberg table (JSON, or YAML with ``Content-Type:
            application/yaml``).

            ``standard``: A_i = Rz(θ_i)·Tz(d_i)·Tx(a_i)·Rx(α_i); ``modified`` (Craig): A_i =
            Rx(α_{i-1})·Tx(a_{i-1})·Rz(θ_i)·Tz(d_i). The robot's frames ``dh_0`` … ``dh_n`` are the
            DH frames (world pose B·A_1⋯A_i) and ``tool`` (the default end effector) is
            dh_n·T_tool.

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
    body: DHTableDoc,
) -> Response[Problem | RobotDetail]:
    """Import Dh Robot

     Add a robot from a DH table; its id is the table's ``name``.

    The body is the table as JSON, or as YAML with ``Content-Type: application/yaml`` (or
    ``text/yaml``); lengths in m/cm/mm and angles in rad/deg as its ``units`` say. The
    service converts it to URDF (frames ``dh_0`` … ``dh_n`` and ``tool``, the default end
    effector) and answers 201 with the robot's description. 409 if the id is taken by any
    robot; 422 naming the field for a bad table (``joints.2.lower``); YAML aliases are
    refused; 413 past 256 KiB (or ``DENAVIT_MAX_UPLOAD_BYTES`` if smaller).

    Args:
        body (DHTableDoc): A Denavit–Hartenberg table (JSON, or YAML with ``Content-Type:
            application/yaml``).

            ``standard``: A_i = Rz(θ_i)·Tz(d_i)·Tx(a_i)·Rx(α_i); ``modified`` (Craig): A_i =
            Rx(α_{i-1})·Tx(a_{i-1})·Rz(θ_i)·Tz(d_i). The robot's frames ``dh_0`` … ``dh_n`` are the
            DH frames (world pose B·A_1⋯A_i) and ``tool`` (the default end effector) is
            dh_n·T_tool.

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
    body: DHTableDoc,
) -> Problem | RobotDetail | None:
    """Import Dh Robot

     Add a robot from a DH table; its id is the table's ``name``.

    The body is the table as JSON, or as YAML with ``Content-Type: application/yaml`` (or
    ``text/yaml``); lengths in m/cm/mm and angles in rad/deg as its ``units`` say. The
    service converts it to URDF (frames ``dh_0`` … ``dh_n`` and ``tool``, the default end
    effector) and answers 201 with the robot's description. 409 if the id is taken by any
    robot; 422 naming the field for a bad table (``joints.2.lower``); YAML aliases are
    refused; 413 past 256 KiB (or ``DENAVIT_MAX_UPLOAD_BYTES`` if smaller).

    Args:
        body (DHTableDoc): A Denavit–Hartenberg table (JSON, or YAML with ``Content-Type:
            application/yaml``).

            ``standard``: A_i = Rz(θ_i)·Tz(d_i)·Tx(a_i)·Rx(α_i); ``modified`` (Craig): A_i =
            Rx(α_{i-1})·Tx(a_{i-1})·Rz(θ_i)·Tz(d_i). The robot's frames ``dh_0`` … ``dh_n`` are the
            DH frames (world pose B·A_1⋯A_i) and ``tool`` (the default end effector) is
            dh_n·T_tool.

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
