"""The numeric solver's tunables, in one frozen object passed by name.

:class:`SolverParameters` holds every constant of the damped-least-squares loop
(:mod:`.dls`, its compiled twin :mod:`.kernel`/:mod:`.search_kernel`), of the restart table
(:mod:`.precompute`) and of the search (:mod:`.search`, :mod:`.compiled`). The defaults,
:data:`DEFAULT_PARAMETERS`, are what every endpoint uses; a caller (a test, a benchmark)
passes another object to :func:`app.kinematics.ik.solve` by name, as pink's
``solve_ik(configuration, tasks, dt, solver, …)`` takes its solver settings.

Units: q in rad (revolute, continuous) or m (prismatic); the error e = [e_p; e_R] in m and
rad, its energy ‖e‖² in m² + rad² (the thresholds below that mix both assume an arm of
about 1 m).
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True, slots=True)
class SolverParameters:
    """Every tunable of the numeric IK solver (defaults: :data:`DEFAULT_PARAMETERS`).

    Attributes
    ----------
    mu
        Damping floor μ added to λ² (keeps A = J Jᵀ + λ² I positive definite at exact
        singularities); units of ‖e‖² (m² + rad²).
    damp
        Error-proportional damping c: λ² = c·‖e‖² + μ (dimensionless).
    null_gain
        Null-space gain α towards the reference configuration (redundant chains only, on the
        attempt from the seed): z = α(E)·(q_ref − q), dimensionless.
    null_energy
        Squared task error (m² + rad²) below which the null-space gain fades proportionally,
        α(E) = null_gain·min(1, E / null_energy): a constant pull would leave a second-order
        task error each step and make convergence linear.
    null_floor
        Squared task error (m² + rad²) below which the faded null-space term is skipped.
    max_step
        Largest joint step ‖Δq‖ per iteration (rad or m), keeps the linearisation honest.
    stall
        Iterations without progress (see ``progress``) before a restart.
    attempt_cap
        Iteration cap of one attempt (from the seed or a restart).
    clamp
        Lock joints pushed against a limit for the step (active-set clamping; redundant
        chains only).
    nearest_first
        Jump from a far seed to the nearest table sample after the first iteration
        (:meth:`~app.kinematics.ik.search.Search.seed_is_far`).
    progress
        An iteration makes progress when ‖e‖² < progress·(best ‖e‖² of the attempt):
        0.81 = 0.9², i.e. ‖e‖ decreased by 10 %.
    rot_weight
        Weight c (m²) of the rotation distance ‖R − R_t‖²_F (dimensionless) against the
        position distance ‖p − p_t‖² (m²) in the ranking of table samples by pose distance to
        a target, for chains 0.4–2.5 m long; scaled with the chain's length outside
        (:func:`app.kinematics.ik.scale.rotation_weight`, :attr:`IKChain.rot_weight`).
    rng_seed
        Seed of the per-chain table of restart configurations.
    table
        Size of that table (configurations uniform within the limits, with their FK poses).
    distinct
        Two solutions are distinct when some revolute joint differs by more than this (rad),
        or some prismatic joint by more than this times the chain's length (m; 1 mm on a 1 m
        chain: :func:`app.kinematics.ik.scale.joint_units`, :attr:`IKChain.distinct`).
    nearest
        Restarts taken from the table samples nearest the target before random jumps.
    nearest_ratio
        The loops jump from the seed to the nearest table sample at once when that sample's
        pose distance to the target is below this fraction of the seed's.
    compiled
        Run the compiled loop (:mod:`.kernel`, :mod:`.search_kernel`) where it applies (full
        pose, a serial chain of 1-DoF joints, Numba installed); False: the Python loop
        (:mod:`.dls`) always, which takes the same iterates (for comparisons).
    chunk_attempts
        Attempts (each at most ``attempt_cap`` iterations, a few tens of µs) per compiled
        call, between two reads of the clock and the cancel flag: the deadline is overrun by
        at most one chunk (~0.1 ms).
    """

    mu: float = 1e-10
    damp: float = 0.01
    null_gain: float = 0.2
    null_energy: float = 1e-2
    null_floor: float = 1e-8
    max_step: float = 2.0
    stall: int = 2
    attempt_cap: int = 20
    clamp: bool = True
    nearest_first: bool = True
    progress: float = 0.81
    rot_weight: float = 0.2
    rng_seed: int = 0x1C0DE
    table: int = 4096
    distinct: float = 1e-3
    nearest: int = 32
    nearest_ratio: float = 0.5
    chunk_attempts: int = 4
    compiled: bool = True


#: The parameters every endpoint uses.
DEFAULT_PARAMETERS = SolverParameters()
