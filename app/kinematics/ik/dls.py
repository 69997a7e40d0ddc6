"""The damped-least-squares loop in Python around Pinocchio calls: every mode, every chain.

One iteration (the error, its Jacobian and the step are derived in :mod:`app.kinematics.ik`):

1. :meth:`_Loop.evaluate`: forward kinematics at the iterate, the error
   e = [p − p_t; log3(R R_tᵀ)] in world axes, and the convergence test on the checked
   components.
2. A converged iterate is offered to the search (verified there); the search then restarts
   elsewhere for further solutions, or stops.
3. Far from the target on the very first iterate: jump to the nearest table sample
   (:meth:`~app.kinematics.ik.search.Search.seed_is_far`).
4. Stall test: no progress (‖e‖ decreased by 10 %) in ``stall`` iterations, or
   ``attempt_cap`` iterations in one attempt, restarts.
5. :meth:`_Loop.step`: the damped least-squares step on the task rows (null-space pull
   towards the seed on redundant chains), clipped to the limits, with the joints pushed
   against a limit locked and the step recomputed.

The tunables are the search's :class:`~app.kinematics.ik.parameters.SolverParameters`, the
same the compiled attempt (:mod:`app.kinematics.ik.kernel`) reads, so both loops take the
same iterates.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
import pinocchio as pin
from scipy.linalg.lapack import dposv as _posv

from app.kinematics.angles import wrap_angle

if TYPE_CHECKING:
    from app.kinematics.ik.search import Search

_EYES = [np.eye(i) for i in range(7)]
# The hot loop's library calls, looked up once.
_jacobians, _placement, _log3 = pin.computeJointJacobians, pin.updateFramePlacement, pin.log3
_LWA = pin.LOCAL_WORLD_ALIGNED
_inner, _dot, _minimum, _maximum = np.inner, np.dot, np.minimum, np.maximum
_isfinite = np.isfinite


def _frame_jacobian_6xn(
    model: pin.Model, data: pin.Data, fid: int, rf: pin.ReferenceFrame
) -> np.ndarray:
    """``pin.getFrameJacobian`` as a (6, nv) array whatever nv (Pinocchio returns (6,) for 1)."""
    return pin.getFrameJacobian(model, data, fid, rf).reshape(6, -1)


class _Loop:
    """The constants of one run (index sets, target, task) and the two heavy steps."""

    __slots__ = (
        "search", "model", "data", "fid", "lo", "hi", "RtT", "pt", "rows", "sw", "full_pose",
        "eye", "q_ref", "tol_p2", "tol_r2", "check_pos", "check_rot", "rows_p", "rows_r",
        "all_plain", "plain", "plain_q", "cont", "cont_q", "cont_q1", "gfj",
        "clamp", "redundant", "cols", "qp", "e", "ev", "ew", "L", "use_jlog", "p", "null_scale",
    )  # fmt: skip

    def __init__(self, s: Search) -> None:
        robot, ch = s.robot, s.ch
        self.search = s
        self.p = p = s.parameters
        self.null_scale = 1.0 / p.null_energy
        self.model, self.data = robot.model, robot.data
        self.fid = ch.frame_id
        self.lo, self.hi = ch.clip_lo, ch.clip_hi
        self.RtT = np.ascontiguousarray(s.target.rotation.T)
        self.pt = s.target.translation
        rows, sw = s.rows, s.sw
        self.rows, self.sw = rows, sw
        self.full_pose = rows.size == 6 and sw is None
        m = rows.size
        self.eye = _EYES[m]
        redundant = ch.k > m
        self.q_ref = s.q_seed[ch.active]
        self.tol_p2, self.tol_r2 = s.tol_p**2, s.tol_r**2
        self.check_pos, self.check_rot = s.check_pos, s.check_rot
        self.rows_p, self.rows_r = rows[rows < 3], rows[rows >= 3]
        self.all_plain = ch.plain.size == ch.k
        self.plain = ch.plain
        self.plain_q = ch.plain_q_sel if self.all_plain else ch.plain_q
        self.cont_q, self.cont_q1 = ch.cont_q, ch.cont_q1
        # Positions of the continuous joints in the active set (None: there are none).
        self.cont = ch.cont if ch.has_continuous else None
        # Pinocchio hands back a 1-D array (6,) for a model with one degree of freedom (a
        # 1-DoF arm, or one joint and its mimic followers): keep it a 6×1 matrix.
        self.gfj = _frame_jacobian_6xn if self.model.nv == 1 else pin.getFrameJacobian
        # A locked joint leaves a square chain short of a task row: clamp redundant ones only.
        self.clamp = p.clamp and redundant
        self.redundant = redundant and p.null_gain > 0.0
        self.cols = ch.cols_sel
        self.qp = robot.to_pin(s.q_seed)
        self.e = np.empty(6)
        self.ev, self.ew = self.e[:3], self.e[3:]  # views: e_p, e_R
        self.L = np.eye(6)  # blockdiag(I, Jlog3(R_e)ᵀ): J_e = L · J_LWA (active columns)
        # With all three rotation rows in the task, J·dq = −e gives the exact Gauss–Newton
        # step (see the module docstring of ik: Jlog3ᵀ·φ = φ); a strict subset of them needs
        # the exact rows of J_e = [J_v; Jlog3(R_e)ᵀ J_ω].
        self.use_jlog = 0 < self.rows_r.size < 3

    def evaluate(self, qa: np.ndarray) -> tuple[bool, float, float, np.ndarray, np.ndarray]:
        """Kinematics at ``qa`` (leaves the joint Jacobians in ``data`` for :meth:`step`).

        Returns whether the checked components are within the tolerances, the task energy
        ‖e_task‖² (weighted), ‖e_p‖², R_e = R R_tᵀ and the task error e_task.
        """
        qp, e, model, data = self.qp, self.e, self.model, self.data
        if self.all_plain:
            qp[self.plain_q] = qa
        else:
            qp[self.plain_q] = qa[self.plain]
            th = qa[self.cont]  # not all plain: some joints are continuous
            qp[self.cont_q] = np.cos(th)
            qp[self.cont_q1] = np.sin(th)
        _jacobians(model, data, qp)
        T = _placement(model, data, self.fid)
        # e = [p − p_t; log3(R R_tᵀ)] in world axes
        Re = T.rotation @ self.RtT
        ev = self.ev
        np.subtract(T.translation, self.pt, out=ev)
        self.ew[:] = _log3(Re)
        energy = e @ e
        ep2 = ev @ ev
        if self.full_pose:
            return ep2 <= self.tol_p2 and energy - ep2 <= self.tol_r2, energy, ep2, Re, e
        conv = True
        if self.check_pos:
            v = e[self.rows_p]
            conv = v @ v <= self.tol_p2
        if conv and self.check_rot:
            v = e[self.rows_r]
            conv = v @ v <= self.tol_r2
        et = e[self.rows]
        if self.sw is not None:
            et = et * self.sw
        return conv, et @ et, ep2, Re, et

    def step(self, qa: np.ndarray, Re: np.ndarray, et: np.ndarray, energy: float) -> np.ndarray:
        """The next iterate: the damped least-squares step on the task rows from ``qa``,
        wrapped (continuous joints) and clipped to the limits, joints pushed against a limit
        locked (redundant chains)."""
        model, data, fid = self.model, self.data, self.fid
        if self.use_jlog:
            self.L[3:, 3:] = pin.Jlog3(Re).T
            Je = self.L @ self.gfj(model, data, fid, _LWA)[:, self.cols]
        else:
            Je = self.gfj(model, data, fid, _LWA)[:, self.cols]
        if self.full_pose:
            Jt = Je
        else:
            Jt = Je[self.rows]
            if self.sw is not None:
                Jt = Jt * self.sw[:, None]
        eye, p = self.eye, self.p
        lam2 = p.damp * energy + p.mu
        A = _inner(Jt, Jt)  # J Jᵀ
        A += lam2 * eye
        # nd = −Δq (the sign folded into the update below)
        if self.redundant and energy > p.null_floor and not self.search.restarts:
            # Preference gain fades with the error (quadratic convergence kept).
            z = (self.q_ref - qa) * (p.null_gain * min(1.0, energy * self.null_scale))
            nd = spd_solve(A, et + _dot(Jt, z)) @ Jt - z
        else:
            nd = spd_solve(A, et) @ Jt
        lo, hi = self.lo, self.hi
        q_new = _move(qa, nd, self.cont, p.max_step)
        q_next = _minimum(_maximum(q_new, lo), hi)
        if self.clamp and (q_next != q_new).any():
            # Joints already at a limit and pushed further are locked for this step (their
            # columns removed) so the other joints take over their share.
            locked = ((q_new < lo) & (qa <= lo)) | ((q_new > hi) & (qa >= hi))
            if locked.any() and not locked.all():
                Jl = Jt * ~locked
                A = _inner(Jl, Jl)
                A += lam2 * eye
                q_new = _move(qa, spd_solve(A, et) @ Jl, self.cont, p.max_step)
                q_next = _minimum(_maximum(q_new, lo), hi)
        return q_next


def spd_solve(A: np.ndarray, b: np.ndarray) -> np.ndarray:
    """x = A⁻¹ b for the damped Gram matrix A = J Jᵀ + λ² I (m, m), by LAPACK ``posv``.

    A is positive definite in exact arithmetic (λ² ≥ μ > 0); when ``posv`` reports that it
    is not in floating point (``info`` ≠ 0: a non-positive pivot, rounding on a huge robot;
    or a non-finite solution: a NaN entry), the more damped system (A + 2‖A‖_F·I) x = b is
    solved instead (positive definite whatever A), and x = 0 (no step) if that fails too:
    never a NaN or garbage step.
    """
    _, x, info = _posv(A, b)
    if info == 0 and _isfinite(x).all():  # (posv reports no error for NaN entries)
        return x
    extra = 2.0 * float(np.linalg.norm(A))
    if math.isfinite(extra):
        _, x, info = _posv(A + extra * np.eye(A.shape[0]), b)
        if info == 0 and np.isfinite(x).all():
            return x
    return np.zeros_like(b, dtype=float)


def _move(qa: np.ndarray, nd: np.ndarray, cont: np.ndarray | None, max_step: float) -> np.ndarray:
    """qa − nd with the step length capped at ``max_step``, the continuous joints (at
    positions ``cont``, None: none) wrapped to (−π, π]; not yet clipped to the limits."""
    n2 = nd @ nd
    if n2 > max_step * max_step:
        nd *= max_step / math.sqrt(n2)
    q_new = qa - nd
    if cont is not None:
        q_new[cont] = wrap_angle(q_new[cont])
    return q_new


def run_python(s: Search, deadline: float, max_iterations: int | None) -> None:
    """Damped least squares from the seed, then from restarts, until ``s`` is done, the
    deadline (``s.clock``) passes or ``max_iterations`` are spent.

    Updates ``s`` in place: its solutions (via :meth:`Search.offer`), iteration and restart
    counts, best iterate and ``timed_out``; raises ``Cancelled`` once ``s.cancel`` is set.
    """
    loop = _Loop(s)
    p = s.parameters
    progress, stall_limit, attempt_cap = p.progress, p.stall, p.attempt_cap
    nearest_first = p.nearest_first
    cap = max_iterations if max_iterations is not None else 1 << 62
    qa = loop.q_ref.copy()
    attempt_iters = 0
    best_attempt = math.inf
    stall = 0
    it = s.iterations
    best_energy, best_qa = s.best_energy, None
    out_of_budget, evaluate, step = s.out_of_budget, loop.evaluate, loop.step
    # The first attempt (from the seed, or from the nearest table sample the far seed jumps
    # to) runs whatever the clock says, capped by the iterations only: a query that finds its
    # budget already spent (a busy event loop) still answers an easy target.
    first = True
    try:
        while True:
            if first:
                if it >= cap:
                    return
            elif out_of_budget(it, cap, deadline):
                return
            conv, energy, ep2, Re, et = evaluate(qa)
            it += 1
            attempt_iters += 1
            if conv:
                s.iterations = it
                if s.offer(qa.copy()) and s.done():
                    return
                # Converged but rejected or a duplicate: jump elsewhere.
                qa = s.restart()
                first = False
                attempt_iters, best_attempt, stall = 0, math.inf, 0
                continue
            # First iterate far from the target: jump to the nearest table sample.
            if it == 1 and nearest_first and loop.full_pose:
                if s.seed_is_far(ep2, Re[0, 0] + Re[1, 1] + Re[2, 2]):
                    qa = s.restart()
                    attempt_iters, best_attempt, stall = 0, math.inf, 0
                    continue
            if energy < best_energy:
                best_energy, best_qa = energy, qa
            if energy < progress * best_attempt:  # ‖e‖ decreased by 10 % (0.81 = 0.9²)
                best_attempt = energy
                stall = 0
            else:
                stall += 1
                if stall >= stall_limit or attempt_iters >= attempt_cap:
                    qa = s.restart()
                    first = False
                    attempt_iters, best_attempt, stall = 0, math.inf, 0
                    continue
            qa = step(qa, Re, et, energy)
    finally:
        s.iterations = it
        if best_qa is not None and best_energy < s.best_energy:
            s.best_energy, s.best_q = best_energy, s.wire(best_qa)
