"""Fast JSON responses: orjson, with NumPy arrays and scalars serialised natively."""

from __future__ import annotations

from typing import Any

import numpy as np
import orjson
from starlette.responses import Response


class ORJSONResponse(Response):
    """JSON via orjson (NumPy arrays serialised natively)."""

    media_type = "application/json"

    def render(self, content: Any) -> bytes:
        return dumps(content)


def dumps(content: Any) -> bytes:
    """``content`` as JSON, the way every answer is sent (HTTP bodies, stream messages)."""
    return orjson.dumps(content, option=orjson.OPT_SERIALIZE_NUMPY, default=_fallback)


def _fallback(obj: Any) -> Any:
    if isinstance(obj, np.ndarray):  # non-contiguous views
        return np.ascontiguousarray(obj)
    if isinstance(obj, np.generic):
        return obj.item()
    raise TypeError(f"cannot serialise {type(obj).__name__}")
