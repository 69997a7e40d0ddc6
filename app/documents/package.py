"""A client's description package, unpacked: its URDF, with every file reference inside it.

:func:`read_package` turns an unpacked archive (see :mod:`app.documents.archive`) into the
URDF (and SRDF) text the service stores:

1. the description is read by its extension: ``.urdf`` as is, ``.xacro`` expanded
   (:func:`app.documents.xacro.expand_xacro`), MJCF ``.xml`` converted
   (:func:`app.documents.mjcf.mjcf_to_urdf`);
2. every ``<mesh>`` and ``<texture>`` ``filename`` is resolved inside the package:
   a relative path or ``file://<relative path>`` against the description's directory,
   ``package://<pkg>/<path>`` against package ``<pkg>``, which is the ``<name>`` of a
   ``package.xml`` in the archive (its directory) or else a top-level folder of the
   archive. ``package://example-robot-data/...`` (the catalog's files) stays as it is when
   no package of the archive has that name. Absolute paths, ``file:///…``, other schemes,
   unknown packages and paths leaving the archive (after normalising ``..``; the archive
   holds no links) are refused, as is a reference to a file the archive does not have;
3. each reference is rewritten to the one canonical form :data:`FILES_PREFIX` +
   ``<path in the archive>``: Pinocchio resolves it with the robot's directory as package
   directory (the files are stored under ``<robot dir>/files/``), and it maps to
   ``GET /robots/{robot_id}/files/<path in the archive>``.

Every refusal is an :class:`~app.kinematics.errors.InvalidInputError` naming the request
field (``description``, ``srdf`` or ``archive``) and the file.
"""

from __future__ import annotations

import posixpath
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from xml.etree.ElementTree import Element, tostring

from app.documents.manifests import package_names, read_member
from app.documents.mjcf import mjcf_to_urdf
from app.documents.urdf import check_resource_uri, resource_elements
from app.documents.xacro import XacroLimits, expand_xacro
from app.kinematics.errors import InvalidInputError
from app.kinematics.meshes import MESH_FORMATS
from app.kinematics.xmldoc import XmlLimits, parse_literal_xml
from app.store import PACKAGE_DIR

#: The prefix of every rewritten reference (``package://files/<path>``): its package name is
#: the directory the store keeps a robot's package files in (:data:`app.store.PACKAGE_DIR`),
#: so Pinocchio resolves it with the robot's directory as package directory.
FILES_PREFIX = f"package://{PACKAGE_DIR}/"
#: The catalog's package, resolved against the example-robot-data share directory.
CATALOG_PACKAGE = "example-robot-data"
DESCRIPTION_TYPES = (".urdf", ".xacro", ".xml")
_SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*://")
_MTLLIB = re.compile(rb"^\s*mtllib\s+(.+?)\s*$", re.MULTILINE)


@dataclass
class Package:
    """The URDF (and SRDF) of an unpacked package, references rewritten.

    ``meshes`` maps each mesh URI as the description wrote it to the file it resolves to
    (under ``root`` or the catalog), for loading at upload.
    """

    urdf: str
    srdf: str | None
    meshes: dict[str, Path] = field(default_factory=dict)


class _Resolver:
    """Resolves the references of one description inside its package."""

    def __init__(
        self, root: Path, base: str, packages: Mapping[str, str], catalog: Path, fld: str
    ) -> None:
        self.root = root
        self.real_root = root.resolve()
        self.base = base
        self.packages = packages
        self.catalog = catalog
        self.field = fld

    def _refuse(self, tag: str, uri: str, reason: str) -> InvalidInputError:
        return InvalidInputError(f"<{tag} filename={uri[:200]!r}>: {reason}", self.field)

    def resolve(self, tag: str, uri: str) -> tuple[str, Path]:
        """``(canonical URI, file)`` for a ``filename``; raises naming it."""
        if any(c.isspace() or ord(c) < 32 or c in "\\%?#" for c in uri) or not uri:
            raise self._refuse(tag, uri, "empty, or whitespace, '\\', '%', '?' or '#' in it")
        if uri.startswith("package://"):
            pkg, _, rest = uri[len("package://") :].partition("/")
            if pkg not in self.packages:
                if pkg == CATALOG_PACKAGE and check_resource_uri(uri) is None:
                    file = self.catalog / pkg / rest
                    if not file.is_file():
                        raise self._refuse(tag, uri, "no such file in the catalog")
                    return uri, file
                known = ", ".join(sorted(self.packages)) or "none"
                raise self._refuse(
                    tag, uri, f"package {pkg!r} is not in the archive (its packages: {known})"
                )
            start = self.packages[pkg]
            path = rest
        elif uri.startswith("file://"):
            path = uri[len("file://") :]
            if path.startswith("/"):
                raise self._refuse(tag, uri, "absolute file:// URIs are not allowed")
            start = self.base
        elif _SCHEME.match(uri):
            scheme = uri.split("://", 1)[0]
            raise self._refuse(tag, uri, f"scheme {scheme}:// is not allowed")
        elif uri.startswith("/") or re.match(r"^[A-Za-z]:", uri):
            raise self._refuse(tag, uri, "absolute paths are not allowed")
        else:
            start, path = self.base, uri
        rel = posixpath.normpath(posixpath.join(start, path)) if path else ".."
        if rel == ".." or rel.startswith("../") or rel.startswith("/") or rel == ".":
            raise self._refuse(tag, uri, "the path leaves the package")
        file = self.root / rel
        if not file.resolve().is_relative_to(self.real_root):
            raise self._refuse(tag, uri, "the path leaves the package")
        if not file.is_file():
            raise self._refuse(tag, uri, f"{rel!r} is not a file of the archive")
        canonical = FILES_PREFIX + rel
        why = check_resource_uri(canonical)
        if why is not None:
            raise self._refuse(tag, uri, f"the file name {rel!r} is not usable ({why})")
        return canonical, file

    def check_obj_materials(self, uri: str, file: Path) -> None:
        """An OBJ's ``mtllib`` files must lie in the package too (assimp opens them)."""
        if file.suffix.lower() != ".obj" or not file.is_relative_to(self.root):
            return
        folder = file.parent.relative_to(self.root).as_posix()
        for match in _MTLLIB.finditer(file.read_bytes()):
            name = match.group(1).decode("utf-8", "replace")
            rel = posixpath.normpath(posixpath.join(folder, name))
            if name.startswith("/") or rel == ".." or rel.startswith("../"):
                raise self._refuse("mesh", uri, f"its material library {name!r} leaves the package")


