"""dh2urdf.table, loaders and parse: units, defaults and every kind of bad input."""

from __future__ import annotations

import copy
import json
import math
from pathlib import Path
from typing import Any

import pytest

from dh2urdf.errors import DHError
from dh2urdf.loaders import format_for_path
from dh2urdf.table import DEFAULT_GEOMETRY_RADIUS, DHTable, Transform


def base_doc() -> dict[str, Any]:
    return {
        "name": "test_arm",
        "convention": "standard",
        "units": {"length": "mm", "angle": "deg"},
        "joints": [
            {
                "name": "shoulder",
                "type": "revolute",
                "a": 30,
                "alpha": -90,
                "d": 0,
                "theta": 0,
                "lower": -170,
                "upper": 170,
            },
            {"type": "revolute", "a": 0, "alpha": -90, "d": 0, "theta": -90},
            {
                "type": "prismatic",
                "a": 0,
                "alpha": 0,
                "d": 100,
                "theta": 0,
                "lower": 0,
                "upper": 400,
            },
        ],
    }


def test_units_are_converted_to_si() -> None:
    t = DHTable.from_dict(base_doc())
    j1, j2, j3 = t.joints
    assert (j1.a, j1.alpha, j1.lower, j1.upper) == (
        0.03,
        math.radians(-90),
        math.radians(-170),
        math.radians(170),
    )
    assert j2.theta == -math.pi / 2
    assert (j3.d, j3.lower, j3.upper) == (0.1, 0.0, 0.4)


def test_mm_and_cm_conversion_is_correctly_rounded() -> None:
    doc = base_doc()
    doc["joints"][0]["a"] = 223.5
    assert DHTable.from_dict(doc).joints[0].a == 0.2235
    doc["units"]["length"] = "cm"
    assert DHTable.from_dict(doc).joints[0].a == 2.235
    doc["units"] = {"length": "m", "angle": "rad"}
    doc["joints"][0].update(lower=-3, upper=3)
    doc["joints"][2].update(lower=0, upper=0.4)
    assert DHTable.from_dict(doc).joints[0].a == 223.5


def test_defaults() -> None:
    doc = {
        "name": "x",
        "convention": "modified",
        "joints": [
            {"a": 1, "alpha": 0, "d": 0, "theta": 0},
            {"a": 1, "alpha": 0, "d": 0, "theta": 0},
        ],
    }
    t = DHTable.from_dict(doc)
    assert t.joint_names == ["j1", "j2"]
    assert t.dof == 2
    j = t.joints[0]
    assert j.type == "revolute"
    assert (j.lower, j.upper) == (-math.pi, math.pi)
    assert j.velocity == math.pi and j.effort == 100.0
    assert t.base == Transform() and t.tool == Transform()
    assert t.base.is_identity
    assert t.geometry_radius == DEFAULT_GEOMETRY_RADIUS
    assert t.description == ""


def test_base_tool_velocity_in_table_units_effort_si() -> None:
    doc = base_doc()
    doc["base"] = {"xyz": [100, 0, 50], "rpy": [0, 0, 90]}
    doc["tool"] = {"xyz": [0, 0, 120]}
    doc["joints"][0].update(velocity=90, effort=12.5)
    doc["joints"][2].update(velocity=250)
    t = DHTable.from_dict(doc)
    assert t.base == Transform((0.1, 0.0, 0.05), (0.0, 0.0, math.pi / 2))
    assert t.tool == Transform((0.0, 0.0, 0.12), (0.0, 0.0, 0.0))
    assert t.joints[0].velocity == math.pi / 2 and t.joints[0].effort == 12.5
    assert t.joints[2].velocity == 0.25


def test_continuous_joint_has_no_limits() -> None:
    doc = base_doc()
    doc["joints"][1]["type"] = "continuous"
    j = DHTable.from_dict(doc).joints[1]
    assert j.type == "continuous" and j.lower is None and j.upper is None


def test_one_sided_revolute_limit_uses_default_for_the_other() -> None:
    doc = base_doc()
    doc["joints"][1]["upper"] = 45
    j = DHTable.from_dict(doc).joints[1]
    assert (j.lower, j.upper) == (-math.pi, math.radians(45))


