"""POST /robots/package, GET /robots/{id}/files/{path}: a lab's package as it is on disk.

The packages are built here from the catalog's own Panda files (tests/packages.py); FK is
checked against yourdfpy's FK of the same URDF, hostile archives and references must be
refused with nothing left in the data directory.
"""

from __future__ import annotations

import gzip
import io
import tarfile
import warnings
import zipfile
from pathlib import Path

import pytest
import yourdfpy
from fastapi.testclient import TestClient

from app.main import create_app
from app.operations.settings import Settings
from tests.helpers import problem
from tests.packages import (
    PANDA_DIR,
    assert_fk_matches,
    huge_header_tgz,
    panda_files,
    panda_urdf,
    tar_gz_bytes,
    zip_bytes,
)

LINK0 = (PANDA_DIR / "meshes" / "collision" / "link0.stl").read_bytes()
TINY_XML = b'<package format="3"><name>tiny</name><version>1.0.0</version></package>'


def tiny_urdf(uri: str) -> bytes:
    """One revolute joint; link ``l1`` has the collision mesh ``uri``."""
    return (
        '<robot name="tiny"><link name="base"/><link name="l1"><collision><geometry>'
        f'<mesh filename="{uri}"/></geometry></collision></link>'
        '<joint name="j" type="revolute"><parent link="base"/><child link="l1"/>'
        '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        "</robot>"
    ).encode()


def tiny_files(uri: str = "meshes/link0.stl") -> dict[str, bytes]:
    return {"package.xml": TINY_XML, "robot.urdf": tiny_urdf(uri), "meshes/link0.stl": LINK0}


def upload(client: TestClient, archive: bytes, name: str = "lab", **fields: str):
    data = {"name": name, "description": "robot.urdf", **fields}
    return client.post("/robots/package", data=data, files={"archive": ("p.zip", archive)})


def robots_dir_entries(settings: Settings) -> list[str]:
    root = settings.data_dir / "robots"
    if not root.exists():
        return []
    return sorted(p.name for p in root.iterdir() if p.name not in (".lock", ".generation"))


@pytest.fixture(scope="module")
def panda_zip() -> bytes:
    return zip_bytes(panda_files())


# ------------------------------------------------------------------------- the Panda
def test_panda_zip_fk_matches_yourdfpy_and_collisions_work(
    client: TestClient, settings: Settings, panda_zip: bytes
) -> None:
    resp = upload(
        client, panda_zip, description="urdf/panda.urdf", srdf="srdf/panda.srdf", summary="lab"
    )
    assert resp.status_code == 201, resp.text
    body = resp.json()
    assert (body["source"], body["description"]) == ("package", "lab")
    assert body["has_collision_geometry"]
    assert body["files"] == {"uri_prefix": "package://files/", "url": "/robots/lab/files/"}
    assert body == client.get("/robots/lab").json()

    reference = yourdfpy.URDF.load(
        io.BytesIO(panda_urdf().encode()), load_meshes=False, load_collision_meshes=False
    )
    links = ["panda_link3", "panda_link7", "panda_hand", "panda_leftfinger", "panda_rightfinger"]
    assert_fk_matches(client, "lab", reference, links, seed=16)

    # A sphere centred on panda_link4's frame (inside the arm) touches its mesh.
    q = body["neutral"]
    center = client.post("/robots/lab/fk", json={"q": q, "frames": ["panda_link4"]}).json()
    position = center["poses"]["panda_link4"]["position"]
    ball = {"name": "ball", "shape": "sphere", "radius": 0.02, "pose": {"position": position}}
    hit = client.post("/robots/lab/collisions", json={"q": q, "obstacles": [ball]})
    assert hit.status_code == 200, hit.text
    assert hit.json()["environment_collision"]
    assert "panda_link4" in {p["a"] for p in hit.json()["pairs"] if p["b"] == "ball"}
    far = {**ball, "pose": {"position": [5.0, 5.0, 5.0]}}
    free = client.post("/robots/lab/collisions", json={"q": q, "obstacles": [far]}).json()
    assert not free["environment_collision"] and free["pairs"] == []

    # The stored URDF names every mesh package://files/<path>, served as files.
    urdf = client.get("/robots/lab/urdf").text
    assert 'filename="package://files/meshes/collision/link4.stl"' in urdf
    assert "../meshes" not in urdf
    mesh = client.get("/robots/lab/files/meshes/collision/link4.stl")
    assert mesh.status_code == 200
    assert mesh.headers["content-type"] == "model/stl"
    assert mesh.content == (PANDA_DIR / "meshes" / "collision" / "link4.stl").read_bytes()
    dae = client.head("/robots/lab/files/meshes/visual/hand.dae")
    assert dae.status_code == 200 and dae.headers["content-type"] == "model/vnd.collada+xml"
    problem(client.get("/robots/lab/files/meshes/nope.stl"), 404, "path")

    # A new app on the same data directory loads it back (meshes from the store).
    with TestClient(create_app(settings), raise_server_exceptions=False) as again:
        hit2 = again.post("/robots/lab/collisions", json={"q": q, "obstacles": [ball]})
        assert hit2.status_code == 200 and hit2.json()["environment_collision"]

    robot_dir = settings.data_dir / "robots" / "lab"
    assert (robot_dir / "files" / "meshes" / "collision" / "link4.stl").is_file()
    assert client.delete("/robots/lab").status_code == 204
    assert not robot_dir.exists()
    assert robots_dir_entries(settings) == []
    problem(client.get("/robots/lab/files/meshes/collision/link4.stl"), 404, "robot_id")


