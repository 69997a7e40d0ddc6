"""Dynamics core: the textbook 2-link arm in a vertical plane (closed form), invariants of
the equations of motion on the catalog's robots (finite differences), payloads, refusals."""

from __future__ import annotations

import math

import numpy as np
import pytest

from app.kinematics.dynamics import (
    GRAVITY,
    compute_dynamics,
    gravity_torques,
    inverse_dynamics,
    payload,
)
from app.kinematics.errors import InvalidInputError, MissingInertiaError, UnknownNameError
from app.kinematics.models import RobotModel
from app.kinematics.payload import max_payload, max_payloads
from tests.kinematics.chains import C1, C2, E1, E2, I1, I2, L1, L2, M1, M2, vertical_2link


@pytest.fixture(scope="module")
def arm() -> RobotModel:
    return RobotModel("vertical2", vertical_2link(), ee_frame="tip")


def closed_form(q, qd, qdd):
    """Spong, Hutchinson & Vidyasagar, *Robot Modeling and Control*, §7.4 (two-link
    planar arm): M, C (Christoffel), g and τ."""
    c2, s2 = math.cos(q[1]), math.sin(q[1])
    m11 = M1 * C1**2 + M2 * (L1**2 + C2**2 + 2 * L1 * C2 * c2) + I1 + I2
    m12 = M2 * (C2**2 + L1 * C2 * c2) + I2
    m22 = M2 * C2**2 + I2
    M = np.array([[m11, m12], [m12, m22]])
    h = -M2 * L1 * C2 * s2
    C = np.array([[h * qd[1], h * (qd[0] + qd[1])], [-h * qd[0], 0.0]])
    g1 = (M1 * C1 + M2 * L1) * GRAVITY * math.cos(q[0]) + M2 * C2 * GRAVITY * math.cos(q[0] + q[1])
    g2 = M2 * C2 * GRAVITY * math.cos(q[0] + q[1])
    g = np.array([g1, g2])
    return M, C, g, M @ qdd + C @ qd + g


STATES = [
    ((0.0, 0.0), (0.0, 0.0), (0.0, 0.0)),
    ((0.3, -0.8), (1.1, -0.4), (0.5, 2.0)),
    ((-1.2, 2.1), (-0.7, 1.9), (-1.5, 0.3)),
    ((2.5, 0.4), (0.2, 0.0), (0.0, -3.0)),
]


@pytest.mark.parametrize("q, qd, qdd", STATES)
def test_two_link_closed_form(arm, q, qd, qdd):
    q, qd, qdd = map(np.array, (q, qd, qdd))
    M, C, g, tau = closed_form(q, qd, qdd)
    d = compute_dynamics(arm, q, qd, qdd)
    np.testing.assert_allclose(d.mass_matrix, M, rtol=0, atol=1e-13)
    np.testing.assert_allclose(d.coriolis_matrix, C, rtol=0, atol=1e-13)
    np.testing.assert_allclose(d.gravity, g, rtol=0, atol=1e-12)
    np.testing.assert_allclose(d.torques, tau, rtol=0, atol=1e-12)
    np.testing.assert_allclose(d.coriolis, C @ qd, rtol=0, atol=1e-13)
    np.testing.assert_allclose(d.inertial, M @ qdd, rtol=0, atol=1e-12)
    assert d.mass == pytest.approx(M1 + M2, abs=1e-15)
    np.testing.assert_allclose(d.effort_limits, [E1, E2])
    np.testing.assert_allclose(d.ratios, np.abs(tau) / [E1, E2], rtol=1e-12)
    assert d.binding == ["j1", "j2"][int(np.argmax(np.abs(tau) / [E1, E2]))]


def test_centre_of_mass_closed_form(arm):
    q = np.array([0.4, -1.1])
    x1, z1 = C1 * math.cos(q[0]), C1 * math.sin(q[0])
    x2 = L1 * math.cos(q[0]) + C2 * math.cos(q[0] + q[1])
    z2 = L1 * math.sin(q[0]) + C2 * math.sin(q[0] + q[1])
    com = np.array([M1 * x1 + M2 * x2, 0.0, M1 * z1 + M2 * z2]) / (M1 + M2)
    np.testing.assert_allclose(compute_dynamics(arm, q).com, com, atol=1e-15)


