"""Untrusted-document checks (app.robots.documents): DH tables, URDF and SRDF, without HTTP.

Each refused document differs from an accepted one by the one thing a check guards, and
the test asserts that check's reason: a document that something else would also refuse
cannot tell whether the guard is there.
"""

from __future__ import annotations

import json

import pytest
import yaml

from app.kinematics.errors import InvalidInputError
from app.kinematics.xmldoc import XmlLimits
from app.robots.documents import dh
from app.robots.documents.dh import MalformedDocumentError, parse_dh_document
from app.robots.documents.srdf import check_srdf_document
from app.robots.documents.urdf import (
    UrdfLimits,
    build_checked_model,
    check_documents,
    check_resource_uri,
)


def joint(name: str, parent: str, child: str, jtype: str = "revolute", **attrs: str) -> str:
    """A URDF joint; ``axis``, ``xyz`` and ``limit`` (inner attributes) override defaults."""
    axis = attrs.get("axis", "0 0 1")
    limit = attrs.get("limit", 'lower="-2" upper="2"')
    lim = f'<limit {limit} effort="10" velocity="2"/>' if limit else ""
    return (
        f'<joint name="{name}" type="{jtype}"><parent link="{parent}"/><child link="{child}"/>'
        f'<origin xyz="{attrs.get("xyz", "0 0 0.5")}" rpy="0 0 0"/><axis xyz="{axis}"/>{lim}'
        "</joint>"
    )


def robot(*joints: str, links: str = "base l1 l2", extra: str = "") -> str:
    body = "".join(f'<link name="{n}"/>' for n in links.split())
    return f'<robot name="r">{body}{"".join(joints)}{extra}</robot>'


#: base --j1--> l1 --j2--> l2: accepted as it is (test_the_base_documents_are_accepted).
J1, J2 = joint("j1", "base", "l1"), joint("j2", "l1", "l2", axis="0 1 0")
GOOD = robot(J1, J2)
SRDF = '<robot name="r"><disable_collisions link1="base" link2="l2" reason="Never"/></robot>'
MESH = '<link name="l2"><visual><geometry><mesh filename="{}"/></geometry></visual></link>'


def refused(urdf: str, reason: str, *, srdf: str | None = None, field: str = "urdf", **kw):
    """Assert that check_documents refuses the documents for ``reason``, naming ``field``."""
    with pytest.raises(InvalidInputError) as err:
        check_documents(urdf, srdf, UrdfLimits(**kw))
    assert err.value.field == field
    assert reason in err.value.message, err.value.message


def test_the_base_documents_are_accepted() -> None:
    check_documents(GOOD, SRDF, UrdfLimits())
    check_documents(
        GOOD.replace('<link name="l2"/>', MESH.format("package://p/m.stl")), None, UrdfLimits()
    )
    assert build_checked_model("r", GOOD, source="upload", srdf=SRDF).n == 2


DOCTYPE = '<?xml version="1.0"?><!DOCTYPE robot>'
ENTITIES = '<?xml version="1.0"?><!DOCTYPE robot [<!ENTITY e "l2">]>'


@pytest.mark.parametrize(
    ("urdf", "reason", "limits"),
    [
        (DOCTYPE + GOOD, "DTDs and entity declarations are not accepted", {}),
        (ENTITIES + GOOD, "DTDs and entity declarations are not accepted", {}),
        (GOOD.replace('"l2"/>', '"l2"/>\x00', 1), "NUL", {}),
        (GOOD, "DENAVIT_MAX_XML_ELEMENTS", {"xml": XmlLimits(max_elements=15)}),
        (
            GOOD,
            "DENAVIT_MAX_XML_ATTRIBUTES_PER_ELEMENT",
            {"xml": XmlLimits(max_attributes_per_element=3)},
        ),
        (GOOD, "DENAVIT_MAX_XML_ATTRIBUTES", {"xml": XmlLimits(max_attributes=25)}),
        (GOOD, "DENAVIT_MAX_XML_DEPTH", {"xml": XmlLimits(max_depth=2)}),
        (GOOD, "DENAVIT_MAX_URDF_JOINTS", {"max_joints": 1}),
        (GOOD, "DENAVIT_MAX_ROBOT_DOF", {"max_dof": 1}),
    ],
)
def test_xml_refusals_and_limits(urdf: str, reason: str, limits: dict) -> None:
    refused(urdf, reason, **limits)


