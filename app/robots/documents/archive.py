"""Unpacking a client's description package (zip or tar.gz) without trusting it.

:func:`unpack_archive` extracts an uploaded archive into an empty directory, refusing
(:class:`~app.kinematics.errors.InvalidInputError` naming ``archive`` and the member) rather
than writing anything outside it or beyond the limits:

- member names: no absolute paths, drive letters (``C:``), backslashes, ``..`` segments,
  empty segments, control characters, over-long names or duplicates (after dropping
  ``.`` segments); a file and a directory may not share a name;
- member kinds: regular files and directories only. Symbolic links, hard links, devices
  and FIFOs are refused (tar types; a zip entry's Unix mode in ``external_attr``), so the
  unpacked tree holds no link and nothing resolves outside it;
- size: at most :attr:`ArchiveLimits.max_files` entries (counted before anything is
  extracted from a zip, and as a tar stream is read) and
  :attr:`ArchiveLimits.max_unpacked_bytes` in total. The bytes are counted as they are
  decompressed, never taken from the sizes an archive declares, so a zip bomb stops at the
  limit; a tar.gz is read as a stream through a counter bounding the whole decompressed
  stream (headers included);
- tar headers: every extended header (pax ``x`` and global ``g``, Solaris ``X``, GNU long
  name ``L`` and long link ``K``) is refused by its declared size, over
  :data:`MAX_EXTENDED_HEADER_BYTES`, before tarfile reads it (tarfile reads one whole,
  then parses it); at most :data:`MAX_EXTENDED_CHAIN` of them in a row (tarfile reads them
  recursively), pax headers of at most :data:`MAX_PAX_RECORDS` well-formed records (parsed
  here in linear time: Python before 3.11.10 searches them in quadratic time), global
  headers of at most :data:`MAX_EXTENDED_HEADER_BYTES` and :data:`MAX_PAX_RECORDS` records
  in all (each member gets a copy of them). GNU sparse members (type ``S``, pax
  ``GNU.sparse.*`` records) are refused. Members are not kept once extracted;
- a zip's central directory records are counted (not built) before zipfile reads them,
  so a directory of a million tiny records costs its own size, not ~8 times it;
- encrypted zip entries, unknown compression methods, corrupt or truncated data (CRC
  errors included) are refused.

Files are created with ``O_EXCL | O_NOFOLLOW`` and mode 0644, directories 0755. On a
refusal the caller removes the directory (some members may have been written).
"""

from __future__ import annotations

import gzip
import io
import os
import re
import stat
import struct
import tarfile
import zipfile
import zlib
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import BinaryIO

from app.kinematics.errors import InvalidInputError

FIELD = "archive"
#: Longest member name (bytes of UTF-8) and path segment; deepest nesting.
MAX_NAME_BYTES = 1024
MAX_SEGMENT_BYTES = 255
MAX_DEPTH = 32
_CHUNK = 1 << 16
_DRIVE = re.compile(r"^[A-Za-z]:")
#: Bytes a tar stream may hold beyond its members' data: headers (with long-name and pax
#: records) and padding per entry, and the end-of-archive record.
_TAR_OVERHEAD_PER_ENTRY = 4096
_TAR_OVERHEAD = 1 << 20
#: Largest tar extended header (a name is at most MAX_NAME_BYTES; a pax header holds a few
#: records: path, times, owner, extended attributes), and largest sum of the global ones.
MAX_EXTENDED_HEADER_BYTES = 64 * 1024
#: Most records in one pax header, and in the global ones together.
MAX_PAX_RECORDS = 256
#: Most extended headers before one member (a global header, a pax header, GNU long name
#: and long link headers: 4 in practice).
MAX_EXTENDED_CHAIN = 8
_EXTENDED = {
    tarfile.XHDTYPE: "pax extended header",
    tarfile.XGLTYPE: "pax global header",
    tarfile.SOLARIS_XHDTYPE: "Solaris extended header",
    tarfile.GNUTYPE_LONGNAME: "GNU long name header",
    tarfile.GNUTYPE_LONGLINK: "GNU long link header",
}
_PAX_LENGTH = re.compile(rb"([0-9]{1,20}) ")


