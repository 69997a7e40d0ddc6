"""Collision checking against closed forms (capsule distances), independent geometry
(mesh vertices inside hulls), the pair rules, and invariants (hulls are conservative)."""

from __future__ import annotations

import math
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest
import trimesh
import yourdfpy
from defusedxml import ElementTree
from scipy.spatial import ConvexHull

import robots
from app.kinematics.collision import GEOMETRY_MODES, collision_filter, collision_model
from app.kinematics.collision_pairs import collision_link_pairs, srdf_disabled_pairs
from app.kinematics.errors import InvalidInputError
from app.kinematics.models import RobotModel
from app.kinematics.obstacles import parse_obstacles
from dh2urdf import DHTable, to_urdf

READY = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785, 0.02]
#: A folded Panda configuration (within limits) that drives the hand into the base (link0).
FOLDED = [0.638, -1.713, -2.25, -2.588, -0.848, 0.027, 2.491, 0.01]

L1, L2, R_LINK = 1.0, 0.8, 0.03  # robots/dh/planar2.yaml


@pytest.fixture(scope="module")
def planar2() -> RobotModel:
    """The course's planar 2-link arm, generated capsules (radius 0.03 m) from dh2urdf."""
    table = DHTable.from_file(robots.dh_tables()["planar2"])
    return RobotModel("planar2", to_urdf(table), source="dh", ee_frame="tool")


def sphere(name: str, centre, radius: float) -> dict:
    return {"name": name, "shape": "sphere", "radius": radius, "pose": {"position": list(centre)}}


