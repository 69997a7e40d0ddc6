"""Logs: one JSON object per line on stderr, with the request id.

Every record is written as ``ts`` (UTC, ISO 8601, ms), ``level``, ``logger``, ``message``,
``request_id`` when inside a request (:data:`REQUEST_ID`, set by
:class:`app.middleware.observability.ObservabilityMiddleware`), any ``extra`` fields, and
``exc_info``
(the formatted traceback) for exceptions. uvicorn's own loggers are routed through the same
handler; its access log is replaced by ``denavit.access`` (:func:`access_line`).
"""

from __future__ import annotations

import logging
import sys
from contextvars import ContextVar
from datetime import UTC, datetime
from typing import Any

import orjson

#: The id of the request being handled (``None`` outside requests).
REQUEST_ID: ContextVar[str | None] = ContextVar("denavit_request_id", default=None)


_RECORD_FIELDS = frozenset(vars(logging.makeLogRecord({}))) | {
    "message",
    "asctime",
    "taskName",
    "color_message",  # uvicorn's ANSI-coloured copy of the message
}


class JsonFormatter(logging.Formatter):
    """One JSON object per record (``ts``, ``level``, ``logger``, ``message``, extras)."""

    def format(self, record: logging.LogRecord) -> str:
        doc: dict[str, Any] = {
            "ts": datetime.fromtimestamp(record.created, UTC).isoformat(timespec="milliseconds"),
            "level": record.levelname.lower(),
            "logger": record.name,
            "message": record.getMessage(),
        }
        request_id = REQUEST_ID.get()
        if request_id is not None:
            doc["request_id"] = request_id
        for key, value in record.__dict__.items():
            if key not in _RECORD_FIELDS and not key.startswith("_"):
                doc[key] = value
        if record.exc_info:
            doc["exc_info"] = self.formatException(record.exc_info)
        elif record.exc_text:
            doc["exc_info"] = record.exc_text
        return orjson.dumps(doc, default=str).decode()


class JsonStderrHandler(logging.StreamHandler):
    """A stream handler that always writes to the *current* ``sys.stderr``."""

    def __init__(self) -> None:
        super().__init__(sys.stderr)
        self.setFormatter(JsonFormatter())

    @property  # type: ignore[override]
    def stream(self) -> Any:
        return sys.stderr

    @stream.setter
    def stream(self, value: Any) -> None:  # StreamHandler.__init__ assigns it
        pass


_UVICORN_LOGGERS = ("uvicorn", "uvicorn.error")
#: uvicorn's access log is replaced by ``denavit.access`` (JSON, with the request id).
_UVICORN_ACCESS = "uvicorn.access"


def logging_config(level: str = "info") -> dict[str, Any]:
    """A :func:`logging.config.dictConfig` dict: JSON on stderr for every logger.

    Given to ``uvicorn.run(log_config=...)`` so that uvicorn's own messages (start-up,
    shutdown, errors) are JSON too, in every worker process.
    """
    lvl = level.upper()
    return {
        "version": 1,
        "disable_existing_loggers": False,
        "handlers": {"stderr": {"()": "app.operations.logs.JsonStderrHandler"}},
        "root": {"handlers": ["stderr"], "level": lvl},
        "loggers": {
            **{
                name: {"handlers": [], "propagate": True, "level": lvl} for name in _UVICORN_LOGGERS
            },
            _UVICORN_ACCESS: {"handlers": [], "propagate": False},
        },
    }


def configure_logging(level: str = "info") -> None:
    """JSON logs on stderr (idempotent; keeps handlers others installed on the root logger).

    Called at application start-up, so ``uvicorn app.main:app`` run without our log config
    also logs JSON.
    """
    lvl = level.upper()
    root = logging.getLogger()
    if not any(isinstance(h, JsonStderrHandler) for h in root.handlers):
        root.addHandler(JsonStderrHandler())
    root.setLevel(lvl)
    for name in _UVICORN_LOGGERS:
        logger = logging.getLogger(name)
        logger.handlers = [h for h in logger.handlers if isinstance(h, JsonStderrHandler)]
        logger.propagate = True
        logger.setLevel(lvl)
    access = logging.getLogger(_UVICORN_ACCESS)
    access.handlers = []
    access.propagate = False


ACCESS_LOGGER = logging.getLogger("denavit.access")


def access_line(method: str, path: str, status: int, fields: dict[str, Any]) -> None:
    """Write the access-log line of a request.

    When our JSON handler is the root's (the service's logging set-up) and nothing else
    listens to ``denavit.access``, the line is built and written directly, under the
    handler's lock: the same JSON as :class:`JsonFormatter` would write, at a fifth of the
    cost of a ``logging`` call (no LogRecord, no caller lookup). Otherwise it goes through
    ``logging`` like any other record.
    """
    message = f"{method} {path} {status}"
    root = logging.getLogger()
    handler = root.handlers[0] if len(root.handlers) == 1 else None
    if not isinstance(handler, JsonStderrHandler) or ACCESS_LOGGER.handlers:
        ACCESS_LOGGER.info(message, extra=fields)
        return
    doc: dict[str, Any] = {
        "ts": datetime.now(UTC).isoformat(timespec="milliseconds"),
        "level": "info",
        "logger": ACCESS_LOGGER.name,
        "message": message,
    }
    request_id = REQUEST_ID.get()
    if request_id is not None:
        doc["request_id"] = request_id
    doc.update(fields)
    line = orjson.dumps(doc, default=str).decode() + "\n"
    handler.acquire()
    try:
        sys.stderr.write(line)
        sys.stderr.flush()
    finally:
        handler.release()
