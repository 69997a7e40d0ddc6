"""Typed keys of a model's lazy cache (:meth:`app.kinematics.models.RobotModel.lazy`).

A :class:`LazyKey` names one companion object built once per model (the collision model of
a geometry mode, an IK chain, the batch recipe) and carries its type, so that
``robot.lazy(key, build)`` and ``robot.cached(key)`` are typed by the key, and a builder
that returns something else fails loudly where it is built.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Generic, TypeVar

T = TypeVar("T")
#: What the cache holds for a key not built yet (None is a value: "no such companion").
MISSING = object()


@dataclass(frozen=True, slots=True)
class LazyKey(Generic[T]):
    """A typed key of :meth:`~app.kinematics.models.RobotModel.lazy`: the companion's name
    (unique per model, e.g. ``"collision.mesh"``) and its type (the built value is checked
    against it; None is allowed too, a cached "there is none")."""

    name: str
    type: type[T]
