"""Strict text loaders for DH table documents: YAML and JSON to plain Python values.

Stricter than ``yaml.safe_load`` and ``json.loads`` where a table needs it: duplicate keys
are refused, YAML reads ``1e-3`` as a float (YAML 1.1 would read a string), and an integer
literal longer than :data:`MAX_INT_DIGITS` digits is kept as its text (:class:`HugeInt`) so
the validator (:mod:`dh2urdf.parse`) refuses it naming the field. Every failure is a
:class:`~dh2urdf.errors.DHError` without a field, its reason starting ``invalid YAML`` or
``invalid JSON``.
"""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any, Literal

import yaml

from dh2urdf.errors import DHError

#: Longest integer literal read as a number (longer ones are refused, naming the field:
#: Python refuses to convert integers of more than 4300 digits, and none is needed here).
MAX_INT_DIGITS = 400


def format_for_path(path: str | Path) -> Literal["yaml", "json"]:
    """``"yaml"`` or ``"json"`` from a file name's extension; :class:`DHError` otherwise."""
    suffix = Path(path).suffix.lower()
    if suffix in (".yaml", ".yml"):
        return "yaml"
    if suffix == ".json":
        return "json"
    raise DHError(
        None, f"unsupported file extension {suffix or '(none)'!r} (use .yaml, .yml or .json)"
    )


class HugeInt(str):
    """An integer literal too long to convert (kept as its text, refused by the validator)."""


def _int_literal(text: str) -> int | HugeInt:
    digits = len(text.lstrip("+-").replace("_", ""))
    return HugeInt(text) if digits > MAX_INT_DIGITS else int(text)


class _TableLoader(yaml.SafeLoader):
    """Safe YAML loader that rejects duplicate keys and reads ``1e-3`` as a float."""


_TableLoader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"^[-+]?(?:[0-9][0-9_]*)(?:\.[0-9_]*)?[eE][-+]?[0-9]+$"),
    list("-+0123456789"),
)


def _construct_mapping(loader: _TableLoader, node: yaml.MappingNode) -> dict[Any, Any]:
    loader.flatten_mapping(node)
    result: dict[Any, Any] = {}
    for key_node, value_node in node.value:
        key = loader.construct_object(key_node, deep=True)
        try:
            duplicate = key in result
        except TypeError as exc:
            raise DHError(
                None, f"invalid YAML: line {key_node.start_mark.line + 1}: unhashable key"
            ) from exc
        if duplicate:
            raise DHError(
                None,
                f"invalid YAML: line {key_node.start_mark.line + 1}: duplicate key {key!r}",
            )
        result[key] = loader.construct_object(value_node, deep=True)
    return result


_TableLoader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_mapping)


def _construct_int(loader: _TableLoader, node: yaml.ScalarNode) -> int | HugeInt:
    text = str(loader.construct_scalar(node))
    digits = len(text.lstrip("+-").replace("_", ""))
    if digits > MAX_INT_DIGITS:
        return HugeInt(text)
    return yaml.SafeLoader.construct_yaml_int(loader, node)


_TableLoader.add_constructor("tag:yaml.org,2002:int", _construct_int)


def load_yaml(text: str) -> Any:
    """The value of a YAML document (safe tags only, no duplicate keys)."""
    try:
        return yaml.load(text, Loader=_TableLoader)  # a SafeLoader subclass
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        where = f"line {mark.line + 1}, column {mark.column + 1}: " if mark else ""
        raise DHError(None, f"invalid YAML: {where}{exc.problem or exc.context}") from exc
    except yaml.YAMLError as exc:
        raise DHError(None, f"invalid YAML: {exc}") from exc


def load_json(text: str) -> Any:
    """The value of a JSON document (no duplicate keys)."""

    def pairs(items: list[tuple[str, Any]]) -> dict[str, Any]:
        out: dict[str, Any] = {}
        for k, v in items:
            if k in out:
                raise DHError(None, f"invalid JSON: duplicate key {k!r}")
            out[k] = v
        return out

    try:
        return json.loads(text, object_pairs_hook=pairs, parse_int=_int_literal)
    except json.JSONDecodeError as exc:
        raise DHError(
            None, f"invalid JSON: line {exc.lineno}, column {exc.colno}: {exc.msg}"
        ) from exc
    except RecursionError as exc:
        raise DHError(None, "invalid JSON: nested too deeply") from exc