def tip_jacobian(q):
    """World-aligned translation Jacobian of the tip in (x, z) (closed form)."""
    s1, c1 = math.sin(q[0]), math.cos(q[0])
    s12, c12 = math.sin(q[0] + q[1]), math.cos(q[0] + q[1])
    return np.array([[-L1 * s1 - L2 * s12, -L2 * s12], [L1 * c1 + L2 * c12, L2 * c12]])


@pytest.mark.parametrize("q, qdd", [((0.3, -0.8), (0.5, 2.0)), ((-1.0, 1.7), (0.0, 0.0))])
def test_point_payload_at_rest_is_jacobian_transpose_of_its_weight_and_inertial_force(arm, q, qdd):
    q, qdd = np.array(q), np.array(qdd)
    mp = 1.7
    Jv = tip_jacobian(q)
    force = mp * (Jv @ qdd + np.array([0.0, GRAVITY]))  # m (a + g ẑ), at rest: J̇ q̇ = 0
    bare = compute_dynamics(arm, q, None, qdd)
    loaded = compute_dynamics(arm, q, None, qdd, load=payload(arm, mp))
    np.testing.assert_allclose(loaded.torques - bare.torques, Jv.T @ force, atol=1e-12)
    assert loaded.mass == pytest.approx(M1 + M2 + mp)


def test_payload_inertia_adds_to_the_mass_matrix(arm):
    """A payload whose centre of mass sits on the tip with inertia I_p about y adds
    mp·(tip Jacobian)ᵀ(tip Jacobian) + I_p·[1 1]ᵀ[1 1] to M (parallel-axis theorem)."""
    q = np.array([0.2, 0.9])
    mp, ip = 0.8, 0.05
    bare = compute_dynamics(arm, q).mass_matrix
    got = compute_dynamics(arm, q, load=payload(arm, mp, inertia=[0.03, 0, 0, ip, 0, 0.03]))
    Jv = tip_jacobian(q)
    np.testing.assert_allclose(
        got.mass_matrix - bare, mp * Jv.T @ Jv + ip * np.ones((2, 2)), atol=1e-13
    )


def test_payload_offset_in_frame_axes(arm):
    """A centre of mass 0.1 m along the tip frame's x is a point payload 0.1 m further out."""
    q = np.array([0.5, -0.3])
    offset = RobotModel(
        "vertical2_long",
        vertical_2link().replace(f'xyz="{L2} 0 0"', f'xyz="{L2 + 0.1} 0 0"'),
        ee_frame="tip",
    )
    a = compute_dynamics(arm, q, load=payload(arm, 2.0, com=[0.1, 0, 0])).gravity
    b = compute_dynamics(offset, q, load=payload(offset, 2.0)).gravity
    np.testing.assert_allclose(a, b, atol=1e-12)


def test_wrench_adds_statics(arm):
    q = np.array([0.3, 0.6])
    F = np.array([3.0, 0.0, -2.0, 0.0, 0.5, 0.0])  # world: fx, fz and a moment about y
    d = compute_dynamics(arm, q, wrench=F)
    Jv = tip_jacobian(q)
    expected = Jv.T @ F[[0, 2]] + np.array([-1.0, -1.0]) * F[4]  # axis −y
    np.testing.assert_allclose(d.wrench_torques, expected, atol=1e-13)
    np.testing.assert_allclose(d.torques, d.gravity + expected, atol=1e-12)


# --- invariants on real robots ---------------------------------------------------------------

ROBOTS = ["ur5", "panda", "kinova", "xarm"]


@pytest.fixture(scope="module", params=ROBOTS)
def robot(request, registry) -> RobotModel:
    return registry.get(request.param)


def state(robot: RobotModel, seed: int):
    rng = np.random.default_rng(seed)
    lo = np.maximum(robot.lower, -3.0)
    hi = np.minimum(robot.upper, 3.0)
    return rng.uniform(lo, hi), rng.normal(size=robot.n), rng.normal(size=robot.n)