def rewrite_references(urdf: str, resolver: _Resolver, limits: XmlLimits) -> Package:
    """The URDF with every mesh/texture reference in canonical form, and its meshes."""
    root = parse_literal_xml(urdf, resolver.field, limits)
    meshes: dict[str, Path] = {}
    for element, uri in resource_elements(root):
        canonical, file = resolver.resolve(element.tag, uri)
        element.set("filename", canonical)
        if element.tag == "mesh":
            if file.suffix.lower() not in MESH_FORMATS:
                raise resolver._refuse(
                    "mesh", uri, f"unsupported format (use {', '.join(sorted(MESH_FORMATS))})"
                )
            resolver.check_obj_materials(uri, file)
            meshes[uri] = file
    return Package(tostring(root, encoding="unicode"), None, meshes)


def read_package(
    root: Path,
    description: str,
    *,
    srdf: str | None,
    xacro_args: Mapping[str, str],
    catalog: Path,
    limits: XmlLimits,
    xacro_limits: XacroLimits = XacroLimits(),
) -> Package:
    """The URDF (references rewritten, see the module docstring) and SRDF of a package.

    Parameters
    ----------
    root
        The unpacked archive.
    description, srdf
        Paths inside the archive (request fields ``description`` and ``srdf``).
    xacro_args
        Arguments of a ``.xacro`` description.
    catalog
        The example-robot-data ``share`` directory (for ``package://example-robot-data``).
    limits, xacro_limits
        XML work bounds; the bounds of a xacro expansion (time, memory, output).
    """
    lowered = description.lower()
    if not lowered.endswith(DESCRIPTION_TYPES):
        raise InvalidInputError(
            f"{description[:200]!r}: the description must be a .urdf, .xacro or MJCF .xml file",
            "description",
        )
    rel, text = read_member(root, description, "description", "description")
    packages = package_names(root, limits)
    if lowered.endswith(".xacro"):
        urdf = expand_xacro(
            root,
            rel,
            xacro_args,
            limits,
            packages=packages,
            timeout_s=xacro_limits.timeout_s,
            memory_bytes=xacro_limits.memory_bytes,
            max_output_chars=xacro_limits.max_output_chars,
        )
    elif lowered.endswith(".xml"):
        urdf = mjcf_to_urdf(root, rel, limits)
    else:
        urdf = text
    resolver = _Resolver(root, posixpath.dirname(rel), packages, catalog, "description")
    package = rewrite_references(urdf, resolver, limits)
    if srdf is not None:
        package.srdf = read_member(root, srdf, "srdf", "srdf")[1]
    return package


def catalog_meshes(urdf: Element, catalog: Path, fld: str) -> dict[str, Path]:
    """The meshes of a single uploaded URDF (no package; its checked root element, see
    :func:`app.documents.urdf.check_documents`): catalog files only.

    Each ``<mesh filename>`` (already a safe ``package://`` URI, see
    :func:`app.documents.urdf.check_resource_uri`) must name a file of
    ``package://example-robot-data/...``; anything else is refused naming it.
    """
    meshes: dict[str, Path] = {}
    for element in urdf.iter("mesh"):
        uri = element.get("filename")
        if uri is None:
            continue
        pkg, _, rest = uri.removeprefix("package://").partition("/")
        file = catalog / pkg / rest
        if pkg != CATALOG_PACKAGE or check_resource_uri(uri) is not None or not file.is_file():
            raise InvalidInputError(
                f"<mesh filename={uri[:200]!r}>: no such file (a URDF on its own may only use "
                f"the catalog's {'package://' + CATALOG_PACKAGE}/... meshes; send a package "
                "with its meshes to POST /robots/package)",
                fld,
            )
        meshes[uri] = file
    return meshes
