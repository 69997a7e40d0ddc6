"""Wire models of robot packages: POST /robots/package (``multipart/form-data``: an archive
and text fields)."""

from __future__ import annotations

from pydantic import Field

from app.api.schemas.common import Schema, Text
from app.storage.store import ID_PATTERN


class PackageUpload(Schema):
    """A robot as a description package: an archive with its description and meshes.

    Sent as ``multipart/form-data``; every field but ``archive`` is a text part.
    """

    name: Text = Field(
        max_length=256,
        json_schema_extra={"pattern": ID_PATTERN.pattern},
        description="Robot id: 1-64 of a-z, 0-9, '_' and '-' (used in /robots/{robot_id}).",
    )
    archive: bytes = Field(
        json_schema_extra={"format": "binary"},
        description="The package: a zip or tar.gz archive (size and entry limits: "
        "DENAVIT_MAX_PACKAGE_BYTES, _FILES, _UNPACKED_BYTES).",
    )
    description: Text = Field(
        max_length=1024,
        description="Path inside the archive of the robot description: .urdf, .xacro or "
        "MJCF .xml (e.g. panda_description/urdf/panda.urdf).",
    )
    srdf: Text | None = Field(
        None,
        max_length=1024,
        description="Path of an SRDF file; one ending .xacro (e.g. ur_moveit_config/srdf/"
        "ur.srdf.xacro) is expanded like a .xacro description, with the same packages.",
    )
    xacro_args: Text | None = Field(
        None,
        max_length=65536,
        description="JSON object of xacro arguments: names to strings, numbers or booleans "
        '({"arm_id": "panda"}); also those of a .xacro SRDF unless srdf_xacro_args is given.',
    )
    srdf_xacro_args: Text | None = Field(
        None,
        max_length=65536,
        description="JSON object of the arguments of a .xacro SRDF, when they differ from "
        'xacro_args ({"name": "ur5e", "prefix": ""}); same rules as xacro_args.',
    )
    ee_frame: Text | None = Field(
        None,
        max_length=256,
        description="Default end-effector frame (default: the SRDF end effector's parent link, "
        "else the tip of the longest serial chain that is not a gripper finger).",
    )
    summary: Text = Field("", max_length=1000, description="Short description of the robot.")


class PackageForm(PackageUpload):
    """The text fields of a package upload (the archive part is read apart)."""

    archive: bytes = b""  # the file part is read apart; the text fields are validated here
