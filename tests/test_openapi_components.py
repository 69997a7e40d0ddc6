"""Shared types of the OpenAPI document: one ``Pose`` in and out, one component per value
set (a generated client gets one enum class per set), one ``JointPositions`` map, and the
response fields that carry a value set typed by it, not as plain strings."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.main import create_app
from app.operations.settings import Settings

REF = "#/components/schemas/"
#: Models whose ``seed`` is a random seed (an integer), not a configuration.
SEEDS = {"BuildRequest", "MapInfo"}


@pytest.fixture(scope="module")
def schema(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    """The document the app serves (built once for the module)."""
    app = create_app(Settings(data_dir=tmp_path_factory.mktemp("openapi") / "data"))
    with TestClient(app) as client:
        return client.get("/openapi.json").json()


def _walk(node: Any, path: tuple[str, ...] = ()) -> Iterator[tuple[tuple[str, ...], Any]]:
    yield path, node
    if isinstance(node, dict):
        for key, value in node.items():
            yield from _walk(value, (*path, key))
    elif isinstance(node, list):
        for i, value in enumerate(node):
            yield from _walk(value, (*path, str(i)))


def _refs(node: Any) -> set[str]:
    """The component names ``node`` refers to (through arrays, maps and unions)."""
    return {
        v["$ref"].removeprefix(REF)
        for _, v in _walk(node)
        if isinstance(v, dict) and isinstance(v.get("$ref"), str)
    }


def test_one_pose_component_in_and_out(schema) -> None:
    """Every pose property of a request or an answer is the one ``Pose``, which has no null,
    no required field and no Input/Output split."""
    components = schema["components"]["schemas"]
    assert not [n for n in components if n.endswith(("-Input", "-Output"))]
    assert not {"Target", "PoseIn", "ObstaclePose"} & set(components)
    pose = components["Pose"]
    assert set(pose["properties"]) == {"position", "orientation", "rpy", "matrix"}
    assert "required" not in pose
    assert not [p for p, v in _walk(pose) if v == "null" or (p and p[-1] == "default")]
    pose_props = {"target", "targets", "to", "via", "waypoints", "poses", "pose"}
    checked = []
    for name, component in components.items():
        for prop, node in (component.get("properties") or {}).items():
            if prop in pose_props and (name, prop) != ("PathResponse", "waypoints"):  # a count
                assert _refs(node) == {"Pose"}, (name, prop, node)
                checked.append((name, prop))
    assert {
        ("IKRequest", "target"),
        ("IKBatchRequest", "targets"),
        ("LineSegment", "to"),
        ("ArcSegment", "via"),
        ("PathRequest", "waypoints"),
        ("QueryRequest", "poses"),
        ("ObstacleIn", "pose"),
        ("ObstacleOut", "pose"),
        ("FKResponse", "poses"),
    } <= set(checked)


def test_every_value_set_is_one_named_component(schema) -> None:
    """No ``enum`` inline: each is a component of its own, and no two components hold the
    same value set (one enum class per set in a generated client)."""
    # (a header's fixed value, X-Content-Type-Options: nosniff, is no value set of a body)
    inline = [
        p
        for p, v in _walk(schema)
        if isinstance(v, dict)
        and "enum" in v
        and len(p) != 3
        and p[:2] != ("components", "headers")
    ]
    assert not inline, f"inline enums (name the value set in app/api/schemas/values.py): {inline}"
    sets: dict[tuple, str] = {}
    for name, component in schema["components"]["schemas"].items():
        if "enum" in component:
            values = tuple(sorted(component["enum"]))
            assert values not in sets, (name, sets.get(values))
            sets[values] = name
    assert {
        "IKStatus",
        "IKReason",
        "IKMode",
        "CollisionGeometry",
        "JacobianReference",
        "JacobianPart",
        "JobStatus",
    } <= set(sets.values())


def test_joint_maps_and_configurations_are_shared(schema) -> None:
    """Every joint map (``joint_positions``, a seed or a path start given by name) is the
    one ``JointPositions``; every ``q`` the one ``Configuration``."""
    components = schema["components"]["schemas"]
    maps = [
        p
        for p, v in _walk(components)
        if isinstance(v, dict)
        and isinstance(v.get("additionalProperties"), dict)
        and v["additionalProperties"].get("type") == "number"
    ]
    # Joint → limit maps of time parameterization and joint → rate maps of the dynamics
    # (velocities, accelerations: one JointRates) are not joint positions.
    assert sorted(maps) == [
        ("JointPositions",),
        ("JointRates",),
        ("TimingIn", "properties", "acceleration_limits", "anyOf", "1"),
        ("TimingIn", "properties", "velocity_limits", "anyOf", "1"),
    ]
    checked = []
    for name, component in components.items():
        for prop, node in (component.get("properties") or {}).items():
            if prop in ("joint_positions", "seed", "start") and name not in SEEDS:
                assert "JointPositions" in _refs(node), (name, prop)
                checked.append(name)
            if prop == "q":
                assert _refs(node) == {"Configuration"}, (name, prop)
    assert {"FKRequest", "IKRequest", "IKResponse", "PathRequest", "NamedStateOut"} <= set(checked)


#: Answer fields that carry a value set, and the component that types them.
TYPED_ANSWERS = {
    ("IKResponse", "status"): "IKStatus",
    ("IKResponse", "reason"): "IKReason",
    ("IKResponse", "mode"): "IKMode",
    ("IKBatchItem", "status"): "IKStatus",
    ("IKBatchItem", "reason"): "IKReason",
    ("IKBatchResponse", "mode"): "IKMode",
    ("PathResponse", "mode"): "IKMode",
    ("PathFailureOut", "reason"): "PathFailureReason",
    ("JobResponse", "status"): "JobStatus",
    ("PairOut", "kind"): "CollisionPairKind",
    ("CollisionResponse", "geometry"): "CollisionGeometry",
    ("CollisionBatchResponse", "geometry"): "CollisionGeometry",
    ("JacobianResponse", "reference"): "JacobianReference",
    ("ManipulabilityResponse", "reference"): "JacobianReference",
    ("ManipulabilityBatchResponse", "reference"): "JacobianReference",
    ("StaticsResponse", "reference"): "JacobianReference",
    ("VelocityResponse", "reference"): "TwistReference",
    ("VelocityResponse", "direction"): "VelocityDirection",
    ("ObstacleOut", "shape"): "ObstacleShape",
    ("MapInfo", "sampling"): "ReachabilitySampling",
    ("MapInfo", "self_collision"): "SelfCollisionMode",
}


@pytest.mark.parametrize(("field", "component"), sorted(TYPED_ANSWERS.items()))
def test_answer_value_sets_are_typed(schema, field, component) -> None:
    model, prop = field
    node = schema["components"]["schemas"][model]["properties"][prop]
    assert _refs(node) == {component}, node