@pytest.mark.parametrize("seed", [0, 1])
def test_equations_of_motion_hold(robot, seed):
    q, qd, qdd = state(robot, seed)
    load = payload(robot, 1.3, com=[0.01, -0.02, 0.04], inertia=[0.01, 0.001, 0, 0.012, 0, 0.009])
    for p in (None, load):
        d = compute_dynamics(robot, q, qd, qdd, load=p)
        np.testing.assert_allclose(
            d.mass_matrix @ qdd + d.coriolis_matrix @ qd + d.gravity, d.torques, atol=1e-12
        )
        np.testing.assert_allclose(d.mass_matrix, d.mass_matrix.T, atol=0)
        assert np.linalg.eigvalsh(d.mass_matrix).min() > 0


def test_mass_matrix_derivative_minus_twice_coriolis_is_skew(robot):
    q, qd, _ = state(robot, 3)
    h = 1e-6
    Md = (
        compute_dynamics(robot, q + h * qd).mass_matrix
        - compute_dynamics(robot, q - h * qd).mass_matrix
    ) / (2 * h)
    S = Md - 2 * compute_dynamics(robot, q, qd).coriolis_matrix
    assert np.abs(S + S.T).max() < 1e-6


def test_gravity_is_the_gradient_of_potential_energy(robot):
    q, _, _ = state(robot, 4)

    def potential(x):
        d = compute_dynamics(robot, x)
        return d.mass * GRAVITY * d.com[2]

    h = 1e-6
    grad = [(potential(q + h * e) - potential(q - h * e)) / (2 * h) for e in np.eye(robot.n)]
    np.testing.assert_allclose(compute_dynamics(robot, q).gravity, grad, atol=1e-6)


def test_kinetic_energy_from_the_mass_matrix(robot):
    """½ q̇ᵀ M q̇ equals the power balance: d/dt(T + V) = q̇ᵀ τ at q̈ from τ (finite steps)."""
    q, qd, qdd = state(robot, 5)
    d = compute_dynamics(robot, q, qd, qdd)

    def energy(t):
        x, v = q + t * qd + 0.5 * t**2 * qdd, qd + t * qdd
        e = compute_dynamics(robot, x)
        return 0.5 * v @ e.mass_matrix @ v + e.mass * GRAVITY * e.com[2]

    h = 1e-5
    assert (energy(h) - energy(-h)) / (2 * h) == pytest.approx(qd @ d.torques, rel=1e-6, abs=1e-6)


def test_batch_matches_single(robot):
    rng = np.random.default_rng(7)
    qs = np.array([state(robot, s)[0] for s in range(4)])
    qds, qdds = rng.normal(size=qs.shape), rng.normal(size=qs.shape)
    got = inverse_dynamics(robot, qs, qds, qdds)
    for k in range(4):
        np.testing.assert_allclose(
            got[k], compute_dynamics(robot, qs[k], qds[k], qdds[k]).torques, atol=1e-13
        )
    np.testing.assert_allclose(
        gravity_torques(robot, qs)[1], compute_dynamics(robot, qs[1]).gravity, atol=1e-13
    )


# --- maximum payload ---------------------------------------------------------------------------


def bisect_payload(robot, q, frame=None, com=(0, 0, 0)):
    """The largest mass whose gravity torques stay within every effort limit, by bisection
    on :func:`compute_dynamics` with the payload attached."""

    def holds(m):
        d = compute_dynamics(robot, q, load=payload(robot, m, frame, com))
        return bool(np.all(~(d.ratios > 1.0)))

    lo, hi = 0.0, 1.0
    while holds(hi):
        lo, hi = hi, 2 * hi
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if holds(mid) else (lo, mid)
    return lo


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_max_payload_matches_bisection(robot, seed):
    q, _, _ = state(robot, 10 + seed)
    got = max_payload(robot, q, com=[0.0, 0.0, 0.05])
    assert got.holds_itself
    expected = bisect_payload(robot, q, com=(0.0, 0.0, 0.05))
    assert got.mass == pytest.approx(expected, rel=1e-9)
    d = compute_dynamics(robot, q, load=payload(robot, got.mass, com=[0, 0, 0.05]))
    assert d.binding == got.limiting_joint
    assert np.nanmax(d.ratios) == pytest.approx(1.0, abs=1e-9)
    np.testing.assert_allclose(got.torques, d.gravity, atol=1e-9)


