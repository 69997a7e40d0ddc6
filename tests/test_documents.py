"""Untrusted-document checks (app.documents): DH tables, URDF and SRDF, without HTTP."""

from __future__ import annotations

import pytest

from app.documents.dh import parse_dh_document
from app.documents.urdf import check_resource_uri
from app.kinematics.errors import InvalidInputError


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
