"""Hostile description packages and requests: each attack's reproducer, and a variant.

Every document here once cost a worker its life, a gigabyte, a host file or a 500:

- a 166-byte ASCII PLY declaring 6e6 vertices, a 226-byte binary PLY declaring 1e8 (coal's
  loader spent seconds or gigabytes on them while holding the GIL: uvicorn's supervisor
  killed the worker as hung after 5 s);
- an OBJ ``mtllib`` followed by 40 000 spaces (the reference check's own regex was
  quadratic), or naming ``../../etc/passwd`` behind a bare ``\\r`` or a ``\\`` continuation
  (the check missed it; assimp opened the file);
- an MJCF arm of 4000 bodies (Pinocchio's MJCF geometry builder), MJCF includes nested
  ~1200 deep (a ``RecursionError``: 500), a cube texture's ``fileright`` outside the
  package;
- xacro's ``$(find)`` and ``xacro.abs_filename()``, which wrote the server's staging path
  into the stored robot.

The live tests run a 2-worker server and check after every hostile request that the
worker PIDs are unchanged and their memory grew by less than :data:`RSS_BOUND_MB`.
"""

from __future__ import annotations

import struct
from collections.abc import Iterator
from pathlib import Path

import httpx
import pytest
from fastapi.testclient import TestClient

from tests.helpers import Server, descendants, problem, serve, worker_pids, worker_rss_mb
from tests.packages import PANDA_DIR, zip_bytes

LINK0 = (PANDA_DIR / "meshes" / "collision" / "link0.stl").read_bytes()
TINY_XML = b'<package format="3"><name>tiny</name><version>1.0.0</version></package>'
#: Most a worker may grow (RSS, MiB) over one hostile request and its answer.
RSS_BOUND_MB = 96


def mesh_urdf(uri: str) -> bytes:
    """One revolute joint; link ``l1`` has the collision and visual mesh ``uri``."""
    geometry = f'<geometry><mesh filename="{uri}"/></geometry>'
    return (
        f'<robot name="tiny"><link name="base"/><link name="l1"><visual>{geometry}</visual>'
        f"<collision>{geometry}</collision></link>"
        '<joint name="j" type="revolute"><parent link="base"/><child link="l1"/>'
        '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        "</robot>"
    ).encode()


def mesh_package(name: str, data: bytes, **extra: bytes) -> bytes:
    """A zip: ``robot.urdf`` whose one link's mesh is ``meshes/<name>`` = ``data``."""
    files = {"package.xml": TINY_XML, "robot.urdf": mesh_urdf(f"meshes/{name}")}
    files[f"meshes/{name}"] = data
    files.update(extra)
    return zip_bytes(files)


def post_package(http, archive: bytes, description: str = "robot.urdf", name: str = "lab"):
    return http.post(
        "/robots/package",
        data={"name": name, "description": description},
        files={"archive": ("p.zip", archive)},
    )


# ------------------------------------------------------------------------ hostile meshes
ASCII_PLY_6E6 = (
    b"ply\nformat ascii 1.0\nelement vertex 6000000\nproperty float x\nproperty float y\n"
    b"property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
    b"0 0 0\n"
)
BINARY_PLY_1E8 = (
    b"ply\nformat binary_little_endian 1.0\nelement vertex 100000000\nproperty float x\n"
    b"property float y\nproperty float z\nelement face 1\n"
    b"property list uchar int vertex_indices\nend_header\n" + struct.pack("<3f", 0, 0, 0)
)


def obj_cube(header: bytes = b"") -> bytes:
    """A unit cube as OBJ (12 triangles), ``header`` first."""
    v = b"".join(b"v %d %d %d\n" % (x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1))
    faces = (
        (1, 2, 4), (1, 4, 3), (5, 7, 8), (5, 8, 6), (1, 5, 6), (1, 6, 2),
        (3, 4, 8), (3, 8, 7), (1, 3, 7), (1, 7, 5), (2, 6, 8), (2, 8, 4),
    )  # fmt: skip
    return header + v + b"".join(b"f %d %d %d\n" % f for f in faces)


