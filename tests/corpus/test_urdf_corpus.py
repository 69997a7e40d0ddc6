"""The URDF/xacro/SRDF corpus: real description packages uploaded as a lab uploads them.

Each case (a folder of ``tests/corpus/``, see its ``PROVENANCE.md`` and README.md) is packed
and sent to POST /robots/package once per module, then checked against the independent
reference of :mod:`tests.corpus.urdf_reference` (the xacro CLI, yourdfpy, python-fcl):

1. ``test_upload``: a 201; the stored URDF names every mesh the reference URDF names, as
   ``package://files/<path in the archive>``, and GET /robots/{id}/files/<path> serves the
   original bytes;
2. ``test_fk``: every link of the reference at 25 random configurations within limits
   (fixed seed), to 1e-9 (position, m, and rotation-matrix entries);
3. ``test_ik``: 100 targets (reference FK of random configurations) on the default tip and
   on each SRDF group's tip, solved by POST /ik/batch and verified by the REFERENCE FK
   within the API's success tolerance (1e-5 m, 1e-5 rad) and the joint limits: ≥ 99/100;
4. ``test_collisions``: the checked pairs (GET /collision_pairs) equal the pairs the
   documented rules give, and on 30 configurations (20 uniform, 10 folded towards the
   limits) the colliding pairs POST /collisions/batch reports equal python-fcl's.
"""

from __future__ import annotations

import io
import posixpath
import shutil
import tarfile
import zlib
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pytest
from fastapi.testclient import TestClient
from lxml import etree

from app.main import create_app
from app.operations.settings import Settings
from tests.corpus.upload import pack_case, upload_case
from tests.corpus.urdf_reference import Reference, ament_prefix, resolve_uri, run_xacro

HERE = Path(__file__).parent
COLLADA = "http://www.collada.org/2005/11/COLLADASchema"
FK_CONFIGS = 25
IK_TARGETS = 100
IK_NEEDED = 99
IK_TOL = 1e-5  # the API's default success tolerance (m and rad)
COLLISION_UNIFORM = 20
COLLISION_FOLDED = 10


@dataclass(frozen=True)
class Case:
    """One corpus case: its folder, the upload's fields and what its checks expect."""

    id: str
    description: str
    #: The case folder, when another case's (the same package uploaded another way).
    folder_id: str | None = None
    srdf: str | None = None
    xacro_args: dict[str, str] = field(default_factory=dict)
    srdf_xacro_args: dict[str, str] | None = None

    @property
    def folder(self) -> Path:
        return HERE / (self.folder_id or self.id)


CASES = [
    Case(
        "abb_irb2400",
        "abb_irb2400_support/urdf/irb2400.xacro",
        srdf="abb_irb2400_moveit_config/config/abb_irb2400.srdf",
    ),
    Case(
        "fanuc_lrmate200id",
        "fanuc_lrmate200id_support/urdf/lrmate200id.xacro",
        srdf="moveit_cfgs/fanuc_lrmate200id_moveit_config/config/fanuc_lrmate200id.srdf",
    ),
    Case(
        "fanuc_moveit_resources",
        "fanuc_description/urdf/fanuc.urdf",
        srdf="fanuc_moveit_config/config/fanuc.srdf",
    ),
    Case("kuka_kr10r900_2", "kuka_kr10_support/urdf/kr10r900_2.xacro"),
    Case(
        "motoman_sia20d",
        "motoman_sia20d_support/urdf/sia20d.xacro",
        srdf="motoman_sia20d_moveit_config/config/motoman_sia20d.srdf",
    ),
    Case(
        "robotiq_2f85",
        "robotiq_description/urdf/robotiq_2f_85_gripper.urdf.xacro",
    ),
    Case(
        "ur20_ros1",
        "ur_description/urdf/ur20.xacro",
        srdf="ur20_moveit_config/config/ur20.srdf",
    ),
    Case(
        "ur20_ros2",
        "ur_description/urdf/ur.urdf.xacro",
        srdf="ur_moveit_config/srdf/ur.srdf.xacro",
        xacro_args={"name": "ur", "ur_type": "ur20"},
    ),
    Case(
        "ur20_ros2_abs_paths",
        "ur_description/urdf/ur.urdf.xacro",
        folder_id="ur20_ros2",
        srdf="ur_moveit_config/srdf/ur.srdf.xacro",
        xacro_args={"name": "ur", "ur_type": "ur20", "force_abs_paths": "true"},
    ),
    Case("xarm6", "xarm_description/urdf/xarm_device.urdf.xacro", xacro_args={"dof": "6"}),
]
IDS = [c.id for c in CASES]


