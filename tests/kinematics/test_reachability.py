"""Reachability maps: vectorised FK/Jacobian vs Pinocchio, orientation bins, the planar
2-link annulus |l1 − l2| ≤ r ≤ l1 + l2 and its closed-form manipulability, process builds,
cancellation, storage, every bad input."""

from __future__ import annotations

import math

import numpy as np
import pytest

from app.kinematics.analysis import (
    compute_manipulability,
    yoshikawa_batch,
    yoshikawa_components,
)
from app.kinematics.chain import PinocchioChain, SerialChain
from app.kinematics.errors import Cancelled, InvalidInputError
from app.kinematics.fk import forward_kinematics
from app.kinematics.models import RobotModel
from app.kinematics.reachability.bins import (
    orientation_bin,
    orientation_bin_from_rotation,
    orientation_bins,
)
from app.kinematics.reachability.build import MapBuilder, Progress, chunk_samples
from app.kinematics.reachability.map import ReachabilityMap, summarize
from app.kinematics.reachability.spec import default_bounds, make_spec
from app.kinematics.rotations import matrix_to_quaternion, quaternion_to_matrix
from app.workers.map_build import build_map
from tests.kinematics.chains import COLLIDING_URDF, L1, L2, planar2_urdf, planar_map_spec


@pytest.fixture(scope="module")
def planar() -> RobotModel:
    return RobotModel("planar2_test", planar2_urdf(), ee_frame="tip")


# ------------------------------------------------------------------------ Yoshikawa
def test_yoshikawa_components_against_svd():
    rng = np.random.default_rng(4)
    for m, k in ((6, 7), (6, 6), (3, 7), (2, 2), (6, 2)):
        J = rng.normal(size=(50, m, k))
        J[0, 0, :] = 0.0  # a rank-deficient one (rows and columns)
        J[0, :, 0] = J[0, :, 1]
        expected = np.prod(np.linalg.svd(J, compute_uv=False), axis=1)
        got = yoshikawa_components(J.transpose(1, 2, 0))
        np.testing.assert_allclose(got[1:], expected[1:], rtol=1e-9)
        assert got[0] == pytest.approx(0.0, abs=1e-6)
        np.testing.assert_allclose(yoshikawa_batch(J)[1:], expected[1:], rtol=1e-9)


# --------------------------------------------------------------------- orientation bins
def random_quaternions(n, seed=0):
    q = np.random.default_rng(seed).normal(size=(n, 4))
    return q / np.linalg.norm(q, axis=1, keepdims=True)


@pytest.mark.parametrize("d", [1, 2, 4, 7])
def test_orientation_bins_consistent_and_cover(d):
    q = random_quaternions(40_000)
    b = orientation_bin(q, d)
    assert np.array_equal(b, orientation_bin(-q, d))  # q and −q are one rotation
    R = quaternion_to_matrix(q)
    assert np.array_equal(b, orientation_bin_from_rotation(R.transpose(1, 2, 0), d))
    counts = np.bincount(b, minlength=orientation_bins(d))
    assert counts.size == 4 * d**3 and counts.min() > 0
    if d <= 2:  # uniform rotations: equal-angle cells differ in volume by at most ~2×
        assert counts.max() / counts.min() < 2.6


def test_orientation_bin_documented_layout():
    """Bins worked out by hand from the module doc (d = 4): index k·d³ + i₀·d² + i₁·d + i₂,
    a_i = arctan(q_i/q_k), i = ⌊(a/(π/2) + 1/2)·d⌋; for face w a rotation θ about x has
    a₀ = θ/2."""
    s60, c60 = math.sin(math.radians(30)), math.cos(math.radians(30))
    cases = {
        (0.0, 0.0, 0.0, 1.0): 3 * 64 + 2 * 16 + 2 * 4 + 2,  # identity: face w, centre
        (s60, 0.0, 0.0, c60): 3 * 64 + 3 * 16 + 2 * 4 + 2,  # 60° about x: a₀ = 30°
        (0.0, -s60, 0.0, c60): 3 * 64 + 2 * 16 + 0 * 4 + 2,  # −60° about y: a₁ = −30°
        (0.0, 0.0, s60, -c60): 3 * 64 + 2 * 16 + 2 * 4 + 0,  # −q of −60° about z: flipped
        (1.0, 0.0, 0.0, 0.0): 0 * 64 + 2 * 16 + 2 * 4 + 2,  # 180° about x: face x
        (0.0, 0.0, 1.0, 0.0): 2 * 64 + 2 * 16 + 2 * 4 + 2,  # 180° about z: face z
    }
    q = np.array(list(cases), dtype=float)
    expected = np.array(list(cases.values()))
    np.testing.assert_array_equal(orientation_bin(q, 4), expected)
    R = quaternion_to_matrix(q).transpose(1, 2, 0)
    np.testing.assert_array_equal(orientation_bin_from_rotation(R, 4), expected)


