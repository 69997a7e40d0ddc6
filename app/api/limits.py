"""The server's caps on one request: batch sizes (``DENAVIT_MAX_BATCH``) and IK budgets
(``DENAVIT_IK_MAX_TIMEOUT_MS`` per target, ``DENAVIT_IK_MAX_REQUEST_S`` per request).

Every check raises :class:`~app.kinematics.errors.InvalidInputError` (422) naming the
field and the cap; every batch route checks its size with :func:`check_batch_size`.
"""

from __future__ import annotations

from app.kinematics.errors import InvalidInputError
from app.operations.settings import Settings


def check_batch_size(count: int, limit: int, noun: str, field: str) -> None:
    """Refuse a batch of ``count`` items (``noun``: configurations, targets, poses) above
    ``limit`` (the settings' ``max_batch``), naming ``field``."""
    if count > limit:
        raise InvalidInputError(f"{count} {noun} exceed the limit of {limit}", field)


def check_budget(settings: Settings, timeout_ms: float) -> None:
    """Refuse a per-target budget ``timeout_ms`` above the server's ``ik_max_timeout_ms``."""
    cap = settings.ik_max_timeout_ms
    if timeout_ms > cap:
        raise InvalidInputError(
            f"{timeout_ms} ms exceeds the server's cap of {cap} ms", "timeout_ms"
        )


def check_request_budget(
    settings: Settings, count: int, noun: str, timeout_ms: float, remedy: str, field: str
) -> None:
    """Refuse a request whose total budget, ``count`` solves × ``timeout_ms``, exceeds the
    server's ``ik_max_request_s`` (naming ``field``; ``noun`` names what is counted,
    ``remedy`` says how to stay within it)."""
    total_s = count * timeout_ms * 1e-3
    cap_s = settings.ik_max_request_s
    if total_s > cap_s:
        raise InvalidInputError(
            f"{count} {noun} × {timeout_ms:g} ms = {total_s:g} s exceeds the server's budget "
            f"of {cap_s:g} s per request: {remedy}",
            field,
        )
