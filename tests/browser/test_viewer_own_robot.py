"""The viewer on a lab's own description package: meshes from GET /robots/{id}/files/...

The packages are uploaded through the API (POST /robots/package) as a lab would: the
catalog's Panda laid out as a ROS package (STL and Collada meshes by relative path), a
one-link robot whose mesh is a Wavefront OBJ cube, and the same cube as an MJCF robot
whose materials give the colours (MuJoCo Menagerie's visual meshes are OBJ files).
"""

from __future__ import annotations

import re

import numpy as np

from tests.browser.tools import Tab, api_fk, rendered_pose, set_q, wait_idle
from tests.packages import panda_files, zip_bytes

CUBE_OBJ = b"""o cube
v -0.05 -0.05 0
v 0.05 -0.05 0
v 0.05 0.05 0
v -0.05 0.05 0
v -0.05 -0.05 0.1
v 0.05 -0.05 0.1
v 0.05 0.05 0.1
v -0.05 0.05 0.1
f 1 3 2
f 1 4 3
f 5 6 7
f 5 7 8
f 1 2 6
f 1 6 5
f 2 3 7
f 2 7 6
f 3 4 8
f 3 8 7
f 4 1 5
f 4 5 8
"""

CUBE_URDF = b"""<?xml version="1.0"?>
<robot name="cube_arm">
  <link name="base"/>
  <link name="arm">
    <visual><geometry><mesh filename="package://cube_arm/meshes/cube.obj"/></geometry></visual>
  </link>
  <link name="tip"/>
  <joint name="j1" type="revolute">
    <parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1.5" upper="1.5" effort="1" velocity="1"/>
  </joint>
  <joint name="j2" type="fixed">
    <parent link="arm"/><child link="tip"/><origin xyz="0.3 0 0.1"/>
  </joint>
</robot>
"""

PACKAGE_XML = (
    b'<?xml version="1.0"?><package format="3"><name>cube_arm</name>'
    b"<version>1.0.0</version><description>test</description></package>"
)


def upload(tab: Tab, name: str, files: dict[str, bytes], description: str) -> None:
    resp = tab.http.post(
        "/robots/package",
        data={"name": name, "description": description},
        files={"archive": ("p.zip", zip_bytes(files))},
    )
    assert resp.status_code == 201, resp.text


def open_and_record(tab: Tab, robot_id: str) -> list[str]:
    """Open the viewer on ``robot_id``; the URL paths of every request the page made."""
    paths: list[str] = []
    tab.page.on("request", lambda r: paths.append(r.url.split("://", 1)[1].split("/", 1)[1]))
    tab.goto(f"/viewer/{robot_id}")
    wait_idle(tab)
    return paths


def test_own_panda_package_loads_its_meshes_from_the_files_route(page: Tab) -> None:
    upload(page, "lab_panda", panda_files(), "urdf/panda.urdf")
    requested = open_and_record(page, "lab_panda")
    stats = page.page.evaluate("denavit.viewer.robot.stats")
    assert stats["meshes"] == stats["loaded"] == 11 and stats["failed"] == 0, stats
    # Each distinct visual mesh file, fetched from the files route (the fingers share one).
    urdf = panda_files()["urdf/panda.urdf"].decode()
    visual = {
        f"robots/lab_panda/files/{m[3:]}" for m in re.findall(r'"(\.\./meshes/visual/[^"]+)"', urdf)
    }
    assert len(visual) == 10
    assert {p for p in requested if p.endswith((".dae", ".stl"))} == visual
    # Posed like the catalog's Panda: the same tip at the same configuration.
    q = [0.2, -0.4, 0.1, -2.0, 0.3, 1.9, 0.5, 0.01]
    set_q(page, q)
    pose = rendered_pose(page, "panda_hand_tcp")
    ref = api_fk(page, "panda", q, "panda_hand_tcp")
    np.testing.assert_allclose(pose["position"], ref["position"], atol=1e-9)
    page.shot("own-panda")
    assert page.errors() == []


def test_obj_mesh_of_an_own_package_is_drawn(page: Tab) -> None:
    files = {
        "package.xml": PACKAGE_XML,
        "urdf/cube_arm.urdf": CUBE_URDF,
        "meshes/cube.obj": CUBE_OBJ,
    }
    upload(page, "cube_arm", files, "urdf/cube_arm.urdf")
    open_and_record(page, "cube_arm")
    stats = page.page.evaluate("denavit.viewer.robot.stats")
    assert (stats["meshes"], stats["loaded"], stats["failed"]) == (1, 1, 0), stats
    # The cube's 12 triangles, as loaded by the OBJ loader.
    triangles = page.page.evaluate(
        """(() => { let n = 0; denavit.viewer.robot.root.traverse((o) => {
             if (o.isMesh) n += o.geometry.attributes.position.count / 3; }); return n; })()"""
    )
    assert triangles == 12
    page.shot("obj")
    assert page.errors() == []


CUBE_MJCF = b"""<mujoco model="cube_mjcf">
  <asset>
    <material name="orange" rgba="1 0.5 0 1"/>
    <mesh name="cube" file="cube.obj"/>
  </asset>
  <worldbody>
    <body name="base">
      <body name="arm">
        <joint name="j1" axis="0 0 1" range="-1.5 1.5"/>
        <geom type="mesh" mesh="cube" material="orange" contype="0" conaffinity="0"
            group="2" mass="1"/>
        <geom type="box" size="0.01 0.01 0.01" pos="0.3 0 0.1" rgba="0 0 1 1"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""


def test_mjcf_materials_colour_the_drawn_meshes(page: Tab) -> None:
    upload(page, "cube_mjcf", {"cube.xml": CUBE_MJCF, "cube.obj": CUBE_OBJ}, "cube.xml")
    open_and_record(page, "cube_mjcf")
    stats = page.page.evaluate("denavit.viewer.robot.stats")
    assert (stats["meshes"], stats["loaded"], stats["failed"]) == (1, 1, 0), stats
    # Every drawn mesh's colour, in linear RGB, by its triangle count (12: the OBJ cube;
    # the box primitive: urdf-loader's unit box).
    colours = page.page.evaluate(
        """(() => { const out = []; denavit.viewer.robot.root.traverse((o) => {
             if (o.isMesh) out.push([o.geometry.attributes.position.count,
                                     o.material.color.toArray()]); }); return out; })()"""
    )
    obj = [c for n, c in colours if n == 36]
    assert len(obj) == 1 and len(colours) == 2, colours
    r, g, b = obj[0]
    assert r == 1 and 0 < g < 0.6 and b == 0, obj  # orange (sRGB 0.5 is 0.21 linear)
    box = [c for n, c in colours if n != 36]
    assert box[0] == [0, 0, 1], colours
    page.shot("mjcf-colours")
    assert page.errors() == []