def test_limits_at_their_value_are_accepted() -> None:
    """GOOD has 16 elements, 26 attributes (4 at most on one), depth 3 and 2 joints."""
    xml = XmlLimits(max_elements=16, max_attributes=26, max_attributes_per_element=4, max_depth=3)
    check_documents(GOOD, None, UrdfLimits(xml=xml, max_joints=2, max_dof=2))


FIXED = '<joint name="f" type="fixed"><parent link="l2"/><child link="l3"/></joint>'
J3 = joint("j3", "l1", "l2")


@pytest.mark.parametrize(
    ("urdf", "reason"),
    [
        (GOOD.replace("robot", "robt"), "the root element must be <robot>, got <robt>"),
        (
            GOOD.replace('<link name="l2"/>', MESH.format("/etc/passwd")),
            "<mesh filename='/etc/passwd'> refused: plain paths are not allowed",
        ),
        (GOOD.replace('xyz="0 0 0.5"', 'xyz="x 0 0.5"', 1), "not a list of numbers"),
        (GOOD.replace('xyz="0 0 0.5"', 'xyz="nan 0 0.5"', 1), "numbers must be finite"),
        (GOOD.replace('xyz="0 1 0"', 'xyz="0 1"'), "expected 3 numbers, got 2"),
        (GOOD.replace('lower="-2"', 'lower="-2 -1"', 1), "expected 1 number, got 2"),
        (GOOD.replace('xyz="0 0 0.5"', 'xyz="2e6 0 0.5"', 1), "magnitudes above 1e+06"),
        (GOOD.replace('xyz="0 1 0"', 'xyz="0 1e-7 0"'), "joint 'j2': the axis is of norm 1e-07"),
        (robot(J1, joint("j2", "l1", "l2", limit="")), "a revolute joint needs <limit>"),
        (robot(J1, joint("j2", "l1", "l2", limit='lower="1" upper="-1"')), "lower (1.0) > upper"),
        (robot(J1, joint("j2", "l1", "l2", limit='lower="0" upper="1e5"')), "must lie within"),
        (GOOD.replace('<link name="l2"/>', '<link name="l2"/><link/>'), "a <link> has no name"),
        (
            GOOD.replace('<link name="l2"/>', '<link name="l2"/><link name="l1"/>'),
            "'l1' is defined twice",
        ),
        ('<robot name="r"/>', "the URDF has no <link>"),
        (robot(J1, J2.replace(' name="j2"', "")), "a <joint> has no name"),
        (robot(J1, J2.replace('"j2"', '"j1"')), "joint 'j1' is defined twice"),
        (robot(J1, joint("j2", "l1", "l2", "planar")), "type 'planar' is not supported"),
        (robot(J1, J2.replace('<parent link="l1"/>', "")), "has no <parent link=...>"),
        (robot(J1, joint("j2", "l1", "ghost")), "child link 'ghost' is not defined"),
        (robot(J1, J2, J3), "link 'l2' has two parent joints ('j2' and 'j3')"),
        (robot(J1, links="base l1 l2"), "one tree with one root; found 2 root links"),
        (
            robot(J1, joint("j2", "l2", "l3"), joint("j3", "l3", "l2"), links="base l1 l2 l3"),
            "the joints form a cycle",
        ),
        (robot(joint("j1", "base", "l1", "fixed"), links="base l1"), "no actuated joint"),
    ],
)
def test_urdf_structure_refusals_name_the_reason(urdf: str, reason: str) -> None:
    refused(urdf, reason)


@pytest.mark.parametrize(
    ("srdf", "reason"),
    [
        (SRDF.replace("robot", "robt"), "the root element must be <robot>, got <robt>"),
        (SRDF.replace('"l2"', '"nope"'), "<disable_collisions link2='nope'>: no such link"),
        (DOCTYPE + SRDF, "DTDs and entity declarations are not accepted"),
    ],
)
def test_srdf_refusals_name_the_reason(srdf: str, reason: str) -> None:
    refused(GOOD, reason, srdf=srdf, field="srdf")
    with pytest.raises(InvalidInputError) as err:
        check_srdf_document(srdf, {"base", "l1", "l2"})
    assert reason in err.value.message