def link2_segment(q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """End points of link 2's axis (closed form: elbow at l1·(c1, s1))."""
    elbow = np.array([L1 * math.cos(q[0]), L1 * math.sin(q[0]), 0.0])
    tip = elbow + L2 * np.array([math.cos(q[0] + q[1]), math.sin(q[0] + q[1]), 0.0])
    return elbow, tip


# ------------------------------------------------------------------- analytic distances
@pytest.mark.parametrize("mode", GEOMETRY_MODES)
def test_sphere_beside_capsule_distance_closed_form(planar2: RobotModel, mode: str) -> None:
    """distance = D − r_link − r_obstacle, witness points on the line of centres."""
    cm = collision_model(planar2, mode)
    rng = np.random.default_rng(3)
    for _ in range(12):
        q = rng.uniform(-math.pi, math.pi, 2)
        elbow, tip = link2_segment(q)
        u = (tip - elbow) / L2
        side = rng.choice([-1.0, 1.0])
        normal = np.array([0.0, 0.0, 1.0]) if rng.random() < 0.3 else side * np.cross([0, 0, 1], u)
        foot = elbow + rng.uniform(0.2, 0.8) * (tip - elbow)
        D, r_obs = rng.uniform(0.05, 0.5), rng.uniform(0.01, 0.1)
        centre = foot + D * normal
        report = cm.check(q, parse_obstacles([sphere("ball", centre, r_obs)]), distances=True)
        pair = next(p for p in report.pairs if p.a == "link_2" and p.b == "ball")
        expected = D - R_LINK - r_obs  # negative: penetration depth
        assert pair.kind == "environment" and pair.in_collision == (expected < 0)
        assert pair.distance == pytest.approx(expected, abs=1e-6)
        np.testing.assert_allclose(pair.point_a, foot + R_LINK * normal, atol=1e-5)
        np.testing.assert_allclose(pair.point_b, centre - r_obs * normal, atol=1e-5)


def test_sphere_beyond_tip_measures_to_end_sphere(planar2: RobotModel) -> None:
    """Past the segment's end the capsule's end sphere is closest: D − r_link − r_obs."""
    cm = collision_model(planar2, "mesh")
    q = np.array([0.4, -1.1])
    elbow, tip = link2_segment(q)
    u = (tip - elbow) / L2
    for D in (0.06, 0.2, 0.7):
        obstacles = parse_obstacles([sphere("ball", tip + D * u, 0.02)])
        report = cm.check(q, obstacles, distances=True)
        pair = next(p for p in report.pairs if p.a == "link_2")
        assert pair.distance == pytest.approx(D - R_LINK - 0.02, abs=1e-9)


def test_obstacle_moved_into_link_toggles_verdict(planar2: RobotModel) -> None:
    cm = collision_model(planar2, "mesh")
    q = np.array([0.3, 0.9])
    elbow, tip = link2_segment(q)
    mid = (elbow + tip) / 2
    free = cm.check(q, parse_obstacles([sphere("rock", mid + [0, 0, 0.2], 0.05)]))
    assert not free.in_collision and free.pairs == [] and free.min_distance is None
    hit = cm.check(q, parse_obstacles([sphere("rock", mid + [0, 0, 0.06], 0.05)]))
    assert hit.in_collision and hit.environment_collision and not hit.self_collision
    assert [(p.a, p.b, p.kind) for p in hit.pairs] == [("link_2", "rock", "environment")]
    assert hit.pairs[0].distance == pytest.approx(0.06 - R_LINK - 0.05, abs=1e-6)


def test_margin_counts_near_pairs_as_colliding(planar2: RobotModel) -> None:
    cm = collision_model(planar2, "convex")
    q = np.array([0.0, 0.5])
    elbow, tip = link2_segment(q)
    obstacles = parse_obstacles([sphere("ball", (elbow + tip) / 2 + [0, 0, 0.13], 0.05)])
    clearance = 0.13 - R_LINK - 0.05  # 0.05 m
    assert not cm.check(q, obstacles, margin=clearance - 0.001).in_collision
    near = cm.check(q, obstacles, margin=clearance + 0.001)
    assert near.in_collision and near.pairs[0].distance == pytest.approx(clearance, abs=1e-6)
    assert not cm.collides(q, obstacles, clearance - 0.001)
    assert cm.collides(q, obstacles, clearance + 0.001)


def test_obstacles_of_every_shape(planar2: RobotModel) -> None:
    """A box, cylinder and capsule near link 1 (the x axis from 0 to 1 m at q = 0).

    Nearest surfaces: the box's bottom face at z = 0.25; the cylinder lying along y
    (local z turned by +90° about x) at z = 0.4 − 0.05; the upright capsule at
    y = 0.5 − 0.04. The distance subtracts the link radius.
    """
    cm = collision_model(planar2, "mesh")
    quarter_x = [math.sin(math.pi / 4), 0.0, 0.0, math.cos(math.pi / 4)]
    cases = {
        "box": ({"size": [0.2, 0.2, 0.1], "pose": {"position": [0.5, 0, 0.3]}}, 0.25),
        "cylinder": (
            {
                "radius": 0.05,
                "length": 0.3,
                "pose": {"position": [0.5, 0, 0.4], "orientation": quarter_x},
            },
            0.35,
        ),
        "capsule": ({"radius": 0.04, "length": 0.2, "pose": {"position": [0.5, 0.5, 0]}}, 0.46),
    }
    for shape, (spec, surface) in cases.items():
        obstacles = parse_obstacles([{"name": shape, "shape": shape, **spec}])
        report = cm.check(np.zeros(2), obstacles, distances=True)
        pair = next(p for p in report.pairs if p.a == "link_1")
        assert pair.distance == pytest.approx(surface - R_LINK, abs=1e-6), shape


# --------------------------------------------------------------------------------- Panda
def test_panda_neutral_and_ready_are_free_with_srdf(registry) -> None:
    panda = registry.get("panda")
    for mode in GEOMETRY_MODES:
        cm = collision_model(panda, mode)
        for q in (panda.neutral(), np.array(READY)):
            report = cm.check(q)
            assert not report.in_collision and not report.self_collision, (mode, q)


def test_panda_without_srdf_reports_the_pairs_the_srdf_disables(registry) -> None:
    """The SRDF matters: at neutral the fingers touch, and the SRDF disables that pair."""
    panda = registry.get("panda")
    bare = RobotModel("panda-bare", panda.urdf_text, package_dirs=panda.package_dirs)
    report = collision_model(bare, "mesh").check(bare.neutral())
    pairs = {(p.a, p.b) for p in report.pairs}
    assert ("panda_leftfinger", "panda_rightfinger") in pairs
    disabled = srdf_disabled_pairs(panda.srdf_text, [])
    assert all(frozenset(p) in disabled for p in pairs)


def _mesh_in_frame(robot: RobotModel, urdf: yourdfpy.URDF, link: str, frame: str) -> np.ndarray:
    """Vertices of ``link``'s collision mesh expressed in ``frame`` (yourdfpy FK)."""
    (collision,) = urdf.link_map[link].collisions
    path = collision.geometry.mesh.filename.replace("package://", robot.package_dirs[0] + "/")
    verts = trimesh.load(path, force="mesh").vertices
    T = np.linalg.inv(urdf.get_transform(frame, urdf.base_link)) @ urdf.get_transform(
        link, urdf.base_link
    )
    T = T @ (collision.origin if collision.origin is not None else np.eye(4))
    return verts @ T[:3, :3].T + T[:3, 3]


def test_panda_folded_hand_in_base_is_reported(registry) -> None:
    panda = registry.get("panda")
    q = np.array(FOLDED)
    for mode in GEOMETRY_MODES:
        report = collision_model(panda, mode).check(q)
        assert report.in_collision and report.self_collision and not report.environment_collision
        assert ("panda_link0", "panda_hand") in {(p.a, p.b) for p in report.pairs}
        assert report.min_distance is not None and report.min_distance <= 0.0
    # Independent evidence: yourdfpy FK + the STL files; some hand vertex lies inside the
    # (convex) base mesh's hull.
    urdf = yourdfpy.URDF.load(
        str(registry.catalog["panda"].urdf_path),
        load_meshes=False,
        build_collision_scene_graph=False,
        load_collision_meshes=False,
    )
    urdf.update_cfg(q)
    base = _mesh_in_frame(panda, urdf, "panda_link0", "panda_link0")
    hand = _mesh_in_frame(panda, urdf, "panda_hand", "panda_link0")
    eq = ConvexHull(base).equations
    inside = np.all(hand @ eq[:, :3].T + eq[:, 3] < -1e-4, axis=1)
    assert inside.any()


@pytest.mark.parametrize("robot_id", ["panda", "ur5", "so100", "z1"])
def test_convex_hulls_are_conservative(registry, robot_id: str) -> None:
    """A hull contains its mesh: hull distances never exceed mesh distances (GJK tol)."""
    robot = registry.get(robot_id)
    mesh, hull = collision_model(robot, "mesh"), collision_model(robot, "convex")
    rng = np.random.default_rng(7)
    lo = np.where(np.isfinite(robot.lower), robot.lower, -math.pi)
    hi = np.where(np.isfinite(robot.upper), robot.upper, math.pi)
    for q in rng.uniform(lo, hi, (6, robot.n)):
        dm = {(p.a, p.b): p.distance for p in mesh.check(q, distances=True).pairs}
        dh = {(p.a, p.b): p.distance for p in hull.check(q, distances=True).pairs}
        assert dm.keys() == dh.keys()
        for key, d in dm.items():
            assert dh[key] <= max(d, 0.0) + 1e-5, key
        if mesh.check(q).in_collision:
            assert hull.check(q).in_collision


# ------------------------------------------------------------------------------ pair rules
def _urdf_joints(urdf_text: str) -> list[tuple[str, str, str]]:
    root = ElementTree.fromstring(urdf_text)
    return [
        (j.get("type"), j.find("parent").get("link"), j.find("child").get("link"))
        for j in root.iter("joint")
        if j.find("parent") is not None
    ]


@pytest.mark.parametrize("robot_id", ["panda", "ur5", "kinova", "z1"])
def test_adjacent_links_never_checked(registry, robot_id: str) -> None:
    """No link joined by a URDF joint to another (directly or via fixed joints) is paired."""
    robot = registry.get(robot_id)
    bare = RobotModel(robot_id + "-bare", robot.urdf_text, package_dirs=robot.package_dirs)
    joints = _urdf_joints(robot.urdf_text)
    # Rigid groups: links connected by fixed joints.
    group = {}
    for _type, parent, child in joints:
        group.setdefault(parent, {parent})
        group.setdefault(child, {child})
    for jtype, parent, child in joints:
        if jtype == "fixed":
            merged = group[parent] | group[child]
            for link in merged:
                group[link] = merged
    forbidden = set()
    for _type, parent, child in joints:
        for a in group[parent]:
            for b in group[child]:
                forbidden.add(frozenset((a, b)))
    for a in group:
        for b in group[a]:
            if a != b:
                forbidden.add(frozenset((a, b)))
    for r in (robot, bare):
        pairs = collision_model(r, "mesh").link_pairs
        assert pairs and not any(frozenset(p) in forbidden for p in pairs)
        assert pairs == collision_link_pairs(r)
    # Reported pairs (distances = every checked pair) also exclude them.
    report = collision_model(robot, "convex").check(robot.mid_range(), distances=True)
    assert not any(frozenset((p.a, p.b)) in forbidden for p in report.pairs)
    # With the SRDF, none of its disabled pairs is checked.
    disabled = srdf_disabled_pairs(robot.srdf_text, [])
    assert not any(frozenset(p) in disabled for p in collision_link_pairs(robot))


def _chain_urdf(with_middle_geometry: bool) -> str:
    """a --j1--> b --j2--> c --j3--> d, boxes on a, c, d and optionally b."""

    def link(name: str, geometry: bool) -> str:
        box = '<collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>'
        return f'<link name="{name}">{box if geometry else ""}</link>'

    def joint(name: str, parent: str, child: str) -> str:
        return (
            f'<joint name="{name}" type="revolute"><parent link="{parent}"/>'
            f'<child link="{child}"/><origin xyz="0 0 0.3"/><axis xyz="0 1 0"/>'
            '<limit lower="-3" upper="3" effort="1" velocity="1"/></joint>'
        )

    return (
        '<robot name="chain">'
        + link("a", True)
        + link("b", with_middle_geometry)
        + link("c", True)
        + link("d", True)
        + joint("j1", "a", "b")
        + joint("j2", "b", "c")
        + joint("j3", "c", "d")
        + "</robot>"
    )


def test_geometryless_bodies_are_bridged() -> None:
    """a and c touch at a geometry-less joint body b: adjacent; with geometry on b, not."""
    bridged = RobotModel("chain1", _chain_urdf(False))
    assert collision_link_pairs(bridged) == [("a", "d")]
    plain = RobotModel("chain2", _chain_urdf(True))
    assert collision_link_pairs(plain) == [("a", "c"), ("a", "d"), ("b", "d")]
    assert collision_model(plain, "mesh").link_pairs == [("a", "c"), ("a", "d"), ("b", "d")]


def test_srdf_rules() -> None:
    srdf = """<robot name="r">
      <disable_collisions link1="a" link2="c" reason="Never"/>
      <disable_default_collisions link="d"/>
      <enable_collisions link1="d" link2="b"/>
    </robot>"""
    disabled = srdf_disabled_pairs(srdf, ["a", "b", "c", "d"])
    assert disabled == {frozenset("ac"), frozenset("da"), frozenset("dc")}
    robot = RobotModel("chain3", _chain_urdf(True), srdf_text=srdf)
    assert collision_link_pairs(robot) == [("b", "d")]


def test_world_fixed_links_are_not_checked_against_obstacles(registry) -> None:
    """A table under the base touches link0 only: not a collision (both are static)."""
    panda = registry.get("panda")
    table = parse_obstacles(
        [{"name": "table", "shape": "box", "size": [1, 1, 0.1], "pose": {"position": [0, 0, 0]}}]
    )
    cm = collision_model(panda, "mesh")
    report = cm.check(np.array(READY), table, distances=True)
    assert not report.in_collision
    assert "panda_link0" not in {p.a for p in report.pairs if p.kind == "environment"}
    assert "panda_link0" not in cm.moving_links


# ------------------------------------------------------------------------------ misc
def test_collision_filter_predicate(planar2: RobotModel) -> None:
    q = np.array([0.0, 0.0])
    block = parse_obstacles([sphere("block", [1.4, 0.0, 0.0], 0.1)])
    accept = collision_filter(planar2, block)
    assert not accept(q)
    assert accept(np.array([0.0, 1.2]))


def test_threads_get_their_own_scratch(registry) -> None:
    """Concurrent checks of different configurations give the sequential answers."""
    panda = registry.get("panda")
    cm = collision_model(panda, "convex")
    qs = [np.array(READY), np.array(FOLDED)] * 40
    expected = [cm.check(q, distances=True).min_distance for q in qs]
    with ThreadPoolExecutor(4) as pool:
        got = list(pool.map(lambda q: cm.check(q, distances=True).min_distance, qs))
    assert got == expected


def test_unknown_geometry_mode(planar2: RobotModel) -> None:
    with pytest.raises(InvalidInputError) as err:
        collision_model(planar2, "voxels")
    assert err.value.field == "geometry"


def test_batch_matches_single_checks(registry) -> None:
    panda = registry.get("panda")
    cm = collision_model(panda, "mesh")
    qs = np.array([READY, FOLDED, panda.neutral()])
    batch = cm.check_batch(qs)
    assert [r.in_collision for r in batch] == [cm.check(q).in_collision for q in qs]
    assert [r.in_collision for r in batch] == [False, True, False]


def test_answers_do_not_depend_on_history(registry) -> None:
    """No GJK warm start: the same query gives bit-identical distances whatever came before."""
    panda = registry.get("panda")
    obstacles = parse_obstacles(
        [{"name": "post", "shape": "cylinder", "radius": 0.05, "length": 1.0}]
    )
    cm = collision_model(panda, "mesh")
    q = np.array(READY)
    first = [(p.a, p.b, p.distance) for p in cm.check(q, obstacles, distances=True).pairs]
    cm.check(np.array(FOLDED), obstacles, distances=True)
    again = [(p.a, p.b, p.distance) for p in cm.check(q, obstacles, distances=True).pairs]
    assert first == again


def test_collision_aware_ik_core(planar2: RobotModel) -> None:
    """ik.solve with the collision predicate skips the elbow the obstacle blocks."""
    import pinocchio as pin

    from app.kinematics import ik
    from app.kinematics.ik.problem import IKOptions

    x, y = 1.2, 0.6
    c2 = (x * x + y * y - L1**2 - L2**2) / (2 * L1 * L2)
    sols = []
    for t2 in (math.acos(c2), -math.acos(c2)):
        sols.append((math.atan2(y, x) - math.atan2(L2 * math.sin(t2), L1 + L2 * math.cos(t2)), t2))
    blocked, free = sols
    elbow = [L1 * math.cos(blocked[0]), L1 * math.sin(blocked[0]), 0.0]
    accept = collision_filter(planar2, parse_obstacles([sphere("rock", elbow, 0.1)]))
    target = pin.SE3(np.eye(3), np.array([x, y, 0.0]))
    res = ik.solve(
        planar2,
        target,
        IKOptions(frame="tool", mode="position", num_solutions=2, timeout_ms=300),
        accept=accept,
    )
    assert res.success and len(res.solutions) == 1
    np.testing.assert_allclose(res.solutions[0].q, free, atol=1e-6)


@pytest.mark.parametrize(
    ("items", "field"),
    [
        ("box", "obstacles"),
        (["box"], "obstacles.0"),
        ([{"name": "a", "shape": "sphere", "radius": True}], "obstacles.0.radius"),
        ([{"name": "a", "shape": "sphere", "radius": math.nan}], "obstacles.0.radius"),
        ([{"name": "a", "shape": "sphere", "radius": math.inf}], "obstacles.0.radius"),
        ([{"name": "a", "shape": "box", "size": "1 1 1"}], "obstacles.0.size"),
        ([{"name": "a", "shape": "box", "size": [1, 1, math.nan]}], "obstacles.0.size.2"),
        ([{"name": "a", "shape": "sphere", "radius": 1, "pose": [0, 0, 0]}], "obstacles.0.pose"),
        (
            [{"name": "a", "shape": "sphere", "radius": 1, "pose": {"rpy": [0, 0, 0]}}],
            "obstacles.0.pose.rpy",
        ),
        ([{"name": "a" * 129, "shape": "sphere", "radius": 1}], "obstacles.0.name"),
        ([{"name": "a", "shape": "sphere", "radius": 1}] * 2, "obstacles.1.name"),
        ([{"name": f"s{i}", "shape": "sphere", "radius": 1} for i in range(1001)], "obstacles"),
    ],
)
def test_parse_obstacles_rejects(items, field: str) -> None:
    with pytest.raises(InvalidInputError) as err:
        parse_obstacles(items)
    assert err.value.field == field


def test_parse_obstacles_normalises_orientation() -> None:
    half = math.sqrt(0.5)
    (o,) = parse_obstacles(
        [
            {
                "name": "a",
                "shape": "box",
                "size": [1, 2, 3],
                "pose": {"position": [1, 2, 3], "orientation": [0, 0, -half * 1.0004, -half]},
            }
        ]
    )
    assert o.orientation[3] > 0 and math.isclose(np.linalg.norm(o.orientation), 1.0)
    M = o.placement()
    np.testing.assert_allclose(M.rotation, [[0, -1, 0], [1, 0, 0], [0, 0, 1]], atol=1e-3)
    assert o.to_json()["size"] == [1.0, 2.0, 3.0]


def test_mesh_by_mesh_geometry_is_pinocchios_own(registry) -> None:
    """The collision geometry built mesh by mesh (headers checked, the GIL released between
    meshes) is exactly what ``pin.buildGeomFromUrdfString`` builds in one call, for every
    built-in robot: names, parent joints and frames, placements, shapes, mesh files,
    scales, triangles and vertices."""
    import pinocchio as pin

    from app.kinematics.meshes import MeshLimits, collision_geometry

    meshes = 0
    robots = [registry.get(robot_id) for robot_id in registry.ids()]
    ur5 = registry.get("ur5")  # and its meshes scaled (with the repeated mesh shared once)
    scaled = ur5.urdf_text.replace('.stl"/>', '.stl" scale="2 1 0.5"/>')
    assert scaled.count('scale="2 1 0.5"') >= 6
    robots.append(RobotModel("scaled", scaled, package_dirs=ur5.package_dirs))
    for robot in robots:
        robot_id, dirs = robot.id, robot.package_dirs
        ref = pin.buildGeomFromUrdfString(
            robot.model, robot.urdf_text, pin.COLLISION, package_dirs=dirs
        )
        ours = collision_geometry(robot.model, robot.urdf_text, dirs, MeshLimits())
        assert ours.ngeoms == ref.ngeoms, robot_id
        for a, b in zip(ref.geometryObjects, ours.geometryObjects, strict=True):
            assert (a.name, a.parentJoint, a.parentFrame) == (b.name, b.parentJoint, b.parentFrame)
            assert np.array_equal(a.placement.homogeneous, b.placement.homogeneous), a.name
            assert type(a.geometry) is type(b.geometry), a.name
            assert (a.meshPath, list(a.meshScale)) == (b.meshPath, list(b.meshScale)), a.name
            if hasattr(a.geometry, "num_tris"):
                meshes += 1
                assert a.geometry.num_tris == b.geometry.num_tris, a.name
                assert np.array_equal(a.geometry.vertices(), b.geometry.vertices()), a.name
    assert meshes > 40
