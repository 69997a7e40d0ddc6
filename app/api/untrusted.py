"""Answers that carry documents a client supplied: never run as pages of the service's origin.

A package may hold any file, and an uploaded URDF any XML: an XHTML ``<script>`` in an
``.xml``, ``.urdf``, ``.srdf``, ``.xacro`` or ``.dae`` (XML types a browser renders), an
SVG, an HTML page. Served verbatim from the service's origin and rendered, its script
would read what the viewer keeps and call the API as the user. So these answers carry:

- ``Content-Security-Policy: default-src 'none'; sandbox`` (:data:`SANDBOX`): a document
  shown anyway gets an opaque origin and runs no script, loads nothing, submits no form;
- ``Content-Disposition: attachment`` (:func:`content_disposition`, an RFC 6266 filename)
  for every type but the raster images of :data:`INLINE_TYPES`: a navigation to the file
  saves it instead of showing it. ``fetch``, XHR and ``<img>`` ignore the disposition, so
  the viewer still loads meshes and textures;
- ``X-Content-Type-Options: nosniff``, which every answer of the service carries
  (:mod:`app.middleware.observability`): the browser keeps to the declared type.

Content types stay truthful (``application/xml`` is XML); the headers, not a disguised
type, keep the browser from running what the file holds.
"""

from __future__ import annotations

import os
from urllib.parse import quote

from starlette.datastructures import Headers
from starlette.responses import (
    FileResponse,
    MalformedRangeHeader,
    RangeNotSatisfiable,
    Response,
)
from starlette.types import Receive, Scope, Send

from app.api.errors import problem

#: The policy of every client-supplied document: nothing runs, nothing loads, opaque origin.
SANDBOX = "default-src 'none'; sandbox"
#: Types shown inline when opened (raster images: a browser never runs them).
INLINE_TYPES = frozenset({"image/png", "image/jpeg"})
#: RFC 8187 ``attr-char`` besides letters, digits and ``-._~`` (which ``quote`` keeps).
_ATTR_CHARS = "!#$&+^`|"


#: The OpenAPI ``headers`` of a 200 answer carrying a client-supplied document.
OPENAPI_HEADERS = {
    "Content-Security-Policy": {
        "description": f"Always `{SANDBOX}`: a browser shows the document, if at all, in an "
        "opaque origin that runs no script.",
        "schema": {"type": "string"},
    },
    "Content-Disposition": {
        "description": "`attachment; filename=...` (RFC 6266), on every type but image/png "
        "and image/jpeg: a browser saves the file instead of opening it.",
        "schema": {"type": "string"},
    },
    "X-Content-Type-Options": {
        "description": "Always `nosniff` (on every answer of the service).",
        "schema": {"type": "string"},
    },
}


def content_disposition(filename: str) -> str:
    """``attachment`` with ``filename`` (RFC 6266): an ASCII ``filename`` every client
    reads (other characters, quotes, backslashes and ``%`` as ``_``) and, when it differs,
    the exact name as ``filename*`` (UTF-8, percent-encoded)."""
    fallback = "".join(c if " " <= c <= "~" and c not in '"\\%' else "_" for c in filename)
    value = f'attachment; filename="{fallback}"'
    if fallback != filename:
        exact = quote(filename, safe=_ATTR_CHARS, encoding="utf-8", errors="replace")
        value += f"; filename*=UTF-8''{exact}"
    return value


def document_headers(filename: str, media_type: str) -> dict[str, str]:
    """The headers of a client-supplied document named ``filename`` of ``media_type``."""
    headers = {"Content-Security-Policy": SANDBOX}
    if media_type not in INLINE_TYPES:
        headers["Content-Disposition"] = content_disposition(filename)
    return headers


class UntrustedFileResponse(FileResponse):
    """A file a client supplied, with :func:`document_headers` on every answer.

    The whole file (200, or headers only for ``HEAD``) and byte ranges (206) carry them;
    a ``Range`` header that is malformed (400) or outside the file (416, with
    ``Content-Range``) is a problem naming ``range`` instead of Starlette's plain text.
    """

    def __init__(self, path: str | os.PathLike[str], stat_result: os.stat_result, media: str):
        name = os.path.basename(path)
        super().__init__(
            path,
            media_type=media,
            headers=document_headers(name, media),
            stat_result=stat_result,
        )

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        refusal = self._range_refusal(scope)
        if refusal is not None:
            await refusal(scope, receive, send)
            return
        await super().__call__(scope, receive, send)

    def _range_refusal(self, scope: Scope) -> Response | None:
        """The problem for a ``Range`` FileResponse would refuse (as it reads one: not
        when ``If-Range`` names another version), else ``None``."""
        headers = Headers(scope=scope)
        http_range = headers.get("range")
        if_range = headers.get("if-range")
        if http_range is None or (if_range is not None and not self._should_use_range(if_range)):
            return None
        assert self.stat_result is not None  # given by the constructor
        size = self.stat_result.st_size
        extra = {"Content-Security-Policy": SANDBOX}
        try:
            self._parse_range_header(http_range, size)
            return None
        except MalformedRangeHeader as exc:
            status, kind = 400, "malformed-range"
            detail = f"{http_range[:100]!r} is malformed ({exc.content.rstrip('.')})"
        except RangeNotSatisfiable:
            status, kind = 416, "range-not-satisfiable"
            detail = f"{http_range[:100]!r} is outside the file ({size} bytes)"
            extra["Content-Range"] = f"bytes */{size}"
        return problem(
            status,
            f"range: {detail}",
            kind=kind,
            field="range",
            instance=scope["path"],
            headers=extra,
        )