@dataclass
class Prepared:
    """A case uploaded (its response) and its reference."""

    case: Case
    status: int
    detail: dict
    ref: Reference
    mesh_paths: dict[str, str]  # mesh URI of the reference URDF → path in the archive


@pytest.fixture(scope="module")
def data_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The module's data directory (no answer may show it)."""
    return tmp_path_factory.mktemp("corpus") / "data"


@pytest.fixture(scope="module")
def corpus_client(data_dir: Path) -> Iterator[TestClient]:
    """One app for the module (uploads are slow-ish): a fresh data directory."""
    with TestClient(create_app(Settings(data_dir=data_dir)), raise_server_exceptions=False) as c:
        yield c


@pytest.fixture(scope="module")
def uploads() -> dict[str, Prepared]:
    """The cases uploaded to this module's app so far (case id → what it answered)."""
    return {}


def _reference(case: Case, prefix: Path) -> tuple[Reference, dict[str, str]]:
    """The case's reference (xacro CLI + yourdfpy + python-fcl) and its meshes' paths in
    the archive (mesh URI → path), built in the install prefix ``prefix``."""
    folder = case.folder
    if case.description.endswith(".urdf"):
        urdf = (folder / case.description).read_text()
        shares = ament_prefix(folder, prefix)
    else:
        urdf, shares = run_xacro(folder, case.description, case.xacro_args, prefix)
    srdf = None
    if case.srdf is not None:
        if case.srdf.endswith(".xacro"):
            args = case.xacro_args if case.srdf_xacro_args is None else case.srdf_xacro_args
            srdf, _ = run_xacro(folder, case.srdf, args, prefix)
        else:
            srdf = (folder / case.srdf).read_text()
    base = (folder / case.description).parent

    def mesh_file(uri: str) -> Path:
        return resolve_uri(uri, folder, shares, base)

    ref = Reference(urdf, mesh_file, srdf)
    paths = {uri: mesh_file(uri).relative_to(folder.resolve()).as_posix() for uri in ref.mesh_uris}
    return ref, paths


@pytest.fixture
def prepared(
    request: pytest.FixtureRequest,
    corpus_client: TestClient,
    uploads: dict[str, Prepared],
    tmp_path_factory: pytest.TempPathFactory,
) -> Prepared:
    """The case of the test's parameter, uploaded once per module, with its reference."""
    case: Case = request.param
    if case.id not in uploads:
        prefix = tmp_path_factory.mktemp(f"prefix-{case.id}")
        ref, paths = _reference(case, prefix)
        fields = {"srdf": case.srdf, "xacro_args": case.xacro_args or None}
        if case.srdf_xacro_args is not None:
            fields["srdf_xacro_args"] = case.srdf_xacro_args
        r = upload_case(
            corpus_client, case.id.replace("_", "-"), case.folder, case.description, **fields
        )
        uploads[case.id] = Prepared(case, r.status_code, r.json(), ref, paths)
    p = uploads[case.id]
    assert p.status == 201, f"{case.id}: upload refused: {p.detail}"
    return p


def _params():
    return pytest.mark.parametrize("prepared", CASES, ids=IDS, indirect=True)


def _q(detail: dict, cfg: dict[str, float]) -> list[float]:
    """A reference configuration (actuated joint → value) in the service's joint order."""
    return [cfg[j["name"]] for j in detail["joints"]]


def _rot_angle(Ra: np.ndarray, Rb: np.ndarray) -> float:
    c = (np.trace(Ra.T @ Rb) - 1.0) / 2.0
    return float(np.arccos(np.clip(c, -1.0, 1.0)))