def test_orientation_bin_neighbours_are_close():
    """Rotations in one bin stay close (d = 4: a bin spans about 45° per axis)."""
    q = random_quaternions(20_000, seed=1)
    b = orientation_bin(q, 4)
    for cell in np.unique(b)[:40]:
        qs = q[b == cell]
        dots = np.abs(qs @ qs.T)
        angle = 2 * np.degrees(np.arccos(np.clip(dots.min(), -1, 1)))
        assert angle < 70.0


# ----------------------------------------------------------------- the planar annulus
def voxel_centres(spec):
    idx = np.stack(np.meshgrid(*[np.arange(n) for n in spec.shape], indexing="ij"), -1)
    return np.asarray(spec.lower) + (idx.reshape(-1, 3) + 0.5) * spec.voxel_size


def test_planar_map_is_the_annulus(planar):
    spec = planar_map_spec(planar)
    best = build_map(planar, spec)
    m = ReachabilityMap({"spec": spec.__dict__.copy(), **summarize(best)}, best)
    c = voxel_centres(spec)
    r = np.hypot(c[:, 0], c[:, 1])
    reach, val, ok = m.query(c, None)
    half_diag = spec.voxel_size * math.sqrt(2) / 2
    inner, outer = abs(L1 - L2), L1 + L2
    well_inside = (r > inner + half_diag + 0.03) & (r < outer - half_diag - 0.03)
    well_outside = (r < inner - half_diag) | (r > outer + half_diag)
    assert ok.all() and well_inside.sum() > 1000
    assert reach[well_inside].all()
    assert not reach[well_outside].any()
    # best manipulability in a voxel ≈ the closed form l1·l2·|sin θ2| at its radius
    c2 = (r**2 - L1**2 - L2**2) / (2 * L1 * L2)
    w = L1 * L2 * np.sqrt(np.clip(1 - c2**2, 0, 1))
    dw = L1 * L2 * half_diag * r / (L1 * L2) / np.sqrt(np.clip(1 - c2**2, 1e-3, 1)) + 1e-2
    sel = well_inside & (np.abs(c2) < 0.9)
    assert np.all(val[sel] <= w[sel] + dw[sel])
    assert np.all(val[sel] >= w[sel] - dw[sel] - 0.02)


def test_planar_exact_manipulability_at_sampled_cells(planar):
    """Each sample's cell and value against the closed form: the tip at
    (l1·c1 + l2·c12, l1·s1 + l2·s12, 0) lands in voxel ⌊(p − lower)/s⌋ with value
    l1·l2·|sin θ2| (float32), sample by sample (one orientation bin, all in the box)."""
    spec = planar_map_spec(planar, samples=4096)
    cells, vals = MapBuilder(planar, spec).cells(0, 4096)
    Q = chunk_samples(spec, 0, 4096)
    t1, t2 = Q[:, 0], Q[:, 1]
    x = L1 * np.cos(t1) + L2 * np.cos(t1 + t2)
    y = L1 * np.sin(t1) + L2 * np.sin(t1 + t2)
    ix = np.floor((x + 1.6) / 0.05).astype(int)
    iy = np.floor((y + 1.6) / 0.05).astype(int)
    assert spec.shape == [64, 64, 1] and vals.size == 4096
    np.testing.assert_array_equal(cells, ix * 64 + iy)  # (x, y, z = 0) row-major, 1 bin
    np.testing.assert_allclose(vals, L1 * L2 * np.abs(np.sin(t2)), rtol=1e-6, atol=1e-7)
    for i in range(0, 4096, 512):
        exact = compute_manipulability(planar, Q[i], "tip", rows=["vx", "vy"]).yoshikawa
        assert vals[i] == pytest.approx(exact, rel=1e-6, abs=1e-7)


def test_grid_sampling_lattice(planar):
    spec = planar_map_spec(planar, sampling="grid", samples=100)
    assert spec.grid_per_joint == 10 and spec.samples == 100
    Q = chunk_samples(spec, 0, spec.samples)
    # a full turn (±π) has no duplicate end point
    grid = np.linspace(-math.pi, math.pi, 10, endpoint=False)
    np.testing.assert_allclose(np.unique(Q[:, 0]), grid)
    np.testing.assert_allclose(np.unique(Q[:, 1]), grid)
    short = RobotModel("p2", planar2_urdf(limit=2.0), ee_frame="tip")
    Q = chunk_samples(planar_map_spec(short, sampling="grid", samples=36), 0, 36)
    np.testing.assert_allclose(np.unique(Q[:, 1]), np.linspace(-2.0, 2.0, 6))


def test_processes_give_the_same_map(planar):
    spec = planar_map_spec(planar, samples=3 * 32_768, orientation_divisions=2)
    one = build_map(planar, spec)
    two = build_map(planar, spec, processes=2, min_samples_per_process=1)
    assert np.array_equal(one, two)


def test_cancel(planar):
    spec = planar_map_spec(planar, samples=10_000_000)
    progress = Progress(spec.samples)
    progress.cancel.set()
    with pytest.raises(Cancelled):
        build_map(planar, spec, progress)


