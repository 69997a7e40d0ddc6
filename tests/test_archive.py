"""app.documents.archive: unpacking untrusted zip and tar.gz archives, entry by entry."""

from __future__ import annotations

import gzip
import io
import tarfile
import zipfile
from pathlib import Path

import pytest

from app.documents.archive import ArchiveLimits, member_parts, unpack_archive
from app.kinematics.errors import InvalidInputError


def _zip(entries: list[tuple[str, bytes]]) -> io.BytesIO:
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zf:
        for name, data in entries:
            zf.writestr(name, data)
    buf.seek(0)
    return buf


def refused(source: io.BytesIO, dest: Path, reason: str, **limits: int) -> None:
    with pytest.raises(InvalidInputError) as err:
        unpack_archive(source, dest, ArchiveLimits(**limits))
    assert err.value.field == "archive"
    assert reason in err.value.message, err.value.message


@pytest.mark.parametrize(
    ("name", "parts"),
    [
        ("a/b.stl", ("a", "b.stl")),
        ("./a/./b.stl", ("a", "b.stl")),
        ("dir/", ("dir",)),
        ("./", ()),
    ],
)
def test_plain_names(name: str, parts: tuple[str, ...]) -> None:
    assert member_parts(name) == parts


@pytest.mark.parametrize(
    ("name", "reason"),
    [
        ("../x", "'..'"),
        ("a/../../x", "'..'"),
        ("a/..", "'..'"),
        ("/etc/passwd", "absolute"),
        ("C:/Windows/x", "drive"),
        ("c:x", "drive"),
        ("a\\..\\x", "backslash"),
        ("a//b", "empty"),
        ("a\x00b", "control"),
        ("x" * 300, "longer than"),
        ("/".join(["d"] * 40), "deeper"),
    ],
)
def test_names_that_could_escape_are_refused(name: str, reason: str) -> None:
    with pytest.raises(InvalidInputError) as err:
        member_parts(name)
    assert reason in err.value.message and err.value.field == "archive"


def test_zip_and_tar_unpack_the_same_tree(tmp_path: Path) -> None:
    entries = [("pkg/a.txt", b"alpha"), ("pkg/sub/b.bin", bytes(range(256)))]
    (tmp_path / "z").mkdir()
    assert unpack_archive(_zip(entries), tmp_path / "z") == 5 + 256
    buf = io.BytesIO()
    with tarfile.open(fileobj=buf, mode="w:gz") as tf:
        for name, data in entries:
            info = tarfile.TarInfo(name)
            info.size = len(data)
            tf.addfile(info, io.BytesIO(data))
    (tmp_path / "t").mkdir()
    assert unpack_archive(io.BytesIO(buf.getvalue()), tmp_path / "t") == 5 + 256
    for root in ("z", "t"):
        assert (tmp_path / root / "pkg" / "a.txt").read_bytes() == b"alpha"
        assert (tmp_path / root / "pkg" / "sub" / "b.bin").read_bytes() == bytes(range(256))


def test_too_many_entries_are_refused_before_anything_is_extracted(tmp_path: Path) -> None:
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_STORED) as zf:
        for i in range(100_000):
            zf.writestr(f"f{i}", b"")
    refused(io.BytesIO(buf.getvalue()), tmp_path, "100000 entries, more than 10000")
    assert list(tmp_path.iterdir()) == []


def test_tar_entries_are_counted_as_the_stream_is_read(tmp_path: Path) -> None:
    buf = io.BytesIO()
    with tarfile.open(fileobj=buf, mode="w:gz") as tf:
        for i in range(50):
            tf.addfile(tarfile.TarInfo(f"f{i}"), io.BytesIO(b""))
    refused(io.BytesIO(buf.getvalue()), tmp_path, "more than 10 entries", max_files=10)
    assert len(list(tmp_path.iterdir())) <= 10


