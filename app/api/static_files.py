"""The package's static files at ``/static``: the viewer (``app/static/viewer``) and the
vendored browser libraries (``app/static/vendor``: three.js, urdf-loader, Swagger UI, ReDoc;
``make viewer-vendor``). Read-only, no folder listings; never guarded by the write token.
"""

from __future__ import annotations

from pathlib import Path

from fastapi import FastAPI
from starlette.routing import Mount
from starlette.staticfiles import StaticFiles
from starlette.types import Receive, Scope, Send

STATIC_DIR = Path(__file__).resolve().parents[1] / "static"
STATIC_URL = "/static"


class LabelledStaticFiles(StaticFiles):
    """:class:`StaticFiles` whose requests name their mount as ``scope["route"]``.

    Metrics and access logs label a request by its route's path; FastAPI sets it for its
    own routes only, so files under ``/static`` would be counted as ``unmatched``.
    """

    mount: Mount | None = None

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if self.mount is not None:
            scope["route"] = self.mount
        await super().__call__(scope, receive, send)


def mount(app: FastAPI) -> None:
    """Serve :data:`STATIC_DIR` at :data:`STATIC_URL` (the route named ``static``)."""
    files = LabelledStaticFiles(directory=STATIC_DIR)
    files.mount = Mount(STATIC_URL, app=files, name="static")  # what app.mount() would add
    app.router.routes.append(files.mount)
