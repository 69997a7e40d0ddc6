"""What a mesh file declares, read without a loader (app.kinematics.mesh_files).

References: trimesh writes the meshes (STL binary and ASCII, PLY binary and ASCII, OBJ) and
knows their sizes; coal's loader (assimp) counts the triangles of every catalog mesh. The
adversarial inputs are several megabytes of what once made a check quadratic (a regex over
40 000 spaces held a worker for seconds); they run in a child process with a generous
backstop, so a check that is not linear fails instead of hanging the suite.
"""

from __future__ import annotations

import struct
import subprocess
import sys
from pathlib import Path

import coal
import numpy as np
import pytest
import trimesh

from app.kinematics.mesh_files import (
    MeshFileError,
    MeshTooLarge,
    Reference,
    mesh_counts,
    mesh_references,
    statements,
)
from app.robots.catalog import erd_share_dir

CATALOG = erd_share_dir() / "example-robot-data" / "robots"
BIG = 10**9


def _write(tmp_path: Path, name: str, data: bytes) -> Path:
    path = tmp_path / name
    path.write_bytes(data)
    return path


# ------------------------------------------------------------------------------ counts
@pytest.mark.parametrize(
    ("suffix", "options"),
    [
        (".stl", {}),
        (".stl", {"file_type": "stl_ascii"}),
        (".ply", {"encoding": "binary"}),
        (".ply", {"encoding": "ascii"}),
        (".obj", {}),
    ],
)
def test_counts_equal_what_trimesh_wrote(tmp_path: Path, suffix: str, options: dict) -> None:
    mesh = trimesh.creation.icosphere(subdivisions=3)  # 642 vertices, 1280 triangles
    data = mesh.export(file_type=options.pop("file_type", suffix[1:]), **options)
    path = _write(tmp_path, f"m{suffix}", data if isinstance(data, bytes) else data.encode())
    counts = mesh_counts(path, BIG)
    assert counts.faces == len(mesh.faces)
    # STL stores three corners per triangle; the others share vertices
    assert counts.vertices == (3 * len(mesh.faces) if suffix == ".stl" else len(mesh.vertices))


def _catalog_folders() -> list[Path]:
    """The example-robot-data folders of the service's catalog robots."""
    from app.robots.catalog import load_catalog

    return sorted({CATALOG / entry.urdf.split("/", 1)[0] for entry in load_catalog().values()})


def test_catalog_meshes_declare_at_least_what_the_loader_makes() -> None:
    """Every STL, OBJ and triangle-only COLLADA mesh of the catalog robots: declared faces
    are the loader's triangles or more (assimp drops degenerate ones); never fewer."""
    checked = 0
    for path in sorted(p for folder in _catalog_folders() for p in folder.rglob("*")):
        if path.suffix.lower() not in (".stl", ".obj", ".dae") or not path.is_file():
            continue
        counts = mesh_counts(path, BIG)
        if path.suffix.lower() == ".dae" and b"<polylist" in path.read_bytes():
            continue  # a polygon is one declared face and several triangles
        bvh = coal.MeshLoader().load(str(path), np.ones(3))
        assert counts.faces >= bvh.num_tris, path
        checked += 1
    assert checked > 100


