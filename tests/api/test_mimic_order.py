"""Mimic joints are read as urdfdom / robot_state_publisher read them: the names of the
joints never change what is accepted, chains compose to their root leader, and what
Pinocchio cannot build is a 422 naming the joint.

References: yourdfpy's FK (it applies ``<mimic>`` itself) of the very document uploaded; for
chains (yourdfpy reads a follower of a follower as 0 + offset), yourdfpy's FK of the same
robot with each follower written against the root leader by hand, as joint_state_publisher
composes them (``m₁·m₂``, ``m₂·o₁ + o₂``).
"""

from __future__ import annotations

import io
import itertools
import zipfile

import numpy as np
import pytest
import yourdfpy

from tests.helpers import problem
from tests.mimic_robots import LIMIT, gripper, joint

LINKS = ["palm", "left", "right", "pad"]


def _yourdfpy(urdf: str) -> yourdfpy.URDF:
    return yourdfpy.URDF.load(io.BytesIO(urdf.encode()), load_meshes=False)


def _fk(client, robot_id: str, positions: dict[str, float]) -> dict[str, np.ndarray]:
    r = client.post(f"/robots/{robot_id}/fk", json={"joint_positions": positions, "frames": LINKS})
    assert r.status_code == 200, r.text
    return {k: np.array(v["matrix"]) for k, v in r.json()["poses"].items()}


def _reference(ref: yourdfpy.URDF, positions: dict[str, float]) -> dict[str, np.ndarray]:
    ref.update_cfg({k: v for k, v in positions.items() if k in ref.actuated_joint_names})
    return {link: ref.get_transform(link, "base") for link in LINKS}


def _configurations(seed: int, n: int = 15) -> list[np.ndarray]:
    rng = np.random.default_rng(seed)
    return [rng.uniform(-1, 1, 3) for _ in range(n)]


@pytest.mark.parametrize("follower_type", ["revolute", "continuous"])
def test_follower_named_before_its_leader_loads_with_yourdfpy_fk(client, follower_type) -> None:
    """The Robotiq 2F-85's case: ``…_inner_knuckle_joint`` (continuous) mimics
    ``…_knuckle_joint``, and its name sorts first."""
    urdf = gripper("b_knuckle_joint", "a_inner_joint", "wrist", "pad_joint", follower_type)
    r = client.post("/robots/urdf", json={"name": "grip", "urdf": urdf})
    assert r.status_code == 201, r.text
    detail = client.get("/robots/grip").json()
    assert {j["name"] for j in detail["joints"]} == {"wrist", "b_knuckle_joint", "pad_joint"}
    assert detail["mimic_joints"] == [
        {"name": "a_inner_joint", "type": follower_type, "leader": "b_knuckle_joint",
         "multiplier": -0.8, "offset": 0.1}
    ]  # fmt: skip
    ref = _yourdfpy(urdf)
    for q in _configurations(seed=1):
        positions = dict(zip(("wrist", "b_knuckle_joint", "pad_joint"), q.tolist(), strict=True))
        got, expected = _fk(client, "grip", positions), _reference(ref, positions)
        for link in LINKS:
            np.testing.assert_allclose(got[link], expected[link], rtol=0, atol=1e-12)


NAMES = ("a_joint", "m_joint", "z_joint", "zz_joint")


@pytest.mark.parametrize("names", list(itertools.permutations(NAMES)), ids="-".join)
def test_joint_names_never_change_acceptance_or_fk(client, names: tuple[str, ...]) -> None:
    """Every assignment of four names (so every order of the leader, its follower and the
    other joints among Pinocchio's name-ordered siblings) loads, with the same FK."""
    leader, follower, wrist, finger = names
    urdf = gripper(leader, follower, wrist, finger)
    r = client.post("/robots/urdf", json={"name": "perm", "urdf": urdf})
    assert r.status_code == 201, r.text
    ref = _yourdfpy(gripper("leader", "follower", "wrist", "finger"))  # one fixed reference
    for q in _configurations(seed=2, n=5):
        by_role = dict(zip(("wrist", "leader", "finger"), q.tolist(), strict=True))
        positions = {wrist: by_role["wrist"], leader: by_role["leader"], finger: by_role["finger"]}
        got, expected = _fk(client, "perm", positions), _reference(ref, by_role)
        for link in LINKS:
            np.testing.assert_allclose(got[link], expected[link], rtol=0, atol=1e-12)


def _chain(order: tuple[str, str, str], flattened: bool) -> str:
    """Three sibling fingers: ``order[0]`` leads, ``order[1]`` mimics it (×2, +0.1),
    ``order[2]`` mimics ``order[1]`` (×-0.5, +0.3); ``flattened``: the last written
    against the root leader by hand (×-1.0, -0.5·0.1 + 0.3 = 0.25)."""
    root, mid, last = order
    last_mimic = (root, -1.0, 0.25) if flattened else (mid, -0.5, 0.3)
    links = "".join(f'<link name="{n}"/>' for n in ("base", "palm", "left", "right", "pad"))
    return (
        f'<robot name="chain">{links}'
        + joint("wrist", "base", "palm", "0 0 0.1", "0 0 1")
        + joint(root, "palm", "left", "0 0.03 0.05", "1 0 0")
        + joint(mid, "palm", "right", "0 -0.03 0.05", "1 0 0", mimic=(root, 2.0, 0.1))
        + joint(last, "palm", "pad", "0.03 0 0.05", "0 1 0", mimic=last_mimic)
        + "</robot>"
    )


