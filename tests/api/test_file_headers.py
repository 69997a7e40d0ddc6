"""The headers of answers that carry client-supplied documents, and nosniff everywhere.

GET (and HEAD) /robots/{robot_id}/files/{path}, GET /robots/{robot_id}/urdf and the YAML
of GET /robots/{robot_id}/dh answer with exactly: ``Content-Security-Policy: default-src
'none'; sandbox``, ``X-Content-Type-Options: nosniff`` (once) and, for every type but
PNG and JPEG, ``Content-Disposition: attachment`` with the file's name (RFC 6266). The
browser side of it (nothing runs, the viewer still loads) is tests/browser/
test_viewer_files_safe.py. A path the file system cannot hold is a 404, never a 500.
"""

from __future__ import annotations

import email.message
import email.utils
from collections.abc import Iterator

import httpx
import pytest
from fastapi.testclient import TestClient

from app.api.untrusted import content_disposition
from app.main import create_app
from app.operations.settings import Settings
from tests.helpers import problem
from tests.packages import PANDA_DIR, zip_bytes

SANDBOX = "default-src 'none'; sandbox"
LINK0 = (PANDA_DIR / "meshes" / "collision" / "link0.stl").read_bytes()
ROBOT_URDF = (
    b'<robot name="files"><link name="base"/><link name="l1"><collision><geometry>'
    b'<mesh filename="meshes/link0.stl"/></geometry></collision></link>'
    b'<joint name="j" type="revolute"><parent link="base"/><child link="l1"/>'
    b'<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
    b"</robot>"
)
PNG = b"\x89PNG\r\n\x1a\n" + b"\0" * 16  # the bytes are served, never decoded

#: Package files by path: (content, content type, shown inline when opened).
SERVED = {
    "meshes/link0.stl": (LINK0, "model/stl", False),
    "meshes/arm.dae": (b"<COLLADA/>", "model/vnd.collada+xml", False),
    "meshes/arm.obj": (b"v 0 0 0\n", "model/obj", False),
    "meshes/arm.ply": (b"ply\n", "application/octet-stream", False),
    "textures/skin.png": (PNG, "image/png", True),
    "textures/skin.jpg": (b"\xff\xd8\xff\xe0", "image/jpeg", True),
    "textures/skin.JPEG": (b"\xff\xd8\xff\xe0", "image/jpeg", True),
    "robot.urdf": (ROBOT_URDF, "application/xml", False),
    "urdf/arm.xacro": (b"<robot/>", "application/xml", False),
    "srdf/arm.srdf": (b"<robot/>", "application/xml", False),
    "package.xml": (b'<package format="3"><name>files</name></package>', "application/xml", False),
    "doc/page.html": (b"<script>alert(1)</script>", "application/octet-stream", False),
    "doc/page.xhtml": (b"<html/>", "application/octet-stream", False),
    "doc/picture.svg": (b"<svg/>", "application/octet-stream", False),
    "doc/notes.txt": (b"hello", "application/octet-stream", False),
    "doc/README": (b"hello", "application/octet-stream", False),
    'doc/caf\u00e9 "menu" 100%.xml': (b"<x/>", "application/xml", False),
}


def package_headers_ok(resp: httpx.Response, name: str, media: str, inline: bool) -> None:
    """The exact headers of a client-supplied file answer named ``name``."""
    assert resp.headers["content-type"] == media
    assert resp.headers.get_list("x-content-type-options") == ["nosniff"]
    assert resp.headers.get_list("content-security-policy") == [SANDBOX]
    if inline:
        assert "content-disposition" not in resp.headers
    else:
        assert resp.headers.get_list("content-disposition") == [content_disposition(name)]
        assert resp.headers["content-disposition"].startswith("attachment; filename=")


@pytest.fixture
def files_client(client: TestClient) -> Iterator[TestClient]:
    """The client, with the robot ``files`` (a package of every served type) added."""
    archive = zip_bytes({path: data for path, (data, _, _) in SERVED.items()})
    resp = client.post(
        "/robots/package",
        data={"name": "files", "description": "robot.urdf"},
        files={"archive": ("p.zip", archive)},
    )
    assert resp.status_code == 201, resp.text
    yield client


