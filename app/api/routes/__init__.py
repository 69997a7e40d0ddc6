"""The routes: one router module per area (its request/response models in
:mod:`app.api.schemas`), mounted by :func:`app.main.create_app` in :data:`ROUTERS` order."""

from __future__ import annotations

from app.api.routes import (
    analysis,
    collisions,
    dynamics,
    fk,
    health,
    ik,
    jacobian,
    packages,
    paths,
    reachability,
    robots,
    scenes,
    stream,
    velocity,
)

#: Routers mounted by :func:`app.main.create_app`, in this order. A request is matched
#: against the routes one by one (~4 µs a route on a loaded core, twice per request), so the
#: hot single-query routes (FK, Jacobian, IK) come first; their paths end in a fixed segment
#: no other route has, so the order changes no answer, only the OpenAPI document's order.
ROUTERS = [
    fk.router,
    jacobian.router,
    ik.router,
    health.router,
    packages.router,  # before robots: /robots/package is not the robot 'package'
    robots.router,
    analysis.router,
    dynamics.router,
    reachability.router,
    collisions.router,
    scenes.router,
    paths.router,
    velocity.router,
    stream.router,  # a WebSocket: not in the OpenAPI document
]
