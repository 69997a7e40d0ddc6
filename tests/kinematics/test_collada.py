"""COLLADA collision meshes read with the file's own connectivity (app/kinematics/collada.py).

coal 3.0.3's loader numbers the vertices of a node's second mesh as if they started at 0:
a file with two primitive lists (two materials) gets triangles that join the first list's
vertices. The oracle here is the file itself: the test writes each triangle's corners and
the node transforms, and computes where they land by hand.
"""

from __future__ import annotations

import math
from pathlib import Path

import coal
import numpy as np
import pytest

from app.kinematics.collada import UnsupportedCollada, read_collada
from app.kinematics.meshes import load_mesh

#: Two primitive lists in one geometry: a triangle near the origin (list 1, 3 vertices),
#: and a quad far away at x = 5 (list 2, as a polylist of one 4-gon), sharing one source.
POSITIONS = [
    (0, 0, 0), (1, 0, 0), (0, 1, 0),  # list 1: a triangle
    (5, 0, 0), (6, 0, 0), (6, 1, 0), (5, 1, 0),  # list 2: a quad
]  # fmt: skip


def _dae(node_transforms: str = "", extra_nodes: str = "", library_nodes: str = "") -> str:
    floats = " ".join(f"{v:g}" for p in POSITIONS for v in p)
    return f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="centimeter" meter="0.01"/><up_axis>Y_UP</up_axis></asset>
  <library_geometries>
    <geometry id="g"><mesh>
      <source id="g-pos"><float_array id="g-pos-a" count="21">{floats}</float_array>
        <technique_common><accessor source="#g-pos-a" count="7" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common></source>
      <source id="g-n"><float_array id="g-n-a" count="3">0 0 1</float_array>
        <technique_common><accessor source="#g-n-a" count="1" stride="3"/></technique_common>
      </source>
      <vertices id="g-v"><input semantic="POSITION" source="#g-pos"/></vertices>
      <triangles material="white" count="1">
        <input semantic="VERTEX" source="#g-v" offset="0"/>
        <input semantic="NORMAL" source="#g-n" offset="1"/>
        <p>0 0 1 0 2 0</p>
      </triangles>
      <polylist material="blue" count="1">
        <input semantic="VERTEX" source="#g-v" offset="0"/>
        <input semantic="NORMAL" source="#g-n" offset="1"/>
        <vcount>4</vcount>
        <p>3 0 4 0 5 0 6 0</p>
      </polylist>
    </mesh></geometry>
  </library_geometries>
  {library_nodes}
  <library_visual_scenes><visual_scene id="s">
    <node id="n">{node_transforms}<instance_geometry url="#g"/></node>
    {extra_nodes}
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
"""


def _corners(vertices: np.ndarray, triangles: np.ndarray) -> set[tuple]:
    return {tuple(sorted(tuple(np.round(v, 9)) for v in vertices[t])) for t in triangles}


def _collides(bvh: coal.BVHModelOBBRSS, centre: tuple[float, float, float]) -> bool:
    box = coal.Box(0.2, 0.2, 0.2)
    result = coal.CollisionResult()
    where = coal.Transform3s(np.eye(3), np.array(centre, dtype=float))
    return coal.collide(bvh, coal.Transform3s(), box, where, coal.CollisionRequest(), result) > 0


def test_both_primitive_lists_keep_their_own_vertices(tmp_path: Path) -> None:
    path = tmp_path / "two.dae"
    path.write_text(_dae())
    dae = read_collada(path)
    assert dae.shared_nodes
    vertices, triangles = dae.vertices, dae.triangles
    P = np.array(POSITIONS, dtype=float)
    expected = {
        tuple(sorted(map(tuple, P[[0, 1, 2]]))),
        tuple(sorted(map(tuple, P[[3, 4, 5]]))),  # the quad as a fan from its first corner
        tuple(sorted(map(tuple, P[[3, 5, 6]]))),
    }
    assert _corners(vertices, triangles) == expected


def test_a_box_on_the_second_list_collides_where_coal_alone_misses_it(tmp_path: Path) -> None:
    path = tmp_path / "two.dae"
    path.write_text(_dae())
    on_quad = (5.5, 0.5, 0.0)
    bvh = load_mesh(path, np.ones(3), "two.dae", "archive")
    assert _collides(bvh, on_quad)
    assert not _collides(bvh, (3.0, 0.5, 0.0))  # between the two pieces: nothing
    # coal's own loader joins the quad's triangles to the first list's vertices: the reason
    # this reader exists (if coal is fixed, this line fails: then the reader may go)
    assert not _collides(coal.MeshLoader().load(str(path)), on_quad)


def test_scale_of_the_urdf_applies(tmp_path: Path) -> None:
    path = tmp_path / "two.dae"
    path.write_text(_dae())
    bvh = load_mesh(path, np.array([2.0, 1.0, 1.0]), "two.dae", "archive")
    assert _collides(bvh, (11.0, 0.5, 0.0)) and not _collides(bvh, (5.5, 0.5, 0.0))


def test_node_transforms_compose_in_document_order_and_unit_and_up_axis_do_not_apply(
    tmp_path: Path,
) -> None:
    # translate then rotate 90° about z: a point p lands at t + Rz(90°) p
    transforms = "<translate>1 0 2</translate><rotate>0 0 1 90</rotate><scale>1 1 3</scale>"
    child = (
        '<node id="m"><matrix>1 0 0 10 0 1 0 0 0 0 1 0 0 0 0 1</matrix>'
        '<instance_node url="#lib"/></node>'
    )
    library = (
        '<library_nodes><node id="lib"><translate>0 0 1</translate>'
        '<instance_geometry url="#g"/></node></library_nodes>'
    )
    path = tmp_path / "nodes.dae"
    path.write_text(_dae(transforms, child, library))
    dae = read_collada(path)
    vertices, triangles = dae.vertices, dae.triangles
    P = np.array(POSITIONS, dtype=float)
    c, s = math.cos(math.pi / 2), math.sin(math.pi / 2)
    Rz = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    first = (Rz @ (P * [1, 1, 3]).T).T + [1, 0, 2]
    second = P + [10, 0, 1]
    expected = set()
    for Q in (first, second):
        for t in ([0, 1, 2], [3, 4, 5], [3, 5, 6]):
            expected.add(tuple(sorted(tuple(np.round(v, 9)) for v in Q[t])))
    assert _corners(vertices, triangles) == expected


def test_what_the_reader_does_not_read_leaves_it_to_coal(tmp_path: Path) -> None:
    path = tmp_path / "skin.dae"
    path.write_text(_dae(extra_nodes='<node id="k"><instance_controller url="#c"/></node>'))
    with pytest.raises(UnsupportedCollada, match="instance_controller"):
        read_collada(path)
    bvh = load_mesh(path, np.ones(3), "skin.dae", "archive")  # coal's reading
    assert bvh.num_tris > 0


def test_a_file_with_one_mesh_per_node_is_coals_own_reading(tmp_path: Path) -> None:
    text = _dae()
    start, end = text.index("      <polylist"), text.index("</polylist>") + len("</polylist>")
    path = tmp_path / "one.dae"
    path.write_text(text[:start] + text[end:])
    assert not read_collada(path).shared_nodes
    ours = load_mesh(path, np.array([1.0, 2.0, 1.0]), "one.dae", "archive")
    coals = coal.MeshLoader().load(str(path), np.array([1.0, 2.0, 1.0]))
    assert np.array_equal(ours.vertices(), coals.vertices()) and ours.num_tris == 1