# ------------------------------------------------------------------------- the files route
def test_every_package_file_type_gets_the_document_headers(files_client: TestClient) -> None:
    for path, (data, media, inline) in SERVED.items():
        name = path.rsplit("/", 1)[-1]
        got = files_client.get(f"/robots/files/files/{path}")
        assert got.status_code == 200, (path, got.text)
        assert got.content == data, path
        package_headers_ok(got, name, media, inline)
        head = files_client.head(f"/robots/files/files/{path}")
        assert head.status_code == 200 and head.content == b"", path
        package_headers_ok(head, name, media, inline)
        assert head.headers["content-length"] == str(len(data))


@pytest.mark.parametrize(
    ("path", "media"),
    [
        ("meshes/collision/link0.stl", "model/stl"),
        ("meshes/visual/link0.dae", "model/vnd.collada+xml"),
        ("srdf/panda.srdf", "application/xml"),
        ("urdf/panda.urdf", "application/xml"),
        ("README.md", "application/octet-stream"),
    ],
)
def test_catalog_files_get_the_document_headers(client: TestClient, path: str, media: str) -> None:
    name = path.rsplit("/", 1)[-1]
    for resp in (
        client.get(f"/robots/panda/files/{path}"),
        client.head(f"/robots/panda/files/{path}"),
    ):
        assert resp.status_code == 200, resp.text
        package_headers_ok(resp, name, media, inline=False)
    assert client.get(f"/robots/panda/files/{path}").content == (PANDA_DIR / path).read_bytes()


def test_byte_ranges_carry_the_headers_and_bad_ranges_are_problems(client: TestClient) -> None:
    url = "/robots/panda/files/srdf/panda.srdf"
    whole = (PANDA_DIR / "srdf" / "panda.srdf").read_bytes()
    part = client.get(url, headers={"Range": "bytes=0-9"})
    assert part.status_code == 206 and part.content == whole[:10]
    package_headers_ok(part, "panda.srdf", "application/xml", inline=False)
    assert part.headers["content-range"] == f"bytes 0-9/{len(whole)}"
    parts = client.get(url, headers={"Range": "bytes=0-1,5-6"})
    assert parts.status_code == 206
    assert parts.headers["content-type"].startswith("multipart/byteranges; boundary=")
    assert parts.headers.get_list("content-security-policy") == [SANDBOX]
    assert parts.headers["content-disposition"] == 'attachment; filename="panda.srdf"'
    head = client.head(url, headers={"Range": "bytes=0-9"})
    assert head.status_code == 206 and head.content == b""
    package_headers_ok(head, "panda.srdf", "application/xml", inline=False)

    for bad in ("bytes=x", "lines=0-9", "bytes=9-1"):
        refused = client.get(url, headers={"Range": bad})
        problem(refused, 400, "range")
        assert refused.headers["content-security-policy"] == SANDBOX
    outside = client.get(url, headers={"Range": f"bytes={len(whole)}-"})
    problem(outside, 416, "range")
    assert outside.headers["content-range"] == f"bytes */{len(whole)}"
    # A stale If-Range: the whole file, as RFC 9110 says (the Range is not even read).
    stale = client.get(url, headers={"Range": "bytes=x", "If-Range": '"stale"'})
    assert stale.status_code == 200 and stale.content == whole


@pytest.mark.parametrize(
    ("name", "fallback"),
    [
        ("link0.stl", None),
        ("caf\u00e9.dae", "caf_.dae"),
        ('say "hi".xml', "say _hi_.xml"),
        ("back\\slash.xml", "back_slash.xml"),
        ("100%.xml", "100_.xml"),
        ("\u65e5\u672c \U0001f916.urdf", "__ _.urdf"),
        ("line\r\nbreak.xml", "line__break.xml"),
        ("semi;colon, comma.xml", None),
    ],
)
def test_content_disposition_names_the_file_safely(name: str, fallback: str | None) -> None:
    value = content_disposition(name)
    assert value.isascii() and "\r" not in value and "\n" not in value
    assert value.startswith(f'attachment; filename="{fallback or name}"')
    assert ("filename*=UTF-8''" in value) == (fallback is not None)
    # A standard parser (RFC 2231) reads the exact name back from filename* when there is
    # one (RFC 6266: a client that knows filename* takes it over filename).
    msg = email.message.Message()
    msg["Content-Disposition"] = value
    params = msg.get_params(header="content-disposition")
    assert params[0] == ("attachment", "")
    names = [v for k, v in params if k == "filename"]
    assert len(names) == (1 if fallback is None else 2)
    assert email.utils.collapse_rfc2231_value(names[-1]) == name


