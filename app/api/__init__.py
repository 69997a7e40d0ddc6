"""The HTTP layer: one router module per area, errors in :mod:`app.api.errors`."""

from __future__ import annotations

from app.api import (
    analysis,
    collisions,
    fk,
    health,
    ik,
    jacobian,
    packages,
    paths,
    reachability,
    robots,
    scenes,
    velocity,
)

#: Routers mounted by :func:`app.main.create_app`, in documentation order.
ROUTERS = [
    health.router,
    packages.router,  # before robots: /robots/package is not the robot 'package'
    robots.router,
    fk.router,
    jacobian.router,
    analysis.router,
    reachability.router,
    collisions.router,
    scenes.router,
    ik.router,
    paths.router,
    velocity.router,
]