def test_max_payload_closed_form(arm):
    q = np.array([0.0, 0.0])  # stretched horizontally: every joint carries the full moment
    g1, g2 = closed_form(q, np.zeros(2), np.zeros(2))[2]
    b1, b2 = GRAVITY * (L1 + L2), GRAVITY * L2
    got = max_payload(arm, q)
    expected = min((E1 - g1) / b1, (E2 - g2) / b2)
    assert got.mass == pytest.approx(expected, rel=1e-12)
    assert got.limiting_joint == ("j1" if (E1 - g1) / b1 < (E2 - g2) / b2 else "j2")
    np.testing.assert_allclose(got.per_kg, [b1, b2], rtol=1e-12)


def test_max_payload_unbounded_and_over_limit(arm):
    up = max_payload(arm, np.array([math.pi / 2, 0.0]))  # straight up: weight along the arm
    assert up.mass == math.inf and up.limiting_joint is None
    weak = RobotModel(
        "weak", vertical_2link().replace(f'effort="{E1}"', 'effort="1"'), ee_frame="tip"
    )
    over = max_payload(weak, np.zeros(2))
    assert over.mass == 0.0 and not over.holds_itself and over.limiting_joint == "j1"


def test_max_payload_along_a_path_with_a_tool(arm):
    qs = np.array([[0.0, 0.0], [0.5, 0.2], [1.0, -0.4]])
    tool = payload(arm, 0.5)
    got = max_payloads(arm, qs, load=tool)
    for q, m in zip(qs, got, strict=True):
        assert m.mass + 0.5 == pytest.approx(max_payload(arm, q).mass, rel=1e-12)


# --- refusals -----------------------------------------------------------------------------------


def test_robot_without_inertias_names_the_link(registry):
    with pytest.raises(MissingInertiaError) as e:
        compute_dynamics(registry.get("planar3r"), np.zeros(3))
    assert e.value.field == "robot_id" and "'link_1'" in e.value.message


def test_one_massless_moving_link_is_refused(arm):
    urdf = vertical_2link().replace(f'<mass value="{M2}"/>', '<mass value="0"/>')
    urdf = urdf.replace(f'iyy="{I2}"', 'iyy="0"').replace('izz="0.02"', 'izz="0"')
    urdf = urdf.replace('ixx="0.01"', 'ixx="0"')
    bad = RobotModel("massless2", urdf, ee_frame="tip")
    with pytest.raises(MissingInertiaError) as e:
        max_payload(bad, np.zeros(2))
    assert "'link2'" in e.value.message


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"mass": -1.0}, "payload.mass"),
        ({"mass": math.nan}, "payload.mass"),
        ({"mass": 2e6}, "payload.mass"),
        ({"mass": 1.0, "com": [0, 0, math.inf]}, "payload.com.2"),
        ({"mass": 1.0, "com": [0, 0]}, "payload.com"),
        ({"mass": 1.0, "inertia": [1, 0, 0, 1, 0]}, "payload.inertia"),
        ({"mass": 1.0, "inertia": [1, 0, 0, 1, 0, 3]}, "payload.inertia"),  # 3 > 1 + 1
        ({"mass": 1.0, "inertia": [1, 0, 0, -1, 0, 1]}, "payload.inertia"),
        ({"mass": 1.0, "inertia": [[1, 0.5, 0], [0, 1, 0], [0, 0, 1]]}, "payload.inertia"),
        ({"mass": 1.0, "inertia": [1, 0, 0, 1, 0, math.nan]}, "payload.inertia.5"),
    ],
)
def test_bad_payload_names_the_field(arm, kwargs, field):
    with pytest.raises(InvalidInputError) as e:
        payload(arm, **kwargs)
    assert e.value.field == field


def test_unknown_payload_frame(arm):
    with pytest.raises(UnknownNameError) as e:
        payload(arm, 1.0, "nope")
    assert e.value.field == "payload.frame"


def test_scratch_model_is_restored_after_a_payload(arm):
    q = np.array([0.3, 0.2])
    before = compute_dynamics(arm, q).torques
    compute_dynamics(arm, q, load=payload(arm, 5.0, inertia=[1, 0, 0, 1, 0, 1]))
    np.testing.assert_array_equal(compute_dynamics(arm, q).torques, before)
