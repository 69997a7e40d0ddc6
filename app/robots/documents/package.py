"""A client's description package, unpacked: its URDF, with every file reference inside it.

:func:`read_package` turns an unpacked archive (see :mod:`app.robots.documents.archive`) into the
URDF (and SRDF) text the service stores:

1. the description is read by its extension: ``.urdf`` as is, ``.xacro`` expanded
   (:func:`app.robots.documents.xacro.expand_xacro`), MJCF ``.xml`` converted
   (:func:`app.robots.documents.mjcf.mjcf_to_urdf`);
   An SRDF ending ``.xacro`` (MoveIt configs such as ``ur_moveit_config`` ship only
   ``srdf/ur.srdf.xacro``) is expanded by the same sandboxed xacro, with the same
   packages, with ``srdf_xacro_args`` if given, else ``xacro_args``;
2. every ``<mesh>`` and ``<texture>`` ``filename`` is resolved inside the package:
   a relative path or ``file://<relative path>`` against the description's directory,
   ``package://<pkg>/<path>`` against package ``<pkg>``, which is the ``<name>`` of a
   ``package.xml`` in the archive (its directory) or else a top-level folder of the
   archive. ``package://example-robot-data/robots/<folder>/<path>`` (the catalog's files)
   when no package of the archive has that name: the archive's own copy when it has one
   (``robots/<folder>/<path>``, ``<folder>/<path>`` or ``<path>`` under the description's
   directory or its nearest ancestor that has one: an uploaded copy of a catalog package
   always uses its own files), else the catalog's file, the URI kept as it is. In an
   expanded xacro, the paths ``$(find)`` gives (``/package/<folder>/…``, with or without
   ``file://``) are the package's files.
   Absolute paths, ``file:///…``, other schemes, unknown packages and paths leaving the
   archive (after normalising ``..``; the archive holds no links) are refused, as is a
   reference to a file the archive does not have;
3. every mesh's header is read (:func:`app.kinematics.meshes.check_header`: declared
   vertices and faces within ``DENAVIT_MAX_MESH_VERTICES``, a collision mesh's faces within
   ``DENAVIT_MAX_COLLISION_TRIANGLES``), and every file a mesh names (OBJ ``mtllib``, MTL
   textures, COLLADA images and URLs, PLY texture comments:
   :func:`app.kinematics.mesh_files.mesh_references`) must lie inside the package, by the
   same rules (a missing one is allowed: no loader opens a file that is not there);
4. each reference is rewritten to the one canonical form :data:`FILES_PREFIX` +
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
from urllib.parse import unquote
from xml.etree.ElementTree import Element, tostring

from app.kinematics.errors import InvalidInputError
from app.kinematics.mesh_files import MeshFileError, mesh_references
from app.kinematics.meshes import MESH_FORMATS, MeshLimits, check_header
from app.kinematics.xmldoc import XmlLimits, parse_literal_xml
from app.robots.documents.limits import UploadLimits
from app.robots.documents.manifests import package_names, read_member
from app.robots.documents.mjcf import mjcf_to_urdf
from app.robots.documents.urdf import check_resource_uri, resource_elements
from app.robots.documents.xacro import expand_xacro
from app.robots.documents.xacro_child import VIRTUAL_ROOT
from app.storage.store import PACKAGE_DIR

#: The prefix of every rewritten reference (``package://files/<path>``): its package name is
#: the directory the store keeps a robot's package files in (:data:`app.storage.store.PACKAGE_DIR`),
#: so Pinocchio resolves it with the robot's directory as package directory.
FILES_PREFIX = f"package://{PACKAGE_DIR}/"
#: The catalog's package, resolved against the example-robot-data share directory.
CATALOG_PACKAGE = "example-robot-data"
DESCRIPTION_TYPES = (".urdf", ".xacro", ".xml")
_SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*://")
_DRIVE = re.compile(r"^[A-Za-z]:")
#: A URI scheme in a name a mesh file writes (two letters at least: ``C:`` is a drive).
_REF_SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]+:")


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
    """Resolves the references of one description inside its package.

    ``virtual_root``: where the description saw the package (an expanded xacro's
    ``/package``): absolute paths under it are the package's files.
    """

    def __init__(
        self,
        root: Path,
        base: str,
        packages: Mapping[str, str],
        catalog: Path,
        fld: str,
        virtual_root: str | None = None,
    ) -> None:
        self.root = root
        self.real_root = root.resolve()
        self.base = base
        self.packages = packages
        self.catalog = catalog
        self.field = fld
        self.virtual_root = virtual_root

    def _refuse(self, tag: str, uri: str, reason: str) -> InvalidInputError:
        return InvalidInputError(f"<{tag} filename={uri[:200]!r}>: {reason}", self.field)

    def _virtual(self, path: str) -> str | None:
        """``path`` relative to the package when it is under :attr:`virtual_root`.

        Repeated leading slashes are one, as the file system reads them: xacro that writes
        ``file:///$(find pkg)/…`` (UFactory's xarm_description) gives ``file:////package/…``.
        """
        root = self.virtual_root
        path = "/" + path.lstrip("/")
        if root is not None and (path == root or path.startswith(root + "/")):
            return path[len(root) + 1 :]
        return None

    def resolve(self, tag: str, uri: str) -> tuple[str, Path]:
        """``(canonical URI, file)`` for a ``filename``; raises naming it."""
        if any(c.isspace() or ord(c) < 32 or c in "\\%?#" for c in uri) or not uri:
            raise self._refuse(tag, uri, "empty, or whitespace, '\\', '%', '?' or '#' in it")
        start = self.base
        if uri.startswith("package://"):
            pkg, _, rest = uri[len("package://") :].partition("/")
            if pkg not in self.packages:
                if pkg == CATALOG_PACKAGE and check_resource_uri(uri) is None:
                    own = self._own_copy(rest)
                    if own is not None:
                        return self._canonical(tag, uri, own)
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
                inside = self._virtual(path)
                if inside is None:
                    raise self._refuse(tag, uri, "absolute file:// URIs are not allowed")
                start, path = "", inside
        elif _SCHEME.match(uri):
            scheme = uri.split("://", 1)[0]
            raise self._refuse(tag, uri, f"scheme {scheme}:// is not allowed")
        elif uri.startswith("/") or _DRIVE.match(uri):
            inside = self._virtual(uri)
            if inside is None:
                raise self._refuse(tag, uri, "absolute paths are not allowed")
            start, path = "", inside
        else:
            path = uri
        rel = self._confined(tag, uri, start, path)
        if not (self.root / rel).is_file():
            raise self._refuse(tag, uri, f"{rel!r} is not a file of the archive")
        return self._canonical(tag, uri, rel)

    def _canonical(self, tag: str, uri: str, rel: str) -> tuple[str, Path]:
        """``(FILES_PREFIX + rel, file)`` for the archive's file ``rel``; refuses a name
        Pinocchio could not resolve."""
        canonical = FILES_PREFIX + rel
        why = check_resource_uri(canonical)
        if why is not None:
            raise self._refuse(tag, uri, f"the file name {rel!r} is not usable ({why})")
        return canonical, self.root / rel

    def _own_copy(self, rest: str) -> str | None:
        """The archive's own copy of the catalog file ``package://example-robot-data/<rest>``
        (a path in the archive), or ``None`` (module doc, step 2).

        ``rest`` is ``robots/<folder>/<path>`` for a catalog package folder: the copy is
        ``robots/<folder>/<path>``, ``<folder>/<path>`` or ``<path>`` (longest first) under
        the description's directory or one of its ancestors (nearest first), so that an
        upload of the folder itself, of a folder holding it or of a copy of
        example-robot-data is found. ``rest`` has plain segments (checked by the caller).
        """
        parts = rest.split("/")
        tails = [rest]
        if parts[0] == "robots" and len(parts) >= 3:
            tails += ["/".join(parts[1:]), "/".join(parts[2:])]
        anchor = self.base
        while True:
            for tail in tails:
                rel = posixpath.join(anchor, tail)
                file = self.root / rel
                if file.is_file() and file.resolve().is_relative_to(self.real_root):
                    return rel
            if not anchor:
                return None
            anchor = posixpath.dirname(anchor)

    def _confined(self, tag: str, uri: str, start: str, path: str) -> str:
        """``start/path`` normalised, if it stays in the package (symlinks followed)."""
        rel = posixpath.normpath(posixpath.join(start, path)) if path else ".."
        if rel == ".." or rel.startswith("../") or rel.startswith("/") or rel == ".":
            raise self._refuse(tag, uri, "the path leaves the package")
        if not (self.root / rel).resolve().is_relative_to(self.real_root):
            raise self._refuse(tag, uri, "the path leaves the package")
        return rel

    def check_named_files(self, uri: str, file: Path) -> None:
        """Every file the mesh ``file`` names (and, for an OBJ, its material libraries
        name) lies inside the package (:func:`app.kinematics.mesh_files.mesh_references`).
        A named file the package lacks is allowed: no loader opens it."""
        todo = [file]
        seen: set[Path] = set()
        while todo:
            current = todo.pop()
            if current in seen or not current.is_relative_to(self.root):
                continue
            seen.add(current)
            folder = current.parent.relative_to(self.root).as_posix()
            where = current.relative_to(self.root).as_posix()
            try:
                references = mesh_references(current)
            except MeshFileError as exc:  # its message names no path
                raise self._refuse("mesh", uri, f"{where} cannot be read ({exc})") from None
            except OSError as exc:  # str(exc) would show where the package is unpacked
                why = exc.strerror or type(exc).__name__
                raise self._refuse("mesh", uri, f"{where} cannot be read ({why})") from None
            for ref in references:
                rel = self._confine_reference(uri, where, ref.what, ref.name, folder)
                target = self.root / rel
                if ref.what == "mtllib" and target.suffix.lower() == ".mtl" and target.is_file():
                    todo.append(target)

    def _confine_reference(self, uri: str, where: str, what: str, name: str, folder: str) -> str:
        """``name`` (written in the file ``where``) relative to the package, or refuse."""
        label = {"mtllib": "material library", "url": "URL"}.get(what, what)
        shown = f"{where} names the {label} {name[:200]!r}"
        if any(ord(c) < 32 for c in name):
            raise self._refuse("mesh", uri, f"{shown}: control characters in it")
        name = name.replace("\\", "/")  # a loader may read a backslash as a separator
        decoded = unquote(name)  # a loader may percent-decode it (COLLADA's URIs)
        if decoded != name:
            self._confine_name(uri, shown, folder, decoded)
        return self._confine_name(uri, shown, folder, name)

    def _confine_name(self, uri: str, shown: str, folder: str, name: str) -> str:
        """``name`` relative to ``folder`` and the package (no scheme but ``file://``, not
        absolute, not leaving it), or refuse with ``shown``."""
        path = name[len("file://") :] if name.lower().startswith("file://") else name
        if path == name and _REF_SCHEME.match(path):
            raise self._refuse("mesh", uri, f"{shown}: no scheme is allowed")
        if path.startswith("/") or _DRIVE.match(path):
            raise self._refuse("mesh", uri, f"{shown}: absolute paths leave the package")
        try:
            return self._confined("mesh", uri, folder, path)
        except InvalidInputError:
            raise self._refuse("mesh", uri, f"{shown}: the path leaves the package") from None


def rewrite_references(
    urdf: str, resolver: _Resolver, limits: XmlLimits, mesh_limits: MeshLimits
) -> Package:
    """The URDF with every mesh/texture reference in canonical form, and its meshes (their
    headers and the files they name checked)."""
    root = parse_literal_xml(urdf, resolver.field, limits)
    collision = {id(m) for c in root.iter("collision") for m in c.iter("mesh")}
    meshes: dict[str, Path] = {}
    for element, uri in resource_elements(root):
        canonical, file = resolver.resolve(element.tag, uri)
        element.set("filename", canonical)
        if element.tag == "mesh":
            if file.suffix.lower() not in MESH_FORMATS:
                raise resolver._refuse(
                    "mesh", uri, f"unsupported format (use {', '.join(sorted(MESH_FORMATS))})"
                )
            check_header(file, uri, mesh_limits, "archive", id(element) in collision)
            resolver.check_named_files(uri, file)
            meshes[uri] = file
    return Package(tostring(root, encoding="unicode"), None, meshes)


def read_package(
    root: Path,
    description: str,
    *,
    srdf: str | None,
    xacro_args: Mapping[str, str],
    catalog: Path,
    limits: UploadLimits = UploadLimits(),
    srdf_xacro_args: Mapping[str, str] | None = None,
) -> Package:
    """The URDF (references rewritten, see the module docstring) and SRDF of a package.

    Parameters
    ----------
    root
        The unpacked archive.
    description, srdf
        Paths inside the archive (request fields ``description`` and ``srdf``).
    xacro_args
        Arguments of a ``.xacro`` description, and of a ``.xacro`` SRDF unless
        ``srdf_xacro_args`` are given.
    srdf_xacro_args
        Arguments of a ``.xacro`` SRDF (refusals name ``srdf_xacro_args``), when they
        differ from the description's.
    catalog
        The example-robot-data ``share`` directory (for ``package://example-robot-data``).
    limits
        The upload's bounds: XML work, the xacro expansion (time, memory, output), the
        meshes, the child converting an MJCF description.
    """
    lowered = description.lower()
    if not lowered.endswith(DESCRIPTION_TYPES):
        raise InvalidInputError(
            f"{description[:200]!r}: the description must be a .urdf, .xacro or MJCF .xml file",
            "description",
        )
    rel, text = read_member(root, description, "description", "description")
    packages = package_names(root, limits.urdf.xml)
    xacro_limits, mesh_limits = limits.xacro, limits.mesh
    virtual_root = None
    resolver = _Resolver(root, posixpath.dirname(rel), packages, catalog, "description")

    def check_mesh(name: str, path: Path) -> None:  # an MJCF mesh asset
        uri = path.relative_to(resolver.real_root).as_posix()
        check_header(path, uri, mesh_limits, "archive", collision=False)
        resolver.check_named_files(uri, resolver.root / uri)

    def expand(path: str, args: Mapping[str, str], **fields: str) -> str:
        """``path`` expanded by the sandboxed xacro, with the package's ``$(find)``."""
        return expand_xacro(
            root,
            path,
            args,
            limits.urdf.xml,
            packages=packages,
            timeout_s=xacro_limits.timeout_s,
            memory_bytes=xacro_limits.memory_bytes,
            max_output_chars=xacro_limits.max_output_chars,
            **fields,
        )

    if lowered.endswith(".xacro"):
        urdf = expand(rel, xacro_args)
        virtual_root = VIRTUAL_ROOT
    elif lowered.endswith(".xml"):
        urdf = mjcf_to_urdf(
            root,
            rel,
            limits.urdf.xml,
            max_bodies=limits.urdf.max_joints,
            child=limits.parse,
            check_mesh=check_mesh,
        )
    else:
        urdf = text
    resolver.virtual_root = virtual_root
    package = rewrite_references(urdf, resolver, limits.urdf.xml, mesh_limits)
    if srdf is not None:
        srdf_rel, package.srdf = read_member(root, srdf, "srdf", "srdf")
        if srdf.lower().endswith(".xacro"):  # e.g. ur_moveit_config's srdf/ur.srdf.xacro
            package.srdf = expand(
                srdf_rel,
                xacro_args if srdf_xacro_args is None else srdf_xacro_args,
                field="srdf",
                args_field="xacro_args" if srdf_xacro_args is None else "srdf_xacro_args",
            )
    return package


def catalog_meshes(urdf: Element, catalog: Path, fld: str) -> dict[str, Path]:
    """The meshes of a single uploaded URDF (no package; its checked root element, see
    :func:`app.robots.documents.urdf.check_documents`): catalog files only.

    Each ``<mesh filename>`` (already a safe ``package://`` URI, see
    :func:`app.robots.documents.urdf.check_resource_uri`) must name a file of
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