@dataclass(frozen=True, slots=True)
class ArchiveLimits:
    """Bounds on one unpacked package (``DENAVIT_MAX_PACKAGE_FILES``,
    ``DENAVIT_MAX_PACKAGE_UNPACKED_BYTES``)."""

    max_files: int = 10_000
    max_unpacked_bytes: int = 256 * 1024 * 1024


def _refuse(reason: str, member: str | None = None) -> InvalidInputError:
    shown = f"member {member[:200]!r}: " if member is not None else ""
    return InvalidInputError(f"{shown}{reason}", FIELD)


def member_parts(name: str) -> tuple[str, ...]:
    """The path segments of an archive member name; raises for a name that could escape.

    Trailing ``/`` (a directory entry) and ``.`` segments are dropped; the result is empty
    for the archive root itself (``./``).
    """
    if any(ord(c) < 32 or ord(c) == 127 for c in name):
        raise _refuse("control characters are not allowed in names", name)
    if "\\" in name:
        raise _refuse("backslashes are not allowed in names", name)
    if name.startswith("/"):
        raise _refuse("absolute paths are not allowed", name)
    if _DRIVE.match(name):
        raise _refuse("drive letters are not allowed", name)
    try:
        encoded = name.encode("utf-8")
    except UnicodeEncodeError:
        raise _refuse("names must be valid UTF-8", name) from None
    if len(encoded) > MAX_NAME_BYTES:
        raise _refuse(f"names are limited to {MAX_NAME_BYTES} bytes", name)
    segments = name.rstrip("/").split("/") if name.rstrip("/") else []
    parts = []
    for segment in segments:
        if segment == "..":
            raise _refuse("'..' is not allowed in names (path escape)", name)
        if segment == "":
            raise _refuse("empty path segments ('//') are not allowed", name)
        if segment == ".":
            continue
        if len(segment.encode("utf-8")) > MAX_SEGMENT_BYTES:
            raise _refuse(f"a name segment is longer than {MAX_SEGMENT_BYTES} bytes", name)
        parts.append(segment)
    if len(parts) > MAX_DEPTH:
        raise _refuse(f"nested deeper than {MAX_DEPTH} directories", name)
    return tuple(parts)


class _Extractor:
    """Writes members under ``dest``, enforcing names, count and total bytes."""

    def __init__(self, dest: Path, limits: ArchiveLimits) -> None:
        self.dest = dest
        self.limits = limits
        self.kinds: dict[tuple[str, ...], str] = {}
        self.total = 0
        self.entries = 0

    def count(self) -> None:
        self.entries += 1
        if self.entries > self.limits.max_files:
            raise _refuse(f"more than {self.limits.max_files} entries (DENAVIT_MAX_PACKAGE_FILES)")

    def _claim(self, name: str, kind: str) -> tuple[str, ...] | None:
        parts = member_parts(name)
        if not parts:
            return None
        for i in range(1, len(parts)):
            if self.kinds.get(parts[:i]) == "file":
                raise _refuse("a file of the archive is used as a directory", name)
        previous = self.kinds.get(parts)
        if previous is not None and not (previous == kind == "dir"):
            raise _refuse("the name appears twice in the archive", name)
        for i in range(1, len(parts)):
            self.kinds.setdefault(parts[:i], "dir")
        self.kinds[parts] = kind
        return parts

    def directory(self, name: str) -> None:
        parts = self._claim(name, "dir")
        if parts is not None:
            self.dest.joinpath(*parts).mkdir(mode=0o755, parents=True, exist_ok=True)

    def file(self, name: str, chunks: Iterator[bytes]) -> None:
        parts = self._claim(name, "file")
        if parts is None:
            raise _refuse("a file entry has no name", name)
        path = self.dest.joinpath(*parts)
        path.parent.mkdir(mode=0o755, parents=True, exist_ok=True)
        fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o644)
        try:
            for chunk in chunks:
                self.total += len(chunk)
                if self.total > self.limits.max_unpacked_bytes:
                    raise _refuse(
                        f"unpacks to more than {self.limits.max_unpacked_bytes} bytes "
                        "(DENAVIT_MAX_PACKAGE_UNPACKED_BYTES)",
                        name,
                    )
                view = memoryview(chunk)
                while view:
                    view = view[os.write(fd, view) :]
        finally:
            os.close(fd)


