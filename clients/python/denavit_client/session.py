"""A client for every operation, with or without a bearer token (hand-written, never generated).

The service asks for ``Authorization: Bearer <token>`` on write operations (robot import,
upload and deletion, scenes, reachability builds) only when it runs with
``DENAVIT_API_TOKEN`` set. :func:`connect` gives an
:class:`~denavit_client.client.AuthenticatedClient`, the type every generated operation
accepts, that sends the header only when a token is given.
"""

from __future__ import annotations

import httpx

from .client import AuthenticatedClient


def connect(
    base_url: str,
    token: str | None = None,
    *,
    timeout: float = 60.0,
    raise_on_unexpected_status: bool = True,
) -> AuthenticatedClient:
    """A client of the service at ``base_url`` (e.g. ``http://127.0.0.1:8000``).

    Parameters
    ----------
    base_url
        The service's root URL, without a trailing path.
    token
        The service's ``DENAVIT_API_TOKEN``, or ``None`` for a service without one: then no
        ``Authorization`` header is sent at all.
    timeout
        Seconds to wait for an answer (IK with a large budget, a package upload).
    raise_on_unexpected_status
        Raise :class:`~denavit_client.errors.UnexpectedStatus` on a status the document does
        not declare for the operation, instead of returning ``None``.

    Returns
    -------
    AuthenticatedClient
        Usable as a context manager (``with connect(url) as client: ...``), which closes its
        connections at the end.
    """
    client = AuthenticatedClient(
        base_url=base_url,
        token=token or "",
        timeout=httpx.Timeout(timeout),
        raise_on_unexpected_status=raise_on_unexpected_status,
    )
    if token is None:
        # The generated client would send "Authorization: Bearer " (an empty token): give
        # it an httpx client with no such header.
        client.set_httpx_client(httpx.Client(base_url=base_url, timeout=httpx.Timeout(timeout)))
    return client