HOSTILE_MESHES = {
    # name: (file name, bytes, what the refusal says)
    "ascii_ply_6e6": ("m.ply", ASCII_PLY_6E6, "DENAVIT_MAX_MESH_VERTICES"),
    "binary_ply_1e8": ("m.ply", BINARY_PLY_1E8, "DENAVIT_MAX_MESH_VERTICES"),
    # variants: a count under the cap the file is far too short for; another format
    "ascii_ply_short": ("m.ply", ASCII_PLY_6E6.replace(b"6000000", b"900000"), "m.ply"),
    "binary_stl_lies": ("m.stl", b"\0" * 80 + struct.pack("<I", 50_000_000), "m.stl"),
    "obj_mtllib_spaces": (
        "m.obj",
        obj_cube(b"mtllib ../../x.mtl" + b" " * 40_000 + b"y.mtl\n"),
        "leaves the package",
    ),
}


@pytest.mark.parametrize("case", sorted(HOSTILE_MESHES))
def test_hostile_mesh_is_a_422_naming_the_file(client: TestClient, case: str) -> None:
    name, data, said = HOSTILE_MESHES[case]
    body = problem(post_package(client, mesh_package(name, data)), 422)
    assert said in body["detail"], body
    assert f"meshes/{name}" in body["detail"], body
    assert client.get("/robots/lab").status_code == 404


@pytest.mark.parametrize(
    "header",
    [
        b"mtllib ok.mtl\rmtllib ../../../../../../etc/passwd\n",  # bare CR ends a line
        b"mtllib ok.mtl \\\n../../../../../../etc/passwd\n",  # a continuation: one statement
        b"mtllib\t../../../../../../etc/passwd\n",
        b"  mtllib ok.mtl /etc/passwd\n",  # several libraries on one line
        b"mtllib ok.mtl\r\nusemtl a\rmtllib sub/../../../x.mtl\r\n",
    ],
)
def test_obj_material_libraries_outside_the_package_are_refused(
    client: TestClient, header: bytes
) -> None:
    archive = mesh_package("m.obj", obj_cube(header), **{"meshes/ok.mtl": b"newmtl a\n"})
    body = problem(post_package(client, archive), 422, "description")
    assert "leaves the package" in body["detail"] or "absolute" in body["detail"], body


def test_mtl_texture_outside_the_package_is_refused(client: TestClient) -> None:
    mtl = b"newmtl a\nmap_Kd -s 1 1 1 ../../../../etc/passwd\n"
    archive = mesh_package("m.obj", obj_cube(b"mtllib ok.mtl\n"), **{"meshes/ok.mtl": mtl})
    body = problem(post_package(client, archive), 422, "description")
    assert "ok.mtl" in body["detail"] and "leaves the package" in body["detail"], body


def test_dae_image_outside_the_package_is_refused(client: TestClient) -> None:
    dae = (PANDA_DIR / "meshes" / "visual" / "link0.dae").read_bytes()
    image = (
        b"<library_images><image id='i'><init_from>file:///etc/passwd</init_from></image>"
        b"</library_images>"
    )
    hostile = dae.replace(b"<library_geometries>", image + b"<library_geometries>", 1)
    assert hostile != dae
    body = problem(post_package(client, mesh_package("m.dae", hostile)), 422, "description")
    assert "m.dae" in body["detail"] and "/etc/passwd" in body["detail"], body


def test_an_obj_with_its_own_material_library_loads(client: TestClient) -> None:
    mtl = b"newmtl a\r\nKd 1 0 0\r\nmap_Kd tex/a.png\r\n"
    archive = mesh_package(
        "m.obj",
        obj_cube(b"mtllib ok.mtl\r\nusemtl a\r\n"),
        **{"meshes/ok.mtl": mtl, "meshes/tex/a.png": b"\x89PNG"},
    )
    resp = post_package(client, archive)
    assert resp.status_code == 201, resp.text


# ------------------------------------------------------------------------ MJCF
def mjcf_chain(bodies: int) -> bytes:
    """An MJCF arm of ``bodies`` nested bodies, each with a hinge and a capsule."""
    body = ""
    for i in reversed(range(bodies)):
        body = (
            f'<body name="b{i}" pos="0 0 0.1"><joint name="j{i}" type="hinge" axis="0 0 1" '
            f'range="-1 1"/><geom type="capsule" size="0.02 0.05"/>{body}</body>'
        )
    return f'<mujoco model="long"><worldbody>{body}</worldbody></mujoco>'.encode()