def test_panda_tar_gz_with_package_uris(client: TestClient) -> None:
    """package://<name of package.xml>/... in a tar.gz whose files are in a top folder."""
    files = panda_files(mesh_prefix="package://lab_panda/", top="lab_panda/")
    resp = client.post(
        "/robots/package",
        data={"name": "lab-tar", "description": "lab_panda/urdf/panda.urdf"},
        files={"archive": ("p.tar.gz", tar_gz_bytes(files), "application/gzip")},
    )
    assert resp.status_code == 201, resp.text
    urdf = client.get("/robots/lab-tar/urdf").text
    assert 'filename="package://files/lab_panda/meshes/collision/link0.stl"' in urdf
    got = client.get("/robots/lab-tar/files/lab_panda/meshes/collision/link0.stl")
    assert got.status_code == 200 and got.content == LINK0


# ------------------------------------------------------------------------- reference forms
@pytest.mark.parametrize(
    ("uri", "stored"),
    [
        ("meshes/link0.stl", "package://files/meshes/link0.stl"),
        ("./meshes/../meshes/link0.stl", "package://files/meshes/link0.stl"),
        ("file://meshes/link0.stl", "package://files/meshes/link0.stl"),
        ("package://tiny/meshes/link0.stl", "package://files/meshes/link0.stl"),
        (
            "package://example-robot-data/robots/panda_description/meshes/collision/link0.stl",
            "package://example-robot-data/robots/panda_description/meshes/collision/link0.stl",
        ),
    ],
)
def test_reference_forms_resolve(client: TestClient, uri: str, stored: str) -> None:
    resp = upload(client, zip_bytes(tiny_files(uri)))
    assert resp.status_code == 201, resp.text
    assert f'filename="{stored}"' in client.get("/robots/lab/urdf").text
    assert client.post("/robots/lab/collisions", json={"q": [0.0]}).status_code == 200


def test_top_folder_is_a_package_name(client: TestClient) -> None:
    files = {"arm/robot.urdf": tiny_urdf("package://arm/meshes/link0.stl")}
    files["arm/meshes/link0.stl"] = LINK0
    resp = upload(client, zip_bytes(files), description="arm/robot.urdf")
    assert resp.status_code == 201, resp.text
    assert client.get("/robots/lab/files/arm/meshes/link0.stl").content == LINK0


