"""Examples in the OpenAPI document: recorded requests and the answers the service gave.

``app/api/examples/exchanges.json`` holds a scenario of requests, run in order against a
fresh service, and the answers (``make examples`` records it; tests/test_openapi_examples.py
runs every request again and compares). :func:`add_examples` puts them into the document:

- each successful exchange gives its operation a request-body example (the body it sent,
  under its media type) and a response example (the body it got, under its status and
  media type), both named after the exchange;
- each error exchange gives its operation an example under its status; an exchange marked
  ``shared`` is also ``components.examples.<name>``, the example of its status on every
  operation that has none of its own (so every declared problem response shows a body the
  service really sends);
- an exchange marked ``doc: false`` is a step of the scenario only (not shown).

A binary answer (the PNG slice) is an ``externalValue``: the recorded file, served at
``/static/examples/``. The file field of a multipart upload shows its name and size.
"""

from __future__ import annotations

import json
from functools import cache
from pathlib import Path
from typing import Any

import yaml

EXCHANGES_FILE = Path(__file__).resolve().parents[1] / "api" / "examples" / "exchanges.json"
_EXAMPLES = "#/components/examples/"


@cache
def exchanges() -> tuple[dict[str, Any], ...]:
    """The recorded exchanges (``request`` spec and ``response``), in scenario order."""
    return tuple(json.loads(EXCHANGES_FILE.read_text(encoding="utf-8"))["exchanges"])


def request_example(spec: dict[str, Any]) -> tuple[str, Any] | None:
    """(media type, example value) of the body a request spec sends, or ``None``."""
    if "json" in spec:
        return "application/json", spec["json"]
    if "text" in spec:
        media = spec["content_type"]
        if media.endswith("json"):
            return media, json.loads(spec["text"])
        if media.endswith("yaml"):  # the data the YAML text stands for, as the schema says
            return media, yaml.safe_load(spec["text"])
        return media, spec["text"]
    if "files" in spec:
        value = dict(spec["form"])
        for field, (name, media, data) in spec["files"].items():
            value[field] = f"<{name}: {media}, {len(data) * 3 // 4} bytes>"
        return "multipart/form-data", value
    return None


def response_example(spec: dict[str, Any], answer: dict[str, Any]) -> dict[str, Any] | None:
    """The Example Object of a recorded answer, or ``None`` when it has no body."""
    summary = f"{spec['method']} {spec['path']}"
    if "json" in answer:
        return {"summary": summary, "value": answer["json"]}
    if "text" in answer:
        if "yaml" in answer["content_type"]:  # the data the YAML text stands for
            return {"summary": summary, "value": yaml.safe_load(answer["text"])}
        return {"summary": summary, "value": answer["text"]}
    if "static" in answer:  # binary: the recorded file, served by the service
        return {
            "summary": summary,
            "description": f"{answer['bytes']} bytes of {answer['content_type']}",
            "externalValue": answer["static"],
        }
    return None


def _content(response: dict[str, Any], media: str) -> dict[str, Any] | None:
    """The media entry of ``response`` an answer of type ``media`` belongs to: the one of
    that type (parameters aside), else the only one (``application/octet-stream`` for a
    file of any type), else ``None``."""
    declared = response.get("content") or {}
    for name, content in declared.items():
        if name.split(";")[0].strip() == media:
            return content
    return next(iter(declared.values())) if len(declared) == 1 else None


def add_examples(
    schema: dict[str, Any], recorded: tuple[dict[str, Any], ...] | None = None
) -> dict[str, Any]:
    """Put the ``recorded`` exchanges (default: :func:`exchanges`) into ``schema`` (in
    place, see the module docstring); returns it."""
    recorded = exchanges() if recorded is None else recorded
    operations = {
        op["operationId"]: op
        for item in schema.get("paths", {}).values()
        for op in item.values()
        if isinstance(op, dict) and "operationId" in op
    }
    shared: dict[str, str] = {}
    components = schema.setdefault("components", {}).setdefault("examples", {})
    for exchange in recorded:
        spec, answer = exchange["request"], exchange["response"]
        op = operations.get(spec["operation"])
        if op is None or spec.get("doc") is False:
            continue
        status = str(answer["status"])
        body = request_example(spec) if status.startswith("2") else None
        if body is not None and "requestBody" in op:
            media, value = body
            content = op["requestBody"]["content"].get(media)
            if content is not None:
                content.setdefault("examples", {})[spec["name"]] = {
                    "summary": spec["name"],
                    "value": value,
                }
        example = response_example(spec, answer)
        response = op["responses"].get(status)
        if example is None or response is None:
            continue
        content = _content(response, answer["content_type"])
        if content is None:
            continue
        if spec.get("shared"):
            components[spec["name"]] = example
            shared.setdefault(status, spec["name"])
            example = {"$ref": _EXAMPLES + spec["name"]}
        content.setdefault("examples", {})[spec["name"]] = example
    for op in operations.values():
        for status, response in op["responses"].items():
            for content in (response.get("content") or {}).values():
                if "examples" not in content and status in shared:
                    content["examples"] = {shared[status]: {"$ref": _EXAMPLES + shared[status]}}
    return schema