def mjcf_bush(bodies: int) -> bytes:
    """An MJCF arm: one root body with ``bodies`` child bodies side by side, each with a
    hinge and a capsule (shallow: no nesting limit applies)."""
    children = "".join(
        f'<body name="b{i}" pos="0 0 0.1"><joint name="j{i}" type="hinge" axis="0 0 1" '
        f'range="-1 1"/><geom type="capsule" size="0.02 0.05"/></body>'
        for i in range(bodies)
    )
    return (
        f'<mujoco model="bush"><worldbody><body name="root">{children}</body></worldbody></mujoco>'
    ).encode()


def test_mjcf_of_thousands_of_bodies_is_refused_before_pinocchio(client: TestClient) -> None:
    resp = post_package(client, zip_bytes({"arm.xml": mjcf_bush(4000)}), "arm.xml")
    body = problem(resp, 422, "description")
    assert "DENAVIT_MAX_URDF_JOINTS" in body["detail"], body


def deep_mjcf() -> bytes:
    """60 includes, each 19 bodies deep inside the previous one's innermost body: every
    file is shallow, the merged model is 1000+ levels deep."""
    files = {
        "arm.xml": b'<mujoco model="deep"><worldbody><body name="root">'
        b'<include file="i0.xml"/></body></worldbody></mujoco>'
    }
    for i in range(60):
        nest = "".join(f"<body name='b{i}_{k}'>" for k in range(19))
        nest += f'<include file="i{i + 1}.xml"/>' if i < 59 else "<geom size='0.1'/>"
        files[f"i{i}.xml"] = f"<mujoco>{nest}{'</body>' * 19}</mujoco>".encode()
    return zip_bytes(files)


def test_mjcf_includes_nested_deep_are_a_422(client: TestClient) -> None:
    body = problem(post_package(client, deep_mjcf(), "arm.xml"), 422, "description")
    assert "DENAVIT_MAX_XML_DEPTH" in body["detail"], body


@pytest.mark.parametrize(
    "attribute", ["fileright", "fileleft", "fileup", "filedown", "filefront", "fileback"]
)
def test_mjcf_cube_texture_files_outside_the_package_are_refused(
    client: TestClient, attribute: str
) -> None:
    arm = mjcf_chain(2).replace(
        b"<worldbody>",
        f'<asset><texture name="sky" type="skybox" {attribute}="../../etc/passwd"/></asset>'
        "<worldbody>".encode(),
    )
    body = problem(post_package(client, zip_bytes({"arm.xml": arm}), "arm.xml"), 422)
    assert attribute in body["detail"] and "outside the package" in body["detail"], body


