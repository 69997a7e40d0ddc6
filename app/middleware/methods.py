"""HTTP methods per path: ``HEAD`` on every ``GET`` route, exact ``Allow`` on every 405.

A pure ASGI middleware with the application's route table, built on the first request:

- A path's *resource* is the path template of the first route (in routing order) whose
  pattern matches it, the way the router resolves it; the methods the path supports are
  those of every route with that template, plus ``HEAD`` where ``GET`` is one. So
  ``/robots/dh`` (``POST`` only) is not taken for the robot ``dh`` of ``/robots/{robot_id}``.
- ``HEAD`` on a ``GET`` route is served by the ``GET`` route with the body dropped: the
  same status and headers, ``Content-Length`` included (FastAPI routes do not answer
  ``HEAD`` by themselves).
- A method the path does not support is answered here, 405 problem+json whose ``Allow``
  lists exactly the supported methods. (The router alone answers with the ``Allow`` of the
  first route it tried: ``/scenes`` advertised ``POST`` but not ``GET``.)
- Paths no route matches pass through untouched (404, trailing-slash redirects).

Cost per request: a dict lookup for a path seen before, else one regex match (~2.5 µs).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from fastapi.routing import iter_route_contexts
from starlette._utils import get_route_path
from starlette.convertors import CONVERTOR_TYPES
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from app.api.errors import problem

#: Order of the methods in ``Allow`` headers.
_ORDER = ("GET", "HEAD", "POST", "PUT", "PATCH", "DELETE", "OPTIONS")
_PARAM = re.compile(r"\{(\w+)(?::(\w+))?\}")


@dataclass
class Resource:
    """One path template and the methods its routes serve."""

    path: str
    native: set[str] = field(default_factory=set)

    @property
    def allowed(self) -> tuple[str, ...]:
        """Methods the template supports (``HEAD`` wherever ``GET`` is), in canonical order."""
        methods = set(self.native)
        if "GET" in methods:
            methods.add("HEAD")
        return tuple(sorted(methods, key=lambda m: (_ORDER.index(m) if m in _ORDER else 99, m)))


def _pattern(template: str) -> str:
    """A regex for ``template`` without capturing groups of its own (Starlette's syntax)."""
    out, pos = [], 0
    for m in _PARAM.finditer(template):
        out.append(re.escape(template[pos : m.start()]))
        regex = CONVERTOR_TYPES[m.group(2) or "str"].regex.replace("(", "(?:")
        out.append(f"(?:{regex})")
        pos = m.end()
    out.append(re.escape(template[pos:]))
    return "".join(out)


class RouteTable:
    """Resources of an application's routes and one regex matching a path to the first."""

    def __init__(self, routes: list[Any]) -> None:
        self.resources: dict[str, Resource] = {}
        self.route_of: dict[str, Any] = {}  # template → a route, for scope["route"]
        for rc in iter_route_contexts(routes):
            path, methods = rc.path, rc.methods
            if path is None or methods is None:  # websockets, mounts
                continue
            resource = self.resources.setdefault(path, Resource(path))
            resource.native |= set(methods)
            self.route_of.setdefault(path, rc)
        self._names = {f"r{i}": p for i, p in enumerate(self.resources)}
        alternatives = (f"(?P<{n}>{_pattern(p)})" for n, p in self._names.items())
        self._regex = re.compile(r"\A(?:" + "|".join(alternatives) + r")\Z")
        self._cache: dict[str, Resource | None] = {}

    def match(self, path: str) -> Resource | None:
        """The resource of ``path`` (first matching template), or ``None``.

        Answers for paths up to 256 characters are remembered (up to 4096 paths, then the
        memory starts afresh): a repeated path costs a dict lookup (~0.1 µs) instead of the
        regex (~2.5 µs).
        """
        try:
            return self._cache[path]
        except KeyError:
            pass
        m = self._regex.match(path)
        found = (
            None if m is None or m.lastgroup is None else self.resources[self._names[m.lastgroup]]
        )
        if len(path) <= 256:
            if len(self._cache) >= 4096:
                self._cache.clear()
            self._cache[path] = found
        return found


class MethodsMiddleware:
    """``HEAD`` for ``GET`` routes; 405 with the path's exact ``Allow`` list."""

    def __init__(self, app: ASGIApp) -> None:
        self.app = app
        self.table: RouteTable | None = None

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        table = self.table
        if table is None:
            table = self.table = RouteTable(scope["app"].routes)
        resource = table.match(get_route_path(scope))
        method = scope["method"]
        if resource is None or method in resource.native:
            await self.app(scope, receive, send)
            return
        if method == "HEAD" and "GET" in resource.native:
            await self._head(scope, receive, send)
            return
        allowed = resource.allowed
        scope["route"] = table.route_of[resource.path]  # metrics: the template, not the path
        listed = ", ".join(allowed[:-1]) + " or " + allowed[-1] if len(allowed) > 1 else allowed[0]
        response = problem(
            405,
            f"method {method} is not allowed here; use {listed}",
            instance=scope["path"],
            headers={"Allow": ", ".join(allowed)},
        )
        await response(scope, receive, send)

    async def _head(self, scope: Scope, receive: Receive, send: Send) -> None:
        """Serve ``HEAD`` by the ``GET`` route, without the body."""
        inner = {**scope, "method": "GET"}

        async def headers_only(message: Message) -> None:
            if message["type"] == "http.response.body" and message.get("body"):
                message = {**message, "body": b""}
            await send(message)

        try:
            await self.app(inner, receive, headers_only)
        finally:
            if "route" in inner:  # for the access log and metrics of the outer scope
                scope["route"] = inner["route"]
