"""Reading an unpacked package's files: one file as text, and the packages it holds.

Both :mod:`app.robots.documents.package` (``package://<pkg>/...`` references) and
:mod:`app.robots.documents.xacro` (``$(find <pkg>)``) name packages by :func:`package_names`, so
the two resolve the same names to the same folders.
"""

from __future__ import annotations

import posixpath
from pathlib import Path

from app.kinematics.errors import InvalidInputError
from app.kinematics.xmldoc import XmlLimits, parse_literal_xml
from app.robots.documents.archive import member_parts

#: Largest description, SRDF or package.xml read from a package (bytes).
MAX_DOCUMENT_BYTES = 8 * 1024 * 1024


def read_member(root: Path, path: str, what: str, fld: str) -> tuple[str, str]:
    """``(normalised path, text)`` of the archive file ``path``."""
    try:
        parts = member_parts(path)
    except InvalidInputError as exc:
        raise InvalidInputError(exc.message.replace("member ", f"{what} ", 1), fld) from None
    file = root.joinpath(*parts)
    if not parts or not file.is_file() or file.is_symlink():
        raise InvalidInputError(f"{path[:200]!r} is not a file of the archive", fld)
    if file.stat().st_size > MAX_DOCUMENT_BYTES:
        raise InvalidInputError(f"{path[:200]!r} is larger than {MAX_DOCUMENT_BYTES} bytes", fld)
    try:
        text = file.read_bytes().decode("utf-8-sig")
    except UnicodeDecodeError:
        raise InvalidInputError(f"{path[:200]!r} is not UTF-8 text", fld) from None
    return "/".join(parts), text


def package_names(root: Path, limits: XmlLimits) -> dict[str, str]:
    """Package name → its directory in the archive (``""`` for the archive's root).

    From each ``package.xml``'s ``<name>``, then every top-level folder not named so.
    Two ``package.xml`` with the same name are refused.
    """
    names: dict[str, str] = {}
    for manifest in sorted(root.rglob("package.xml")):
        if not manifest.is_file():
            continue
        rel = manifest.relative_to(root).as_posix()
        _, text = read_member(root, rel, "package.xml", "archive")
        try:
            doc = parse_literal_xml(text, "archive", limits)
        except InvalidInputError as exc:
            raise InvalidInputError(f"{rel}: {exc.message}", "archive") from None
        name = (doc.findtext("name") or "").strip()
        if doc.tag != "package" or not name:
            continue
        folder = posixpath.dirname(rel)
        if name in names:
            raise InvalidInputError(
                f"package {name!r} is defined twice ({names[name] or '.'}/package.xml and {rel})",
                "archive",
            )
        names[name] = folder
    for top in sorted(root.iterdir()):
        if top.is_dir() and top.name not in names:
            names[top.name] = top.name
    return names