# ------------------------------------------------------------------------ server paths
XACRO_PATHS = b"""<?xml version="1.0"?>
<robot name="${xacro.abs_filename('robot.urdf.xacro')}" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="base"/>
  <link name="l1"><collision><geometry>
    <mesh filename="file://$(find tiny)/meshes/link0.stl"/></geometry></collision>
    <visual><geometry><mesh filename="$(find tiny)/meshes/link0.stl"/></geometry></visual>
  </link>
  <joint name="j" type="revolute"><parent link="base"/><child link="l1"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""


def test_no_stored_field_or_file_holds_a_server_path(client: TestClient, settings) -> None:
    files = {"package.xml": TINY_XML, "robot.urdf.xacro": XACRO_PATHS, "meshes/link0.stl": LINK0}
    resp = post_package(client, zip_bytes(files), "robot.urdf.xacro")
    assert resp.status_code == 201, resp.text
    data_dir = str(Path(settings.data_dir).resolve())
    urdf = client.get("/robots/lab/urdf").text
    assert data_dir not in urdf and str(settings.data_dir) not in urdf
    assert urdf.count('filename="package://files/meshes/link0.stl"') == 2, urdf
    for path in (Path(settings.data_dir) / "robots").rglob("*"):
        if path.is_file() and path.suffix in (".urdf", ".json", ".srdf", ".yaml"):
            assert data_dir not in path.read_text(errors="replace"), path


def test_error_messages_hold_no_server_path(client: TestClient, settings) -> None:
    broken = XACRO_PATHS.replace(b"meshes/link0.stl", b"meshes/missing.stl")
    files = {"package.xml": TINY_XML, "robot.urdf.xacro": broken, "meshes/link0.stl": LINK0}
    body = problem(post_package(client, zip_bytes(files), "robot.urdf.xacro"), 422)
    assert "missing.stl" in body["detail"], body
    assert str(Path(settings.data_dir).resolve()) not in body["detail"], body
    assert ".staging" not in body["detail"], body


# ------------------------------------------------------------------------ a live server
@pytest.fixture(scope="module")
def live(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Server]:
    data = tmp_path_factory.mktemp("live-hostile")
    env = {"DENAVIT_XACRO_TIMEOUT_S": "8"}
    with serve(data, "--workers", "2", env=env) as server:
        yield server


def _assert_workers_alive(server: Server, pids: list[int], rss: dict[int, float]) -> None:
    assert worker_pids(server) == pids, "a worker was replaced"
    for pid in pids:
        grown = worker_rss_mb(pid) - rss[pid]
        assert grown < RSS_BOUND_MB, f"worker {pid} grew by {grown:.0f} MiB"


@pytest.mark.parametrize("case", sorted(HOSTILE_MESHES))
def test_hostile_meshes_kill_no_worker_and_cost_little_memory(live: Server, case: str) -> None:
    pids = worker_pids(live)
    assert len(pids) == 2
    rss = {pid: worker_rss_mb(pid) for pid in pids}
    name, data, _ = HOSTILE_MESHES[case]
    with httpx.Client(base_url=live.url, timeout=120) as http:
        for attempt in range(2):  # each worker should see one
            resp = post_package(http, mesh_package(name, data), name=f"h{attempt}")
            assert resp.status_code == 422, resp.text[:500]
        assert http.get("/health").status_code == 200
    _assert_workers_alive(live, pids, rss)


def test_mjcf_of_thousands_of_bodies_kills_no_worker(live: Server) -> None:
    pids = worker_pids(live)
    rss = {pid: worker_rss_mb(pid) for pid in pids}
    with httpx.Client(base_url=live.url, timeout=120) as http:
        for _ in range(2):
            resp = post_package(http, zip_bytes({"arm.xml": mjcf_bush(4000)}), "arm.xml")
            assert resp.status_code == 422, resp.text[:500]
    _assert_workers_alive(live, pids, rss)


def test_a_stored_hostile_mesh_cannot_kill_a_worker_through_collisions(live: Server) -> None:
    """A robot stored before the checks (its mesh swapped on disk for the 6e6 PLY): the
    unauthenticated collision check is refused; no loader sees the file."""
    with httpx.Client(base_url=live.url, timeout=120) as http:
        resp = post_package(http, mesh_package("m.ply", ply_triangle()), name="legacy")
        assert resp.status_code == 201, resp.text
        data_dir = live.data_dir
        (data_dir / "robots" / "legacy" / "files" / "meshes" / "m.ply").write_bytes(ASCII_PLY_6E6)
        pids = worker_pids(live)
        rss = {pid: worker_rss_mb(pid) for pid in pids}
        for _ in range(2):
            resp = http.post("/robots/legacy/collisions", json={"q": [0.0]})
            assert resp.status_code in (409, 422), resp.text[:500]
            assert "DENAVIT_MAX_MESH_VERTICES" in resp.json()["detail"], resp.text
        _assert_workers_alive(live, pids, rss)


def ply_triangle() -> bytes:
    return (
        b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        b"property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
        b"end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"
    )


# ------------------------------------------------------------------------ the pools
SLOW_XACRO = b"""<?xml version="1.0"?>
<robot name="slow" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="grow" params="n">
    <xacro:if value="${n > 0}"><xacro:grow n="${n - 1}"/><xacro:grow n="${n - 1}"/></xacro:if>
    <link name="x"/>
  </xacro:macro>
  <xacro:grow n="30"/>
</robot>
"""


def _expansions_running(server: Server) -> int:
    """Sandbox children (xacro expansions here) running under the server's processes."""
    return sum(
        1
        for pid in descendants(server.proc.pid)
        if b"sandbox_child" in Path(f"/proc/{pid}/cmdline").read_bytes()
    )


