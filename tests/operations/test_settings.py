"""DENAVIT_* settings: parsing, validation, and a clean one-line failure at start-up."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from app.__main__ import local_url, server_options
from app.operations.settings import Settings, SettingsError, load_settings

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture
def clean_env(monkeypatch: pytest.MonkeyPatch) -> pytest.MonkeyPatch:
    """No DENAVIT_* variable from the outer environment leaks into a test."""
    for name in list(os.environ):
        if name.upper().startswith("DENAVIT_"):
            monkeypatch.delenv(name)
    return monkeypatch


def test_defaults(clean_env) -> None:
    s = load_settings()
    assert (s.host, s.port, s.workers) == ("127.0.0.1", 8000, 1)
    assert s.data_dir == Path("data")
    assert s.api_token is None and s.cors_origins == [] and s.access_log is True
    assert s.max_body_bytes == 64 * 1024 * 1024 and s.max_batch == 100_000
    assert s.log_level == "info" and s.ik_max_timeout_ms == 1000.0
    assert s.ik_batch_processes is None  # every core the process may use


def test_every_variable_is_read(clean_env, tmp_path) -> None:
    env = {
        "DENAVIT_HOST": "0.0.0.0",
        "DENAVIT_PORT": "9001",
        "DENAVIT_WORKERS": "3",
        "DENAVIT_DATA_DIR": str(tmp_path / "d"),
        "DENAVIT_LOG_LEVEL": "WARNING",
        "DENAVIT_ACCESS_LOG": "false",
        "DENAVIT_API_TOKEN": "  s3cret-token  ",
        "DENAVIT_CORS_ORIGINS": "https://a.example, http://localhost:3000/",
        "DENAVIT_MAX_BODY_BYTES": "2048",
        "DENAVIT_MAX_BATCH": "7",
        "DENAVIT_IK_MAX_TIMEOUT_MS": "250.5",
        "DENAVIT_GRACEFUL_TIMEOUT_S": "3",
        "DENAVIT_IK_BATCH_PROCESSES": "2",
    }
    for k, v in env.items():
        clean_env.setenv(k, v)
    s = load_settings()
    assert (s.host, s.port, s.workers) == ("0.0.0.0", 9001, 3)
    assert s.data_dir == tmp_path / "d"
    assert s.log_level == "warning" and s.access_log is False
    assert s.api_token == "s3cret-token"
    assert s.cors_origins == ["https://a.example", "http://localhost:3000"]
    assert (s.max_body_bytes, s.max_batch, s.ik_max_timeout_ms) == (2048, 7, 250.5)
    assert s.graceful_timeout_s == 3 and s.ik_batch_processes == 2


def test_cors_origins_as_json_list_and_empty(clean_env) -> None:
    clean_env.setenv("DENAVIT_CORS_ORIGINS", '["https://x.example", "*"]')
    assert load_settings().cors_origins == ["https://x.example", "*"]
    clean_env.setenv("DENAVIT_CORS_ORIGINS", "")
    assert load_settings().cors_origins == []


def test_empty_token_means_no_token(clean_env) -> None:
    clean_env.setenv("DENAVIT_API_TOKEN", "   ")
    assert load_settings().api_token is None


@pytest.mark.parametrize(
    ("variable", "value", "reason"),
    [
        ("DENAVIT_PORT", "abc", "integer"),
        ("DENAVIT_PORT", "0", "greater than or equal to 1"),
        ("DENAVIT_PORT", "70000", "less than or equal to 65535"),
        ("DENAVIT_WORKERS", "0", "greater than or equal to 1"),
        ("DENAVIT_HOST", "not a host", "IP address or a host name"),
        ("DENAVIT_LOG_LEVEL", "loud", "must be one of"),
        ("DENAVIT_ACCESS_LOG", "maybe", "boolean"),
        ("DENAVIT_API_TOKEN", "two words", "without spaces"),
        ("DENAVIT_CORS_ORIGINS", "example.org", "is not an origin"),
        ("DENAVIT_CORS_ORIGINS", "[not json", "not a JSON list"),
        ("DENAVIT_MAX_BODY_BYTES", "10", "greater than or equal to 1024"),
        ("DENAVIT_MAX_BATCH", "-1", "greater than or equal to 1"),
        ("DENAVIT_IK_MAX_TIMEOUT_MS", "0", "greater than 0"),
        ("DENAVIT_IK_MAX_TIMEOUT_MS", "nan", "greater than 0"),
        ("DENAVIT_GRACEFUL_TIMEOUT_S", "-2", "greater than or equal to 0"),
        ("DENAVIT_IK_BATCH_PROCESSES", "0", "greater than or equal to 1"),
        ("DENAVIT_IK_BATCH_PROCESSES", "257", "less than or equal to 256"),
        ("DENAVIT_IK_BATCH_PROCESSES", "two", "integer"),
    ],
)
def test_bad_value_names_the_variable(clean_env, variable, value, reason) -> None:
    clean_env.setenv(variable, value)
    with pytest.raises(SettingsError) as info:
        load_settings()
    message = str(info.value)
    assert "\n" not in message
    assert message.startswith("invalid settings: ")
    assert variable in message and reason in message


def test_data_dir_that_is_a_file_is_refused(clean_env, tmp_path) -> None:
    f = tmp_path / "file"
    f.write_text("x")
    clean_env.setenv("DENAVIT_DATA_DIR", str(f))
    with pytest.raises(SettingsError, match="DENAVIT_DATA_DIR.*is not a directory"):
        load_settings()


def test_every_bad_variable_is_listed(clean_env) -> None:
    clean_env.setenv("DENAVIT_PORT", "x")
    clean_env.setenv("DENAVIT_WORKERS", "y")
    with pytest.raises(SettingsError) as info:
        load_settings()
    assert "DENAVIT_PORT='x'" in str(info.value) and "DENAVIT_WORKERS='y'" in str(info.value)


def _start(args: list[str], **env: str) -> subprocess.CompletedProcess[str]:
    base = {k: v for k, v in os.environ.items() if not k.upper().startswith("DENAVIT_")}
    return subprocess.run(
        [sys.executable, *args],
        cwd=ROOT,
        env={**base, **env},
        capture_output=True,
        text=True,
        timeout=120,
    )


@pytest.mark.parametrize(
    "args", [["-c", "import app.main"], ["-m", "app"]], ids=["import", "python -m app"]
)
def test_start_up_with_a_bad_variable_exits_with_one_line(args) -> None:
    done = _start(args, DENAVIT_PORT="eighty")
    assert done.returncode != 0
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1, done.stderr
    assert lines[0].startswith("denavit: invalid settings: DENAVIT_PORT='eighty'")
    assert "Traceback" not in done.stderr


def test_unknown_command_line_is_a_usage_error() -> None:
    done = _start(["-m", "app", "serve-please"])
    assert done.returncode == 2 and "usage: python -m app" in done.stderr


def test_server_options_follow_the_settings(tmp_path) -> None:
    s = Settings(host="0.0.0.0", port=8123, workers=4, data_dir=tmp_path, graceful_timeout_s=5)
    opts = server_options(s)
    assert (opts["host"], opts["port"], opts["workers"]) == ("0.0.0.0", 8123, 4)
    assert opts["timeout_graceful_shutdown"] == 5
    assert opts["access_log"] is False  # replaced by the JSON access log
    assert (opts["loop"], opts["http"]) == ("uvloop", "app.server.http_protocol:HttpToolsProtocol")
    # WebSockets: no compression, uvicorn's frame limit is the stream's message limit
    # (tests/api/test_memory_before_auth.py checks them on a live server)
    assert (opts["ws"], opts["ws_per_message_deflate"]) == ("websockets-sansio", False)
    assert opts["ws_max_size"] == 1 << 20
    assert server_options(Settings(stream_max_message_bytes=4096))["ws_max_size"] == 4096


def test_healthcheck_url_reaches_a_wildcard_bind_on_loopback(tmp_path) -> None:
    assert local_url(Settings(host="0.0.0.0", port=1234), "/health") == (
        "http://127.0.0.1:1234/health"
    )
    assert local_url(Settings(host="::", port=1234), "/x") == "http://[::1]:1234/x"
    assert local_url(Settings(host="127.0.0.2", port=80), "/x") == "http://127.0.0.2:80/x"
