"""Configuration from ``DENAVIT_*`` environment variables, in one place."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from pydantic import Field, field_validator
from pydantic_settings import BaseSettings, SettingsConfigDict


class Settings(BaseSettings):
    """Service settings; every field reads ``DENAVIT_<NAME>`` from the environment."""

    model_config = SettingsConfigDict(env_prefix="DENAVIT_", extra="ignore")

    host: str = Field("127.0.0.1", description="Address uvicorn binds to.")
    port: int = Field(8000, ge=1, le=65535, description="TCP port.")
    workers: int = Field(1, ge=1, le=256, description="Number of uvicorn worker processes.")
    data_dir: Path = Field(Path("data"), description="Directory of user-added robots and maps.")
    log_level: str = Field("info", description="Logging level: debug, info, warning, error.")
    api_token: str | None = Field(None, description="Bearer token required on write endpoints.")
    cors_origins: list[str] = Field(default_factory=list, description="Allowed CORS origins.")
    max_body_bytes: int = Field(64 * 1024 * 1024, ge=1024, description="Largest request body.")
    max_upload_bytes: int = Field(
        5 * 1024 * 1024, ge=1024, description="Largest robot upload (POST /robots/urdf, /dh)."
    )
    max_batch: int = Field(100_000, ge=1, description="Largest batch (configurations, targets).")
    ik_max_timeout_ms: float = Field(1000.0, gt=0, description="Cap on an IK request's budget.")

    @field_validator("log_level")
    @classmethod
    def _level(cls, value: str) -> str:
        value = value.lower()
        if value not in {"critical", "error", "warning", "info", "debug"}:
            raise ValueError("must be one of critical, error, warning, info, debug")
        return value


@lru_cache
def get_settings() -> Settings:
    """The process-wide settings, read once."""
    return Settings()