def test_non_ascii_file_names_round_trip(files_client: TestClient) -> None:
    path = 'doc/caf\u00e9 "menu" 100%.xml'
    resp = files_client.get(f"/robots/files/files/{path}")
    assert resp.status_code == 200 and resp.content == b"<x/>"
    assert resp.headers["content-disposition"] == (
        'attachment; filename="caf_ _menu_ 100_.xml"; '
        "filename*=UTF-8''caf%C3%A9%20%22menu%22%20100%25.xml"
    )


# ------------------------------------------------------------------------- long paths
@pytest.mark.parametrize("token", [None, "a-token-for-writes"])
@pytest.mark.parametrize(
    "path",
    [
        "x" * 300,
        "meshes/" + "x" * 300 + ".stl",
        "\u00e9" * 128,  # 128 characters, 256 bytes
        "/".join(["y" * 250] * 20),  # segments the OS takes, a path it does not
    ],
    ids=["segment", "nested", "bytes", "deep"],
)
def test_paths_the_file_system_cannot_hold_are_404(
    settings: Settings, token: str | None, path: str
) -> None:
    app = create_app(settings.model_copy(update={"api_token": token}))
    with TestClient(app, raise_server_exceptions=False) as client:
        archive = zip_bytes({"robot.urdf": ROBOT_URDF, "meshes/link0.stl": LINK0})
        headers = {"Authorization": f"Bearer {token}"} if token else {}
        resp = client.post(
            "/robots/package",
            data={"name": "lab", "description": "robot.urdf"},
            files={"archive": ("p.zip", archive)},
            headers=headers,
        )
        assert resp.status_code == 201, resp.text
        for robot in ("panda", "lab"):
            problem(client.get(f"/robots/{robot}/files/{path}"), 404, "path")
            assert client.head(f"/robots/{robot}/files/{path}").status_code == 404


# ------------------------------------------------------------------------- /urdf and /dh
def test_urdf_of_every_robot_is_a_sandboxed_download(files_client: TestClient) -> None:
    doc = ROBOT_URDF.decode().replace(
        "meshes/link0.stl",
        "package://example-robot-data/robots/panda_description/meshes/collision/link0.stl",
    )
    assert files_client.post("/robots/urdf", json={"name": "up", "urdf": doc}).status_code == 201
    for robot in ("panda", "planar2", "files", "up"):
        for resp in (
            files_client.get(f"/robots/{robot}/urdf"),
            files_client.head(f"/robots/{robot}/urdf"),
        ):
            assert resp.status_code == 200, resp.text
            package_headers_ok(resp, f"{robot}.urdf", "application/xml", inline=False)
            assert resp.headers["content-disposition"] == f'attachment; filename="{robot}.urdf"'
    assert files_client.get("/robots/up/urdf").text == doc  # as uploaded


def test_dh_yaml_is_a_sandboxed_download_and_json_an_answer(client: TestClient) -> None:
    yaml = client.get("/robots/planar2/dh", headers={"Accept": "application/yaml"})
    assert yaml.status_code == 200
    package_headers_ok(yaml, "planar2.yaml", "application/yaml", inline=False)
    json = client.get("/robots/planar2/dh")
    assert json.headers["content-type"] == "application/json"
    assert json.headers.get_list("x-content-type-options") == ["nosniff"]
    assert "content-disposition" not in json.headers


# ------------------------------------------------------------------------- nosniff
@pytest.mark.parametrize(
    ("method", "path"),
    [
        ("GET", "/health"),
        ("GET", "/robots"),
        ("GET", "/robots/nobody"),
        ("DELETE", "/health"),
        ("GET", "/metrics"),
        ("GET", "/viewer"),
        ("GET", "/static/viewer/api.js"),
        ("GET", "/static/nothing.js"),
        ("GET", "/docs"),
        ("GET", "/openapi.json"),
        ("POST", "/robots/panda/fk"),
        ("GET", "/nowhere"),
    ],
)
def test_every_answer_says_nosniff_once(client: TestClient, method: str, path: str) -> None:
    resp = client.request(method, path, content=b"{")
    assert resp.headers.get_list("x-content-type-options") == ["nosniff"], resp.status_code