def _read_chunks(stream: BinaryIO) -> Iterator[bytes]:
    while chunk := stream.read(_CHUNK):
        yield chunk


# ---------------------------------------------------------------------------- zip
def _zip_entries(source: BinaryIO) -> int | None:
    """The records of a zip's central directory, counted as zipfile walks them but without
    building them (zipfile makes a ~350-byte object of each 46-byte record before they can
    be counted); ``None`` when there is no directory to count (zipfile says why)."""
    try:  # zipfile's own private reader of the end record, so both find the same directory
        end = zipfile._EndRecData(source)
    except OSError:
        return None
    if not end:
        return None
    size = end[zipfile._ECD_SIZE]
    start = end[zipfile._ECD_LOCATION] - size  # where zipfile reads it (start_dir)
    if end[zipfile._ECD_SIGNATURE] == zipfile.stringEndArchive64:
        start -= zipfile.sizeEndCentDir64 + zipfile.sizeEndCentDir64Locator
    if start < 0:
        return None
    source.seek(start)
    directory = source.read(size)
    count = pos = 0
    while pos + 46 <= len(directory):  # fixed part: 46 bytes; name, extra, comment lengths
        name, extra, comment = struct.unpack_from("<3H", directory, pos + 28)
        pos += 46 + name + extra + comment
        count += 1
    return count


def _unpack_zip(source: BinaryIO, out: _Extractor) -> None:
    count = _zip_entries(source)
    if count is not None and count > out.limits.max_files:
        raise _refuse(
            f"{count} entries, more than {out.limits.max_files} (DENAVIT_MAX_PACKAGE_FILES)"
        )
    source.seek(0)
    try:
        archive = zipfile.ZipFile(source)
    except (zipfile.BadZipFile, zipfile.LargeZipFile, OSError, ValueError, EOFError) as exc:
        raise _refuse(f"not a valid zip archive ({exc})") from None
    with archive:
        infos = archive.infolist()
        if len(infos) > out.limits.max_files:  # before extracting anything
            raise _refuse(
                f"{len(infos)} entries, more than {out.limits.max_files} "
                "(DENAVIT_MAX_PACKAGE_FILES)"
            )
        for info in infos:
            name = info.filename
            out.count()
            mode = info.external_attr >> 16
            if stat.S_ISLNK(mode):
                raise _refuse("symbolic links are not allowed", name)
            if stat.S_IFMT(mode) not in (0, stat.S_IFREG, stat.S_IFDIR):  # 0: no Unix mode
                raise _refuse("only regular files and directories are allowed", name)
            if info.flag_bits & 0x1:
                raise _refuse("encrypted entries are not supported", name)
            if info.is_dir() or stat.S_ISDIR(mode):
                out.directory(name)
                continue
            try:
                with archive.open(info) as stream:
                    out.file(name, _read_chunks(stream))
            # zipfile raises NotImplementedError for a compression method it lacks (e.g.
            # Deflate64): a refusal of that member, like a corrupt stream.
            except (zipfile.BadZipFile, zlib.error, EOFError, NotImplementedError) as exc:
                raise _refuse(f"cannot be decompressed ({exc})", name) from None
            except OSError as exc:
                raise _refuse(f"cannot be extracted ({exc.strerror or exc})", name) from None


# ---------------------------------------------------------------------------- tar
class _Budget(io.RawIOBase):
    """A read-only stream that refuses to deliver more than ``limit`` bytes in total."""

    def __init__(self, inner: BinaryIO, limit: int) -> None:
        self.inner = inner
        self.limit = limit
        self.delivered = 0

    def readable(self) -> bool:
        return True

    def read(self, size: int | None = -1) -> bytes:
        if size is None or size < 0 or self.delivered + size > self.limit:
            size = self.limit - self.delivered + 1
        data = self.inner.read(size)
        self.delivered += len(data)
        if self.delivered > self.limit:
            raise _refuse(
                f"the decompressed tar stream is longer than {self.limit} bytes "
                "(DENAVIT_MAX_PACKAGE_UNPACKED_BYTES plus headers)"
            )
        return data