@pytest.mark.parametrize(
    ("name", "data", "error", "said"),
    [
        ("a.ply", b"ply\nformat ascii 1.0\nelement vertex 6000000\nproperty float x\n"
         b"end_header\n0\n", MeshTooLarge, "6000000 vertex elements"),
        ("a.ply", b"ply\nformat binary_little_endian 1.0\nelement vertex 900\nproperty float x\n"
         b"property float y\nproperty float z\nend_header\n" + b"\0" * 100, MeshFileError,
         "at least 10800 bytes"),
        ("a.ply", b"ply\nformat ascii 1.0\nelement vertex 900\nproperty float x\nend_header\n"
         b"0\n", MeshFileError, "at least 1800 bytes"),
        ("a.ply", b"ply\nformat ascii 1.0\nelement face 2000000\nend_header\n", MeshTooLarge,
         "2000000 face elements"),
        ("a.ply", b"ply\nformat ascii 1.0\nelement vertex 1e3\nend_header\n", MeshFileError,
         "element line"),
        ("a.ply", b"ply\n" + b" " * 70_000, MeshFileError, "end_header"),
        ("a.stl", b"\0" * 80 + struct.pack("<I", 2_000_000), MeshFileError, "needs 100000084"),
        ("a.stl", b"\0" * 80 + struct.pack("<I", 400_000) + b"\0" * 20_000_000, MeshTooLarge,
         "1200000 vertices"),
        ("a.stl", b"", MeshFileError, "the file has 0"),
        ("a.obj", b"v 0 0 0\n" * 1_000_001, MeshTooLarge, "1000001 vertices"),
        ("a.dae", b"<COLLADA><!DOCTYPE x></COLLADA>", MeshFileError, "not a valid COLLADA"),
        ("a.dae", b'<!DOCTYPE x [<!ENTITY a "b">]><COLLADA/>', MeshFileError, "DTDs"),
        ("a.dae", b"<COLLADA><triangles count='x'/></COLLADA>", MeshFileError, "count='x'"),
        ("a.dae", b"<COLLADA><triangles count='3000000'/></COLLADA>", MeshTooLarge,
         "3000000 faces"),
    ],
)  # fmt: skip
def test_a_header_beyond_the_file_or_the_limit_is_refused(
    tmp_path: Path, name: str, data: bytes, error: type, said: str
) -> None:
    with pytest.raises(error) as info:
        mesh_counts(_write(tmp_path, name, data), 1_000_000)
    assert said in str(info.value)
    assert str(tmp_path) not in str(info.value)


def test_collada_positions_and_primitives_are_counted(tmp_path: Path) -> None:
    dae = b"""<COLLADA><library_geometries><geometry><mesh>
      <source id="pos"><float_array count="9">0 0 0 1 0 0 0 1 0</float_array>
        <technique_common><accessor source="#arr" count="3" stride="3"/></technique_common>
      </source>
      <source id="nrm"><float_array count="3">0 0 1</float_array>
        <technique_common><accessor count="1" stride="3"/></technique_common></source>
      <vertices id="v"><input semantic="POSITION" source="#pos"/></vertices>
      <triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles>
      <polylist count="2"><vcount>3 3</vcount><p>0 1 2 0 1 2</p></polylist>
    </mesh></geometry></library_geometries></COLLADA>"""
    counts = mesh_counts(_write(tmp_path, "m.dae", dae), BIG)
    assert (counts.vertices, counts.faces) == (3, 3)


# ------------------------------------------------------------------------------ references
def test_obj_statements_in_both_views(tmp_path: Path) -> None:
    data = (
        b"# comment\rmtllib a.mtl\r\n"  # a bare CR ends the comment
        b"mtllib b.mtl \\\nc.mtl\n"  # continued: b.mtl c.mtl on one statement
        b"mtllib\td e.mtl\f"  # a form feed ends a line too
        b"v 0 0 0\x00mtllib f.mtl"  # so does NUL; no final newline
    )
    path = _write(tmp_path, "m.obj", data)
    names = {r.name for r in mesh_references(path)}
    assert {"a.mtl", "b.mtl", "c.mtl", "b.mtl c.mtl", "d", "e.mtl", "d e.mtl", "f.mtl"} <= names
    assert all(r.what == "mtllib" for r in mesh_references(path))
    assert [b"v", b"0", b"0", b"0"] in list(statements(path))


def test_mtl_textures_every_word_but_options(tmp_path: Path) -> None:
    path = _write(
        tmp_path,
        "m.mtl",
        b"newmtl a\nmap_Kd -s 1 1 1 -clamp on tex/a.png\nbump -bm 2 ../b.png\nKd 1 0 0\n"
        b"refl -type sphere c.png\nMAP_KA d.png\n",
    )
    names = {r.name for r in mesh_references(path)}
    assert {"tex/a.png", "../b.png", "c.png", "d.png", "sphere"} <= names
    assert not {"-s", "-clamp", "-bm", "-type"} & names
    assert "newmtl" not in names and "a" not in names


