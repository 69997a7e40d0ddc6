"""Reading a client's MJCF (MuJoCo) arm into URDF text, confined to its package.

Contract (the package upload calls this; being written):
``mjcf_to_urdf(root, description, limits) -> str``.
"""

from __future__ import annotations

from pathlib import Path

from app.kinematics.xmldoc import XmlLimits


def mjcf_to_urdf(root: Path, description: str, limits: XmlLimits) -> str:
    """URDF text equivalent to the MJCF file ``root / description``.

    Mesh ``filename``s in the result are paths relative to the description's directory.
    Raises :class:`~app.kinematics.errors.InvalidInputError` (a joint that is not a hinge
    or slide names the joint and its type).
    """
    raise NotImplementedError("MJCF import: being written")