def test_a_compute_request_never_waits_for_uploads(tmp_path: Path) -> None:
    """Before: each expansion held one of the worker's two compute threads; four slow
    uploads made an IK request wait for them. Now uploads have their own pool."""
    import threading

    results: list[int] = []

    def slow_upload(server: Server, i: int) -> None:
        files = {"package.xml": TINY_XML, "robot.urdf.xacro": SLOW_XACRO}
        with httpx.Client(base_url=server.url, timeout=120) as http:
            resp = post_package(http, zip_bytes(files), "robot.urdf.xacro", name=f"slow{i}")
            results.append(resp.status_code)

    with serve(tmp_path, env={"DENAVIT_XACRO_TIMEOUT_S": "5"}) as server:
        threads = [threading.Thread(target=slow_upload, args=(server, i)) for i in range(4)]
        for t in threads:
            t.start()
        with httpx.Client(base_url=server.url, timeout=120) as http:
            while _expansions_running(server) < 2:  # both threads of a pool busy expanding
                assert not results, "an upload ended before the IK request was sent"
            target = http.post("/robots/ur5/fk", json={"q": [0.1] * 6}).json()
            pose = target["poses"][next(iter(target["poses"]))]
            ik = http.post(
                "/robots/ur5/ik",
                json={"target": {"position": pose["position"], "orientation": pose["orientation"]},
                      "timeout_ms": 50},
            )  # fmt: skip
            assert ik.status_code == 200, ik.text
            assert not results, "the IK answer came after an upload ended: it waited for it"
        for t in threads:
            t.join()
    assert results == [422] * 4


# ------------------------------------------------------------------------ triangles
def ply_polygon(corners: int) -> bytes:
    """One face of ``corners`` vertices (a fan of ``corners - 2`` triangles): its header
    declares 1 face, the loader makes ``corners - 2`` triangles of it."""
    import math

    points = b"".join(
        b"%r %r 0\n" % (math.cos(2 * math.pi * k / corners), math.sin(2 * math.pi * k / corners))
        for k in range(corners)
    )
    face = b"%d " % corners + b" ".join(b"%d" % k for k in range(corners)) + b"\n"
    return (
        (
            b"ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
            b"property float z\nelement face 1\nproperty list ushort int vertex_indices\n"
            b"end_header\n" % corners
        )
        + points
        + face
    )


def binary_stl(triangles: int) -> bytes:
    """A valid binary STL of ``triangles`` small triangles (fixed seed)."""
    import numpy as np

    records = np.zeros(triangles, dtype=[("data", "<f4", (12,)), ("attr", "<u2")])
    records["data"] = np.random.default_rng(0).random((triangles, 12), dtype=np.float32) * 0.01
    return b"\0" * 80 + struct.pack("<I", triangles) + records.tobytes()


def test_collision_triangles_are_bounded_per_file_and_per_robot(tmp_path: Path) -> None:
    """Per collision mesh file (what a worker reads in one hold of the GIL): declared faces
    in the header, refused before any loader; triangles the loader makes of a polygon the
    header calls one face, refused by the child. Per robot (what a worker holds): the
    loader's total. Visual meshes are bounded by DENAVIT_MAX_MESH_VERTICES only."""
    from app.main import create_app
    from app.operations.settings import Settings

    settings = Settings(
        data_dir=tmp_path / "data", max_collision_mesh_triangles=1000, max_collision_triangles=1500
    )
    per_file = "DENAVIT_MAX_COLLISION_MESH_TRIANGLES"
    with TestClient(create_app(settings), raise_server_exceptions=False) as client:
        body = problem(post_package(client, mesh_package("m.stl", binary_stl(1001))), 422)
        assert "declares 1001 faces" in body["detail"] and per_file in body["detail"], body
        body = problem(post_package(client, mesh_package("m.ply", ply_polygon(1100))), 422)
        assert "1098 triangles" in body["detail"] and per_file in body["detail"], body
        two = mesh_urdf("meshes/a.stl").replace(
            b"</robot>",
            b'<link name="l2"><collision><geometry><mesh filename="meshes/b.stl"/></geometry>'
            b'</collision></link><joint name="j2" type="fixed"><parent link="l1"/>'
            b'<child link="l2"/></joint></robot>',
        )
        files = {"package.xml": TINY_XML, "robot.urdf": two}
        files |= {"meshes/a.stl": binary_stl(800), "meshes/b.stl": binary_stl(801)}
        body = problem(post_package(client, zip_bytes(files)), 422)
        assert "1601 triangles" in body["detail"], body
        assert "DENAVIT_MAX_COLLISION_TRIANGLES" in body["detail"], body
        files["meshes/b.stl"] = binary_stl(700)
        assert post_package(client, zip_bytes(files), name="fine").status_code == 201
        visual = (
            mesh_urdf("meshes/v.stl")
            .replace(b"<collision>", b"<!--")
            .replace(b"</collision>", b"-->")
        )
        files = {"package.xml": TINY_XML, "robot.urdf": visual, "meshes/v.stl": binary_stl(5000)}
        assert post_package(client, zip_bytes(files), name="visual").status_code == 201


