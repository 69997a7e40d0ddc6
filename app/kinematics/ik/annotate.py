"""An answer's branch flags and manipulability in compiled code, from the solver's own chain.

The HTTP answer labels every solution with its ``branch`` (:mod:`.branches`) and its
``manipulability`` (:mod:`.ranking`). Done with Pinocchio from Python, that is two more
kinematics passes (``computeJointJacobians`` for the label, a frame Jacobian for Yoshikawa's
measure) and some thirty interpreter round trips: ~50–70 µs, as much as the solve. The
compiled loop (:mod:`.kernel`) already walks the chain's joint frames; :func:`annotation`
walks them once more at the answered configuration (~1 µs) and gives both numbers:

- the branch code of :func:`app.kinematics.ik.branch_kernel.flags` from the joints' world
  axes z_i (direction of positive motion), their origins o_i (a point of each axis), the
  wrist point w (fixed in link 5, carried in the kernel's frame of joint 5) and the frame
  origin p: the definitions of :mod:`.branches`, read there;
- Yoshikawa's w = √det(G) of the frame's world Jacobian J (6, k) (Pinocchio's
  ``LOCAL_WORLD_ALIGNED``: column i = [z_i × (p − o_i); z_i] for a revolute joint, [z_i; 0]
  for a prismatic one), G = J Jᵀ when k ≥ 6, else Jᵀ J, det by LU with partial pivoting,
  √max(det, 0): :func:`app.kinematics.analysis.yoshikawa_batch`'s definition.

Frames: everything in the root (world) frame, m and rad. The kernel's frame of joint i has
its z axis along the joint axis and its origin at the joint's origin (Pinocchio's oMi
rotated, :class:`app.kinematics.chain.SerialChain`), so o_i and z_i are those of
:mod:`.branches`. The answer's configuration is verified by Pinocchio before this runs
(:meth:`~app.kinematics.ik.search.Search.offer`); the tests hold these numbers against
:func:`~app.kinematics.ik.branches.branch_label` and Pinocchio's Jacobian on many random
configurations.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from app.kinematics.ik import branch_kernel, joint_frames
from app.kinematics.jit import direct, jit

if TYPE_CHECKING:
    from app.kinematics.ik.precompute import IKChain
    from app.kinematics.models import RobotModel

#: The code of a chain without branch flags (its solutions are clusters, :mod:`.ranking`).
NO_FLAGS = -1


class AnnotationConstants(NamedTuple):
    """What :func:`annotation` reads of one chain besides its kinematics.

    ``labelled``: the chain has branch flags; ``kind``, ``elbow``, ``tip_axis4``:
    :func:`app.kinematics.ik.branch_kernel.form_arrays` of its form; ``wrist`` (3,): the
    wrist point in the kernel's frame of the fifth moving joint (m; zeros without one);
    ``tail``: every argument of :func:`annotation` after ``qa``, built once.
    """

    labelled: bool
    kind: int
    elbow: bool
    tip_axis4: bool
    wrist: np.ndarray
    tail: tuple


@jit
def _det(G):  # pragma: no cover
    """det G (r, r) by LU with partial pivoting (``G`` is overwritten)."""
    r = G.shape[0]
    det = 1.0
    for c in range(r):
        piv = c
        big = abs(G[c, c])
        for i in range(c + 1, r):
            if abs(G[i, c]) > big:
                big = abs(G[i, c])
                piv = i
        if big == 0.0:
            return 0.0
        if piv != c:
            for j in range(r):
                G[c, j], G[piv, j] = G[piv, j], G[c, j]
            det = -det
        d = G[c, c]
        det *= d
        for i in range(c + 1, r):
            f = G[i, c] / d
            for j in range(c + 1, r):
                G[i, j] -= f * G[c, j]
    return det


@jit
def yoshikawa(J):  # pragma: no cover
    """√max(det G, 0) of J (m, k), G = J Jᵀ if m ≤ k else Jᵀ J (the smaller Gram matrix)."""
    m, k = J.shape
    if m <= k:
        G = np.empty((m, m))
        for i in range(m):
            for j in range(i + 1):
                v = 0.0
                for s in range(k):
                    v += J[i, s] * J[j, s]
                G[i, j] = v
                G[j, i] = v
    else:
        G = np.empty((k, k))
        for i in range(k):
            for j in range(i + 1):
                v = 0.0
                for s in range(m):
                    v += J[s, i] * J[s, j]
                G[i, j] = v
                G[j, i] = v
    return math.sqrt(max(_det(G), 0.0))


@jit
def annotation(  # pragma: no cover
    qa, C, t, prism, last_C, last_t, labelled, kind, elbow, tip_axis4, wrist
):
    """(branch code, manipulability) at the chain configuration ``qa`` (k,).

    ``C``, ``t``, ``prism``, ``last_C``, ``last_t``: the chain's kinematics
    (:class:`~app.kinematics.ik.boundary.ChainConstants`); the rest:
    :class:`AnnotationConstants`. The code is :data:`NO_FLAGS` when not ``labelled``.
    """
    k = qa.shape[0]
    z = np.empty((k, 3))
    o = np.empty((k, 3))
    R = np.empty((3, 3))
    p = np.empty(3)
    w = np.zeros(3)
    joint_frames.frames(qa, C, t, prism, last_C, last_t, R, p, z, o, w, wrist)
    J = np.empty((6, k))
    for s in range(k):
        zx, zy, zz = z[s, 0], z[s, 1], z[s, 2]
        if prism[s]:
            J[0, s], J[1, s], J[2, s] = zx, zy, zz
            J[3, s] = J[4, s] = J[5, s] = 0.0
        else:
            dx, dy, dz = p[0] - o[s, 0], p[1] - o[s, 1], p[2] - o[s, 2]
            J[0, s] = zy * dz - zz * dy
            J[1, s] = zz * dx - zx * dz
            J[2, s] = zx * dy - zy * dx
            J[3, s], J[4, s], J[5, s] = zx, zy, zz
    code = NO_FLAGS
    if labelled:
        code = branch_kernel.flags(z, o, w, p, kind, elbow, tip_axis4)
    return code, yoshikawa(J)


def annotation_constants(robot: RobotModel, ch: IKChain) -> AnnotationConstants | None:
    """The chain's :class:`AnnotationConstants`, or None without the compiled loop
    (:attr:`IKChain.compiled`): then :mod:`.ranking` uses Pinocchio."""
    cc = ch.compiled
    if cc is None:
        return None
    form = ch.branch_form
    wrist = np.zeros(3)
    if form is None:
        return _constants(cc, False, 0, False, False, wrist)
    kind, elbow, tip_axis4 = branch_kernel.form_arrays(form)
    wrist = joint_frames.wrist_in_kernel_frame(robot, ch)
    return _constants(cc, True, int(kind), bool(elbow), bool(tip_axis4), wrist)


def _constants(cc, labelled: bool, kind: int, elbow: bool, tip_axis4: bool, wrist: np.ndarray):
    """:class:`AnnotationConstants` with its ``tail`` (the chain's kinematics first)."""
    wrist = np.ascontiguousarray(wrist, dtype=np.float64)
    tail = (cc.C, cc.t, cc.prism, cc.last_C, cc.last_t, labelled, kind, elbow, tip_axis4, wrist)
    return AnnotationConstants(labelled, kind, elbow, tip_axis4, wrist, tail)


def annotate(ch: IKChain, qa: np.ndarray) -> tuple[str | None, float]:
    """(branch label or None for a chain without flags, manipulability) of the chain
    configuration ``qa`` (k,) (rad or m); requires :attr:`IKChain.annotation`."""
    a = ch.annotation
    code, w = _entry()(np.ascontiguousarray(qa, dtype=np.float64), *a.tail)
    return (branch_kernel.label(ch.branch_form, code) if a.labelled else None), w


def _entry():
    """:func:`annotation`'s compiled entry point (:func:`app.kinematics.jit.direct`)."""
    return direct(annotation, *_EXAMPLE)


_Z3 = np.zeros(3)
#: Arguments of the types :func:`annotate` passes (a 1-joint chain).
_EXAMPLE = (np.zeros(1), np.eye(3)[None].copy(), np.zeros((1, 3)), np.zeros(1, np.bool_),
            np.eye(3), _Z3, False, 0, False, False, _Z3)  # fmt: skip


def warm_up() -> None:
    """Compile :func:`annotation` for the argument types :func:`annotate` passes."""
    _entry()(*_EXAMPLE)
