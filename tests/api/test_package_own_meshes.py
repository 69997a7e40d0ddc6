"""An uploaded copy of example-robot-data's Panda package uses its own meshes.

The package is the catalog's ``panda_description`` folder as it is installed (no
package.xml; its URDF names every mesh ``package://example-robot-data/robots/
panda_description/...``), with the collision mesh of ``panda_link1`` replaced by a 2 cm
cube and a visual mesh changed. The stored URDF must name the uploaded files, the files
served at the URIs it names must be the uploaded bytes, and collision distances must be
those of the cube (computed here in closed form), not of the catalog's mesh.
"""

from __future__ import annotations

import itertools
import math
import struct

import numpy as np
import pytest
from fastapi.testclient import TestClient

from tests.packages import PANDA_DIR, zip_bytes

HALF = 0.01  # the cube's half edge (m), centred on panda_link1's origin


def cube_stl(half: float) -> bytes:
    """A binary STL of the cube [-half, half]³: 12 outward triangles."""
    triangles = []
    for axis, sign in itertools.product(range(3), (-1.0, 1.0)):
        u, v = [a for a in range(3) if a != axis]
        corners = []
        for du, dv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            p = [0.0, 0.0, 0.0]
            p[axis], p[u], p[v] = sign * half, du * half, dv * half
            corners.append(p)
        normal = [0.0, 0.0, 0.0]
        normal[axis] = sign
        a, b, c, d = corners
        for tri in ((a, b, c), (a, c, d)):
            e1, e2 = np.subtract(tri[1], tri[0]), np.subtract(tri[2], tri[0])
            if np.dot(np.cross(e1, e2), normal) < 0:
                tri = (tri[0], tri[2], tri[1])
            triangles.append((normal, tri))
    out = bytearray(b"cube".ljust(80, b" ") + struct.pack("<I", len(triangles)))
    for normal, tri in triangles:
        out += struct.pack("<12fH", *normal, *tri[0], *tri[1], *tri[2], 0)
    return bytes(out)


CUBE = cube_stl(HALF)
VISUAL = (
    (PANDA_DIR / "meshes" / "visual" / "link1.dae")
    .read_bytes()
    .replace(b"</COLLADA>", b"<!-- the lab's own copy -->\n</COLLADA>")
)


def erd_panda_files(top: str) -> dict[str, bytes]:
    """The installed panda_description folder, two meshes changed, under ``top``."""
    files = {
        p.relative_to(PANDA_DIR).as_posix(): p.read_bytes()
        for p in sorted(PANDA_DIR.rglob("*"))
        if p.is_file()
    }
    assert "package://example-robot-data/robots/panda_description/meshes/collision/link1.stl" in (
        files["urdf/panda.urdf"].decode()
    )
    assert files["meshes/collision/link1.stl"] != CUBE
    files["meshes/collision/link1.stl"] = CUBE
    files["meshes/visual/link1.dae"] = VISUAL
    return {top + name: data for name, data in files.items()}


def cube_distance(center: np.ndarray, radius: float) -> float:
    """Distance (m) between the cube [-HALF, HALF]³ and a sphere outside it."""
    return float(np.linalg.norm(center - np.clip(center, -HALF, HALF)) - radius)


@pytest.mark.parametrize("top", ["", "panda_description/"])
def test_uploaded_erd_panda_uses_its_own_meshes(client: TestClient, top: str) -> None:
    resp = client.post(
        "/robots/package",
        data={
            "name": "lab",
            "description": f"{top}urdf/panda.urdf",
            "srdf": f"{top}srdf/panda.srdf",
        },
        files={"archive": ("panda.zip", zip_bytes(erd_panda_files(top)))},
    )
    assert resp.status_code == 201, resp.text
    files = resp.json()["files"]

    # The stored URDF names the package's files, and they are served as uploaded.
    urdf = client.get("/robots/lab/urdf").text
    assert "package://example-robot-data" not in urdf
    for name, data in (("collision/link1.stl", CUBE), ("visual/link1.dae", VISUAL)):
        uri = files["uri_prefix"] + f"{top}meshes/{name}"
        assert f'filename="{uri}"' in urdf
        served = client.get(files["url"] + uri.removeprefix(files["uri_prefix"]))
        assert served.status_code == 200 and served.content == data, name

    # A ball 10 cm below panda_link1's origin, in its frame: inside the catalog's link1
    # mesh (the cylinder down to the base), 8.9 cm from the cube.
    q = resp.json()["neutral"]
    fk = client.post("/robots/lab/fk", json={"q": q, "frames": ["panda_link1"]}).json()
    pose = np.array(fk["poses"]["panda_link1"]["matrix"])
    local, radius = np.array([0.05, 0.0, -0.1]), 0.01
    center = pose[:3, :3] @ local + pose[:3, 3]
    ball = {"name": "ball", "shape": "sphere", "radius": radius, "pose": {"position": [*center]}}
    for geometry in ("mesh", "convex"):
        answer = client.post(
            "/robots/lab/collisions",
            json={"q": q, "obstacles": [ball], "distances": True, "geometry": geometry},
        )
        assert answer.status_code == 200, answer.text
        pairs = answer.json()["pairs"]
        (pair,) = [p for p in pairs if (p["a"], p["b"]) == ("panda_link1", "ball")]
        assert not pair["in_collision"], pair
        assert math.isclose(pair["distance"], cube_distance(local, radius), abs_tol=1e-6), pair
