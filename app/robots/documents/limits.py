"""Every bound on an uploaded robot, in one object (the ``DENAVIT_*`` upload settings)."""

from __future__ import annotations

from dataclasses import dataclass

from app.kinematics.meshes import MeshLimits
from app.robots.documents.archive import ArchiveLimits
from app.robots.documents.sandbox import PARSE_LIMITS, ChildLimits
from app.robots.documents.urdf import UrdfLimits
from app.robots.documents.xacro import XacroLimits


@dataclass(frozen=True, slots=True)
class UploadLimits:
    """The bounds of one upload.

    Attributes
    ----------
    urdf
        Work a URDF or SRDF may cause (``DENAVIT_MAX_XML_*``, ``DENAVIT_MAX_URDF_JOINTS``,
        ``DENAVIT_MAX_ROBOT_DOF``).
    archive
        An unpacked package (``DENAVIT_MAX_PACKAGE_FILES``, ``_UNPACKED_BYTES``).
    xacro
        A xacro expansion's child (``DENAVIT_XACRO_*``).
    mesh
        Every mesh file's header, a robot's collision triangles
        (``DENAVIT_MAX_MESH_VERTICES``, ``DENAVIT_MAX_COLLISION_TRIANGLES``): at upload and
        before a worker loads a mesh.
    parse
        The child that reads the meshes or converts an MJCF model (``DENAVIT_PARSE_*``).
    """

    urdf: UrdfLimits = UrdfLimits()
    archive: ArchiveLimits = ArchiveLimits()
    xacro: XacroLimits = XacroLimits()
    mesh: MeshLimits = MeshLimits()
    parse: ChildLimits = PARSE_LIMITS