@pytest.mark.parametrize("order", list(itertools.permutations(("j_a", "j_b", "j_c"))), ids="-".join)
def test_mimic_chain_in_any_order_composes_to_its_root_leader(client, order) -> None:
    r = client.post("/robots/urdf", json={"name": "chain", "urdf": _chain(order, False)})
    assert r.status_code == 201, r.text
    mimics = {m["name"]: m for m in client.get("/robots/chain").json()["mimic_joints"]}
    assert mimics[order[2]] == {"name": order[2], "type": "revolute", "leader": order[0],
                                "multiplier": -1.0, "offset": 0.25}  # fmt: skip
    ref = _yourdfpy(_chain(order, True))
    for q in _configurations(seed=3, n=8):
        positions = {"wrist": float(q[0]), order[0]: float(q[1])}
        got, expected = _fk(client, "chain", positions), _reference(ref, positions)
        for link in LINKS:
            np.testing.assert_allclose(got[link], expected[link], rtol=0, atol=1e-12)


def _two(
    leader_type: str = "revolute",
    follower_type: str = "revolute",
    mimic: str = "lead",
    follower_child: str = "b",
) -> str:
    lim = LIMIT if leader_type in ("revolute", "prismatic") else ""
    flim = LIMIT if follower_type in ("revolute", "prismatic") else ""
    return ('<robot name="r"><link name="base"/><link name="a"/><link name="b"/>'
            f'<joint name="lead" type="{leader_type}"><parent link="base"/><child link="a"/>'
            f'<axis xyz="0 0 1"/>{lim}</joint>'
            f'<joint name="follow" type="{follower_type}"><parent link="base"/>'
            f'<child link="{follower_child}"/><axis xyz="0 0 1"/>{flim}'
            f'<mimic joint="{mimic}"/></joint>'
            '<joint name="other" type="revolute"><parent link="a"/><child link="c"/>'
            f'<axis xyz="0 0 1"/>{LIMIT}</joint><link name="c"/></robot>')  # fmt: skip


CARRIER = (
    '<robot name="r"><link name="base"/><link name="a"/><link name="b"/>'
    f'<joint name="lift" type="revolute"><parent link="base"/><child link="a"/>{LIMIT}'
    '<mimic joint="top"/></joint>'
    f'<joint name="top" type="revolute"><parent link="a"/><child link="b"/>{LIMIT}</joint></robot>'
)
#: Two branches, each holding the leader of a follower in the other: no depth-first order
#: puts both leaders first.
CROSSED = (
    '<robot name="r">'
    + "".join(f'<link name="{n}"/>' for n in ("base", "x", "x2", "y", "y2"))
    + joint("x1", "base", "x", "0 0 0", "0 0 1")
    + joint("x2j", "x", "x2", "0 0 0", "0 0 1", mimic=("y1", 1.0, 0.0))
    + joint("y1", "base", "y", "0 0 0", "0 0 1")
    + joint("y2j", "y", "y2", "0 0 0", "0 0 1", mimic=("x1", 1.0, 0.0))
    + "</robot>"
)


@pytest.mark.parametrize(
    ("urdf", "words"),
    [
        (_two(mimic="nowhere"), ["'follow'", "'nowhere'", "not a joint"]),
        (_two(mimic="follow"), ["'follow'", "cycle"]),
        (_two(leader_type="fixed"), ["'lead'", "fixed"]),
        (_two(leader_type="continuous"), ["'lead'", "continuous"]),
        (CARRIER, ["'lift'", "'top'", "carries"]),
        (CROSSED, ["'x1'", "'y1'", "cannot be ordered"]),
    ],
    ids=[
        "unknown",
        "self",
        "fixed-leader",
        "continuous-leader",
        "carries-its-leader",
        "crossed",
    ],  # fmt: skip
)
def test_mimic_pinocchio_cannot_build_is_a_422_naming_thejoint(client, urdf, words) -> None:
    body = problem(client.post("/robots/urdf", json={"name": "bad", "urdf": urdf}), 422, "urdf")
    assert all(w in body["detail"] for w in words), body["detail"]
    assert "from file" not in body["detail"].lower() and "/" not in body["detail"]
    assert client.get("/robots/bad").status_code == 404


def test_mimic_cycle_of_two_is_a_422(client) -> None:
    lead_end = f'{LIMIT}</joint><joint name="follow"'
    urdf = _two().replace(lead_end, lead_end.replace("</joint>", '<mimic joint="follow"/></joint>'))
    body = problem(client.post("/robots/urdf", json={"name": "bad", "urdf": urdf}), 422, "urdf")
    assert "cycle" in body["detail"] and "'lead'" in body["detail"]


def test_package_with_follower_named_first_loads(client) -> None:
    """The same gripper as a package: the bounded child that builds its collision geometry
    uses the same builder (a box on each finger)."""
    box = '<collision><geometry><box size="0.01 0.01 0.02"/></geometry></collision>'
    urdf = gripper("b_knuckle_joint", "a_inner_joint", "wrist", "pad_joint")
    for link in ("left", "right"):
        urdf = urdf.replace(f'<link name="{link}"/>', f'<link name="{link}">{box}</link>')
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w") as z:
        z.writestr("grip/urdf/grip.urdf", urdf)
    r = client.post(
        "/robots/package",
        data={"name": "gripz", "description": "grip/urdf/grip.urdf"},
        files={"archive": ("grip.zip", buf.getvalue(), "application/zip")},
    )
    assert r.status_code == 201, r.text
    ref = _yourdfpy(urdf)
    for q in _configurations(seed=4, n=5):
        positions = dict(zip(("wrist", "b_knuckle_joint", "pad_joint"), q.tolist(), strict=True))
        got, expected = _fk(client, "gripz", positions), _reference(ref, positions)
        for link in LINKS:
            np.testing.assert_allclose(got[link], expected[link], rtol=0, atol=1e-12)