def test_zip_bomb_stops_at_the_limit(tmp_path: Path) -> None:
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zf:
        zf.writestr("zeros", bytes(8 << 20))  # 8 MiB of zeros, ~8 KiB compressed
    assert len(buf.getvalue()) < 64 * 1024
    refused(buf, tmp_path, "more than 1048576 bytes", max_unpacked_bytes=1 << 20)
    assert (tmp_path / "zeros").stat().st_size <= (1 << 20) + (1 << 16)


def test_a_huge_pax_header_is_not_inflated_into_memory(tmp_path: Path) -> None:
    """tarfile reads a pax header whole: the stream budget refuses it first."""
    header = tarfile.TarInfo("././@PaxHeader")
    header.type = tarfile.XHDTYPE
    header.size = 64 << 20
    raw = io.BytesIO()
    raw.write(header.tobuf(format=tarfile.USTAR_FORMAT))
    raw.write(bytes(64 << 20))
    data = gzip.compress(raw.getvalue(), compresslevel=1)
    refused(io.BytesIO(data), tmp_path, "decompressed tar stream", max_unpacked_bytes=1 << 20)


@pytest.mark.parametrize(
    ("kind", "reason"),
    [
        (tarfile.SYMTYPE, "symbolic"),
        (tarfile.LNKTYPE, "hard links"),
        (tarfile.CHRTYPE, "devices"),
        (tarfile.BLKTYPE, "devices"),
        (tarfile.FIFOTYPE, "FIFOs"),
    ],
)
def test_tar_links_and_devices_are_refused(tmp_path: Path, kind: bytes, reason: str) -> None:
    buf = io.BytesIO()
    with tarfile.open(fileobj=buf, mode="w:gz") as tf:
        info = tarfile.TarInfo("evil")
        info.type = kind
        info.linkname = "/etc/passwd"
        tf.addfile(info)
    refused(io.BytesIO(buf.getvalue()), tmp_path, reason)
    assert list(tmp_path.iterdir()) == []


def test_zip_symlink_and_encrypted_entries_are_refused(tmp_path: Path) -> None:
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w") as zf:
        info = zipfile.ZipInfo("link")
        info.external_attr = 0o120777 << 16
        zf.writestr(info, "/etc/passwd")
    refused(io.BytesIO(buf.getvalue()), tmp_path, "symbolic links")
    data = bytearray(_zip([("secret", b"x")]).getvalue())
    data[6] |= 1  # general purpose flag of the local header: encrypted
    central = data.rfind(b"PK\x01\x02")
    data[central + 8] |= 1  # and of the central directory entry
    refused(io.BytesIO(bytes(data)), tmp_path, "encrypted")


def test_a_file_used_as_a_directory_is_refused(tmp_path: Path) -> None:
    refused(_zip([("a", b"x"), ("a/b", b"y")]), tmp_path, "used as a directory")


@pytest.mark.parametrize(
    ("data", "reason"),
    [
        (b"", "not a zip or tar.gz"),
        (b"PK\x03\x04garbage", "not a valid zip"),
        # mtime=0: the same bytes (and test id) in every xdist worker
        (gzip.compress(b"not a tar stream at all" * 40, mtime=0), "not a valid tar"),
        (b"\x1f\x8b\x08\x00garbage", "not a valid tar"),
    ],
    ids=["empty", "bad-zip", "gzip-not-tar", "bad-gzip"],
)
def test_corrupt_archives_are_refused(tmp_path: Path, data: bytes, reason: str) -> None:
    refused(io.BytesIO(data), tmp_path, reason)


def test_a_crc_error_is_refused(tmp_path: Path) -> None:
    data = bytearray(_zip([("a.txt", b"hello world" * 10)]).getvalue())
    crc = data.find(b"PK\x03\x04") + 14
    data[crc] ^= 0xFF  # CRC-32 of the local header
    central = data.rfind(b"PK\x01\x02") + 16
    data[central] ^= 0xFF  # and of the central directory
    refused(io.BytesIO(bytes(data)), tmp_path, "cannot be decompressed")
