"""The triangles of a COLLADA (``.dae``) mesh as the file connects them, for collision.

coal 3.0.3's mesh loader (assimp underneath) reads a COLLADA node that holds several
meshes wrongly: assimp makes one mesh per primitive list (``<triangles>``, ``<polylist>``
… one per material), and coal numbers the vertices of the second and later ones as if
each started at 0, so their triangles join vertices of the first mesh. A multi-material
collision mesh (the Kinova Gen3's ``base_link.dae``: a white and a blue polylist) then
has the right vertices but wrong triangles, and a collision check misses real contacts
(a 1.1 mm penetration reported as a 1.7 mm gap). :func:`read_collada` reads the
triangles from the file itself, with coal's conventions, and says whether a node holds
several meshes, so the caller can build the BVH from them where coal's is wrong:

- a ``<node>``'s ``<matrix>`` (row-major), ``<translate>``, ``<rotate>`` (axis, degrees)
  and ``<scale>`` apply, composed in document order, down the node tree of the visual scene
  (the scene's ``<instance_visual_scene>``, else the first one); ``<instance_node>`` of
  ``<library_nodes>`` is followed;
- the ``<asset>``'s ``<unit>`` and ``<up_axis>`` do not apply (coal leaves out assimp's
  root transform, which carries them);
- ``<triangles>``, ``<polylist>``, ``<polygons>`` (fans), ``<trifans>`` and
  ``<tristrips>`` give triangles; lines and points give none; degenerate triangles (a
  repeated corner) are dropped.

Anything else in the node tree (``<instance_controller>``, ``<lookat>``, ``<skew>``, a
missing source) raises :class:`UnsupportedCollada`: the caller keeps coal's reading.
The document is parsed without DTDs or entities and with literal names
(:func:`app.kinematics.xmldoc.parse_literal_xml`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from xml.etree.ElementTree import Element

import numpy as np

from app.kinematics.xmldoc import TRUSTED, parse_literal_xml

#: A node's transform elements (``lookat`` and ``skew`` are not read).
_TRANSFORMS = ("matrix", "translate", "rotate", "scale", "lookat", "skew")
#: The primitive lists that give triangles (``lines`` and ``linestrips`` give none).
_PRIMITIVES = ("triangles", "polylist", "polygons", "trifans", "tristrips")


class UnsupportedCollada(ValueError):
    """The file uses what :func:`read_collada` does not read (module doc)."""


def _local(tag: str) -> str:
    return tag.rsplit(":", 1)[-1].rsplit("}", 1)[-1]


def _children(element: Element, name: str) -> list[Element]:
    return [c for c in element if _local(c.tag) == name]


def _child(element: Element, name: str) -> Element | None:
    found = _children(element, name)
    return found[0] if found else None


def _numbers(element: Element | None, kind: type = float) -> np.ndarray:
    if element is None or element.text is None:
        return np.zeros(0, dtype=kind)
    return np.array(element.text.split(), dtype=kind)


def _rotation(axis: np.ndarray, degrees: float) -> np.ndarray:
    """4×4 rotation about ``axis`` (normalised) by ``degrees`` (Rodrigues)."""
    n = float(np.linalg.norm(axis))
    T = np.eye(4)
    if n == 0.0:
        return T
    x, y, z = axis / n
    a = math.radians(degrees)
    c, s, C = math.cos(a), math.sin(a), 1.0 - math.cos(a)
    T[:3, :3] = [
        [c + x * x * C, x * y * C - z * s, x * z * C + y * s],
        [y * x * C + z * s, c + y * y * C, y * z * C - x * s],
        [z * x * C - y * s, z * y * C + x * s, c + z * z * C],
    ]
    return T


def _node_transform(node: Element) -> np.ndarray:
    """The node's own transform: its transform elements composed in document order."""
    T = np.eye(4)
    for element in node:
        tag = _local(element.tag)
        values = _numbers(element) if tag in _TRANSFORMS else None
        if tag == "matrix":
            if values.size != 16:
                raise UnsupportedCollada("a <matrix> without 16 numbers")
            T = T @ values.reshape(4, 4)
        elif tag == "translate":
            step = np.eye(4)
            step[:3, 3] = values[:3]
            T = T @ step
        elif tag == "rotate":
            T = T @ _rotation(values[:3], float(values[3]))
        elif tag == "scale":
            T = T @ np.diag([*values[:3], 1.0])
        elif tag in ("lookat", "skew"):
            raise UnsupportedCollada(f"<{tag}> in a node")
    return T