def test_collada_image_sources_and_external_urls(tmp_path: Path) -> None:
    dae = b"""<COLLADA>
      <library_images>
        <image id="i1"><init_from>textures/a%20b.png</init_from></image>
        <image id="i2"><init_from><ref>file:///etc/passwd</ref></init_from></image>
      </library_images>
      <library_effects><effect id="e"><profile_COMMON><newparam sid="s"><surface type="2D">
        <init_from>i1</init_from></surface></newparam></profile_COMMON></effect></library_effects>
      <library_visual_scenes><visual_scene id="v"><node>
        <instance_geometry url="#g"/><instance_geometry url="other.dae#g"/>
      </node></visual_scene></library_visual_scenes></COLLADA>"""
    refs = mesh_references(_write(tmp_path, "m.dae", dae))
    assert Reference("image", "textures/a%20b.png") in refs
    assert Reference("image", "file:///etc/passwd") in refs
    assert Reference("url", "other.dae#g") in refs
    assert all(r.name not in ("i1", "#g") for r in refs)  # an image id, a local reference


def test_ply_texture_comment(tmp_path: Path) -> None:
    data = (
        b"ply\nformat ascii 1.0\ncomment TextureFile ../../secret.png\nelement vertex 0\n"
        b"end_header\n"
    )
    assert mesh_references(_write(tmp_path, "m.ply", data)) == [
        Reference("texture", "../../secret.png")
    ]


def test_a_line_longer_than_a_mebibyte_is_refused(tmp_path: Path) -> None:
    path = _write(tmp_path, "m.obj", b"mtllib " + b"a" * (2 << 20) + b"\n")
    with pytest.raises(MeshFileError, match="longer than"):
        mesh_references(path)


# ------------------------------------------------------------------------------ linear
ADVERSARIAL = r"""
import sys
from pathlib import Path
from app.kinematics.mesh_files import mesh_counts, mesh_references, MeshFileError

folder = Path(sys.argv[1])
n = 4 << 20
cases = {
    "spaces.obj": b"mtllib a" + b" " * (n // 2) + b"b\n" + b"mtllib" + b"\t " * (n // 4),
    "cr.obj": b"mtllib a\r" * (n // 9),
    "continued.obj": b"mtllib \\\n" * (n // 9),
    "backslashes.obj": b"\\" * (1 << 19) + b"\n" + b"mtllib a \\ \\ \\\n" * (n // 16),
    "faces.obj": b"f" + b" 1" * (1 << 19) + b"\n",
    "spaces.mtl": b"map_Kd" + b" -s" * (n // 3),
    "words.stl": b"solid " + b"vertexvertex" * (n // 12),
    "header.ply": b"ply\nformat ascii 1.0\n" + b"comment " * 8000 + b"\nend_header\n",
    "deep.dae": b"<a>" * 200_000 + b"</a>" * 200_000,
    "text.dae": b"<COLLADA><image><init_from>" + b"x " * (n // 2) + b"</init_from></image>",
}
for name, data in cases.items():
    path = folder / name
    path.write_bytes(data)
    for check in (lambda p: mesh_counts(p, 10**9), mesh_references):
        try:
            check(path)
        except MeshFileError:
            pass
print("ok")
"""


def test_every_check_is_linear_on_adversarial_lengths(tmp_path: Path) -> None:
    """Megabytes of spaces, bare CRs, continuations, backslashes, nesting: each check reads
    them in well under the backstop (a quadratic one would not finish for hours)."""
    root = Path(__file__).resolve().parents[2]
    out = subprocess.run(
        [sys.executable, "-c", ADVERSARIAL, str(tmp_path)],
        cwd=root,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert out.returncode == 0 and out.stdout.strip() == "ok", out.stderr[-2000:]