# ------------------------------------------------------------------------- refusals
BAD_REFERENCES = {
    "relative escape": ("../../etc/passwd", "description", "leaves the package"),
    "package escape": ("package://tiny/../../../etc/passwd", "description", "leaves the package"),
    "other package": ("package://other/meshes/link0.stl", "description", "'other'"),
    "absolute file URI": ("file:///etc/passwd", "description", "absolute file://"),
    "absolute path": ("/etc/passwd", "description", "absolute paths"),
    "http": ("http://169.254.169.254/a.stl", "description", "scheme http://"),
    "missing": ("meshes/missing.stl", "description", "not a file of the archive"),
    "catalog missing": (
        "package://example-robot-data/robots/panda_description/meshes/nope.stl",
        "description",
        "no such file",
    ),
    "garbage mesh": ("meshes/garbage.stl", "archive", "cannot be read"),
    "empty mesh": ("meshes/empty.stl", "archive", "cannot be read"),
    "unsupported format": ("meshes/link0.gltf", "description", "unsupported format"),
}


@pytest.mark.parametrize("case", list(BAD_REFERENCES))
def test_bad_mesh_references_are_422_naming_the_file(
    client: TestClient, settings: Settings, case: str
) -> None:
    uri, field, reason = BAD_REFERENCES[case]
    files = tiny_files(uri)
    files["meshes/garbage.stl"] = b"this is no mesh at all" * 10
    files["meshes/empty.stl"] = b""
    files["meshes/link0.gltf"] = b"{}"
    body = problem(upload(client, zip_bytes(files)), 422, field)
    assert uri in body["detail"] and reason in body["detail"], body["detail"]
    assert robots_dir_entries(settings) == []
    problem(client.get("/robots/lab"), 404, "robot_id")


def test_obj_material_library_outside_the_package_is_refused(
    client: TestClient, settings: Settings
) -> None:
    files = tiny_files("meshes/a.obj")
    files["meshes/a.obj"] = b"mtllib ../../../etc/passwd\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
    body = problem(upload(client, zip_bytes(files)), 422, "description")
    assert "material library" in body["detail"]
    assert robots_dir_entries(settings) == []


def _zip_with(name: str, data: bytes = b"x", mode: int | None = None) -> bytes:
    return zip_bytes({**tiny_files(), name: data}, modes={name: mode} if mode else None)


def _tar_with(kind: bytes, target: str) -> bytes:
    return tar_gz_bytes(tiny_files(), links={"meshes/evil.stl": (kind, target)})


def _zip_duplicate() -> bytes:
    """The mesh twice: the second copy would overwrite the first on extraction."""
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w") as zf:
        for name, data in tiny_files().items():
            zf.writestr(name, data)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)  # "Duplicate name"
            zf.writestr("meshes/link0.stl", b"other")
    return buf.getvalue()


def _zip_bomb() -> bytes:
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED, compresslevel=9) as zf:
        for name, data in tiny_files().items():
            zf.writestr(name, data)
        with zf.open("meshes/zeros.stl", "w", force_zip64=True) as out:
            chunk = bytes(1 << 20)
            for _ in range(300):  # 300 MiB of zeros, ~300 KiB compressed
                out.write(chunk)
    return buf.getvalue()


def _tar_chain(n: int) -> bytes:
    """The tiny package as a tar.gz whose first member follows ``n`` pax headers."""
    buf = io.BytesIO()
    with tarfile.open(fileobj=buf, mode="w:gz", format=tarfile.PAX_FORMAT) as tf:
        for name, data in tiny_files().items():
            info = tarfile.TarInfo(name)
            info.size = len(data)
            tf.addfile(info, io.BytesIO(data))
    raw = gzip.decompress(buf.getvalue())
    pax = tarfile.TarInfo("././@PaxHeader")
    pax.type, pax.size = tarfile.XHDTYPE, 12
    header = pax.tobuf(format=tarfile.USTAR_FORMAT) + b"12 comment=\n".ljust(512, b"\0")
    return gzip.compress(header * n + raw, mtime=0)


