"""The viewer: a page served by the service that shows any robot it knows and drives the API.

- GET /viewer               the page, on the first robot of GET /robots (a picker switches)
- GET /viewer/{robot_id}    the page on that robot (404 problem for an unknown id)
- GET /static/...           its ES modules and styles (app/static/viewer) and the vendored
                            libraries (app/static/vendor: three.js, urdf-loader; see
                            scripts/vendor_web.py), so that nothing is fetched from a CDN;
                            mounted by :mod:`app.api.static_files`, not by this router

The page is plain HTML and ES modules; it calls the API exactly as any client does (same
JSON; a token field for the write routes when ``DENAVIT_API_TOKEN`` is set). None of these
routes is part of the OpenAPI document.
"""

from __future__ import annotations

import html

from fastapi import APIRouter
from fastapi.responses import HTMLResponse

from app.api.deps import RegistryDep
from app.api.schemas.common import RobotId
from app.api.static_files import STATIC_DIR
from app.kinematics.errors import UnknownNameError

PAGE = STATIC_DIR / "viewer" / "index.html"

router = APIRouter(tags=["viewer"], include_in_schema=False)


def _page(robot_id: str) -> HTMLResponse:
    text = PAGE.read_text(encoding="utf-8").replace("{{robot_id}}", html.escape(robot_id))
    return HTMLResponse(text, headers={"Cache-Control": "no-cache"})


@router.get("/viewer")
async def viewer_page() -> HTMLResponse:
    """The viewer; its picker starts on the first robot GET /robots lists."""
    return _page("")


@router.get("/viewer/{robot_id}")
async def viewer_robot_page(robot_id: RobotId, reg: RegistryDep) -> HTMLResponse:
    """The viewer on one robot; an unknown ``robot_id`` is a 404 problem naming it."""
    if not reg.exists(robot_id):
        raise UnknownNameError("robot", robot_id, "robot_id", reg.ids())
    return _page(robot_id)
