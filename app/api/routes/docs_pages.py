"""The API documentation pages, ``GET /docs`` (Swagger UI) and ``GET /redoc`` (ReDoc), offline.

FastAPI's own pages load their script, styles, favicon and fonts from CDNs
(cdn.jsdelivr.net, fastapi.tiangolo.com, fonts.googleapis.com): without internet, ``/docs``
is a blank page. These pages are the same HTML (:mod:`fastapi.openapi.docs`) pointing at
the copies vendored in the package (``app/static/vendor``, pinned with their licenses,
refreshed by ``make viewer-vendor``), served under ``/static``; no request leaves the
machine:

- Swagger UI's spec validator (``validatorUrl``, a call to validator.swagger.io) is off;
- ReDoc without Google Fonts (system fonts instead);
- ReDoc 2's sidebar shows Redocly's logo from ``cdn.redoc.ly``, in every configuration:
  its bundle is served at ``/redoc/redoc.standalone.js`` with that image replaced by an
  inline transparent one (:func:`redoc_bundle`); the vendored file is left as published.

Every URL is prefixed with the ASGI ``root_path`` (behind a proxy serving the API under a
prefix), as FastAPI's own pages do for ``openapi_url``.
"""

from __future__ import annotations

import functools
import logging

from fastapi import FastAPI, Request
from fastapi.openapi.docs import (
    get_redoc_html,
    get_swagger_ui_html,
    get_swagger_ui_oauth2_redirect_html,
)
from starlette.responses import HTMLResponse, Response

from app.api.static_files import STATIC_DIR, STATIC_URL

log = logging.getLogger("denavit")

SWAGGER = STATIC_URL + "/vendor/swagger-ui-dist"
SWAGGER_JS = SWAGGER + "/swagger-ui-bundle.js"
SWAGGER_CSS = SWAGGER + "/swagger-ui.css"
FAVICON = SWAGGER + "/favicon-32x32.png"

#: The vendored ReDoc bundle, and where its offline copy (:func:`redoc_bundle`) is served.
REDOC_BUNDLE = STATIC_DIR / "vendor" / "redoc" / "bundles" / "redoc.standalone.js"
REDOC_JS = "/redoc/redoc.standalone.js"
#: The image ReDoc 2 fetches for its "API docs by Redocly" link, and what replaces it: a
#: transparent 1x1 GIF.
REDOC_LOGO = b"https://cdn.redoc.ly/redoc/logo-mini.svg"
BLANK_IMAGE = b"data:image/gif;base64,R0lGODlhAQABAIAAAAAAAP///yH5BAEAAAAALAAAAAABAAEAAAIBRAA7"


@functools.cache
def redoc_bundle() -> bytes:
    """The vendored ReDoc bundle with its one external image (:data:`REDOC_LOGO`) inlined.

    Read once per process. A bundle without that URL (another ReDoc version) is served as
    it is, with a warning: tests/browser/test_docs_pages.py then sees any new request.
    """
    data = REDOC_BUNDLE.read_bytes()
    if REDOC_LOGO not in data:
        log.warning("%s no longer holds %s", REDOC_BUNDLE, REDOC_LOGO.decode())
    return data.replace(REDOC_LOGO, BLANK_IMAGE)


def _root(request: Request) -> str:
    """The ASGI ``root_path`` of the request, without a trailing slash."""
    return request.scope.get("root_path", "").rstrip("/")


def install(app: FastAPI) -> None:
    """Serve the offline ``/docs``, ``/docs/oauth2-redirect`` and ``/redoc``.

    The application must be created with ``docs_url=None, redoc_url=None`` (FastAPI's CDN
    pages off); their assets are under ``/static`` (:func:`app.api.static_files.mount`). The
    pages are not added when the application has no OpenAPI document (``openapi_url=None``).
    """
    openapi_url = app.openapi_url
    if not openapi_url:
        return
    redirect_url = app.swagger_ui_oauth2_redirect_url
    parameters = {**(app.swagger_ui_parameters or {}), "validatorUrl": None}

    async def swagger_ui(request: Request) -> HTMLResponse:
        root = _root(request)
        return get_swagger_ui_html(
            openapi_url=root + openapi_url,
            title=f"{app.title} - Swagger UI",
            swagger_js_url=root + SWAGGER_JS,
            swagger_css_url=root + SWAGGER_CSS,
            swagger_favicon_url=root + FAVICON,
            oauth2_redirect_url=root + redirect_url if redirect_url else None,
            init_oauth=app.swagger_ui_init_oauth,
            swagger_ui_parameters=parameters,
        )

    async def swagger_ui_redirect(request: Request) -> HTMLResponse:
        return get_swagger_ui_oauth2_redirect_html()

    async def redoc(request: Request) -> HTMLResponse:
        root = _root(request)
        return get_redoc_html(
            openapi_url=root + openapi_url,
            title=f"{app.title} - ReDoc",
            redoc_js_url=root + REDOC_JS,
            redoc_favicon_url=root + FAVICON,
            with_google_fonts=False,
        )

    async def redoc_js(request: Request) -> Response:
        return Response(redoc_bundle(), media_type="text/javascript; charset=utf-8")

    # FastAPI routes (not Starlette's, as FastAPI's own pages are): labelled in metrics.
    pages = [("/docs", swagger_ui), ("/redoc", redoc), (REDOC_JS, redoc_js)]
    if redirect_url:
        pages.append((redirect_url, swagger_ui_redirect))
    for path, endpoint in pages:
        app.add_api_route(
            path, endpoint, methods=["GET"], include_in_schema=False, response_class=Response
        )
