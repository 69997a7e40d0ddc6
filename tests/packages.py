"""Description packages built in the tests from the catalog's own Panda files.

:func:`panda_files` lays the Panda out as a lab ships it: ``package.xml``, ``urdf/panda.urdf``
naming its meshes by relative path (``../meshes/collision/link0.stl``), the meshes under
``meshes/``, and the SRDF; :func:`zip_bytes` and :func:`tar_gz_bytes` pack a
name → bytes mapping (with hostile entries where a test asks for them);
:func:`huge_header_tgz` puts a tar extended header of hundreds of MiB in front of a tar.gz.
"""

from __future__ import annotations

import gzip
import io
import tarfile
import zipfile
from collections.abc import Mapping

import numpy as np
import yourdfpy
from fastapi.testclient import TestClient

from app.robots.catalog import erd_share_dir

PANDA_DIR = erd_share_dir() / "example-robot-data" / "robots" / "panda_description"
CATALOG_PREFIX = "package://example-robot-data/robots/panda_description/"
PACKAGE_XML = (
    '<?xml version="1.0"?><package format="3"><name>lab_panda</name>'
    "<version>1.0.0</version><description>test</description></package>"
)


def panda_urdf(mesh_prefix: str = "../") -> str:
    """The catalog's Panda URDF with its mesh URIs rewritten to ``mesh_prefix`` + path."""
    return (PANDA_DIR / "urdf" / "panda.urdf").read_text().replace(CATALOG_PREFIX, mesh_prefix)


def panda_files(mesh_prefix: str = "../", top: str = "") -> dict[str, bytes]:
    """The Panda package: name → bytes (under the folder ``top`` when given)."""
    files = {
        "package.xml": PACKAGE_XML.encode(),
        "urdf/panda.urdf": panda_urdf(mesh_prefix).encode(),
        "srdf/panda.srdf": (PANDA_DIR / "srdf" / "panda.srdf").read_bytes(),
    }
    for mesh in sorted((PANDA_DIR / "meshes").rglob("*")):
        if mesh.is_file():
            files[mesh.relative_to(PANDA_DIR).as_posix()] = mesh.read_bytes()
    return {f"{top}{name}": data for name, data in files.items()}


def zip_bytes(files: Mapping[str, bytes], *, modes: Mapping[str, int] | None = None) -> bytes:
    """A zip of ``files``; ``modes`` sets an entry's Unix mode (e.g. a symlink's)."""
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zf:
        for name, data in files.items():
            info = zipfile.ZipInfo(name)
            info.compress_type = zipfile.ZIP_DEFLATED
            mode = (modes or {}).get(name)
            if mode is not None:
                info.external_attr = mode << 16
            zf.writestr(info, data)
    return buf.getvalue()


def tar_gz_bytes(files: Mapping[str, bytes], links: Mapping[str, tuple[bytes, str]] = {}) -> bytes:  # noqa: B006
    """A tar.gz of ``files``, plus ``links``: name → (tar type, link target)."""
    buf = io.BytesIO()
    with tarfile.open(fileobj=buf, mode="w:gz", compresslevel=1) as tf:
        for name, data in files.items():
            info = tarfile.TarInfo(name)
            info.size = len(data)
            tf.addfile(info, io.BytesIO(data))
        for name, (kind, target) in links.items():
            info = tarfile.TarInfo(name)
            info.type = kind
            info.linkname = target
            tf.addfile(info)
    return buf.getvalue()


#: 1 MiB of ``a`` as one gzip member: a gzip stream may be many members, so a tgz of
#: hundreds of MiB is built (and stored) at ~1/1000 of its size without compressing it.
A_MIB_GZ = gzip.compress(b"a" * (1 << 20), compresslevel=9, mtime=0)
PAX_KINDS = (tarfile.XHDTYPE, tarfile.XGLTYPE, tarfile.SOLARIS_XHDTYPE)


def huge_header_tgz(kind: bytes, size: int, after: bytes) -> bytes:
    """A tar.gz whose first header is an extended header (tar type ``kind``: pax ``x``,
    ``g``, Solaris ``X``, GNU ``L``, ``K``) of ``size`` bytes of ``a`` (for pax kinds one
    record ``comment=aaa…``, as tarfile parses them), then the tar.gz ``after``; ~1/1000 of
    ``size`` long."""
    info = tarfile.TarInfo("././@PaxHeader" if kind in PAX_KINDS else "././@LongLink")
    info.type, info.size = kind, size
    record = kind in PAX_KINDS
    prefix = f"{size} comment=".encode() if record else b""
    mib, rest = divmod(size - len(prefix) - record, 1 << 20)
    head = gzip.compress(info.tobuf(format=tarfile.USTAR_FORMAT) + prefix, mtime=0)
    tail = gzip.compress(b"a" * rest + b"\n" * record + bytes(-size % 512), mtime=0)
    return head + A_MIB_GZ * mib + tail + after


def assert_fk_matches(
    client: TestClient, robot_id: str, reference: yourdfpy.URDF, links: list[str], *, seed: int
) -> None:
    """FK over HTTP of 10 random configurations within the limits equals ``reference``'s
    (yourdfpy) for every link of ``links``, to 1e-12; the joints are the same, in order."""
    detail = client.get(f"/robots/{robot_id}").json()
    assert [j["name"] for j in detail["joints"]] == reference.actuated_joint_names
    lower = np.array([j["limits"]["lower"] for j in detail["joints"]])
    upper = np.array([j["limits"]["upper"] for j in detail["joints"]])
    rng = np.random.default_rng(seed)
    for _ in range(10):
        q = rng.uniform(lower, upper)
        fk = client.post(f"/robots/{robot_id}/fk", json={"q": q.tolist(), "frames": links})
        assert fk.status_code == 200, fk.text
        reference.update_cfg(q)
        for link in links:
            expected = reference.get_transform(link, reference.base_link)
            got = np.array(fk.json()["poses"][link]["matrix"])
            np.testing.assert_allclose(got, expected, rtol=0, atol=1e-12, err_msg=link)