HOSTILE_ARCHIVES = {
    "zip slip": (lambda: _zip_with("../x.stl"), "'..'"),
    "zip slip deep": (lambda: _zip_with("meshes/../../x.stl"), "'..'"),
    "absolute name": (lambda: _zip_with("/etc/cron.d/x"), "absolute"),
    "drive letter": (lambda: _zip_with("C:/x.stl"), "drive"),
    "backslash": (lambda: _zip_with("..\\x.stl"), "backslash"),
    "zip symlink": (lambda: _zip_with("meshes/evil.stl", b"/etc/passwd", 0o120777), "symbolic"),
    "zip device": (lambda: _zip_with("meshes/dev", b"", 0o020644), "regular files"),
    "tar symlink": (lambda: _tar_with(tarfile.SYMTYPE, "/etc/passwd"), "symbolic"),
    "tar hardlink": (lambda: _tar_with(tarfile.LNKTYPE, "/etc/passwd"), "hard links"),
    "tar device": (lambda: _tar_with(tarfile.CHRTYPE, ""), "devices"),
    "duplicate": (_zip_duplicate, "twice"),
    "duplicate after dot": (lambda: _zip_with("./meshes/link0.stl"), "twice"),
    "zip bomb": (_zip_bomb, "more than"),
    # 250 MiB of pax header in ~250 KB: refused by its size before it is read
    "tar huge pax header": (
        lambda: huge_header_tgz(tarfile.XHDTYPE, 250 << 20, tar_gz_bytes(tiny_files())),
        "pax extended header of 262144000 bytes: the limit is 65536 bytes",
    ),
    # tarfile reads extended headers recursively: thousands in a row were a 500
    "tar header chain": (lambda: _tar_chain(3000), "9 extended headers in a row"),
    "not an archive": (lambda: b"just text, no archive", "not a zip or tar.gz"),
    "corrupt zip": (lambda: zip_bytes(tiny_files())[:-300], "zip"),
}


@pytest.mark.parametrize("case", list(HOSTILE_ARCHIVES))
def test_hostile_archives_are_refused_and_nothing_stored(
    client: TestClient, settings: Settings, case: str
) -> None:
    build, reason = HOSTILE_ARCHIVES[case]
    body = problem(upload(client, build()), 422, "archive")
    assert reason in body["detail"], body["detail"]
    assert robots_dir_entries(settings) == []
    problem(client.get("/robots/lab"), 404, "robot_id")


def test_file_count_limit_from_settings(tmp_path: Path) -> None:
    settings = Settings(data_dir=tmp_path / "data", max_package_files=5)
    files = {**tiny_files(), **{f"extra/{i}.txt": b"" for i in range(3)}}
    with TestClient(create_app(settings), raise_server_exceptions=False) as client:
        body = problem(upload(client, zip_bytes(files)), 422, "archive")
        assert "DENAVIT_MAX_PACKAGE_FILES" in body["detail"]
        assert robots_dir_entries(settings) == []
        files = {**tiny_files(), "extra/0.txt": b""}
        assert upload(client, zip_bytes(files)).status_code == 201


def test_a_hundred_thousand_files_are_refused_with_the_default_limit(
    client: TestClient, settings: Settings
) -> None:
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_STORED) as zf:
        for name, data in tiny_files().items():
            zf.writestr(name, data)
        for i in range(100_000):
            zf.writestr(f"f/{i}", b"")
    body = problem(upload(client, buf.getvalue()), 422, "archive")
    assert "100003 entries" in body["detail"]
    assert robots_dir_entries(settings) == []


def test_upload_size_limit_is_413(tmp_path: Path) -> None:
    settings = Settings(data_dir=tmp_path / "data", max_package_bytes=4096)
    with TestClient(create_app(settings), raise_server_exceptions=False) as client:
        body = problem(upload(client, zip_bytes(tiny_files())), 413, "body")
        assert "DENAVIT_MAX_PACKAGE_BYTES" in body["detail"]
        assert robots_dir_entries(settings) == []


