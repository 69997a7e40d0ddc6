"""Binary response bodies declared as binary strings in the OpenAPI document.

The reachability heat map (``image/png``) and a package's files
(``application/octet-stream``) are declared by their routes with no schema or a plain string
schema. Client generators read a body by its schema: without one, openapi-python-client drops
the answer (``None``), and with ``{"type": "string"}`` it types the bytes as text.
:func:`binary_responses` gives every such media type the schema ``{"type": "string",
"format": "binary"}``, which generators map to a file or ``Blob``; JSON, problem+json, text
and XML answers are left as they are.
"""

from __future__ import annotations

from typing import Any

#: The schema of a body of raw bytes.
BINARY = {"type": "string", "format": "binary"}


def is_binary(media_type: str) -> bool:
    """Whether answers of ``media_type`` are raw bytes (images, octet streams)."""
    return media_type.startswith("image/") or media_type == "application/octet-stream"


def binary_responses(schema: dict[str, Any]) -> dict[str, Any]:
    """Rewrite ``schema`` (an OpenAPI document) in place; returns it."""
    for item in schema.get("paths", {}).values():
        for op in item.values():
            if not isinstance(op, dict):
                continue
            for response in op.get("responses", {}).values():
                for media_type, content in response.get("content", {}).items():
                    if is_binary(media_type):
                        content["schema"] = dict(BINARY)
    return schema
