"""Packing a corpus case folder and uploading it through POST /robots/package.

A case folder (``tests/corpus/<case_id>/``) holds the vendor's files laid out as their
repositories lay them out (package folders with their ``package.xml``), plus
``PROVENANCE.md``. :func:`pack_case` packs the folder as a tar.gz (deterministic: sorted
names, zero mtimes, no owners) and :func:`upload_case` sends it as the multipart form a lab
sends.
"""

from __future__ import annotations

import gzip
import io
import json
import tarfile
from pathlib import Path
from typing import Any

import httpx

#: Files of a case folder that are the corpus' own, not the vendor's: never uploaded.
NOT_UPLOADED = frozenset({"PROVENANCE.md"})


def pack_case(folder: Path | str) -> bytes:
    """The case folder as a tar.gz, member names relative to ``folder``.

    Parameters
    ----------
    folder
        The case folder. Every regular file under it is packed (``PROVENANCE.md`` at its top
        and ``__pycache__`` folders excepted), in sorted order, with mtime 0, mode 0644 and
        no owner, so the same folder always gives the same bytes.

    Returns
    -------
    bytes
        The gzip-compressed tar archive.
    """
    root = Path(folder)
    raw = io.BytesIO()
    with tarfile.open(fileobj=raw, mode="w", format=tarfile.PAX_FORMAT) as tf:
        for path in sorted(root.rglob("*")):
            rel = path.relative_to(root).as_posix()
            if not path.is_file() or rel in NOT_UPLOADED or "__pycache__" in path.parts:
                continue
            data = path.read_bytes()
            info = tarfile.TarInfo(rel)
            info.size = len(data)
            info.mode = 0o644
            info.mtime = 0
            tf.addfile(info, io.BytesIO(data))
    return gzip.compress(raw.getvalue(), compresslevel=6, mtime=0)


def upload_case(
    client: Any, name: str, folder: Path | str, description: str, **fields: Any
) -> httpx.Response:
    """POST /robots/package with the packed case folder, as a lab uploads it.

    Parameters
    ----------
    client
        A FastAPI ``TestClient`` (or any httpx-like client with ``post``).
    name
        The robot id.
    folder
        The case folder (packed with :func:`pack_case`).
    description
        Path inside the archive of the robot description (``.urdf``, ``.xacro`` or MJCF).
    **fields
        Other form fields (``srdf``, ``xacro_args``, ``srdf_xacro_args``, ``ee_frame``,
        ``summary``...). A dict value (``xacro_args={"name": "ur"}``) is sent as JSON;
        ``None`` values are left out.

    Returns
    -------
    httpx.Response
        The service's response (201 with the robot's detail on success).
    """
    data = {"name": name, "description": description}
    for key, value in fields.items():
        if value is None:
            continue
        data[key] = json.dumps(value) if isinstance(value, dict) else str(value)
    files = {"archive": (f"{name}.tar.gz", pack_case(folder), "application/gzip")}
    return client.post("/robots/package", data=data, files=files)
