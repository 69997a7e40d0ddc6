"""``file://$(find pkg)/…`` meshes (UFactory's xarm_description, UR's ``force_abs_paths``)
resolve like ``package://``; every other absolute reference stays refused, and no refusal
of the upload path shows a server path (the data directory, a temporary directory, the
sandbox's code).

Reference for the accepted packages: yourdfpy's FK of the catalog's Panda (the same URDF
with its meshes by ``package://``), and the stored URDF naming each mesh as the canonical
``package://files/<path in the archive>``.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import pytest
import yourdfpy
from fastapi.testclient import TestClient

from app.kinematics.errors import InvalidInputError
from app.robots.documents import package as package_module
from app.robots.documents.package import _Resolver
from tests.helpers import ROOT, problem
from tests.packages import PANDA_DIR, assert_fk_matches, panda_files, zip_bytes

LINK0 = (PANDA_DIR / "meshes" / "collision" / "link0.stl").read_bytes()
TINY_XML = b'<package format="3"><name>tiny</name><version>1.0.0</version></package>'


def _post(client: TestClient, files: dict[str, bytes], description: str, **fields: str):
    return client.post(
        "/robots/package",
        data={"name": "lab", "description": description, **fields},
        files={"archive": ("lab.zip", zip_bytes(files), "application/zip")},
    )


@pytest.mark.parametrize(
    ("top", "package", "prefix"),
    [
        ("panda_ws/", "lab_panda", "file://$(find lab_panda)/"),  # by package.xml <name>
        ("panda_ws/", "lab_panda", "$(find lab_panda)/"),
        ("my_arm/", "my_arm", "file://$(find my_arm)/"),  # by top folder (no package.xml)
        ("my_arm/", "my_arm", "$(find my_arm)/"),
        # xArm's xacro writes file:///$(find xarm_description)/...: four slashes once expanded
        ("my_arm/", "my_arm", "file:///$(find my_arm)/"),
    ],
    ids=[
        "file-find-by-manifest",
        "find-by-manifest",
        "file-find-by-folder",
        "find-by-folder",
        "file-slash-find",
    ],
)
def test_find_mesh_paths_resolve_inside_the_package(
    client: TestClient, top: str, package: str, prefix: str
) -> None:
    files = panda_files(prefix, top)
    files[f"{top}urdf/panda.urdf.xacro"] = files.pop(f"{top}urdf/panda.urdf")
    if package != "lab_panda":
        del files[f"{top}package.xml"]
    r = _post(client, files, f"{top}urdf/panda.urdf.xacro")
    assert r.status_code == 201, r.text
    urdf = client.get("/robots/lab/urdf").text
    assert "file://" not in urdf and "/package/" not in urdf
    assert f'filename="package://files/{top}meshes/collision/link0.stl"' in urdf
    reference = yourdfpy.URDF.load(
        str(PANDA_DIR / "urdf" / "panda.urdf"), load_meshes=False, build_scene_graph=True
    )
    assert_fk_matches(client, "lab", reference, ["panda_link8", "panda_hand"], seed=7)


XACRO = """<?xml version="1.0"?>
<robot name="tiny" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="base"/>
  <link name="l1"><collision><geometry><mesh filename="{mesh}"/></geometry></collision></link>
  <joint name="j" type="revolute"><parent link="base"/><child link="l1"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  {extra}
</robot>
"""


def _tiny(mesh: str = "file://$(find tiny)/meshes/link0.stl", extra: str = "") -> bytes:
    return XACRO.format(mesh=mesh, extra=extra).encode()


def _files(description: bytes, **more: bytes) -> dict[str, bytes]:
    return {"tiny/package.xml": TINY_XML, "tiny/robot.urdf.xacro": description,
            "tiny/meshes/link0.stl": LINK0, **more}  # fmt: skip


#: (files, description, srdf, what the detail must say): one refusal of each kind the
#: upload path has, each with the unpacked package somewhere under the data directory.
REFUSALS = {
    "file-outside": (_files(_tiny("file:///etc/passwd")), None, "absolute file://"),
    "file-outside-slashes": (_files(_tiny("file:////etc/passwd")), None, "absolute file://"),
    "find-escapes": (_files(_tiny("file://$(find tiny)/../../x.stl")), None, "leaves the package"),
    "find-missing": (_files(_tiny("file://$(find tiny)/meshes/no.stl")), None, "not a file"),
    "find-folder": (_files(_tiny("file://$(find tiny)/meshes")), None, "not a file"),
    "plain-absolute": (_files(_tiny("/usr/share/x.stl")), None, "absolute paths"),
    "find-unknown": (_files(_tiny("$(find other)/m.stl")), None, "other"),
    "include-missing": (
        _files(_tiny(extra='<xacro:include filename="$(find tiny)/nope.xacro"/>')),
        None,
        "nope",
    ),
    "include-outside": (
        _files(_tiny(extra='<xacro:include filename="/etc/hostname"/>')),
        None,
        "outside",
    ),
    "bad-xml": (_files(b"<robot><link></robot>"), None, "robot.urdf.xacro"),
    "bad-mesh": (
        _files(_tiny("file://$(find tiny)/meshes/bad.stl"), **{"tiny/meshes/bad.stl": b"x" * 90}),
        None,
        "bad.stl",
    ),
    "srdf-missing": (_files(_tiny()), "tiny/nope.srdf", "nope.srdf"),
    "srdf-bad": (_files(_tiny(), **{"tiny/r.srdf": b"<robot><group"}), "tiny/r.srdf", "not well"),
}


@pytest.mark.parametrize("case", list(REFUSALS))
def test_refusals_show_no_server_path(client: TestClient, settings, case: str) -> None:
    files, srdf, words = REFUSALS[case]
    fields = {"srdf": srdf} if srdf else {}
    body = problem(_post(client, files, "tiny/robot.urdf.xacro", **fields), 422)
    detail = body["detail"]
    assert words in detail, detail
    for server_path in (
        str(Path(settings.data_dir).resolve()),
        str(settings.data_dir),
        tempfile.gettempdir() + "/",
        str(ROOT),
        ".staging",
        "/project/",
    ):
        assert server_path not in detail, (server_path, detail)
    assert client.get("/robots/lab").status_code == 404


def test_a_mesh_file_that_cannot_be_read_names_no_server_path(tmp_path: Path, monkeypatch):
    """An OSError while reading a mesh's named files carries its path: not in the message."""
    (tmp_path / "m.obj").write_text("mtllib a.mtl\n")

    def unreadable(path: Path):
        raise PermissionError(13, "Permission denied", str(path))

    monkeypatch.setattr(package_module, "mesh_references", unreadable)
    resolver = _Resolver(tmp_path, "", {}, tmp_path, "description")
    with pytest.raises(InvalidInputError) as info:
        resolver.check_named_files("m.obj", tmp_path / "m.obj")
    assert "Permission denied" in info.value.message
    assert str(tmp_path) not in info.value.message