class _TarInfo(tarfile.TarInfo):
    """A tar header whose extended headers are bounded before tarfile reads them.

    tarfile's documented extension point: ``_proc_member`` chooses how a header is
    processed (``_proc_pax``, ``_proc_gnulong``, ``_proc_sparse``, ``_proc_builtin``), and
    an extended header processes the header after it (recursively) before returning it.
    """

    def _proc_member(self, archive: tarfile.TarFile) -> tarfile.TarInfo:
        assert isinstance(archive, _TarFile)
        kind = _EXTENDED.get(self.type)
        if kind is None:
            archive.extended_chain = 0
            if self.type == tarfile.GNUTYPE_SPARSE:
                raise _refuse("GNU sparse members are not supported", self.name)
            return super()._proc_member(archive)
        archive.extended_chain += 1
        if archive.extended_chain > MAX_EXTENDED_CHAIN:
            raise _refuse(
                f"{archive.extended_chain} extended headers in a row: the limit is "
                f"{MAX_EXTENDED_CHAIN}",
                self.name,
            )
        if not 0 <= self.size <= MAX_EXTENDED_HEADER_BYTES:
            raise _refuse(
                f"a {kind} of {self.size} bytes: the limit is {MAX_EXTENDED_HEADER_BYTES} bytes",
                self.name,
            )
        if self.type == tarfile.XGLTYPE:
            archive.global_bytes += self.size
            if archive.global_bytes > MAX_EXTENDED_HEADER_BYTES:
                raise _refuse(
                    f"pax global headers of more than {MAX_EXTENDED_HEADER_BYTES} bytes in all",
                    self.name,
                )
        return super()._proc_member(archive)  # _proc_pax below, or tarfile's _proc_gnulong

    def _proc_pax(self, archive: tarfile.TarFile) -> tarfile.TarInfo:
        """tarfile's ``_proc_pax`` (Python 3.11.10's strict parser) without GNU sparse
        files, with the records bounded."""
        buf = archive.fileobj.read(self._block(self.size))
        raw = _pax_records(buf[: self.size], self.name)
        encoding = "utf-8"  # the first hdrcharset record may say the names are raw bytes
        charset = next((value for key, value in raw if key == b"hdrcharset"), None)
        if charset == b"BINARY":
            encoding = archive.encoding
        records: dict[str, str] = {}
        for raw_key, raw_value in raw:
            key = self._decode_pax_field(raw_key, "utf-8", "utf-8", archive.errors)
            if key.startswith("GNU.sparse."):
                raise _refuse(f"GNU sparse files are not supported (pax record {key})", self.name)
            if key in tarfile.PAX_NAME_FIELDS:
                value = self._decode_pax_field(
                    raw_value, encoding, archive.encoding, archive.errors
                )
            else:
                value = self._decode_pax_field(raw_value, "utf-8", "utf-8", archive.errors)
            records[key] = value
        if self.type == tarfile.XGLTYPE:
            pax_headers = archive.pax_headers  # for every later member
        else:
            pax_headers = archive.pax_headers.copy()
        pax_headers.update(records)
        if len(pax_headers) > MAX_PAX_RECORDS:
            raise _refuse(f"more than {MAX_PAX_RECORDS} records in its pax headers", self.name)

        try:
            following = self.fromtarfile(archive)
        except tarfile.HeaderError as exc:
            raise tarfile.SubsequentHeaderError(str(exc)) from None
        if self.type in (tarfile.XHDTYPE, tarfile.SOLARIS_XHDTYPE):
            following._apply_pax_info(pax_headers, archive.encoding, archive.errors)
            following.offset = self.offset
            if "size" in pax_headers:  # the member's size replaced: where the next one starts
                offset = following.offset_data
                if following.isreg() or following.type not in tarfile.SUPPORTED_TYPES:
                    offset += following._block(following.size)
                archive.offset = offset
        return following


