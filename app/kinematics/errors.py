"""Errors raised by the kinematics core.

The core knows nothing of HTTP; the API layer (``app.api.errors``) maps each class to a
status code and an RFC 9457 problem body. Every error names the offending ``field`` (a
dotted path such as ``q.3`` or ``target.orientation``) so a client can point at it.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable


class KinematicsError(Exception):
    """Base class: a request the core cannot answer, with the field to blame."""

    def __init__(self, message: str, field: str | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.field = field


class InvalidInputError(KinematicsError):
    """A value is malformed: wrong length, not finite, out of its domain."""


class UnknownNameError(KinematicsError):
    """A robot, frame or joint name that does not exist, with close matches.

    ``list_known``: name every candidate in the message (short lists such as a robot's
    joints), not only the close matches.
    """

    def __init__(
        self,
        kind: str,
        name: str,
        field: str,
        candidates: Iterable[str],
        *,
        list_known: bool = False,
    ) -> None:
        self.kind = kind
        self.name = name
        known = list(candidates)
        self.suggestions = difflib.get_close_matches(name, known, n=5, cutoff=0.5)
        hint = (
            f"; did you mean {', '.join(map(repr, self.suggestions))}?" if self.suggestions else ""
        )
        if list_known:
            hint += f" (known: {', '.join(known) or 'none'})"
        super().__init__(f"unknown {kind} {name!r}{hint}", field)


class ConflictError(KinematicsError):
    """The request clashes with the current state (e.g. a robot id already taken)."""


class ForbiddenError(KinematicsError):
    """The operation is not allowed on this resource (e.g. deleting a built-in robot)."""


class UnavailableError(KinematicsError):
    """A resource the service needs cannot be used right now (e.g. a database file that is
    corrupt or not writable): the request may succeed once an operator has fixed it."""


class Cancelled(Exception):  # noqa: N818 - an outcome, not a fault of the request
    """The caller withdrew the work (e.g. its HTTP client disconnected): it stopped early.

    Not a :class:`KinematicsError`: nothing was wrong with the request, and nobody is left to
    answer. Long computations take an optional ``threading.Event`` (``cancel``) and raise
    this once it is set.
    """


class MissingInertiaError(KinematicsError):
    """The robot cannot answer a dynamics question: a link that moves carries no inertia.

    Torques computed from zero or default inertias would be wrong without a sign of it, so
    the core refuses (the API answers 422 ``missing-inertia``, naming the link).
    """

    def __init__(self, link: str) -> None:
        self.link = link
        super().__init__(
            f"link {link!r} has no inertia (its URDF <inertial> is missing, or its mass and "
            "inertia are 0): dynamics need the mass, centre of mass and inertia of every link "
            "that moves; give them in the URDF (or the DH table's mass, com and inertia)",
            "robot_id",
        )
