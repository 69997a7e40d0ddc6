from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.problem import Problem
from ...models.robot_detail import RobotDetail
from ...models.urdf_upload import UrdfUpload
from ...types import Response


def _get_kwargs(
    *,
    body: UrdfUpload,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/robots/urdf",
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
    body: UrdfUpload,
) -> Response[Problem | RobotDetail]:
    """Upload Urdf Robot

     Add a robot from URDF text (and optional SRDF); its id is ``name``.

    The XML is checked first, read as Pinocchio reads it (names taken literally, namespaces
    ignored): DTDs and entity declarations are refused, mesh filenames must be exactly
    ``package://<package>/<path>`` URIs without ``..`` or whitespace, joint axes need a norm
    of at least 1e-6, lengths and angles at most 1e6, and the links must form one tree with
    at least one actuated joint; then Pinocchio builds the model. The work a document may
    cause is bounded (422 naming the limit): XML elements, attributes (in total and per
    element), nesting depth, joints and movable joints (``DENAVIT_MAX_XML_*``,
    ``DENAVIT_MAX_URDF_JOINTS``, ``DENAVIT_MAX_ROBOT_DOF``). Text must be valid Unicode
    (no lone surrogates). 201 with the robot's description; 409 if the id is taken; 413
    past the upload limit.

    Args:
        body (UrdfUpload): A robot given as URDF text (and optionally SRDF).

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
    body: UrdfUpload,
) -> Problem | RobotDetail | None:
    """Upload Urdf Robot

     Add a robot from URDF text (and optional SRDF); its id is ``name``.

    The XML is checked first, read as Pinocchio reads it (names taken literally, namespaces
    ignored): DTDs and entity declarations are refused, mesh filenames must be exactly
    ``package://<package>/<path>`` URIs without ``..`` or whitespace, joint axes need a norm
    of at least 1e-6, lengths and angles at most 1e6, and the links must form one tree with
    at least one actuated joint; then Pinocchio builds the model. The work a document may
    cause is bounded (422 naming the limit): XML elements, attributes (in total and per
    element), nesting depth, joints and movable joints (``DENAVIT_MAX_XML_*``,
    ``DENAVIT_MAX_URDF_JOINTS``, ``DENAVIT_MAX_ROBOT_DOF``). Text must be valid Unicode
    (no lone surrogates). 201 with the robot's description; 409 if the id is taken; 413
    past the upload limit.

    Args:
        body (UrdfUpload): A robot given as URDF text (and optionally SRDF).

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
    body: UrdfUpload,
) -> Response[Problem | RobotDetail]:
    """Upload Urdf Robot

     Add a robot from URDF text (and optional SRDF); its id is ``name``.

    The XML is checked first, read as Pinocchio reads it (names taken literally, namespaces
    ignored): DTDs and entity declarations are refused, mesh filenames must be exactly
    ``package://<package>/<path>`` URIs without ``..`` or whitespace, joint axes need a norm
    of at least 1e-6, lengths and angles at most 1e6, and the links must form one tree with
    at least one actuated joint; then Pinocchio builds the model. The work a document may
    cause is bounded (422 naming the limit): XML elements, attributes (in total and per
    element), nesting depth, joints and movable joints (``DENAVIT_MAX_XML_*``,
    ``DENAVIT_MAX_URDF_JOINTS``, ``DENAVIT_MAX_ROBOT_DOF``). Text must be valid Unicode
    (no lone surrogates). 201 with the robot's description; 409 if the id is taken; 413
    past the upload limit.

    Args:
        body (UrdfUpload): A robot given as URDF text (and optionally SRDF).

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
    body: UrdfUpload,
) -> Problem | RobotDetail | None:
    """Upload Urdf Robot

     Add a robot from URDF text (and optional SRDF); its id is ``name``.

    The XML is checked first, read as Pinocchio reads it (names taken literally, namespaces
    ignored): DTDs and entity declarations are refused, mesh filenames must be exactly
    ``package://<package>/<path>`` URIs without ``..`` or whitespace, joint axes need a norm
    of at least 1e-6, lengths and angles at most 1e6, and the links must form one tree with
    at least one actuated joint; then Pinocchio builds the model. The work a document may
    cause is bounded (422 naming the limit): XML elements, attributes (in total and per
    element), nesting depth, joints and movable joints (``DENAVIT_MAX_XML_*``,
    ``DENAVIT_MAX_URDF_JOINTS``, ``DENAVIT_MAX_ROBOT_DOF``). Text must be valid Unicode
    (no lone surrogates). 201 with the robot's description; 409 if the id is taken; 413
    past the upload limit.

    Args:
        body (UrdfUpload): A robot given as URDF text (and optionally SRDF).

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
