"""Compiled damped-least-squares attempts for serial chains (the hot loop of :mod:`ik`).

The numeric solver in :mod:`app.kinematics.ik` spends its time in one loop: forward
kinematics and the frame Jacobian at the current iterate, the pose error, one 6×6 linear
solve, the joint-limit clamp. Written in Python around Pinocchio calls, an iteration costs
some twenty interpreter round trips (about 15 µs); compiled with Numba as one function over
the chain's constants, about 1 µs. This module is that function and the chain data it reads.
Everything around it (restarts, the table of restart samples, the time budget, verifying a
converged iterate with Pinocchio before it counts as a solution) stays in :mod:`ik`: a
mistake here can cost solve rate or time, never a wrong answer.

Kinematics
----------
The chain is :class:`app.kinematics.chain.SerialChain`'s: every joint rewritten in
a frame whose z axis is its axis, so with the running rotation R and position p (root
frame), joint j applies its fixed placement (p += R·t_j, R = R·C_j), then its motion about
or along z: R = R·Rz(q_j) (revolute, continuous) or p += q_j·R e_z (prismatic). After the
last joint the frame's own placement (last_C, last_t). The Jacobian is the world one
(Pinocchio LOCAL_WORLD_ALIGNED): column j = [z_j × (p − o_j); z_j] (revolute) or [z_j; 0]
(prismatic), with z_j, o_j the axis and origin of joint j in the root frame.

Error and step
--------------
Exactly those of :mod:`app.kinematics.ik` (full pose, unit weights): e = [p − p_t;
log3(R R_tᵀ)], A = J Jᵀ + (c‖e‖² + μ) I, Δq = z − Jᵀ A⁻¹ (e + J z) with the null-space
preference z on the attempt from the seed, the step capped at 2 (rad or m), continuous
joints wrapped, every iterate clipped to the limits, joints pushed against a limit locked
for the step on redundant chains. A is solved by Cholesky (it is symmetric positive
definite: λ² ≥ μ > 0).

Numba compiles on first use (a few seconds) and caches the machine code next to this file
(or under ``NUMBA_CACHE_DIR``); :func:`available` says whether it can be used at all.
"""

from __future__ import annotations

import math

import numpy as np

from app.kinematics.chain import SerialChain
from app.kinematics.ik.boundary import ChainConstants, StepParameters
from app.kinematics.jit import jit

#: Attempt outcomes returned by :func:`attempt`.
CONVERGED, RESTART, CAPPED = 0, 1, 2


@jit
def _pose_jacobian(qa, C, t, prism, last_C, last_t, R, p, J, want_j, tmp):  # pragma: no cover
    """Pose (R (3, 3), p (3,)) of the frame and, if ``want_j``, its world Jacobian J (6, k)
    at the chain configuration ``qa`` (k,): written into R, p, J (``tmp``: (3, 3) scratch)."""
    k = qa.shape[0]
    for i in range(3):
        p[i] = 0.0
        for j in range(3):
            R[i, j] = 1.0 if i == j else 0.0
    for s in range(k):
        # fixed placement: p += R t_s ; R = R C_s
        for i in range(3):
            p[i] += R[i, 0] * t[s, 0] + R[i, 1] * t[s, 1] + R[i, 2] * t[s, 2]
        for i in range(3):
            for j in range(3):
                tmp[i, j] = R[i, 0] * C[s, 0, j] + R[i, 1] * C[s, 1, j] + R[i, 2] * C[s, 2, j]
        for i in range(3):
            for j in range(3):
                R[i, j] = tmp[i, j]
        if want_j:
            # axis z_s (third column) and origin o_s, kept in J until p is final
            for i in range(3):
                J[3 + i, s] = R[i, 2]
                J[i, s] = p[i]
        if prism[s]:
            for i in range(3):
                p[i] += qa[s] * R[i, 2]
        else:
            c = math.cos(qa[s])
            sn = math.sin(qa[s])
            for i in range(3):
                x = R[i, 0]
                y = R[i, 1]
                R[i, 0] = c * x + sn * y
                R[i, 1] = c * y - sn * x
    for i in range(3):
        p[i] += R[i, 0] * last_t[0] + R[i, 1] * last_t[1] + R[i, 2] * last_t[2]
    for i in range(3):
        for j in range(3):
            tmp[i, j] = R[i, 0] * last_C[0, j] + R[i, 1] * last_C[1, j] + R[i, 2] * last_C[2, j]
    for i in range(3):
        for j in range(3):
            R[i, j] = tmp[i, j]
    if want_j:
        for s in range(k):
            zx, zy, zz = J[3, s], J[4, s], J[5, s]
            if prism[s]:
                J[0, s], J[1, s], J[2, s] = zx, zy, zz
                J[3, s] = J[4, s] = J[5, s] = 0.0
            else:
                dx, dy, dz = p[0] - J[0, s], p[1] - J[1, s], p[2] - J[2, s]
                J[0, s] = zy * dz - zz * dy
                J[1, s] = zz * dx - zx * dz
                J[2, s] = zx * dy - zy * dx


