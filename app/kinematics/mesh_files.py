"""What a mesh file declares, read without a mesh loader: its sizes and the files it names.

A client's mesh is read here before any loader sees it (coal's, which is assimp, in the
upload's child process; coal's again in a worker building a collision model), so that a
186-byte file declaring six million vertices is refused in microseconds instead of costing
a loader seconds or gigabytes. Everything here is linear in the file's size, reads it in
bounded chunks, and uses no regular expression that could backtrack.

Sizes (:func:`mesh_counts`, checked against ``max_vertices``):

- STL: binary (an 80-byte header, a triangle count, 50 bytes per triangle: the file must
  hold them) or ASCII (``solid`` …; its ``vertex`` statements are counted);
- PLY: the header's ``element <name> <count>`` lines (every element, vertices and faces
  included, at most ``max_vertices``), which must fit in the file: a binary body holds at
  least the bytes of its scalar properties per element, an ASCII one two bytes per value;
- OBJ: ``v``/``vn``/``vt`` statements (vertices) and ``f`` statements (triangles: a face of
  k corners is k − 2);
- COLLADA (``.dae``): the ``count`` of the accessors of the ``POSITION`` sources (vertices)
  and of the primitives (``triangles``, ``polylist``, ``polygons``, ``trifans``,
  ``tristrips``: faces), by a streaming XML parse without DTDs or entities.

References (:func:`mesh_references`): OBJ ``mtllib`` (every name on the statement and the
whole rest of it, as tinyobj and assimp read it), MTL texture statements (``map_*``,
``bump``, ``disp``, ``decal``, ``refl``, ``norm``: every word that is not an option),
COLLADA ``<image>`` sources (``<init_from>``, 1.4 and 1.5) and every ``url``/``source``/
``target`` attribute that is not a local ``#id``, PLY ``comment TextureFile``. OBJ and MTL
lines end at ``\\n``, ``\\r``, ``\\f`` or NUL (assimp's line ends), and a line ending in
``\\`` continues on the next: references are read in both views (lines as they are, and
continued lines joined), so neither a bare CR nor a continuation hides one.

This module imports nothing outside the standard library.
"""

from __future__ import annotations

import struct
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from xml.parsers import expat

#: Mesh formats read here and accepted in uploads (file extension, lower-case).
MESH_FORMATS = frozenset({".stl", ".dae", ".obj", ".ply"})
#: Longest OBJ/MTL line (bytes, continuations joined), longest PLY header.
MAX_LINE_BYTES = 1 << 20
MAX_PLY_HEADER_BYTES = 1 << 16
_CHUNK = 1 << 20
#: OBJ/MTL line ends (assimp's IsLineEnd) mapped to ``\n``.
_LINE_ENDS = bytes.maketrans(b"\r\f\0", b"\n\n\n")
#: Bytes per PLY scalar type.
_PLY_SIZES = {
    **dict.fromkeys((b"char", b"uchar", b"int8", b"uint8"), 1),
    **dict.fromkeys((b"short", b"ushort", b"int16", b"uint16"), 2),
    **dict.fromkeys((b"int", b"uint", b"int32", b"uint32", b"float", b"float32"), 4),
    **dict.fromkeys((b"double", b"float64"), 8),
}
_MTL_TEXTURES = frozenset({b"bump", b"disp", b"decal", b"refl", b"norm"})
_DAE_PRIMITIVES = frozenset({"triangles", "polylist", "polygons", "trifans", "tristrips"})


class MeshFileError(ValueError):
    """The file is refused before any loader sees it: not a valid file of its format;
    ``str(exc)`` says why (no path)."""


class MeshTooLarge(MeshFileError):
    """The file declares more than the limits allow."""


@dataclass(frozen=True, slots=True)
class MeshCounts:
    """Sizes a mesh file declares: ``vertices`` (positions) and ``faces`` (triangles for
    STL and OBJ; polygons or strips for PLY and COLLADA)."""

    vertices: int
    faces: int


@dataclass(frozen=True, slots=True)
class Reference:
    """A file a mesh file names: ``what`` (``mtllib``, ``texture``, ``image``, ``url``) and
    the name as written, relative to the mesh's folder."""

    what: str
    name: str