# ---------------------------------------------------------------------------------- tests
@_params()
def test_upload(prepared: Prepared, corpus_client: TestClient) -> None:
    """201, the same actuated joints as the reference, every mesh (and every texture a
    COLLADA mesh names) stored and served byte for byte."""
    detail, ref = prepared.detail, prepared.ref
    assert sorted(j["name"] for j in detail["joints"]) == sorted(ref.actuated)
    assert detail["has_collision_geometry"]
    urdf = corpus_client.get(f"/robots/{detail['id']}/urdf")
    assert urdf.status_code == 200
    prefix = detail["files"]["uri_prefix"]
    stored = set()
    for mesh in etree.fromstring(urdf.content).iter("mesh"):
        uri = mesh.get("filename")
        assert uri.startswith(prefix), uri
        stored.add(uri[len(prefix) :])
    assert stored == set(prepared.mesh_paths.values())
    files = set(stored)
    for path in stored:
        if path.endswith(".dae"):
            images = etree.parse(str(prepared.case.folder / path)).iter(f"{{{COLLADA}}}image")
            for image in images:
                name = image.findtext(f"{{{COLLADA}}}init_from")
                files.add(posixpath.normpath(posixpath.join(posixpath.dirname(path), name)))
    for path in sorted(files):
        got = corpus_client.get(f"/robots/{detail['id']}/files/{path}")
        assert got.status_code == 200, path
        assert got.content == (prepared.case.folder / path).read_bytes(), path


@_params()
def test_fk(prepared: Prepared, corpus_client: TestClient) -> None:
    """Every reference link's pose at random configurations, to 1e-9."""
    detail, ref = prepared.detail, prepared.ref
    rng = np.random.default_rng(20260126)
    for cfg in ref.random_configs(rng, FK_CONFIGS):
        expected = ref.fk(cfg)
        r = corpus_client.post(
            f"/robots/{detail['id']}/fk", json={"q": _q(detail, cfg), "frames": ref.links}
        )
        assert r.status_code == 200, r.text
        poses = r.json()["poses"]
        for link, T in expected.items():
            got = np.array(poses[link]["matrix"])
            assert np.abs(got - T).max() <= 1e-9, (link, cfg, np.abs(got - T).max())


def _ik_check(prepared: Prepared, client: TestClient, tip: str, group: dict | None) -> None:
    detail, ref = prepared.detail, prepared.ref
    rng = np.random.default_rng([7, zlib.crc32(tip.encode())])
    neutral = dict(zip((j["name"] for j in detail["joints"]), detail["neutral"], strict=True))
    moving = set(group["joints"]) if group else set(ref.actuated)
    configs = []
    for cfg in ref.random_configs(rng, IK_TARGETS):
        configs.append({j: (v if j in moving else neutral[j]) for j, v in cfg.items()})
    targets = [{"matrix": ref.fk(cfg)[tip].tolist()} for cfg in configs]
    body = {
        "targets": targets,
        "frame": tip,
        "chain_seeds": False,
        "seed": [neutral[j["name"]] for j in detail["joints"]],
        "random_seed": 11,
        "timeout_ms": 250.0,
        "max_iterations": 4000,
    }
    if group:
        body["group"] = group["name"]
    r = client.post(f"/robots/{detail['id']}/ik/batch", json=body)
    assert r.status_code == 200, r.text
    out = r.json()
    names = out["joint_names"]
    verified = 0
    for target, res in zip(targets, out["results"], strict=True):
        if not res["success"]:
            continue
        cfg = dict(zip(names, res["q"], strict=True))
        inside = all(
            ref.limits(j)[0] - 1e-9 <= cfg[j] <= ref.limits(j)[1] + 1e-9
            for j in names
            if ref.urdf.joint_map[j].type != "continuous"
        )
        T = ref.fk(cfg)[tip]
        Tt = np.array(target["matrix"])
        pos = float(np.linalg.norm(T[:3, 3] - Tt[:3, 3]))
        ang = _rot_angle(T[:3, :3], Tt[:3, :3])
        if inside and pos <= IK_TOL + 1e-9 and ang <= IK_TOL + 1e-9:
            verified += 1
    assert verified >= IK_NEEDED, (
        f"{prepared.case.id} tip {tip} group {group and group['name']}: "
        f"{verified}/{IK_TARGETS} verified ({out['solved']} reported solved)"
    )


@_params()
def test_ik_default_tip(prepared: Prepared, corpus_client: TestClient) -> None:
    """IK on the default end effector, verified by the reference FK."""
    _ik_check(prepared, corpus_client, prepared.detail["end_effector"], None)


@_params()
def test_ik_groups(prepared: Prepared, corpus_client: TestClient) -> None:
    """IK on each SRDF group's tip (the group's joints move), verified by the reference."""
    groups = prepared.detail["groups"]
    if prepared.case.srdf is not None:
        assert groups, f"{prepared.case.id}: the SRDF's groups are missing"
    for g in groups:
        _ik_check(prepared, corpus_client, g["tip"], g)