@jit
def _log3(M, out):  # pragma: no cover
    """Rotation vector φ of the rotation M (|φ| ≤ π), into ``out``: the angle from
    atan2(sin, cos) (accurate at every angle), the axis from the skew part, or near π from
    the symmetric part."""
    wx = M[2, 1] - M[1, 2]
    wy = M[0, 2] - M[2, 0]
    wz = M[1, 0] - M[0, 1]
    c = 0.5 * (M[0, 0] + M[1, 1] + M[2, 2] - 1.0)
    s = 0.5 * math.sqrt(wx * wx + wy * wy + wz * wz)
    th = math.atan2(s, c)
    if th < 1e-4:
        f = 0.5 * (1.0 + th * th / 6.0)  # θ / (2 sin θ)
        out[0], out[1], out[2] = f * wx, f * wy, f * wz
    elif th < math.pi - 1e-3:
        f = 0.5 * th / s
        out[0], out[1], out[2] = f * wx, f * wy, f * wz
    else:
        # near π: k kᵀ = ((M + Mᵀ)/2 − cos θ·I)/(1 − cos θ); largest diagonal first
        d = 1.0 - c
        i = 0
        if M[1, 1] > M[i, i]:
            i = 1
        if M[2, 2] > M[i, i]:
            i = 2
        w = (wx, wy, wz)
        ki = math.sqrt(max(0.0, (M[i, i] - c) / d))
        if w[i] < 0.0:
            ki = -ki
        for j in range(3):
            if j == i:
                out[j] = th * ki
            else:
                out[j] = th * (M[i, j] + M[j, i]) / (2.0 * d * ki)


@jit
def _solve_spd(A, b, x):  # pragma: no cover
    """x = A⁻¹ b for a symmetric positive definite A (m, m), by Cholesky (A is overwritten
    by its factor). Returns False, ``x`` undefined, when a pivot is not positive (A is not
    positive definite in floating point, or holds a NaN)."""
    m = A.shape[0]
    for j in range(m):
        d = A[j, j]
        for k in range(j):
            d -= A[j, k] * A[j, k]
        if not d > 0.0:
            return False
        d = math.sqrt(d)
        A[j, j] = d
        for i in range(j + 1, m):
            v = A[i, j]
            for k in range(j):
                v -= A[i, k] * A[j, k]
            A[i, j] = v / d
    for i in range(m):
        v = b[i]
        for k in range(i):
            v -= A[i, k] * x[k]
        x[i] = v / A[i, i]
    for i in range(m - 1, -1, -1):
        v = x[i]
        for k in range(i + 1, m):
            v -= A[k, i] * x[k]
        x[i] = v / A[i, i]
    return True


@jit
def _gram(J, lam2, locked, A, norm):  # pragma: no cover
    """A = J Jᵀ + λ² I over the unlocked columns; returns its Frobenius norm if ``norm``
    (else 0)."""
    k = J.shape[1]
    f = 0.0
    for i in range(6):
        for j in range(i + 1):
            v = 0.0
            for s in range(k):
                if not locked[s]:
                    v += J[i, s] * J[j, s]
            A[i, j] = v
            A[j, i] = v
        A[i, i] += lam2
    if norm:
        for i in range(6):
            for j in range(6):
                f += A[i, j] * A[i, j]
    return math.sqrt(f)