def _pax_records(buf: bytes, member: str) -> list[tuple[bytes, bytes]]:
    """The records ``b"%d %s=%s\\n"`` of a pax header, in linear time; a record that is
    not one, or more than :data:`MAX_PAX_RECORDS`, is refused (trailing NULs end them)."""
    records, pos = [], 0
    while pos < len(buf) and buf[pos] != 0:
        match = _PAX_LENGTH.match(buf, pos)
        end = pos + int(match[1]) - 1 if match else -1  # the record's last byte, a newline
        if match is None or end < match.end() or end >= len(buf) or buf[end] != 0x0A:
            raise _refuse(f"malformed pax record at byte {pos}", member)
        key, equals, value = buf[match.end() : end].partition(b"=")
        if not key or not equals:
            raise _refuse(f"malformed pax record at byte {pos}", member)
        records.append((key, value))
        if len(records) > MAX_PAX_RECORDS:
            raise _refuse(f"more than {MAX_PAX_RECORDS} records in its pax headers", member)
        pos = end + 1
    return records


class _TarFile(tarfile.TarFile):
    """tarfile reading with :class:`_TarInfo`, and what the bounds count across headers."""

    tarinfo = _TarInfo
    extended_chain = 0  # extended headers since the last member
    global_bytes = 0  # bytes of pax global headers so far


def _unpack_tar(source: BinaryIO, out: _Extractor, compressed: bool) -> None:
    inner: BinaryIO = gzip.GzipFile(fileobj=source, mode="rb") if compressed else source
    budget = _Budget(
        inner,
        out.limits.max_unpacked_bytes
        + _TAR_OVERHEAD_PER_ENTRY * (out.limits.max_files + 1)
        + _TAR_OVERHEAD,
    )
    try:
        with _TarFile.open(fileobj=budget, mode="r|") as archive:
            while (member := archive.next()) is not None:
                archive.members.clear()  # a stream's members are kept, with their pax records
                name = member.name
                out.count()
                if member.issym():
                    raise _refuse("symbolic links are not allowed", name)
                if member.islnk():
                    raise _refuse("hard links are not allowed", name)
                if member.isdir():
                    out.directory(name)
                elif member.isreg():
                    if not 0 <= member.size <= out.limits.max_unpacked_bytes:
                        raise _refuse(
                            f"declares {member.size} bytes, more than "
                            f"{out.limits.max_unpacked_bytes} (DENAVIT_MAX_PACKAGE_UNPACKED_BYTES)",
                            name,
                        )
                    stream = archive.extractfile(member)
                    if stream is None:  # pragma: no cover - isreg() members have data
                        raise _refuse("has no data", name)
                    out.file(name, _read_chunks(stream))
                else:
                    raise _refuse(
                        "only regular files and directories are allowed (no devices or FIFOs)",
                        name,
                    )
    except InvalidInputError:
        raise
    except (tarfile.TarError, EOFError, zlib.error, gzip.BadGzipFile) as exc:
        raise _refuse(f"not a valid tar archive ({exc})") from None
    except OSError as exc:
        raise _refuse(f"cannot be extracted ({exc.strerror or exc})") from None


# ---------------------------------------------------------------------------- entry
def unpack_archive(source: BinaryIO, dest: Path, limits: ArchiveLimits | None = None) -> int:
    """Extract the zip or tar(.gz) archive ``source`` into the empty directory ``dest``.

    Parameters
    ----------
    source
        The archive, a seekable binary stream (its format is told by its first bytes).
    dest
        An existing, empty directory; on a refusal it may hold part of the archive (the
        caller removes it).
    limits
        File count and unpacked-size bounds; default :class:`ArchiveLimits`.

    Returns
    -------
    int
        Total bytes of the extracted files.

    Raises
    ------
    InvalidInputError
        ``field == "archive"``; the message names the member and the reason.
    """
    limits = limits or ArchiveLimits()
    out = _Extractor(Path(dest), limits)
    source.seek(0)
    magic = source.read(512)
    source.seek(0)
    if magic.startswith((b"PK\x03\x04", b"PK\x05\x06")):
        _unpack_zip(source, out)
    elif magic.startswith(b"\x1f\x8b"):
        _unpack_tar(source, out, compressed=True)
    elif len(magic) >= 262 and magic[257:262] == b"ustar":
        _unpack_tar(source, out, compressed=False)
    else:
        raise _refuse("not a zip or tar.gz archive")
    if out.entries == 0:
        raise _refuse("the archive is empty")
    return out.total
