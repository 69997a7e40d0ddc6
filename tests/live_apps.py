"""Test-only application factories for live servers (``uvicorn --factory``).

Never imported by the service: these add routes that exist only to make a test's failure
happen on purpose (a bug that raises), which the real API has no way to trigger.
"""

from __future__ import annotations

from fastapi import FastAPI

from app.main import create_app


def make_app_with_a_bug() -> FastAPI:
    """The service plus ``GET /test/bug``, which raises an unexpected exception."""
    app = create_app()

    @app.get("/test/bug", include_in_schema=False)
    async def bug() -> None:
        raise RuntimeError("a bug, on purpose")

    return app