@jit
def _dls(J, e, lam2, locked, nd, A, y):  # pragma: no cover
    """nd = Jᵀ (J Jᵀ + λ² I)⁻¹ e over the unlocked columns (locked columns count as 0);
    ``A`` (6, 6) and ``y`` (6,) are scratch.

    A is positive definite in exact arithmetic (λ² ≥ μ > 0); when its Cholesky meets a
    non-positive pivot anyway (rounding on a huge robot, a NaN), the step is the more
    damped one with λ² + 2‖A‖_F (A + 2‖A‖_F·I is positive definite whatever A), and a zero
    step if that fails too (non-finite entries): never a NaN step."""
    k = J.shape[1]
    _gram(J, lam2, locked, A, False)
    if not _solve_spd(A, e, y):
        extra = 2.0 * _gram(J, lam2, locked, A, True)
        ok = False
        if math.isfinite(extra):
            for i in range(6):
                A[i, i] += extra
            ok = _solve_spd(A, e, y)
        if not ok:
            for i in range(6):
                y[i] = 0.0
    for s in range(k):
        if locked[s]:
            nd[s] = 0.0
        else:
            nd[s] = (
                J[0, s] * y[0] + J[1, s] * y[1] + J[2, s] * y[2]
                + J[3, s] * y[3] + J[4, s] * y[4] + J[5, s] * y[5]
            )  # fmt: skip


@jit
def _step_to(q_old, nd, max_step, cont, lo, hi, q_new, qa):  # pragma: no cover
    """q_new = q_old − nd (step capped at max_step, continuous joints wrapped); qa = q_new
    clipped to [lo, hi]. Returns whether the clip changed anything."""
    k = q_old.shape[0]
    n2 = 0.0
    for s in range(k):
        n2 += nd[s] * nd[s]
    scale = 1.0
    if n2 > max_step * max_step:
        scale = max_step / math.sqrt(n2)
    two_pi = 2.0 * math.pi
    clipped = False
    for s in range(k):
        v = q_old[s] - scale * nd[s]
        if cont[s]:  # wrapped to (−π, π] (app.kinematics.angles.wrap_scalar)
            v = v - two_pi * math.ceil((v - math.pi) / two_pi)
        q_new[s] = v
        if v < lo[s]:
            v = lo[s]
            clipped = True
        elif v > hi[s]:
            v = hi[s]
            clipped = True
        qa[s] = v
    return clipped


@jit
def pose_error(qa, chain, Rt, pt):  # pragma: no cover
    """(‖p − p_t‖², ‖log3(R R_tᵀ)‖², trace(R R_tᵀ)) of the frame at ``qa`` (``chain``: the
    :class:`ChainConstants`)."""
    C, t, prism, last_C, last_t = chain.C, chain.t, chain.prism, chain.last_C, chain.last_t
    k = qa.shape[0]
    R = np.empty((3, 3))
    p = np.empty(3)
    J = np.empty((6, k))
    _pose_jacobian(qa, C, t, prism, last_C, last_t, R, p, J, False, np.empty((3, 3)))
    Re = np.empty((3, 3))
    for i in range(3):
        for j in range(3):
            Re[i, j] = R[i, 0] * Rt[j, 0] + R[i, 1] * Rt[j, 1] + R[i, 2] * Rt[j, 2]
    phi = np.empty(3)
    _log3(Re, phi)
    ep2 = 0.0
    for i in range(3):
        ep2 += (p[i] - pt[i]) ** 2
    return ep2, phi[0] ** 2 + phi[1] ** 2 + phi[2] ** 2, Re[0, 0] + Re[1, 1] + Re[2, 2]