class _Document:
    def __init__(self, root: Element) -> None:
        self.ids: dict[str, Element] = {}
        for element in root.iter():
            if "id" in element.attrib:
                self.ids[element.get("id", "")] = element
        self.root = root

    def target(self, url: str | None) -> Element:
        if not url or not url.startswith("#") or url[1:] not in self.ids:
            raise UnsupportedCollada(f"the reference {url!r} is not an element of the file")
        return self.ids[url[1:]]

    def positions(self, mesh: Element) -> np.ndarray:
        vertices = _child(mesh, "vertices")
        if vertices is None:
            raise UnsupportedCollada("a <mesh> without <vertices>")
        for put in _children(vertices, "input"):
            if put.get("semantic") == "POSITION":
                source = self.target(put.get("source"))
                accessor = source.find(".//technique_common/accessor")
                stride = int(accessor.get("stride", "3")) if accessor is not None else 3
                values = _numbers(_child(source, "float_array"))
                if stride < 3 or values.size % stride:
                    raise UnsupportedCollada("a POSITION source that is not xyz triples")
                return values.reshape(-1, stride)[:, :3]
        raise UnsupportedCollada("<vertices> without a POSITION input")

    def triangles(self, primitive: Element) -> np.ndarray:
        """Corner indices (into the positions) of the primitive list's triangles."""
        inputs = _children(primitive, "input")
        stride = 1 + max((int(i.get("offset", "0")) for i in inputs), default=0)
        vertex = [int(i.get("offset", "0")) for i in inputs if i.get("semantic") == "VERTEX"]
        if not vertex:
            raise UnsupportedCollada(f"<{_local(primitive.tag)}> without a VERTEX input")
        lists = [_numbers(p, int) for p in _children(primitive, "p")]
        if any(p.size % stride for p in lists):
            raise UnsupportedCollada("a <p> whose length is not a multiple of the inputs")
        corners = [p.reshape(-1, stride)[:, vertex[0]] for p in lists]
        tag = _local(primitive.tag)
        out: list[np.ndarray] = []
        if tag == "triangles":
            flat = np.concatenate(corners) if corners else np.zeros(0, dtype=int)
            out.append(flat[: len(flat) - len(flat) % 3].reshape(-1, 3))
        elif tag == "polylist":
            counts = _numbers(_child(primitive, "vcount"), int)
            flat = np.concatenate(corners) if corners else np.zeros(0, dtype=int)
            if counts.sum() != len(flat):
                raise UnsupportedCollada("a <polylist> whose <vcount> does not match its <p>")
            start = 0
            for k in counts:
                out.append(_fan(flat[start : start + k]))
                start += k
        elif tag in ("polygons", "trifans"):
            out.extend(_fan(c) for c in corners)
        else:  # tristrips
            for c in corners:
                strip = [
                    (c[i], c[i + 1], c[i + 2]) if i % 2 == 0 else (c[i + 1], c[i], c[i + 2])
                    for i in range(len(c) - 2)
                ]
                out.append(np.array(strip, dtype=int).reshape(-1, 3))
        return np.concatenate(out) if out else np.zeros((0, 3), dtype=int)


def _fan(corners: np.ndarray) -> np.ndarray:
    if len(corners) < 3:
        return np.zeros((0, 3), dtype=int)
    return np.array(
        [(corners[0], corners[i], corners[i + 1]) for i in range(1, len(corners) - 1)],
        dtype=int,
    )


@dataclass(frozen=True)
class ColladaMesh:
    """A COLLADA file's triangles: ``vertices`` (n, 3) in the file's units, placed by the
    node tree; ``triangles`` (m, 3) indices into them; ``shared_nodes``: whether a node
    holds several meshes (primitive lists with triangles, one per material and geometry):
    what coal misreads."""

    vertices: np.ndarray
    triangles: np.ndarray
    shared_nodes: bool


def read_collada(path: Path) -> ColladaMesh:
    """The triangles of the COLLADA file ``path`` (module doc).

    Raises
    ------
    UnsupportedCollada
        What this reader does not read (the caller keeps coal's reading).
    """
    try:
        root = parse_literal_xml(path.read_text("utf-8", "replace"), "mesh", TRUSTED)
    except Exception as exc:  # the header check already parsed it; be safe anyway
        raise UnsupportedCollada(f"not parsed ({exc})") from None
    doc = _Document(root)
    scene = root.find(".//scene/instance_visual_scene")
    if scene is not None:
        visual = doc.target(scene.get("url"))
    else:
        visual = root.find(".//library_visual_scenes/visual_scene")
    if visual is None:
        raise UnsupportedCollada("no visual scene")
    vertices: list[np.ndarray] = []
    triangles: list[np.ndarray] = []
    total = 0
    shared = False

    def visit(node: Element, parent: np.ndarray, depth: int) -> None:
        nonlocal total, shared
        if depth > 64:
            raise UnsupportedCollada("nodes nested too deeply")
        T = parent @ _node_transform(node)
        meshes = 0
        for child in node:
            tag = _local(child.tag)
            if tag == "instance_controller":
                raise UnsupportedCollada("<instance_controller> (a skin)")
            if tag == "instance_node":
                visit(doc.target(child.get("url")), T, depth + 1)
            elif tag == "node":
                visit(child, T, depth + 1)
            elif tag == "instance_geometry":
                mesh = _child(doc.target(child.get("url")), "mesh")
                if mesh is None:
                    raise UnsupportedCollada("a geometry that is not a <mesh>")
                points = doc.positions(mesh)
                placed = points @ T[:3, :3].T + T[:3, 3]
                for primitive in mesh:
                    if _local(primitive.tag) in _PRIMITIVES:
                        tris = doc.triangles(primitive)
                        if tris.size and (tris.min() < 0 or tris.max() >= len(points)):
                            raise UnsupportedCollada("a vertex index outside its source")
                        keep = (tris[:, 0] != tris[:, 1]) & (tris[:, 1] != tris[:, 2])
                        keep &= tris[:, 0] != tris[:, 2]
                        triangles.append(tris[keep] + total)
                        meshes += len(tris) > 0
                vertices.append(placed)
                total += len(placed)
        shared = shared or meshes > 1

    for node in _children(visual, "node"):
        visit(node, np.eye(4), 0)
    if not triangles or not sum(len(t) for t in triangles):
        raise UnsupportedCollada("no triangles")
    return ColladaMesh(np.concatenate(vertices), np.concatenate(triangles), shared)
