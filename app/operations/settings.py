"""Configuration from ``DENAVIT_*`` environment variables, in one place.

Every field of :class:`Settings` reads ``DENAVIT_<FIELD>`` (case-insensitive). Values are
validated when the process starts: a bad value stops the service with one line naming the
variable (:func:`get_settings` raises ``SystemExit``), never a traceback.

``DENAVIT_CORS_ORIGINS`` is a comma-separated list (``https://a.example,https://b.example``)
or a JSON list; empty (the default) turns CORS off.
"""

from __future__ import annotations

import ipaddress
import re
from functools import lru_cache
from pathlib import Path
from typing import Annotated

import orjson
from pydantic import Field, ValidationError, field_validator
from pydantic_settings import BaseSettings, NoDecode, SettingsConfigDict

ENV_PREFIX = "DENAVIT_"

_LABEL = r"[A-Za-z0-9]([A-Za-z0-9-]{0,61}[A-Za-z0-9])?"
_HOSTNAME = re.compile(rf"^(?=.{{1,253}}$){_LABEL}(\.{_LABEL})*$")
_ORIGIN = re.compile(r"^https?://[^\s/?#]+$")
_TOKEN = re.compile(r"^[\x21-\x7e]+$")


class Settings(BaseSettings):
    """Service settings; every field reads ``DENAVIT_<NAME>`` from the environment."""

    model_config = SettingsConfigDict(env_prefix=ENV_PREFIX, extra="ignore")

    host: str = Field("127.0.0.1", description="Address uvicorn binds to (IP or host name).")
    port: int = Field(8000, ge=1, le=65535, description="TCP port.")
    workers: int = Field(1, ge=1, le=256, description="Number of uvicorn worker processes.")
    data_dir: Path = Field(Path("data"), description="Directory of user-added robots and maps.")
    log_level: str = Field("info", description="Logging level: debug, info, warning, error.")
    access_log: bool = Field(True, description="One JSON log line per request.")
    api_token: str | None = Field(None, description="Bearer token required on write endpoints.")
    cors_origins: Annotated[list[str], NoDecode] = Field(
        default_factory=list, description="Allowed CORS origins (comma-separated); empty = off."
    )
    max_body_bytes: int = Field(64 * 1024 * 1024, ge=1024, description="Largest request body.")
    max_upload_bytes: int = Field(
        5 * 1024 * 1024, ge=1024, description="Largest robot upload (POST /robots/urdf, /dh)."
    )
    max_package_bytes: int = Field(
        32 * 1024 * 1024,
        ge=1024,
        description="Largest POST /robots/package body (the multipart form with its archive).",
    )
    max_package_files: int = Field(
        10_000, ge=1, description="Most entries (files and directories) in a package archive."
    )
    max_package_unpacked_bytes: int = Field(
        256 * 1024 * 1024,
        ge=1024,
        description="Largest total size of a package's files once unpacked (bytes).",
    )
    max_batch: int = Field(100_000, ge=1, description="Largest batch (configurations, targets).")
    ik_max_timeout_ms: float = Field(1000.0, gt=0, description="Cap on an IK request's budget.")
    max_xml_elements: int = Field(
        20_000, ge=100, description="Most XML elements in an uploaded URDF or SRDF."
    )
    max_xml_attributes: int = Field(
        50_000, ge=100, description="Most XML attributes in total in an uploaded URDF or SRDF."
    )
    max_xml_attributes_per_element: int = Field(
        64,
        ge=8,
        le=10_000,
        description="Most attributes on one XML element (the URDF parser's cost is quadratic).",
    )
    max_xml_depth: int = Field(32, ge=8, le=1000, description="Deepest XML element nesting.")
    max_urdf_joints: int = Field(
        256, ge=1, le=4096, description="Most joints (any type) in an uploaded URDF."
    )
    max_robot_dof: int = Field(
        64,
        ge=1,
        le=512,
        description="Most movable joints in an uploaded URDF (Pinocchio's per-thread Data "
        "grows as ~34·dof³ bytes: 15 MB at 64, 80 MB at 128, 570 MB at 256).",
    )
    xacro_timeout_s: float = Field(
        20.0,
        gt=0,
        le=3600,
        allow_inf_nan=False,
        description="Wall-clock limit of one xacro expansion (its child process is killed).",
    )
    xacro_memory_bytes: int = Field(
        512 * 1024 * 1024,
        ge=32 * 1024 * 1024,
        description="Address space a xacro expansion's child process may add (RLIMIT_AS).",
    )
    xacro_max_output_chars: int = Field(
        8 * 1024 * 1024, ge=1024, description="Longest URDF a xacro expansion may produce."
    )
    max_mesh_vertices: int = Field(
        1_000_000,
        ge=1000,
        description="Most vertices, and most faces, one mesh file of an upload may declare "
        "(read from its header before any mesh loader sees it).",
    )
    max_collision_triangles: int = Field(
        200_000,
        ge=1000,
        description="Most triangles of one uploaded robot's collision meshes in total: each "
        "worker holds them (~0.7 KB each).",
    )
    max_collision_mesh_triangles: int = Field(
        100_000,
        ge=1000,
        description="Most triangles of one collision mesh file: a worker reads it while holding "
        "the GIL (~10 µs per triangle, ~30 µs with every core busy), and uvicorn's supervisor "
        "kills a worker that holds it for 5 s.",
    )
    parse_timeout_s: float = Field(
        60.0,
        gt=0,
        le=3600,
        allow_inf_nan=False,
        description="Wall-clock limit of the child process that reads an upload's meshes or "
        "converts its MJCF (it is killed).",
    )
    parse_memory_bytes: int = Field(
        1024 * 1024 * 1024,
        ge=64 * 1024 * 1024,
        description="Address space the child process that reads an upload's meshes or converts "
        "its MJCF may add (RLIMIT_AS).",
    )
    upload_workers: int = Field(
        2,
        ge=1,
        le=64,
        description="Threads of one worker for robot uploads (DH, URDF, packages: unpacking, "
        "checks, waiting on their child processes); never the compute pool's.",
    )
    ik_max_request_s: float = Field(
        30.0,
        gt=0,
        le=86400,
        allow_inf_nan=False,
        description="Cap on an IK batch's total budget, targets × timeout_ms (s), and on a "
        "Cartesian path's, points × timeout_ms (also its deadline): one request cannot hold a "
        "pool worker longer.",
    )
    ik_batch_processes: int | None = Field(
        None,
        ge=1,
        le=256,
        description="Worker processes of one server worker for IK batches with chain_seeds "
        "false (each uvicorn worker has its own pool: workers × this many processes); 1 "
        "solves them in the request's thread; default every core the process may use.",
    )
    stream_max_in_flight: int = Field(
        32,
        ge=1,
        le=4096,
        description="WS /robots/{id}/stream: most messages read but not yet answered on one "
        "socket; the server stops reading a socket that many answers behind (backpressure).",
    )
    stream_max_message_bytes: int = Field(
        1024 * 1024,
        ge=1024,
        le=64 * 1024 * 1024,
        description="WS /robots/{id}/stream: largest message (bytes); a longer one closes the "
        "socket with code 1009.",
    )
    graceful_timeout_s: int = Field(
        8,
        ge=0,
        le=3600,
        description="On SIGTERM, how long in-flight requests may take to finish (s).",
    )

    @field_validator("host")
    @classmethod
    def _host(cls, value: str) -> str:
        value = value.strip()
        try:
            ipaddress.ip_address(value)
        except ValueError:
            if not _HOSTNAME.match(value):
                raise ValueError("must be an IP address or a host name") from None
        return value

    @field_validator("log_level")
    @classmethod
    def _level(cls, value: str) -> str:
        value = value.strip().lower()
        if value not in {"critical", "error", "warning", "info", "debug"}:
            raise ValueError("must be one of critical, error, warning, info, debug")
        return value

    @field_validator("data_dir")
    @classmethod
    def _data_dir(cls, value: Path) -> Path:
        if not str(value).strip():
            raise ValueError("must not be empty")
        if value.exists() and not value.is_dir():
            raise ValueError(f"{value} exists and is not a directory")
        return value

    @field_validator("api_token", mode="before")
    @classmethod
    def _token(cls, value: object) -> object:
        if isinstance(value, str):
            value = value.strip()
            if not value:
                return None  # an empty variable means "no token"
            if not _TOKEN.match(value):
                raise ValueError("must be printable ASCII without spaces")
        return value

    @field_validator("cors_origins", mode="before")
    @classmethod
    def _origins(cls, value: object) -> object:
        if isinstance(value, str):
            text = value.strip()
            if text.startswith("["):
                try:
                    value = orjson.loads(text)
                except orjson.JSONDecodeError as exc:
                    raise ValueError(f"not a JSON list ({exc})") from None
            else:
                value = [part.strip() for part in text.split(",") if part.strip()]
        if isinstance(value, list):
            origins = []
            for origin in value:
                if isinstance(origin, str):
                    origin = origin.strip().rstrip("/") or origin
                if not isinstance(origin, str) or not (origin == "*" or _ORIGIN.match(origin)):
                    raise ValueError(
                        f"{origin!r} is not an origin like https://example.org (or '*')"
                    )
                origins.append(origin)
            value = origins
        return value


class SettingsError(ValueError):
    """A ``DENAVIT_*`` variable has a bad value; the message is one line naming it."""


def describe(exc: ValidationError) -> str:
    """One line naming every bad variable: ``DENAVIT_PORT='abc': Input should be ...``."""
    parts = []
    for err in exc.errors():
        name = ENV_PREFIX + "_".join(str(p) for p in err["loc"][:1]).upper()
        value = err.get("input")
        shown = f"={value!r}" if isinstance(value, str | int | float) else ""
        message = str(err["msg"]).removeprefix("Value error, ")
        parts.append(f"{name}{shown}: {message}")
    return "invalid settings: " + "; ".join(parts)


def load_settings(**overrides: object) -> Settings:
    """Read the settings from the environment; raises :class:`SettingsError` (one line)."""
    try:
        return Settings(**overrides)
    except ValidationError as exc:
        raise SettingsError(describe(exc)) from None


@lru_cache
def get_settings() -> Settings:
    """The process-wide settings, read once; a bad variable exits with a one-line message."""
    try:
        return load_settings()
    except SettingsError as exc:
        raise SystemExit(f"denavit: {exc}") from None
