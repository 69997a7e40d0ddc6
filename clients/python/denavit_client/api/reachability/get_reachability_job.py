from http import HTTPStatus
from typing import Any
from urllib.parse import quote

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.job_response import JobResponse
from ...models.problem import Problem
from ...types import Response


def _get_kwargs(
    robot_id: str,
    job_id: str,
) -> dict[str, Any]:

    _kwargs: dict[str, Any] = {
        "method": "get",
        "url": "/robots/{robot_id}/reachability/jobs/{job_id}".format(
            robot_id=quote(str(robot_id), safe=""),
            job_id=quote(str(job_id), safe=""),
        ),
    }

    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> JobResponse | Problem | None:
    if response.status_code == 200:
        response_200 = JobResponse.from_dict(response.json())

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
) -> Response[JobResponse | Problem]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    robot_id: str,
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
) -> Response[JobResponse | Problem]:
    """Get Reachability Job

     Status and progress (percent, samples/s, ETA) of a build.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        job_id (str): Build job id.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[JobResponse | Problem]
    """

    kwargs = _get_kwargs(
        robot_id=robot_id,
        job_id=job_id,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    robot_id: str,
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
) -> JobResponse | Problem | None:
    """Get Reachability Job

     Status and progress (percent, samples/s, ETA) of a build.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        job_id (str): Build job id.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        JobResponse | Problem
    """

    return sync_detailed(
        robot_id=robot_id,
        job_id=job_id,
        client=client,
    ).parsed


async def asyncio_detailed(
    robot_id: str,
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
) -> Response[JobResponse | Problem]:
    """Get Reachability Job

     Status and progress (percent, samples/s, ETA) of a build.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        job_id (str): Build job id.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[JobResponse | Problem]
    """

    kwargs = _get_kwargs(
        robot_id=robot_id,
        job_id=job_id,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    robot_id: str,
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
) -> JobResponse | Problem | None:
    """Get Reachability Job

     Status and progress (percent, samples/s, ETA) of a build.

    Args:
        robot_id (str): Robot id, as listed by GET /robots.
        job_id (str): Build job id.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        JobResponse | Problem
    """

    return (
        await asyncio_detailed(
            robot_id=robot_id,
            job_id=job_id,
            client=client,
        )
    ).parsed
