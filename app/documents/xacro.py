"""Expanding a client's ``.urdf.xacro`` into URDF text, confined to its package.

Contract (the package upload calls this; being written):
``expand_xacro(root, description, args, limits) -> str``.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

from app.kinematics.xmldoc import XmlLimits


def expand_xacro(root: Path, description: str, args: Mapping[str, str], limits: XmlLimits) -> str:
    """The URDF text of the xacro file ``root / description`` expanded with ``args``.

    ``root`` is the unpacked package (every include must resolve inside it);
    ``description`` is the file's path relative to ``root``. Raises
    :class:`~app.kinematics.errors.InvalidInputError` naming the file and line.
    """
    raise NotImplementedError("xacro expansion: being written")