@jit
def attempt(  # pragma: no cover
    qa, chain, Rt, pt, q_ref, null_on, clamp, tol_p2, tol_r2, max_iters, step, best, best_q
):
    """One attempt of damped least squares from ``qa`` (k,), updated in place.

    ``chain`` is the chain's :class:`ChainConstants`, ``step`` the loop's
    :class:`StepParameters`; ``Rt`` (3, 3), ``pt`` (3,) the target (root frame); ``tol_p2``,
    ``tol_r2`` the squared tolerances (m², rad²). Iterates until the pose error is within
    tolerance (returns ``CONVERGED``, ``qa`` the converged iterate), the error stalls (no
    progress, ‖e‖² < ``step.progress``·best of the attempt, in ``step.stall`` iterations) or
    ``step.attempt_cap`` iterations pass (``RESTART``), or ``max_iters`` run out
    (``CAPPED``). ``null_on`` adds the null-space pull towards ``q_ref``; ``clamp`` locks
    joints pushed against a limit. ``best`` (1,) and ``best_q`` (k,) hold the lowest error
    energy ‖e‖² of unconverged iterates seen so far, updated in place.

    Returns (outcome, iterations evaluated).
    """
    C, t, prism, last_C, last_t = chain.C, chain.t, chain.prism, chain.last_C, chain.last_t
    lo, hi, cont = chain.lo, chain.hi, chain.cont
    damp, mu, gain, null_scale = step.damp, step.mu, step.gain, step.null_scale
    null_floor, max_step, progress = step.null_floor, step.max_step, step.progress
    stall_limit, attempt_cap = step.stall, step.attempt_cap
    k = qa.shape[0]
    R = np.empty((3, 3))
    p = np.empty(3)
    J = np.empty((6, k))
    Re = np.empty((3, 3))
    e = np.empty(6)
    phi = np.empty(3)
    rhs = np.empty(6)
    z = np.zeros(k)
    nd = np.empty(k)
    q_old = np.empty(k)
    q_new = np.empty(k)
    locked = np.zeros(k, dtype=np.bool_)
    none_locked = np.zeros(k, dtype=np.bool_)
    tmp = np.empty((3, 3))
    A = np.empty((6, 6))
    y = np.empty(6)
    best_attempt = np.inf
    stall = 0
    it = 0
    while True:
        if it >= max_iters:
            return CAPPED, it
        _pose_jacobian(qa, C, t, prism, last_C, last_t, R, p, J, True, tmp)
        it += 1
        for i in range(3):
            for j in range(3):
                Re[i, j] = R[i, 0] * Rt[j, 0] + R[i, 1] * Rt[j, 1] + R[i, 2] * Rt[j, 2]
        _log3(Re, phi)
        for i in range(3):
            e[i] = p[i] - pt[i]
            e[3 + i] = phi[i]
        ep2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2]
        er2 = e[3] * e[3] + e[4] * e[4] + e[5] * e[5]
        energy = ep2 + er2
        if ep2 <= tol_p2 and er2 <= tol_r2:
            return CONVERGED, it
        if energy < best[0]:
            best[0] = energy
            for s in range(k):
                best_q[s] = qa[s]
        if energy < progress * best_attempt:
            best_attempt = energy
            stall = 0
        else:
            stall += 1
            if stall >= stall_limit or it >= attempt_cap:
                return RESTART, it
        lam2 = damp * energy + mu
        if null_on and energy > null_floor:
            # Δq = z − Jᵀ A⁻¹ (e + J z): nd = −Δq = Jᵀ A⁻¹ (e + J z) − z
            a = gain * min(1.0, energy * null_scale)
            for s in range(k):
                z[s] = (q_ref[s] - qa[s]) * a
            for i in range(6):
                v = e[i]
                for s in range(k):
                    v += J[i, s] * z[s]
                rhs[i] = v
            _dls(J, rhs, lam2, none_locked, nd, A, y)
            for s in range(k):
                nd[s] -= z[s]
        else:
            _dls(J, e, lam2, none_locked, nd, A, y)
        for s in range(k):
            q_old[s] = qa[s]
        clipped = _step_to(q_old, nd, max_step, cont, lo, hi, q_new, qa)
        if clamp and clipped:
            n_locked = 0
            for s in range(k):
                locked[s] = (q_new[s] < lo[s] and q_old[s] <= lo[s]) or (
                    q_new[s] > hi[s] and q_old[s] >= hi[s]
                )
                if locked[s]:
                    n_locked += 1
            if 0 < n_locked < k:
                _dls(J, e, lam2, locked, nd, A, y)
                _step_to(q_old, nd, max_step, cont, lo, hi, q_new, qa)