def _collision_configs(ref: Reference) -> list[dict[str, float]]:
    rng = np.random.default_rng(4242)
    configs = ref.random_configs(rng, COLLISION_UNIFORM)
    for _ in range(COLLISION_FOLDED):
        cfg = {}
        for j in ref.actuated:
            lo, hi = ref.limits(j)
            cfg[j] = lo + (hi - lo) * float(rng.choice([0.03, 0.97]))
        configs.append(cfg)
    return configs


@_params()
def test_collisions(prepared: Prepared, corpus_client: TestClient) -> None:
    """Checked pairs by the documented rules; colliding pairs equal python-fcl's."""
    detail, ref = prepared.detail, prepared.ref
    pairs = ref.pairs()
    r = corpus_client.get(f"/robots/{detail['id']}/collision_pairs")
    assert r.status_code == 200
    assert {frozenset(p) for p in r.json()["pairs"]} == pairs
    configs = _collision_configs(ref)
    r = corpus_client.post(
        f"/robots/{detail['id']}/collisions/batch",
        json={"configurations": [_q(detail, c) for c in configs]},
    )
    assert r.status_code == 200, r.text
    got = r.json()["pairs"]
    colliding = 0
    for i, cfg in enumerate(configs):
        expected = ref.colliding(cfg, pairs)
        colliding += bool(expected)
        assert {frozenset(p) for p in got[i]} == expected, (i, cfg)
    assert colliding >= 1, f"{prepared.case.id}: no configuration collides"


# ------------------------------------------------------------------------------ refusals
def _case(case_id: str) -> Case:
    return next(c for c in CASES if c.id == case_id)


def _assert_refused(r, field: str, names: str, data_dir: Path) -> None:
    """A 422 problem naming ``field`` and ``names``, showing no server path."""
    assert r.status_code == 422, r.text
    problem = r.json()
    assert problem["field"] == field, problem
    assert names in problem["detail"], problem
    for leak in (str(data_dir), str(data_dir.parent), "/tmp/", "/package/", "/work/"):
        assert leak not in r.text, (leak, problem)


def test_refused_missing_mesh(corpus_client: TestClient, data_dir: Path, tmp_path: Path) -> None:
    """The IRB 2400 without one collision mesh its xacro names: a 422 naming that mesh
    (its path in the archive), no server path; nothing stored."""
    case = _case("abb_irb2400")
    folder = tmp_path / case.id
    shutil.copytree(case.folder, folder)
    missing = "abb_irb2400_support/meshes/irb2400/collision/link_3.stl"
    (folder / missing).unlink()
    r = upload_case(corpus_client, "abb-missing-mesh", folder, case.description, srdf=case.srdf)
    _assert_refused(r, "description", f"'{missing}'", data_dir)
    assert corpus_client.get("/robots/abb-missing-mesh").status_code == 404


def test_refused_unknown_variant(corpus_client: TestClient, data_dir: Path) -> None:
    """The UR description with a ur_type it has no configuration for: xacro cannot load
    config/ur99/…; a 422 naming that file (in the archive), no server path; nothing
    stored."""
    case = _case("ur20_ros2")
    r = upload_case(
        corpus_client,
        "ur-unknown-variant",
        case.folder,
        case.description,
        xacro_args={"name": "ur", "ur_type": "ur99"},
    )
    _assert_refused(r, "description", "'ur_description/config/ur99/", data_dir)
    assert corpus_client.get("/robots/ur-unknown-variant").status_code == 404


# --------------------------------------------------------------------------- the packing
def test_pack_case_is_the_vendor_files_byte_for_byte() -> None:
    """pack_case gives the same bytes every time; the archive holds every vendor file of
    the folder as a regular file with its bytes (a linked file too), not PROVENANCE.md."""
    folder = _case("ur20_ros1").folder
    packed = pack_case(folder)
    assert pack_case(folder) == packed
    assert packed[4:8] == bytes(4)  # the gzip header's mtime: none
    with tarfile.open(fileobj=io.BytesIO(packed)) as tf:
        members = {m.name: m for m in tf.getmembers()}
        expected = {
            p.relative_to(folder).as_posix()
            for p in folder.rglob("*")
            if p.is_file() and p.name != "PROVENANCE.md"
        }
        assert set(members) == expected
        for name, member in members.items():
            assert member.isfile(), name
            assert tf.extractfile(member).read() == (folder / name).read_bytes(), name
    assert any((folder / name).is_symlink() for name in members)