def test_a_model_without_actuated_joint_is_refused_by_build_checked_model() -> None:
    urdf = robot(joint("j1", "base", "l1", "fixed"), links="base l1")
    with pytest.raises(InvalidInputError) as err:
        build_checked_model("r", urdf, source="upload", urdf_field="body")
    assert err.value.field == "body" and "no actuated joint" in err.value.message


# ---------------------------------------------------------------------- DH documents
def test_deep_flow_nesting_is_refused_before_the_yaml_parser_runs(monkeypatch) -> None:
    """PyYAML's scanner is slow on deep flow nesting: brackets are counted first."""

    def no_parse(*_a, **_k):
        raise AssertionError("the YAML parser ran")

    monkeypatch.setattr(dh.yaml, "parse", no_parse)
    with pytest.raises(MalformedDocumentError) as err:
        parse_dh_document("[" * 17 + "]" * 17, "yaml")
    assert err.value.field == "body" and "nested deeper than 16 levels" in err.value.message


@pytest.mark.parametrize("fmt", ["yaml", "json"])
def test_at_most_64_rows(fmt: str) -> None:
    def doc(rows: int) -> str:
        joints = [{"a": 1, "alpha": 0, "d": 0, "theta": 0} for _ in range(rows)]
        table = {"name": "t", "convention": "standard", "joints": joints}
        return yaml.safe_dump(table) if fmt == "yaml" else json.dumps(table)

    assert parse_dh_document(doc(64), fmt).dof == 64
    with pytest.raises(InvalidInputError) as err:
        parse_dh_document(doc(65), fmt)
    assert err.value.field == "joints" and "at most 64 rows, got 65" in err.value.message


@pytest.mark.parametrize(
    ("raised", "kind", "field", "reason"),
    [
        (RecursionError(), MalformedDocumentError, "body", "invalid YAML: nested too deeply"),
        (TypeError("odd value"), InvalidInputError, "body", "not a valid DH table (odd value)"),
    ],
)
def test_unexpected_errors_inside_dh2urdf_are_4xx(monkeypatch, raised, kind, field, reason):
    """Whatever dh2urdf misses (a recursion, a type it did not expect) is a 4xx, not a 500."""

    def boom(*_a, **_k):
        raise raised

    monkeypatch.setattr(dh.DHTable, "from_text", boom)
    with pytest.raises(kind) as err:
        parse_dh_document("name: t\n", "yaml")
    assert err.value.field == field and err.value.message == reason


@pytest.mark.parametrize(
    ("uri", "ok"),
    [
        ("package://example-robot-data/robots/ur_description/meshes/base.stl", True),
        ("package://pkg/meshes/a.dae", True),
        ("package://../../etc/passwd", False),
        ("package://pkg/../../etc/passwd", False),
        ("package://pkg/./a.stl", False),
        ("package://pkg//a.stl", False),
        ("package://pkg", False),
        ("package://pkg/%2e%2e/x", False),
        ("file:///etc/passwd", False),
        ("/etc/passwd", False),
        ("meshes/a.stl", False),
        ("../a.stl", False),
        ("http://example.org/a.stl", False),
        ("package://pkg\\..\\x", False),
        ("", False),
        ("package://user@pkg/a.stl", False),
        ("package://pkg:8080/a.stl", False),
        ("package://pkg/a b.stl", False),
        ("package://pkg/a.stl?x=1", False),
        ("Package://pkg/a.stl", False),
    ],
)
def test_mesh_uris(uri: str, ok: bool) -> None:
    assert (check_resource_uri(uri) is None) is ok


def test_dh_document_errors_name_fields() -> None:
    with pytest.raises(InvalidInputError) as err:
        parse_dh_document(
            "name: x\nconvention: standard\njoints:\n - {a: 1, alpha: 0, d: 0}\n", "yaml"
        )
    assert err.value.field == "joints.0.theta"
    with pytest.raises(InvalidInputError) as err:
        parse_dh_document("a: &x [1]\nb: *x\n", "yaml")
    assert "alias" in err.value.message