@jit
def sample_distances(MT, W2, x, d):  # pragma: no cover
    """d = W2 + Mᵀᵀ·x for the restart table (MT: (12, N) float32, one pass per column, so
    the loops over N vectorise); returns the index of the smallest distance."""
    n = d.shape[0]
    for i in range(n):
        d[i] = W2[i]
    for j in range(MT.shape[0]):
        c = x[j]
        for i in range(n):
            d[i] += MT[j, i] * c
    best = 0
    m = d[0]  # the smallest so far, kept in a register (no reload of d[best])
    for i in range(1, n):
        v = d[i]
        if v < m:
            m = v
            best = i
    return best


class CompiledChain:
    """The constants :func:`attempt` reads for one (robot, frame), or ``None`` from
    :meth:`build` when the chain is not a plain serial chain of 1-DoF joints."""

    def __init__(self, C, t, prism, last_C, last_t) -> None:
        self.C = np.ascontiguousarray(C, dtype=np.float64)
        self.t = np.ascontiguousarray(t, dtype=np.float64)
        self.prism = np.ascontiguousarray(prism, dtype=np.bool_)
        self.last_C = np.ascontiguousarray(last_C, dtype=np.float64)
        self.last_t = np.ascontiguousarray(last_t, dtype=np.float64)

    @classmethod
    def build(cls, robot, frame: str, active: np.ndarray) -> CompiledChain | None:
        """The chain of ``frame`` if its joints, in chain order, are exactly ``active``
        (wire indices) and all 1-DoF (no mimic, no multi-DoF joints); else ``None``."""
        cj = SerialChain.build(robot, frame)
        if cj is None or not np.array_equal(cj.wire, active) or not cj.steps:
            return None
        return cls(
            np.array([s.C for s in cj.steps]),
            np.array([s.t for s in cj.steps]),
            np.array([s.prismatic for s in cj.steps]),
            cj.last_C,
            cj.last_t,
        )

    def constants(self, lo: np.ndarray, hi: np.ndarray, cont: np.ndarray) -> ChainConstants:
        """This chain's :class:`ChainConstants` with the limits ``lo``, ``hi`` (k,) and the
        continuous joints ``cont`` (k,) bool."""
        return ChainConstants(
            self.C, self.t, self.prism, self.last_C, self.last_t,
            np.ascontiguousarray(lo, dtype=np.float64), np.ascontiguousarray(hi, dtype=np.float64),
            np.ascontiguousarray(cont, dtype=np.bool_),
        )  # fmt: skip

    def pose(self, qa: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Rotation, position and world Jacobian at ``qa`` (for tests and diagnostics)."""
        k = qa.shape[0]
        R, p, J = np.empty((3, 3)), np.empty(3), np.empty((6, k))
        _pose_jacobian(
            np.ascontiguousarray(qa, dtype=np.float64),
            self.C, self.t, self.prism, self.last_C, self.last_t, R, p, J, True, np.empty((3, 3)),
        )  # fmt: skip
        return R, p, J


def log3(M: np.ndarray) -> np.ndarray:
    """Rotation vector of the rotation matrix ``M`` (for tests)."""
    out = np.empty(3)
    _log3(np.ascontiguousarray(M, dtype=np.float64), out)
    return out


def warm_up() -> None:
    """Compile (or load from the cache) every kernel of this module once, with the argument
    types the solver uses (a dummy 1-joint chain). Called by
    :func:`app.kinematics.ik.warmup.warm_up`, which says when all kernels are ready."""
    k = 1
    q = np.zeros(k)
    best = np.array([np.inf])
    consts = (
        np.eye(3)[None].copy(),
        np.zeros((1, 3)),
        np.zeros(1, dtype=np.bool_),
        np.eye(3),
        np.zeros(3),
    )
    chain = ChainConstants(*consts, np.full(k, -1.0), np.full(k, 1.0), np.zeros(1, dtype=np.bool_))
    pose_error(q, chain, np.eye(3), np.zeros(3))
    step = StepParameters(0.01, 1e-10, 0.2, 100.0, 1e-8, 2.0, 0.81, 2, 20)
    attempt(
        q.copy(),
        chain,
        np.eye(3),
        np.zeros(3),
        q.copy(),
        True,
        True,
        1e-10,
        1e-10,
        1,
        step,
        best,
        q.copy(),
    )
    f32 = np.float32
    sample_distances(np.zeros((12, 4), f32), np.zeros(4, f32), np.zeros(12, f32), np.empty(4, f32))
    CompiledChain(*consts).pose(q)