def test_yaml_and_json_text(tmp_path: Path) -> None:
    yaml_text = """
name: yaml_arm   # a comment
convention: standard
units: {length: m, angle: rad}
geometry: {radius: 0}
joints:
  - {a: 1e-3, alpha: 0, d: 2.5E+1, theta: 0}
"""
    t = DHTable.from_yaml(yaml_text)
    assert t.joints[0].a == 1e-3 and t.joints[0].d == 25.0
    assert t.geometry_radius == 0.0
    j = DHTable.from_json(json.dumps(base_doc()))
    assert j == DHTable.from_dict(base_doc())
    (tmp_path / "arm.json").write_text(json.dumps(base_doc()))
    (tmp_path / "arm.yml").write_text(yaml_text)
    assert DHTable.from_file(tmp_path / "arm.json") == j
    assert DHTable.from_file(tmp_path / "arm.yml") == t
    assert DHTable.from_text(yaml_text, "yaml") == t


def test_to_dict_round_trips_exactly() -> None:
    doc = base_doc()
    doc["base"] = {"xyz": [1, 2, 3], "rpy": [10, 20, 30]}
    doc["tool"] = {"xyz": [0, 0, 33.3], "rpy": [0, 90, 0]}
    doc["description"] = "round trip"
    doc["joints"][1]["type"] = "continuous"
    t = DHTable.from_dict(doc)
    again = DHTable.from_dict(t.to_dict())
    assert again == t
    assert DHTable.from_json(json.dumps(t.to_dict())) == t


def test_yaml_dump_of_to_dict_round_trips_exactly() -> None:
    """The service stores ``yaml.safe_dump(table.to_dict())`` and reloads it."""
    import yaml

    doc = base_doc()
    doc["joints"][0].update(a=1e-5, d=123456789.125, theta=1 / 3)
    doc["tool"] = {"xyz": [1e-20, 0, 2 / 3]}
    t = DHTable.from_dict(doc)
    assert DHTable.from_yaml(yaml.safe_dump(t.to_dict(), sort_keys=False)) == t


def test_format_for_path() -> None:
    assert format_for_path("a.YAML") == "yaml"
    assert format_for_path("a.yml") == "yaml"
    assert format_for_path("a.json") == "json"
    with pytest.raises(DHError, match="unsupported file extension '.txt'"):
        format_for_path("a.txt")


def test_dh_error_is_value_error_with_field() -> None:
    doc = base_doc()
    doc["joints"][2]["lower"] = 10
    doc["joints"][2]["upper"] = 5
    with pytest.raises(ValueError) as info:
        DHTable.from_dict(doc)
    err = info.value
    assert isinstance(err, DHError)
    assert str(err) == "joints[2].lower: lower (10) > upper (5)"
    assert err.field == "joints[2].lower"
    assert err.reason == "lower (10) > upper (5)"


def _set(path: str, value: Any):
    """A mutation setting ``doc[path]`` (dotted, with [i] indices); DELETE removes it."""

    def mutate(doc: dict[str, Any]) -> None:
        parts = path.replace("]", "").replace("[", ".").split(".")
        target: Any = doc
        for p in parts[:-1]:
            target = target[int(p)] if p.isdigit() else target.setdefault(p, {})
        last = parts[-1]
        if value is DELETE:
            del target[int(last) if last.isdigit() else last]
        else:
            target[int(last) if last.isdigit() else last] = value

    return mutate


DELETE = object()