@pytest.mark.parametrize(
    ("fields", "field"),
    [
        ({"name": "package"}, "name"),
        ({"name": "panda"}, "name"),
        ({"description": "nope.urdf"}, "description"),
        ({"description": "../robot.urdf"}, "description"),
        ({"description": "meshes/link0.stl"}, "description"),
        ({"srdf": "missing.srdf"}, "srdf"),
        ({"xacro_args": "[1, 2]"}, "xacro_args"),
        ({"ee_frame": "nowhere"}, "ee_frame"),
        ({"colour": "red"}, "colour"),
    ],
)
def test_bad_fields_are_4xx_naming_them(
    client: TestClient, settings: Settings, fields: dict, field: str
) -> None:
    resp = upload(client, zip_bytes(tiny_files()), **fields)
    assert resp.status_code in (409, 422), resp.text
    problem(resp, resp.status_code, field)
    assert robots_dir_entries(settings) == []


def test_a_bad_urdf_in_a_package_names_the_description(
    client: TestClient, settings: Settings
) -> None:
    files = tiny_files()
    files["robot.urdf"] = files["robot.urdf"].replace(b'type="revolute"', b'type="floating"')
    body = problem(upload(client, zip_bytes(files)), 422, "description")
    assert "floating" in body["detail"]
    files["robot.urdf"] = b"<robot"
    problem(upload(client, zip_bytes(files)), 422, "description")
    assert robots_dir_entries(settings) == []


def test_missing_archive_and_wrong_content_type(client: TestClient) -> None:
    form = (
        b'--b\r\nContent-Disposition: form-data; name="name"\r\n\r\nx\r\n'
        b'--b\r\nContent-Disposition: form-data; name="description"\r\n\r\na.urdf\r\n--b--\r\n'
    )
    headers = {"content-type": "multipart/form-data; boundary=b"}
    problem(client.post("/robots/package", content=form, headers=headers), 422, "archive")
    text_archive = client.post("/robots/package", data={"name": "x", "archive": "text"}, files={})
    problem(text_archive, 415, "content-type")
    problem(client.post("/robots/package", json={"name": "x"}), 415, "content-type")
    resp = client.post(
        "/robots/package",
        data={"name": "x", "description": "a.urdf"},
        files={"archive": ("a.zip", b"x"), "srdf": ("s.srdf", b"<robot/>")},
    )
    problem(resp, 422, "srdf")


# ------------------------------------------------------------------------- files route
def test_catalog_robot_files_are_served(client: TestClient) -> None:
    detail = client.get("/robots/panda").json()
    prefix = "package://example-robot-data/robots/panda_description/"
    assert detail["files"] == {"uri_prefix": prefix, "url": "/robots/panda/files/"}
    resp = client.get("/robots/panda/files/meshes/collision/link0.stl")
    assert resp.status_code == 200 and resp.content == LINK0
    assert resp.headers["content-type"] == "model/stl"
    assert client.get("/robots/panda/files/srdf/panda.srdf").status_code == 200


@pytest.mark.parametrize(
    "path",
    [
        "%2e%2e/%2e%2e/%2e%2e/etc/passwd",
        "meshes/%2e%2e/%2e%2e/ur_description/urdf/ur5_robot.urdf",
        "meshes//collision/link0.stl",
        "meshes%5c..%5c..%5cx",
    ],
)
def test_file_paths_escaping_are_refused(client: TestClient, path: str) -> None:
    resp = client.get(f"/robots/panda/files/{path}")
    assert 400 <= resp.status_code < 500, resp.text
    assert resp.headers["content-type"] == "application/problem+json"


def test_robots_without_files_answer_404(client: TestClient) -> None:
    problem(client.get("/robots/planar2/files/x.stl"), 404, "path")
    problem(client.get("/robots/nobody/files/x.stl"), 404, "robot_id")


# ------------------------------------------------------------------------- POST /robots/urdf
def test_urdf_upload_with_unresolvable_or_relative_meshes_is_422(
    client: TestClient, settings: Settings
) -> None:
    missing = "package://example-robot-data/robots/panda_description/meshes/nope.stl"
    for uri in (missing, "meshes/link0.stl", "package://nowhere/a.stl"):
        doc = tiny_urdf(uri).decode()
        body = problem(client.post("/robots/urdf", json={"name": "one", "urdf": doc}), 422, "urdf")
        assert uri in body["detail"]
    assert robots_dir_entries(settings) == []
