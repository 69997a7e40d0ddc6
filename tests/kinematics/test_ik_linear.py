"""The damped least-squares step's linear solve when A = J Jᵀ + λ² I is not positive
definite in floating point: LAPACK ``posv`` (the Python loop) and the compiled Cholesky
(:mod:`app.kinematics.ik.kernel`) must give a finite step, never NaN nor the garbage of a
failed factorisation."""

from __future__ import annotations

import numpy as np
import pytest

from app.kinematics import jit
from app.kinematics.ik import kernel
from app.kinematics.ik.dls import spd_solve

#: Symmetric, indefinite (eigenvalues 3 and −1): Cholesky meets a negative pivot.
INDEFINITE = np.array([[1.0, 2.0], [2.0, 1.0]])


def test_posv_failure_falls_back_to_a_more_damped_solve() -> None:
    b = np.array([1.0, -0.5])
    x = spd_solve(INDEFINITE, b)
    assert np.isfinite(x).all()
    # x solves (A + δI) x = b for one δ making A + δI positive definite (δ > 1): a damped,
    # descent step (bᵀx > 0), not the untouched right-hand side posv leaves behind
    delta = (b - INDEFINITE @ x) / x
    assert delta[0] == pytest.approx(delta[1], rel=1e-9)
    assert delta[0] > 1.0
    assert b @ x > 0.0


def test_posv_with_non_finite_entries_gives_no_step() -> None:
    A = np.array([[np.nan, 0.0], [0.0, 1.0]])
    x = spd_solve(A, np.array([1.0, 1.0]))
    np.testing.assert_array_equal(x, [0.0, 0.0])


def test_posv_of_a_positive_definite_matrix_is_the_exact_solve() -> None:
    A = np.array([[4.0, 1.0], [1.0, 3.0]])
    b = np.array([1.0, 2.0])
    np.testing.assert_allclose(spd_solve(A, b), np.linalg.solve(A, b), rtol=1e-14)


@pytest.mark.skipif(not jit.available(), reason="Numba not installed")
def test_compiled_cholesky_reports_a_non_positive_pivot() -> None:
    A = np.eye(6)
    A[:2, :2] = INDEFINITE
    x = np.empty(6)
    assert not kernel._solve_spd(A.copy(), np.ones(6), x)
    B = np.eye(6) * 2.0
    assert kernel._solve_spd(B.copy(), np.ones(6), x)
    np.testing.assert_allclose(x, np.full(6, 0.5), rtol=1e-15)


@pytest.mark.skipif(not jit.available(), reason="Numba not installed")
@pytest.mark.parametrize("lam2", [-5.0, np.nan])
def test_compiled_step_is_finite_when_the_damped_matrix_is_not_positive_definite(lam2) -> None:
    """λ² < 0 makes J Jᵀ + λ² I indefinite (a stand-in for rounding on a huge robot); a NaN
    makes it unusable: the step is then the more damped one, or zero, never NaN."""
    rng = np.random.default_rng(4)
    J = rng.normal(size=(6, 7))
    e = rng.normal(size=6)
    nd = np.empty(7)
    kernel._dls(J, e, lam2, np.zeros(7, np.bool_), nd, np.empty((6, 6)), np.empty(6))
    assert np.isfinite(nd).all()
    if np.isnan(lam2):
        np.testing.assert_array_equal(nd, 0.0)
    else:
        # nd = Jᵀ y with (J Jᵀ + (λ² + δ) I) y = e for some δ > 5: a descent direction
        assert e @ (J @ nd) > 0.0