BAD_INPUTS = [
    # (id, mutation, exact message or prefix ending with '...')
    (
        "unknown convention",
        _set("convention", "craig"),
        "convention: unknown convention 'craig' (expected 'standard' or 'modified')",
    ),
    ("missing convention", _set("convention", DELETE), "convention: field required"),
    (
        "unknown joint type",
        _set("joints[1].type", "spherical"),
        "joints[1].type: unknown joint type 'spherical' "
        "(expected 'revolute', 'prismatic', 'continuous')",
    ),
    (
        "unknown length unit",
        _set("units.length", "inch"),
        "units.length: unknown length unit 'inch'...",
    ),
    (
        "unknown angle unit",
        _set("units.angle", "grad"),
        "units.angle: unknown angle unit 'grad'...",
    ),
    ("unknown units field", _set("units.time", "s"), "units.time: unknown field..."),
    ("missing a", _set("joints[0].a", DELETE), "joints[0].a: field required"),
    ("missing alpha", _set("joints[1].alpha", DELETE), "joints[1].alpha: field required"),
    ("missing d", _set("joints[2].d", DELETE), "joints[2].d: field required"),
    ("missing theta", _set("joints[1].theta", DELETE), "joints[1].theta: field required"),
    ("null theta", _set("joints[1].theta", None), "joints[1].theta: field required"),
    ("string number", _set("joints[0].a", "30"), "joints[0].a: expected a number, got '30'"),
    (
        "comma decimal",
        _set("joints[0].d", "223,5"),
        "joints[0].d: expected a number, got '223,5' (use '.' as the decimal separator)",
    ),
    ("bool number", _set("joints[0].alpha", True), "joints[0].alpha: expected a number..."),
    ("list number", _set("joints[2].lower", [0]), "joints[2].lower: expected a number..."),
    ("nan", _set("joints[1].d", float("nan")), "joints[1].d: must be finite, got nan"),
    ("inf", _set("joints[1].a", float("inf")), "joints[1].a: must be finite, got inf"),
    (
        "-inf limit",
        _set("joints[0].lower", float("-inf")),
        "joints[0].lower: must be finite, got -inf",
    ),
    ("huge int", _set("joints[0].a", 10**400), "joints[0].a: must be finite..."),
    ("lower > upper", _set("joints[0].lower", 175), "joints[0].lower: lower (175) > upper (170)"),
    ("one-sided bound beyond default", _set("joints[1].lower", 200), "joints[1].lower: lower..."),
    ("no joints", _set("joints", []), "joints: at least one joint is required"),
    ("joints missing", _set("joints", DELETE), "joints: field required"),
    ("joints not a list", _set("joints", {"a": 1}), "joints: expected a list of joint rows..."),
    ("row not a mapping", _set("joints[1]", [0, 0, 0, 0]), "joints[1]: expected a mapping..."),
    (
        "joint name with slash",
        _set("joints[0].name", "arm/shoulder"),
        "joints[0].name: invalid joint name 'arm/shoulder'...",
    ),
    (
        "joint name with dots",
        _set("joints[0].name", "../etc"),
        "joints[0].name: invalid joint name '../etc'...",
    ),
    (
        "joint name with backslash",
        _set("joints[0].name", "a\\b"),
        "joints[0].name: invalid joint name...",
    ),
    (
        "joint name with space",
        _set("joints[0].name", "my joint"),
        "joints[0].name: invalid joint name 'my joint'...",
    ),
    (
        "joint name with xml chars",
        _set("joints[0].name", 'a"<b>'),
        "joints[0].name: invalid joint name...",
    ),
    ("empty joint name", _set("joints[0].name", ""), "joints[0].name: invalid joint name ''..."),
    ("joint name too long", _set("joints[0].name", "j" * 65), "joints[0].name: invalid..."),
    (
        "joint name not a string",
        _set("joints[0].name", 7),
        "joints[0].name: expected a string, got int (7)",
    ),
    (
        "duplicate joint names",
        _set("joints[2].name", "shoulder"),
        "joints[2].name: duplicate joint name 'shoulder' (also joints[0])",
    ),
    (
        "duplicate default name",
        _set("joints[0].name", "j2"),
        "joints[1].name: duplicate joint name 'j2' (also joints[0])",
    ),
    (
        "reserved joint name",
        _set("joints[0].name", "tool"),
        "joints[0].name: 'tool' is reserved for a frame of the generated model",
    ),
    (
        "pinocchio's universe",
        _set("joints[0].name", "universe"),
        "joints[0].name: 'universe' is reserved...",
    ),
    ("reserved dh name", _set("joints[1].name", "dh_3"), "joints[1].name: 'dh_3' is reserved..."),
    ("robot name with path", _set("name", "../robot"), "name: invalid robot name '../robot'..."),
    ("robot name upper case", _set("name", "Puma"), "name: invalid robot name 'Puma'..."),
    ("robot name too long", _set("name", "r" * 65), "name: invalid robot name..."),
    ("robot name missing", _set("name", DELETE), "name: field required"),
    (
        "prismatic without lower",
        _set("joints[2].lower", DELETE),
        "joints[2].lower: field required for a prismatic joint",
    ),
    (
        "prismatic without upper",
        _set("joints[2].upper", DELETE),
        "joints[2].upper: field required for a prismatic joint",
    ),
    (
        "continuous with limits",
        _set("joints[0].type", "continuous"),
        "joints[0].lower: a continuous joint has no position limits",
    ),
    ("negative radius", _set("geometry.radius", -0.01), "geometry.radius: must be >= 0, got -0.01"),
    (
        "radius not a number",
        _set("geometry.radius", "thin"),
        "geometry.radius: expected a number, got 'thin'",
    ),
    ("zero velocity", _set("joints[0].velocity", 0), "joints[0].velocity: must be > 0, got 0"),
    ("negative effort", _set("joints[1].effort", -5), "joints[1].effort: must be > 0, got -5"),
    ("unknown joint field", _set("joints[1].alfa", 3), "joints[1].alfa: unknown field..."),
    ("unknown top-level field", _set("dof", 3), "dof: unknown field..."),
    (
        "base xyz length",
        _set("base.xyz", [0, 0]),
        "base.xyz: expected a list of 3 numbers, got 2 items",
    ),
    ("tool rpy element", _set("tool.rpy", [0, "x", 0]), "tool.rpy[1]: expected a number..."),
    ("tool not a mapping", _set("tool", [0, 0, 1]), "tool: expected a mapping..."),
    ("description not a string", _set("description", 5), "description: expected a string..."),
    (
        "description too long",
        _set("description", "x" * 1001),
        "description: longer than 1000 characters",
    ),
    (
        "lone surrogate in a key",
        _set("joints[0].\ud800", 1),
        "joints[0]: keys must be valid Unicode text (a lone surrogate is not)",
    ),
    (
        "lone surrogate in a value",
        _set("joints[0].name", "j\udc00"),
        "joints[0].name: must be valid Unicode text (a lone UTF-16 surrogate is not)",
    ),
]


