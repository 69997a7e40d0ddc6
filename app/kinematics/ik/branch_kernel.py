"""The branch flags of :mod:`.branches` as one compiled function, for compiled callers.

:func:`flags` computes the same signs as :func:`app.kinematics.ik.branches.branch_label`
(read the definitions there) from world quantities that a compiled solver or path check
already has at a configuration: the unit axes of the chain's moving joints, a point on each
axis, the wrist point and the frame origin. It returns them as a bit code; :func:`label`
spells a code as the label string, :func:`form_arrays` gives the switches of a
:class:`~app.kinematics.ik.branches.BranchForm` as :func:`flags` takes them.

Bit code
--------
- bit 0: ``shoulder_right`` (6R forms) or ``elbow_up`` (planar 2-link arm);
- bit 1: ``elbow_up`` (6R forms with an elbow flag);
- bit 2: ``wrist_noflip`` (6R forms).

A triple product that is exactly 0 counts as positive, as in :mod:`.branches`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from app.kinematics import jit

if TYPE_CHECKING:
    from app.kinematics.ik.branches import BranchForm

#: ``kind`` of :func:`flags`: a 6R arm (UR type or spherical wrist), a planar 2-link arm.
KIND_6R = 0
KIND_PLANAR2 = 1

SHOULDER_RIGHT = 1  # bit 0 of a 6R code
PLANAR_ELBOW_UP = 1  # bit 0 of a planar code
ELBOW_UP = 2
WRIST_NOFLIP = 4


@jit.jit
def _triple(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> float:
    """(a × b)·c of three 3-vectors, in the operation order of :mod:`.branches`."""
    return (
        (a[1] * b[2] - a[2] * b[1]) * c[0]
        + (a[2] * b[0] - a[0] * b[2]) * c[1]
        + (a[0] * b[1] - a[1] * b[0]) * c[2]
    )


@jit.jit
def flags(
    z: np.ndarray,
    o: np.ndarray,
    w: np.ndarray,
    p: np.ndarray,
    kind: int,
    elbow: bool,
    tip_axis4: bool,
) -> int:
    """The branch flags of one configuration as a bit code (module docstring).

    Parameters
    ----------
    z
        (k, 3) world unit axes of the chain's moving joints, each in its direction of
        positive motion.
    o
        (k, 3) a world point on each axis (m); any point of the axis gives the same flags.
    w
        (3,) the world wrist point (m; 6R forms: the form's wrist point carried by joint 5).
    p
        (3,) the world origin of the chain's frame (m; planar arms).
    kind
        :data:`KIND_6R` or :data:`KIND_PLANAR2`.
    elbow, tip_axis4
        The form's switches (:class:`~app.kinematics.ik.branches.BranchForm`).
    """
    if kind == KIND_PLANAR2:
        up = _triple(z[0], o[1] - o[0], p - o[1]) >= 0.0
        return PLANAR_ELBOW_UP if up else 0
    shoulder = _triple(z[0], z[1], w - o[1])
    code = SHOULDER_RIGHT if shoulder >= 0.0 else 0
    if elbow:
        t = o[3] if tip_axis4 else w
        turn = _triple(z[1], o[2] - o[1], t - o[2])
        if turn * shoulder < 0.0:
            code |= ELBOW_UP
    if _triple(z[3], z[5], z[4]) >= 0.0:
        code |= WRIST_NOFLIP
    return code


def form_arrays(form: BranchForm) -> tuple[int, bool, bool]:
    """``(kind, elbow, tip_axis4)`` of a branch form, as :func:`flags` takes them."""
    kind = KIND_PLANAR2 if form.kind == "planar2" else KIND_6R
    return kind, bool(form.elbow), bool(form.tip_axis4)


def label(form: BranchForm, code: int) -> str:
    """The label string of a bit code, spelled as
    :func:`~app.kinematics.ik.branches.branch_label` spells it for ``form``."""
    if form.kind == "planar2":
        return "elbow_up" if code & PLANAR_ELBOW_UP else "elbow_down"
    parts = ["shoulder_right" if code & SHOULDER_RIGHT else "shoulder_left"]
    if form.elbow:
        parts.append("elbow_up" if code & ELBOW_UP else "elbow_down")
    parts.append("wrist_noflip" if code & WRIST_NOFLIP else "wrist_flip")
    return "/".join(parts)