# ------------------------------------------------------------------------------ counts
def mesh_counts(path: Path, max_vertices: int) -> MeshCounts:
    """The sizes ``path`` declares, each at most ``max_vertices``; else :class:`MeshFileError`.

    The format is the file's extension (one of :data:`MESH_FORMATS`).
    """
    suffix = path.suffix.lower()
    if suffix == ".stl":
        counts = _stl_counts(path)
    elif suffix == ".ply":
        counts = _ply_counts(path, max_vertices)
    elif suffix == ".obj":
        counts = _obj_counts(path)
    elif suffix == ".dae":
        counts = _dae_counts(path)
    else:
        raise MeshFileError(f"format {suffix or '(none)'!r} is not a mesh format")
    for what, n in (("vertices", counts.vertices), ("faces", counts.faces)):
        if n > max_vertices:
            raise MeshTooLarge(
                f"declares {n} {what}, more than {max_vertices} (DENAVIT_MAX_MESH_VERTICES)"
            )
    return counts


def _stl_counts(path: Path) -> MeshCounts:
    size = path.stat().st_size
    with open(path, "rb") as f:
        head = f.read(84)
    declared = struct.unpack("<I", head[80:84])[0] if len(head) == 84 else None
    binary_fits = declared is not None and size >= 84 + 50 * declared
    if head.lstrip()[:5].lower() == b"solid" and not (binary_fits and size == 84 + 50 * declared):
        vertices = _count_word(path, b"vertex")
        return MeshCounts(vertices, -(-vertices // 3))
    if declared is None or not binary_fits:
        raise MeshFileError(
            f"not a valid STL: a binary STL of {declared or 0} triangles needs "
            f"{84 + 50 * (declared or 0)} bytes, the file has {size}"
        )
    return MeshCounts(3 * declared, declared)


def _count_word(path: Path, word: bytes) -> int:
    """Occurrences of ``word`` (any case) in the file, read in chunks. The tail kept between
    chunks is one byte shorter than ``word``: it holds no whole occurrence, so none is
    counted twice, and one split across chunks is counted once."""
    count, tail = 0, b""
    with open(path, "rb") as f:
        while chunk := f.read(_CHUNK):
            data = tail + chunk.lower()
            count += data.count(word)
            tail = data[len(data) - len(word) + 1 :]
    return count


def _ply_counts(path: Path, max_vertices: int) -> MeshCounts:
    with open(path, "rb") as f:
        head = f.read(MAX_PLY_HEADER_BYTES)
    end = head.find(b"end_header")
    if not head.startswith(b"ply") or end < 0:
        raise MeshFileError(
            f"not a valid PLY: no 'ply' ... 'end_header' in its first {MAX_PLY_HEADER_BYTES} bytes"
        )
    newline = head.find(b"\n", end)
    body = path.stat().st_size - (newline + 1 if newline >= 0 else len(head))
    fmt = b""
    elements: list[tuple[bytes, int, int, int]] = []  # name, count, min bytes, min values
    for raw in head[:end].translate(_LINE_ENDS).split(b"\n"):
        words = raw.split()
        if not words:
            continue
        if words[0] == b"format" and len(words) >= 2:
            fmt = words[1]
        elif words[0] == b"element":
            if len(words) != 3 or not words[2].isdigit():
                raise MeshFileError(f"not a valid PLY: element line {raw[:60]!r}")
            count = int(words[2])
            if count > max_vertices:
                raise MeshTooLarge(
                    f"declares {count} {words[1].decode(errors='replace')[:40]} elements, "
                    f"more than {max_vertices} (DENAVIT_MAX_MESH_VERTICES)"
                )
            elements.append((words[1], count, 0, 0))
        elif words[0] == b"property" and elements:
            name, count, size, values = elements[-1]
            if len(words) >= 2 and words[1] == b"list":
                size += _PLY_SIZES.get(words[2], 1) if len(words) > 2 else 1
            else:
                size += _PLY_SIZES.get(words[1], 1) if len(words) > 1 else 1
            elements[-1] = (name, count, size, values + 1)
    if fmt not in (b"ascii", b"binary_little_endian", b"binary_big_endian"):
        raise MeshFileError(f"not a valid PLY: format {fmt[:40]!r}")
    # at least: binary, the bytes of each scalar (a list's count); ASCII, "0 " per value
    needed = sum(n * (size if fmt != b"ascii" else 2 * values) for _, n, size, values in elements)
    if needed > body:
        raise MeshFileError(
            f"not a valid PLY: its header declares at least {needed} bytes of data, "
            f"the file holds {body}"
        )
    counts = {name: n for name, n, _, _ in elements}
    return MeshCounts(
        counts.get(b"vertex", 0), counts.get(b"face", 0) + counts.get(b"tristrips", 0)
    )


# ------------------------------------------------------------------------------ OBJ, MTL
def text_lines(path: Path) -> Iterator[bytes]:
    """The lines of an OBJ or MTL file, each ending at ``\\n``, ``\\r``, ``\\f`` or NUL.

    Raises :class:`MeshFileError` for a line longer than :data:`MAX_LINE_BYTES`.
    """
    pending = b""
    with open(path, "rb") as f:
        while chunk := f.read(_CHUNK):
            lines = (pending + chunk).translate(_LINE_ENDS).split(b"\n")
            pending = lines.pop()
            if len(pending) > MAX_LINE_BYTES:
                raise MeshFileError(f"a line is longer than {MAX_LINE_BYTES} bytes")
            for line in lines:
                if len(line) > MAX_LINE_BYTES:
                    raise MeshFileError(f"a line is longer than {MAX_LINE_BYTES} bytes")
                yield line
    yield pending


def statements(path: Path) -> Iterator[list[bytes]]:
    """The words of every OBJ/MTL statement, in both views: each line as it is (a trailing
    ``\\`` dropped), and each line ending in ``\\`` joined to the next (the backslash
    dropped)."""
    joined = b""
    for line in text_lines(path):
        stripped = line.rstrip()
        continued = stripped.endswith(b"\\")
        words = (stripped[:-1] if continued else line).split()
        if words:
            yield words
        if continued:
            joined += stripped[:-1] + b" "
            if len(joined) > MAX_LINE_BYTES:
                raise MeshFileError(f"a continued line is longer than {MAX_LINE_BYTES} bytes")
            continue
        if joined:
            yield (joined + line).split()
            joined = b""
    if joined:
        yield joined.split()


def _obj_counts(path: Path) -> MeshCounts:
    counts = {b"v": 0, b"vn": 0, b"vt": 0}
    faces = 0
    for line in text_lines(path):
        words = line.split(None, 1)
        if not words:
            continue
        key = words[0]
        if key in counts:
            counts[key] += 1
        elif key == b"f":
            faces += max(1, len(line.split()) - 3)
    vertices = max(counts.values())
    return MeshCounts(vertices, faces)


def _obj_references(path: Path) -> list[Reference]:
    out: list[Reference] = []
    for words in statements(path):
        if words[0] == b"mtllib" and len(words) > 1:
            names = {w.decode("utf-8", "replace") for w in words[1:]}
            names.add(b" ".join(words[1:]).decode("utf-8", "replace"))
            out.extend(Reference("mtllib", name) for name in sorted(names))
    return out


def _mtl_references(path: Path) -> list[Reference]:
    out: list[Reference] = []
    for words in statements(path):
        key = words[0].lower()
        if key.startswith(b"map_") or key in _MTL_TEXTURES:
            names = {w.decode("utf-8", "replace") for w in words[1:] if not w.startswith(b"-")}
            out.extend(Reference("texture", name) for name in sorted(names))
    return out


# ------------------------------------------------------------------------------ COLLADA
class _DaeReader:
    """Streaming COLLADA reader: accessor counts, positions, primitives, references."""

    def __init__(self) -> None:
        self.stack: list[str] = []
        self.source: str | None = None
        self.accessors: dict[str, int] = {}
        self.positions: list[str] = []
        self.faces = 0
        self.references: list[Reference] = []
        self.text: list[str] | None = None

    def start(self, name: str, attrs: dict[str, str]) -> None:
        tag = name.rsplit(":", 1)[-1]
        parent = self.stack[-1] if self.stack else ""
        self.stack.append(tag)
        if tag == "source" and "id" in attrs:
            self.source = attrs["id"]
        elif tag == "accessor" and self.source is not None:
            self.accessors[self.source] = _count(attrs.get("count", "0"), "accessor")
        elif tag == "input" and parent == "vertices" and attrs.get("semantic") == "POSITION":
            self.positions.append(attrs.get("source", "").removeprefix("#"))
        elif tag in _DAE_PRIMITIVES:
            self.faces += _count(attrs.get("count", "0"), tag)
        if tag == "init_from" and "image" in self.stack or tag == "ref" and parent == "init_from":
            self.text = []
        for key in ("url", "source", "target"):
            value = attrs.get(key)
            if value is not None and not value.startswith("#") and tag != "accessor":
                self.references.append(Reference("url", value))

    def data(self, text: str) -> None:
        if self.text is not None:
            self.text.append(text)
            if sum(map(len, self.text)) > MAX_LINE_BYTES:
                raise MeshFileError(f"an image reference is longer than {MAX_LINE_BYTES} bytes")

    def end(self, name: str) -> None:
        tag = self.stack.pop() if self.stack else ""
        if self.text is not None and tag in ("init_from", "ref"):
            value = "".join(self.text).strip()
            self.text = None
            if value:
                self.references.append(Reference("image", value))
        if tag == "source":
            self.source = None

    def vertices(self) -> int:
        return sum(self.accessors.get(source, 0) for source in self.positions)


def _count(text: str, what: str) -> int:
    if not text.strip().isdigit() or len(text) > 20:
        raise MeshFileError(f"not a valid COLLADA file: <{what} count={text[:40]!r}>")
    return int(text)


def _read_dae(path: Path) -> _DaeReader:
    reader = _DaeReader()

    def refuse(*_: object) -> None:
        raise MeshFileError("not a valid COLLADA file: DTDs and entities are not accepted")

    parser = expat.ParserCreate()  # no namespaces: names as written
    parser.StartElementHandler = reader.start
    parser.EndElementHandler = reader.end
    parser.CharacterDataHandler = reader.data
    parser.StartDoctypeDeclHandler = refuse
    parser.EntityDeclHandler = refuse
    parser.ExternalEntityRefHandler = refuse
    parser.SetParamEntityParsing(expat.XML_PARAM_ENTITY_PARSING_NEVER)
    try:
        with open(path, "rb") as f:
            while chunk := f.read(_CHUNK):
                parser.Parse(chunk, False)
        parser.Parse(b"", True)
    except expat.ExpatError as exc:
        raise MeshFileError(
            f"not a valid COLLADA file ({expat.ErrorString(exc.code)}: line {exc.lineno})"
        ) from None
    except RecursionError:  # pragma: no cover - expat does not recurse
        raise MeshFileError("not a valid COLLADA file (nested too deeply)") from None
    return reader


def _dae_counts(path: Path) -> MeshCounts:
    reader = _read_dae(path)
    return MeshCounts(reader.vertices(), reader.faces)


# ------------------------------------------------------------------------------ references
def mesh_references(path: Path) -> list[Reference]:
    """The files ``path`` names (an OBJ, MTL, COLLADA or PLY file; others name none).

    Raises :class:`MeshFileError` for a file that cannot be read as its format.
    """
    suffix = path.suffix.lower()
    if suffix == ".obj":
        return _obj_references(path)
    if suffix == ".mtl":
        return _mtl_references(path)
    if suffix == ".dae":
        return _read_dae(path).references
    if suffix == ".ply":
        with open(path, "rb") as f:
            head = f.read(MAX_PLY_HEADER_BYTES)
        end = head.find(b"end_header")
        out = []
        for raw in head[: end if end >= 0 else len(head)].translate(_LINE_ENDS).split(b"\n"):
            words = raw.split(None, 2)
            if len(words) == 3 and words[0] == b"comment" and words[1].lower() == b"texturefile":
                out.append(Reference("texture", words[2].strip().decode("utf-8", "replace")))
        return out
    return []