@pytest.mark.parametrize(
    "mutate,expected", [(m, e) for _, m, e in BAD_INPUTS], ids=[i for i, _, _ in BAD_INPUTS]
)
def test_bad_input_names_the_field(mutate, expected: str) -> None:
    doc = copy.deepcopy(base_doc())
    mutate(doc)
    with pytest.raises(DHError) as info:
        DHTable.from_dict(doc)
    message = str(info.value)
    if expected.endswith("..."):
        assert message.startswith(expected[:-3]), message
    else:
        assert message == expected
    assert "\n" not in message


@pytest.mark.parametrize("value", [None, [], "table", 3])
def test_document_must_be_a_mapping(value: Any) -> None:
    with pytest.raises(DHError, match=r"^expected a mapping"):
        DHTable.from_dict(value)


@pytest.mark.parametrize(
    "text,expected",
    [
        ("name: [unclosed\n", "invalid YAML: line 2, column 1: "),
        ("name: a\nname: b\n", "invalid YAML: line 2: duplicate key 'name'"),
        ("- 1\n- 2\n", "expected a mapping (YAML/JSON object), got list"),
        ("", "expected a mapping (YAML/JSON object), got NoneType"),
        ("name: x\n\tconvention: standard\n", "invalid YAML: "),
        ("name: x\n1: 2\n", "keys must be strings, got int (1)"),
    ],
)
def test_bad_yaml(text: str, expected: str) -> None:
    with pytest.raises(DHError) as info:
        DHTable.from_yaml(text)
    assert str(info.value).startswith(expected), str(info.value)
    assert info.value.field is None


@pytest.mark.parametrize(
    "text,expected",
    [
        ('{"name": "x",}', "invalid JSON: line 1, column 14: "),
        ('{"name": "x", "name": "y"}', "invalid JSON: duplicate key 'name'"),
        ("[1, 2]", "expected a mapping (YAML/JSON object), got list"),
        ("[" * 100_000 + "]" * 100_000, "invalid JSON: nested too deeply"),
    ],
    ids=["trailing comma", "duplicate key", "list", "deep nesting"],
)
def test_bad_json(text: str, expected: str) -> None:
    with pytest.raises(DHError) as info:
        DHTable.from_json(text)
    assert str(info.value).startswith(expected), str(info.value)


def test_json_nan_is_rejected() -> None:
    doc = json.dumps(base_doc()).replace('"d": 100', '"d": NaN')
    with pytest.raises(DHError, match=r"^joints\[2\]\.d: must be finite, got nan$"):
        DHTable.from_json(doc)


def test_from_file_errors(tmp_path: Path) -> None:
    with pytest.raises(OSError):
        DHTable.from_file(tmp_path / "missing.yaml")
    (tmp_path / "table.txt").write_text("name: x")
    with pytest.raises(DHError, match="unsupported file extension"):
        DHTable.from_file(tmp_path / "table.txt")
