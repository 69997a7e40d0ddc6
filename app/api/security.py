"""Write protection: a bearer token on every endpoint that changes state.

When ``DENAVIT_API_TOKEN`` is set, write endpoints (robot import, upload, delete, scenes,
reachability builds) require ``Authorization: Bearer <token>``: 401 without a token, 403
with a wrong one. Reads stay open. Tokens are compared in constant time.
"""

from __future__ import annotations

import hmac

from fastapi import HTTPException, Request

from app.api.deps import SettingsDep


async def require_token(request: Request, settings: SettingsDep) -> None:
    """FastAPI dependency for write routes: ``dependencies=[Depends(require_token)]``
    (``async``: no thread hop)."""
    expected = settings.api_token
    if not expected:
        return
    header = request.headers.get("authorization", "")
    scheme, _, token = header.partition(" ")
    if scheme.lower() != "bearer" or not token:
        raise HTTPException(
            401,
            "authorization: this endpoint needs 'Authorization: Bearer <token>'",
            headers={"WWW-Authenticate": "Bearer"},
        )
    if not hmac.compare_digest(token.strip().encode(), expected.encode()):
        raise HTTPException(403, "authorization: the bearer token is not valid")