def test_default_bounds_contain_the_workspace(registry):
    robot = registry.get("ur5")
    lo, hi = default_bounds(robot, robot.ee_frame)
    chain = SerialChain.build(robot, robot.ee_frame)
    Q = np.random.default_rng(0).uniform(-2 * math.pi, 2 * math.pi, (5000, 6))
    _, p, _ = chain(Q)
    assert np.all(p >= lo) and np.all(p <= hi)


# ---------------------------------------------------------------------- bad inputs
@pytest.mark.parametrize(
    ("kw", "field"),
    [
        ({"voxel_size": 0.0}, "voxel_size"),
        ({"voxel_size": -0.1}, "voxel_size"),
        ({"lower": [0, 0, 0], "upper": [1, -1, 1]}, "bounds.max.1"),
        ({"lower": [0, 0, 0], "upper": [0, 1, 1]}, "bounds.max.0"),
        ({"voxel_size": 1e-4}, "voxel_size"),  # too many cells
        ({"orientation_divisions": 13}, "orientation_divisions"),
        ({"samples": 0}, "samples"),
        ({"sampling": "sobol"}, "sampling"),
        ({"self_collision": "maybe"}, "self_collision"),
        ({"rows": ["vq"]}, "rows.0"),
    ],
)
def test_bad_specs(planar, kw, field):
    with pytest.raises(InvalidInputError) as e:
        planar_map_spec(planar, **kw)
    assert e.value.field == field


def test_quaternion_bins_from_matrices_roundtrip():
    q = random_quaternions(100, seed=5)
    back = matrix_to_quaternion(quaternion_to_matrix(q))
    assert np.array_equal(orientation_bin(q, 3), orientation_bin(back, 3))


def test_self_collision_hook_drops_folded_samples():
    """Folded back (|θ2| ≈ π) link 2 enters the base box (|x|, |y| ≤ 0.4): with the hook
    those tip positions (r ≈ 0.3) disappear; without it they are reachable."""
    robot = RobotModel("planar_boxes", COLLIDING_URDF, ee_frame="tip")
    kw = dict(
        voxel_size=0.1,
        lower=[-1.6, -1.6, -0.05],
        upper=[1.6, 1.6, 0.05],
        orientation_divisions=0,
        samples=4000,
        sampling="grid",
    )
    plain = build_map(robot, make_spec(robot, "tip", **kw))
    checked = build_map(robot, make_spec(robot, "tip", self_collision="convex", **kw))
    spec = make_spec(robot, "tip", **kw)
    c = voxel_centres(spec)
    r = np.hypot(c[:, 0], c[:, 1])
    near = (r > 0.32) & (r < 0.4)
    assert (plain.reshape(-1)[near] >= 0).all()
    assert not (checked.reshape(-1)[near] >= 0).any()
    far = (r > 1.0) & (r < 1.4)
    assert (checked.reshape(-1)[far] >= 0).all()


def test_worker_failure_is_reported(planar):
    """A worker that cannot build its model fails the build with the worker's error."""
    broken = RobotModel("planar2_test", planar2_urdf(), ee_frame="tip")
    broken.urdf_text = "<robot name='x'><link name='a'/></robot>"  # no frame 'tip' there
    spec = planar_map_spec(broken, samples=4 * 32_768)
    with pytest.raises(RuntimeError, match="build process failed"):
        build_map(broken, spec, processes=2, min_samples_per_process=1)


def test_pinocchio_fallback_gives_the_same_map(planar, monkeypatch):
    """Chains the vectorised path cannot take (mimic, multi-DoF joints) use Pinocchio per
    sample: forcing that path must give the same map."""
    spec = planar_map_spec(planar, samples=8192, orientation_divisions=3)
    fast = build_map(planar, spec)
    monkeypatch.setattr(SerialChain, "build", classmethod(lambda cls, robot, frame: None))
    assert isinstance(MapBuilder(planar, spec).chain, PinocchioChain)
    slow = build_map(planar, spec)
    assert np.array_equal(fast >= 0, slow >= 0)
    np.testing.assert_allclose(fast, slow, rtol=1e-6, atol=1e-7)


def test_sampled_poses_are_in_the_map(registry):
    """Every sampled configuration's pose (Pinocchio FK) is reachable in the map, with a
    cell value at least its Yoshikawa index (from the analysis module's SVD)."""
    robot = registry.get("ur5")
    spec = make_spec(robot, robot.ee_frame, voxel_size=0.1, samples=4096, orientation_divisions=3)
    best = build_map(robot, spec)
    m = ReachabilityMap({"spec": spec.__dict__.copy(), **summarize(best)}, best)
    Q = chunk_samples(spec, 0, 4096)
    pos, quat, w = [], [], []
    for q in Q[::97]:
        T = forward_kinematics(robot, q, [robot.ee_frame])[robot.ee_frame]
        pos.append(T[:3, 3])
        quat.append(matrix_to_quaternion(T[:3, :3]))
        w.append(compute_manipulability(robot, q, robot.ee_frame).yoshikawa)
    reach, val, ok = m.query(np.array(pos), np.array(quat))
    assert ok.all() and reach.all()
    assert np.all(val >= np.array(w) * (1 - 1e-6) - 1e-9)
