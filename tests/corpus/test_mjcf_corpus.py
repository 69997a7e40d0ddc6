"""MuJoCo Menagerie descriptions uploaded as a lab uploads them, checked against MuJoCo.

Each case folder (``tests/corpus/menagerie_*``, see its ``PROVENANCE.md``) is packed and
sent to POST /robots/package as it is published, once per upload (a module-scoped app on a
temporary data directory). Every check compares the service's HTTP answers with MuJoCo's
own compiler and kinematics (:mod:`tests.corpus.mjcf_reference`), never with the service's
code:

- upload: 201; every mesh file the MJCF names is in the stored URDF (``package://files/…``)
  with MuJoCo's scale, and GET /robots/{id}/files/<path> serves its bytes;
- FK: every MJCF body and site, by name, on 20 random configurations within the limits
  (fixed seed), equals MuJoCo's ``mj_kinematics`` pose to 1e-9;
- IK: 100 targets (MuJoCo poses of the default tip at random configurations) solved by
  POST /ik/batch, ≥ 99 of them verified by MuJoCo's FK of the returned configuration
  within the API's success tolerance (1e-5 m, 1e-5 rad);
- self-collision: the colliding link pairs of POST /collisions/batch (``convex``: MuJoCo
  collides meshes as convex hulls) equal MuJoCo's (``mj_geomDistance``) on 20
  configurations, five of them folded until they collide, with the pair filter of the
  module docstring of :mod:`tests.corpus.mjcf_reference` (also the pairs GET
  /collision_pairs lists); pairs within 1e-5 m of contact may go either way;
- materials: each visual geom's colour, as MuJoCo colours it, is a colour of a visual of
  its body's link in the stored URDF; the default tip is the model's TCP site, not a finger.

The Robotiq 2F-85 closes its four-bar linkages with ``<equality><connect>`` and drives its
two fingers through the fixed ``<tendon>`` ``split``: a tree-shaped model cannot be that
gripper, so the expected answer is a 422 naming the coupling element (issue: "a tendon that
couples joints is a 422 naming it"), and nothing stored.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from fastapi.testclient import TestClient

from app.main import create_app
from app.operations.settings import Settings
from tests.corpus import mjcf_reference
from tests.corpus.upload import upload_case
from tests.helpers import problem

HERE = Path(__file__).parent
#: The API's IK success tolerance (ik_schemas.Tolerance defaults), metres and radians.
IK_TOL = 1e-5
#: Pairs whose MuJoCo distance is within this band of 0 (m) may be called either way.
CONTACT_BAND = 1e-5


@dataclass(frozen=True)
class Upload:
    """One upload of a corpus case: the robot id, the case folder and the description."""

    robot_id: str
    case: str
    description: str
    tip: str  # the model's TCP site: the expected default tip

    @property
    def folder(self) -> Path:
        return HERE / self.case

    @property
    def path(self) -> Path:
        return self.folder / self.description


UPLOADS = [
    # Kinova Gen3 through its scene.xml (includes gen3.xml, which has <keyframe>s) and
    # through gen3.xml itself: continuous joints, colours set by a default class.
    Upload("gen3_scene", "menagerie_gen3", "kinova_gen3/scene.xml", "pinch_site"),
    Upload("gen3", "menagerie_gen3", "kinova_gen3/gen3.xml", "pinch_site"),
    # Trossen ViperX 300 S through its scene.xml and its vx300s.xml: childclass defaults
    # (axes, ranges, slide fingers), a keyframe, fingers mirrored by a joint equality (the
    # follower, left_finger, sorts before its leader), a TCP site "pinch".
    Upload("vx300s_scene", "menagerie_vx300s", "trossen_vx300s/scene.xml", "pinch"),
    Upload("vx300s", "menagerie_vx300s", "trossen_vx300s/vx300s.xml", "pinch"),
]
IDS = [u.robot_id for u in UPLOADS]


@pytest.fixture(scope="module")
def corpus_client(tmp_path_factory: pytest.TempPathFactory) -> Iterator[TestClient]:
    settings = Settings(data_dir=tmp_path_factory.mktemp("mjcf_corpus") / "data")
    with TestClient(create_app(settings), raise_server_exceptions=False) as c:
        yield c


@pytest.fixture(scope="module")
def uploaded(corpus_client: TestClient) -> dict[str, Any]:
    """Upload results by robot id, each case uploaded once (lazily, on first use)."""
    return {}


def _robot(corpus_client: TestClient, uploaded: dict[str, Any], up: Upload) -> dict[str, Any]:
    """The 201 detail of ``up`` (uploading it on first use); fails the test otherwise."""
    if up.robot_id not in uploaded:
        r = upload_case(corpus_client, up.robot_id, up.folder, up.description)
        uploaded[up.robot_id] = (r.status_code, r.json())
    status, body = uploaded[up.robot_id]
    assert status == 201, f"{up.description}: {status} {body}"
    return body


@pytest.fixture(scope="module")
def references() -> dict[str, mjcf_reference.Reference]:
    return {u.robot_id: mjcf_reference.load(u.path) for u in UPLOADS}


def _configurations(
    detail: dict[str, Any], ref: mjcf_reference.Reference, n: int, seed: int
) -> list[dict[str, float]]:
    """``n`` random configurations of the service's joints within MuJoCo's ranges."""
    rng = np.random.default_rng(seed)
    names = [j["name"] for j in detail["joints"]]
    missing = [name for name in names if name not in ref.joints]
    assert not missing, f"joints not in the MJCF: {missing}"
    lo = np.array([ref.joints[name][0] for name in names])
    hi = np.array([ref.joints[name][1] for name in names])
    return [dict(zip(names, rng.uniform(lo, hi).tolist(), strict=True)) for _ in range(n)]


def _vector(detail: dict[str, Any], values: dict[str, float]) -> list[float]:
    return [values[j["name"]] for j in detail["joints"]]


def _rotation_angle(R: np.ndarray) -> float:
    return math.acos(max(-1.0, min(1.0, (np.trace(R) - 1.0) / 2.0)))


def _quat_to_matrix(xyzw: list[float]) -> np.ndarray:
    x, y, z, w = xyzw
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def _matrix_to_quat(R: np.ndarray) -> list[float]:
    """Unit quaternion [x, y, z, w] of a rotation matrix (Shepperd's method)."""
    t = np.trace(R)
    if t > 0:
        s = 2.0 * math.sqrt(t + 1.0)
        q = [(R[2, 1] - R[1, 2]) / s, (R[0, 2] - R[2, 0]) / s, (R[1, 0] - R[0, 1]) / s, s / 4]
    else:
        i = int(np.argmax(np.diag(R)))
        j, k = (i + 1) % 3, (i + 2) % 3
        s = 2.0 * math.sqrt(1.0 + R[i, i] - R[j, j] - R[k, k])
        q = [0.0, 0.0, 0.0, (R[k, j] - R[j, k]) / s]
        q[i] = s / 4
        q[j] = (R[j, i] + R[i, j]) / s
        q[k] = (R[k, i] + R[i, k]) / s
    return q


# -- 1. upload, meshes and files ---------------------------------------------------------


@pytest.mark.parametrize("up", UPLOADS, ids=IDS)
def test_upload_names_and_serves_every_mesh(corpus_client, uploaded, up: Upload) -> None:
    detail = _robot(corpus_client, uploaded, up)
    assert detail["files"]["uri_prefix"] == "package://files/"
    urdf = corpus_client.get(f"/robots/{up.robot_id}/urdf").text
    stored: dict[str, set[tuple[float, ...]]] = {}
    for el in ET.fromstring(urdf).iter("mesh"):
        scale = tuple(float(v) for v in (el.get("scale") or "1 1 1").split())
        stored.setdefault(el.get("filename", ""), set()).add(scale)
    meshes = mjcf_reference.mesh_files(up.path, up.folder)
    assert meshes
    for rel, scale in meshes.items():
        uri = f"package://files/{rel}"
        assert uri in stored, f"{rel} is not in the stored URDF"
        for got in stored[uri]:
            np.testing.assert_allclose(got, scale, rtol=0, atol=1e-15, err_msg=rel)
        served = corpus_client.get(f"/robots/{up.robot_id}/files/{rel}")
        assert served.status_code == 200, rel
        assert served.content == (up.folder / rel).read_bytes(), rel


# -- 2. forward kinematics ---------------------------------------------------------------


@pytest.mark.parametrize("up", UPLOADS, ids=IDS)
def test_fk_of_every_body_and_site_matches_mujoco(
    corpus_client, uploaded, references, up: Upload
) -> None:
    detail = _robot(corpus_client, uploaded, up)
    ref = references[up.robot_id]
    frames = {f["name"] for f in detail["frames"]}
    names = sorted(ref.poses({}))
    assert not set(names) - frames, f"MJCF bodies/sites with no frame: {set(names) - frames}"
    for values in _configurations(detail, ref, 20, seed=20):
        r = corpus_client.post(
            f"/robots/{up.robot_id}/fk",
            json={"q": _vector(detail, values), "frames": names},
        )
        assert r.status_code == 200, r.text
        poses = r.json()["poses"]
        expected = ref.poses(values)
        for name in names:
            np.testing.assert_allclose(
                poses[name]["matrix"], expected[name], rtol=0, atol=1e-9, err_msg=name
            )


# -- 3. inverse kinematics on the default tip --------------------------------------------


@pytest.mark.parametrize("up", UPLOADS, ids=IDS)
def test_ik_on_the_default_tip_verified_by_mujoco(
    corpus_client, uploaded, references, up: Upload
) -> None:
    detail = _robot(corpus_client, uploaded, up)
    ref = references[up.robot_id]
    tip = detail["end_effector"]
    configs = _configurations(detail, ref, 100, seed=30)
    targets = []
    for values in configs:
        T = ref.poses(values)[tip]
        targets.append({"position": T[:3, 3].tolist(), "orientation": _matrix_to_quat(T[:3, :3])})
    r = corpus_client.post(
        f"/robots/{up.robot_id}/ik/batch",
        # The work is bounded by iterations, not time (the slowest target here needs < 100):
        # the answer does not depend on the machine's speed or load.
        json={
            "targets": targets,
            "chain_seeds": False,
            "random_seed": 7,
            "max_iterations": 3000,
            "timeout_ms": 250,
        },
    )
    assert r.status_code == 200, r.text
    out = r.json()
    assert out["frame"] == tip and out["joint_names"] == [j["name"] for j in detail["joints"]]
    verified = 0
    for target, res in zip(targets, out["results"], strict=True):
        if not res["success"]:
            continue
        T = ref.poses(dict(zip(out["joint_names"], res["q"], strict=True)))[tip]
        dp = float(np.linalg.norm(T[:3, 3] - target["position"]))
        dr = _rotation_angle(_quat_to_matrix(target["orientation"]).T @ T[:3, :3])
        verified += dp <= IK_TOL and dr <= IK_TOL
    assert verified >= 99, f"{verified}/100 verified by MuJoCo"


# -- 4. self-collision -------------------------------------------------------------------


def _collision_configurations(
    detail: dict[str, Any], ref: mjcf_reference.Reference, pairs: set[frozenset[str]]
) -> list[dict[str, float]]:
    """15 random configurations, then 5 folded ones that collide by MuJoCo's account.

    Folded: every joint in the outer 15 % of its range, on a random side (seeded draw);
    the first five of those whose closest checked pair overlaps are taken.
    """
    configs = _configurations(detail, ref, 15, seed=40)
    rng = np.random.default_rng(41)
    names = [j["name"] for j in detail["joints"]]
    lo = np.array([ref.joints[name][0] for name in names])
    hi = np.array([ref.joints[name][1] for name in names])
    folded = []
    for _ in range(200):
        u = rng.uniform(0.0, 0.15, len(names)) * (hi - lo)
        q = np.where(rng.integers(0, 2, len(names)) == 1, hi - u, lo + u)
        values = dict(zip(names, q.tolist(), strict=True))
        if min(ref.pair_distances(values, pairs).values()) < -CONTACT_BAND:
            folded.append(values)
            if len(folded) == 5:
                break
    assert len(folded) == 5, "the folded draw has too few colliding configurations"
    return configs + folded


@pytest.mark.parametrize("up", UPLOADS, ids=IDS)
def test_self_collision_pairs_match_mujoco(corpus_client, uploaded, references, up: Upload) -> None:
    detail = _robot(corpus_client, uploaded, up)
    ref = references[up.robot_id]
    pairs = ref.checked_pairs()
    checked = corpus_client.get(f"/robots/{up.robot_id}/collision_pairs").json()
    assert {frozenset(p) for p in checked["pairs"]} == pairs
    configs = _collision_configurations(detail, ref, pairs)
    r = corpus_client.post(
        f"/robots/{up.robot_id}/collisions/batch",
        json={"configurations": [_vector(detail, v) for v in configs], "geometry": "convex"},
    )
    assert r.status_code == 200, r.text
    found = r.json()["pairs"]
    for i, values in enumerate(configs):
        dist = ref.pair_distances(values, pairs)
        service = {frozenset(p) for p in found[i]}
        sure = {p for p, d in dist.items() if abs(d) > CONTACT_BAND}
        expected = {p for p in sure if dist[p] < 0}
        assert service & sure == expected, f"configuration {i}: {values}"


# -- materials and the default tip -------------------------------------------------------


def _urdf_colours(urdf: str) -> dict[str, list[np.ndarray]]:
    """Link name → rgba of each of its visuals (inline colour or a named material)."""
    root = ET.fromstring(urdf)
    named = {}
    for mat in root.findall("material"):
        colour = mat.find("color")
        if colour is not None:
            named[mat.get("name")] = colour.get("rgba")
    out: dict[str, list[np.ndarray]] = {}
    for link in root.iter("link"):
        for visual in link.findall("visual"):
            mat = visual.find("material")
            if mat is None:
                continue
            colour = mat.find("color")
            rgba = colour.get("rgba") if colour is not None else named.get(mat.get("name"))
            if rgba:
                out.setdefault(link.get("name"), []).append(np.array(rgba.split(), float))
    return out


@pytest.mark.parametrize("up", UPLOADS, ids=IDS)
def test_material_colours_survive(corpus_client, uploaded, references, up: Upload) -> None:
    _robot(corpus_client, uploaded, up)
    urdf = _urdf_colours(corpus_client.get(f"/robots/{up.robot_id}/urdf").text)
    expected = references[up.robot_id].visual_colours()
    assert expected
    for body, colours in expected.items():
        stored = urdf.get(body, [])
        for rgba in colours:
            assert any(np.allclose(rgba, s, rtol=0, atol=1e-6) for s in stored), (
                f"{body}: rgba {rgba.tolist()} not among its visuals' {stored}"
            )


@pytest.mark.parametrize("up", UPLOADS, ids=IDS)
def test_default_tip_is_the_tcp_site(corpus_client, uploaded, up: Upload) -> None:
    detail = _robot(corpus_client, uploaded, up)
    assert detail["end_effector"] == up.tip
    assert "finger" not in detail["end_effector"]


# -- the Robotiq 2F-85: a closed linkage, refused by name --------------------------------


@pytest.mark.parametrize(
    ("description", "named"),
    [
        # The first loop-closing <equality><connect> of 2f85.xml, by the bodies it ties.
        ("robotiq_2f85/2f85.xml", ("<equality><connect> (bodies 'right_follower' and",)),
        # scene.xml adds a hanging box on a free joint: refusing that by name is right too.
        ("robotiq_2f85/scene.xml", ("<equality><connect> (bodies", "of type 'free'")),
    ],
)
def test_2f85_linkage_is_refused_by_name(
    corpus_client, description: str, named: tuple[str, ...]
) -> None:
    name = "robotiq_" + Path(description).stem
    r = upload_case(corpus_client, name, HERE / "menagerie_2f85", description)
    detail = problem(r, 422, "description")["detail"]
    assert any(word in detail for word in named), detail
    assert not re.search(r"(^|[\s'\"(])/[A-Za-z]", detail), f"a server path in: {detail}"
    problem(corpus_client.get(f"/robots/{name}"), 404, "robot_id")
