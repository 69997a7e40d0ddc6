"""Heat-map images of reachability maps: the colour map and a dependency-free PNG encoder.

:func:`slice_image` renders one voxel layer of a map (colour = best manipulability over
orientations, viridis scaled to the map's maximum, light grey = unreached) with the first
remaining axis increasing to the right and the second increasing upwards (row 0 of the image
is the layer's top: the largest coordinate of the second axis). :func:`png_bytes` encodes
an RGB array as an 8-bit PNG.
"""

from __future__ import annotations

import struct
import zlib

import numpy as np

from app.kinematics.errors import InvalidInputError
from app.kinematics.reachability.map import ReachabilityMap

#: Viridis, sampled at six points (low → high manipulability).
_VIRIDIS = np.array(
    [[68, 1, 84], [65, 68, 135], [42, 120, 142], [34, 168, 132], [122, 209, 81], [253, 231, 37]],
    dtype=float,
)
UNREACHED_RGB = (235, 235, 235)


def colour_map(values: np.ndarray, vmax: float) -> np.ndarray:
    """RGB (…, 3) uint8: viridis over [0, vmax]; negative values (unreached) light grey."""
    t = np.clip(values / vmax, 0.0, 1.0) if vmax > 0 else np.zeros_like(values)
    x = t * (len(_VIRIDIS) - 1)
    i = np.minimum(np.floor(x).astype(int), len(_VIRIDIS) - 2)
    f = (x - i)[..., None]
    rgb = _VIRIDIS[i] * (1 - f) + _VIRIDIS[i + 1] * f
    rgb[values < 0] = UNREACHED_RGB
    return np.round(rgb).astype(np.uint8)


def png_bytes(rgb: np.ndarray) -> bytes:
    """An 8-bit RGB PNG (zlib + struct; filter 0 on every row)."""
    h, w, _ = rgb.shape
    raw = b"".join(b"\x00" + rgb[r].tobytes() for r in range(h))

    def chunk(kind: bytes, data: bytes) -> bytes:
        return (
            struct.pack(">I", len(data))
            + kind
            + data
            + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
        )

    return (
        b"\x89PNG\r\n\x1a\n"
        + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
        + chunk(b"IDAT", zlib.compress(raw, 6))
        + chunk(b"IEND", b"")
    )


def slice_image(m: ReachabilityMap, axis: int, value: float, scale: int | None) -> np.ndarray:
    """RGB image of the voxel layer containing ``value`` along ``axis`` (0 x, 1 y, 2 z).

    Colour = best manipulability over orientations in the voxel. Horizontal axis: the
    first remaining axis (x for z and y slices, y for x slices), increasing to the right;
    vertical: the second, increasing upwards.
    """
    spec = m.spec
    name = "xyz"[axis]
    lo, hi = spec.lower[axis], spec.upper[axis]
    if not lo <= value < hi:
        raise InvalidInputError(f"{value} is outside the map's {name} range [{lo}, {hi})", name)
    i = min(int(np.floor((value - lo) / spec.voxel_size)), spec.shape[axis] - 1)
    if not 0 <= i < spec.shape[axis]:
        raise InvalidInputError(
            f"{value} is outside the map's {name} range [{lo}, {spec.upper[axis]})", name
        )
    layer = np.take(m.voxel_best(), i, axis=axis)  # (first, second) remaining axes
    img_vals = layer.T[::-1]  # rows: second axis, top = largest
    vmax = m.meta.get("max_manipulability") or 0.0
    rgb = colour_map(img_vals.astype(float), float(vmax))
    if scale is None:
        scale = max(1, min(32, 512 // max(rgb.shape[0], rgb.shape[1])))
    return np.repeat(np.repeat(rgb, scale, axis=0), scale, axis=1)