def test_a_robot_stored_before_the_checks_is_checked_in_the_child(tmp_path: Path) -> None:
    """A record without the loader's triangle count (stored before these checks), whose
    collision mesh the header check alone would let through: read in the child on first
    load, and refused (409) before any worker loads it."""
    import json

    from app.main import create_app
    from app.operations.settings import Settings

    settings = Settings(data_dir=tmp_path / "data", max_collision_mesh_triangles=1000)
    with TestClient(create_app(settings), raise_server_exceptions=False) as client:
        assert post_package(client, mesh_package("m.ply", ply_triangle())).status_code == 201
    record = settings.data_dir / "robots" / "lab"
    meta = json.loads((record / "robot.json").read_text())
    assert meta.pop("collision_triangles") == 1
    (record / "robot.json").write_text(json.dumps(meta))
    (record / "files" / "meshes" / "m.ply").write_bytes(ply_polygon(1500))
    with TestClient(create_app(settings), raise_server_exceptions=False) as client:
        for path in ("/robots/lab", "/robots/lab/collisions"):
            resp = client.post(path, json={"q": [0.0]}) if "coll" in path else client.get(path)
            body = problem(resp, 409, "robot_id")
            assert "DENAVIT_MAX_COLLISION_MESH_TRIANGLES" in body["detail"], body


# ------------------------------------------------------------------------ every finding, live
def _hostile_requests() -> dict[str, tuple[str, str, dict]]:
    """name → (method, path, httpx keyword arguments) of the hostile requests
    not sent by the tests above."""
    import tarfile

    from tests.packages import huge_header_tgz, tar_gz_bytes

    def package(archive: bytes, description: str = "robot.urdf") -> dict:
        return {
            "data": {"name": "h", "description": description},
            "files": {"archive": ("p.tgz", archive)},
        }

    tiny = {"package.xml": TINY_XML, "robot.urdf": mesh_urdf("meshes/m.stl")}
    tiny["meshes/m.stl"] = LINK0
    cube = mjcf_chain(2).replace(
        b"<worldbody>",
        b'<asset><texture name="s" type="skybox" fileright="../../etc/passwd"/></asset><worldbody>',
    )
    return {
        "pax header of 250 MiB": (
            "POST",
            "/robots/package",
            package(huge_header_tgz(tarfile.XHDTYPE, 250 << 20, tar_gz_bytes(tiny))),
        ),
        "obj mtllib behind a bare CR": (
            "POST",
            "/robots/package",
            package(mesh_package("m.obj", obj_cube(b"mtllib a.mtl\rmtllib ../../../etc/passwd\n"))),
        ),
        "mjcf includes 1000 deep": ("POST", "/robots/package", package(deep_mjcf(), "arm.xml")),
        "mjcf cube texture": (
            "POST",
            "/robots/package",
            package(zip_bytes({"a.xml": cube}), "a.xml"),
        ),
        "long path segment": ("GET", "/robots/panda/files/" + "a" * 300, {}),
        "long path segment, package": ("GET", "/robots/nobody/files/" + "a" * 300 + "/b", {}),
    }


def test_every_hostile_request_leaves_the_workers_alive_and_small(live: Server) -> None:
    """Each hostile request not sent above, to the live 2-worker server: a 4xx
    (never a 5xx or a dropped connection), the same worker PIDs, RSS growth bounded."""
    pids = worker_pids(live)
    rss = {pid: worker_rss_mb(pid) for pid in pids}
    with httpx.Client(base_url=live.url, timeout=120) as http:
        for name, (method, path, kwargs) in _hostile_requests().items():
            for _ in range(2):  # each worker should see one
                resp = http.request(method, path, **kwargs)
                assert 400 <= resp.status_code < 500, (name, resp.status_code, resp.text[:300])
                assert resp.headers["content-type"].startswith("application/problem+json")
            _assert_workers_alive(live, pids, rss)
