"""app.robots.documents.archive: unpacking untrusted zip and tar.gz archives, entry by entry."""

from __future__ import annotations

import gzip
import io
import struct
import tarfile
import tracemalloc
import zipfile
from pathlib import Path

import pytest

from app.kinematics.errors import InvalidInputError
from app.robots.documents.archive import ArchiveLimits, member_parts, unpack_archive
from tests.packages import huge_header_tgz


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


def _central_directory_zip(entries: int) -> io.BytesIO:
    """A zip of ``entries`` minimal central directory records (46 bytes and a one-byte
    name each) and nothing else: no local header is ever read, it is refused first."""
    record = struct.pack("<4s4B4HL2L5H2L", b"PK\x01\x02", *[20, 3, 20, 0], *[0] * 7, 1,
                         *[0] * 6) + b"a"  # fmt: skip
    directory = record * entries
    end = struct.pack("<4s4H2LH", b"PK\x05\x06", 0, 0, 0xFFFF, 0xFFFF, len(directory), 30, 0)
    return io.BytesIO(b"PK\x03\x04" + bytes(26) + directory + end)


def test_a_huge_central_directory_is_counted_before_zipfile_reads_it(tmp_path: Path) -> None:
    """8 MiB of 47-byte directory records: zipfile builds an object of ~350 bytes for each
    before they could be counted (a 32 MiB upload peaked at 250 MiB); they are counted
    from the records first, in about the directory's own size."""
    source = _central_directory_zip((8 << 20) // 47)
    size = len(source.getvalue())
    peak = _peak_of_refusal(source, tmp_path, "178481 entries, more than 10000")
    assert peak < size + (4 << 20), f"peak {peak / 2**20:.1f} MiB for {size} bytes"


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


# ------------------------------------------------------------------- tar headers
END = bytes(1024)  # the end-of-archive blocks


def _header(name: str, kind: bytes, size: int) -> bytes:
    info = tarfile.TarInfo(name)
    info.type, info.size = kind, size
    return info.tobuf(format=tarfile.USTAR_FORMAT)


def _padded(data: bytes) -> bytes:
    return data + bytes(-len(data) % 512)


def _member(name: str, data: bytes = b"") -> bytes:
    return _header(name, tarfile.REGTYPE, len(data)) + _padded(data)


def _records(records: dict[str, str]) -> bytes:
    """pax records ``"%d %s=%s\\n"`` (the length counts itself)."""
    out = b""
    for key, value in records.items():
        body = f" {key}={value}\n".encode()
        n = len(body) + 1
        while len(str(n)) + len(body) != n:
            n = len(str(n)) + len(body)
        out += str(n).encode() + body
    return out


def _pax(records: dict[str, str], kind: bytes = tarfile.XHDTYPE) -> bytes:
    data = _records(records)
    return _header("././@PaxHeader", kind, len(data)) + _padded(data)


def _tgz(*parts: bytes) -> io.BytesIO:
    return io.BytesIO(gzip.compress(b"".join(parts), compresslevel=1, mtime=0))


def _huge(kind: bytes, size: int) -> io.BytesIO:
    """A small tgz: an extended header of ``size`` bytes before the file ``pkg/a.txt``."""
    after = gzip.compress(_member("pkg/a.txt", b"alpha") + END, mtime=0)
    return io.BytesIO(huge_header_tgz(kind, size, after))


def _peak_of_refusal(source: io.BytesIO, dest: Path, reason: str, **limits: int) -> int:
    """Refused naming ``archive`` and ``reason``; the peak of Python's allocations (bytes)
    while unpacking (tracemalloc: every bytes and str object, deterministic)."""
    tracemalloc.start()
    try:
        refused(source, dest, reason, **limits)
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


@pytest.mark.parametrize(
    ("kind", "size", "reason"),
    [
        (tarfile.XHDTYPE, 250 << 20, "pax extended header of 262144000 bytes"),
        (tarfile.XGLTYPE, 100 << 20, "pax global header of 104857600 bytes"),
        (tarfile.SOLARIS_XHDTYPE, 100 << 20, "Solaris extended header of 104857600 bytes"),
        (tarfile.GNUTYPE_LONGNAME, 100 << 20, "GNU long name header of 104857600 bytes"),
        (tarfile.GNUTYPE_LONGLINK, 100 << 20, "GNU long link header of 104857600 bytes"),
    ],
    ids=["pax-250MiB", "pax-global", "solaris", "gnu-long-name", "gnu-long-link"],
)
def test_a_huge_extended_header_is_refused_before_it_is_read(
    tmp_path: Path, kind: bytes, size: int, reason: str
) -> None:
    """A ~250 KB tgz whose one header claims 250 MiB (tarfile would read it whole, then
    parse it: ~780 MB): refused by its size, naming the header and the limit."""
    source = _huge(kind, size)
    assert len(source.getvalue()) < 300 << 10
    peak = _peak_of_refusal(source, tmp_path, reason)
    assert peak < 16 << 20, f"peak {peak / 2**20:.1f} MiB"
    refused(_huge(kind, size), tmp_path, "limit is 65536 bytes")
    assert list(tmp_path.iterdir()) == []


def _sparse_member() -> bytes:
    """An old-GNU sparse member (type ``S``): tarfile writes none, so a retyped header."""
    buf = bytearray(_member("pkg/sparse", b"x"))
    buf[156:157] = tarfile.GNUTYPE_SPARSE
    buf[148:156] = b" " * 8
    buf[148:155] = b"%06o\0" % sum(buf[:512])
    return bytes(buf)


SPARSE_10 = {"GNU.sparse.major": "1", "GNU.sparse.minor": "0", "GNU.sparse.name": "pkg/s",
             "GNU.sparse.realsize": "10"}  # fmt: skip
SPARSE_01 = {"GNU.sparse.size": "10", "GNU.sparse.numblocks": "1", "GNU.sparse.map": "0,1"}


@pytest.mark.parametrize(
    ("parts", "reason"),
    [
        ([_sparse_member()], "GNU sparse members are not supported"),
        ([_pax(SPARSE_10), _member("pkg/s", b"1\n0\n1\n")], "GNU.sparse.major"),
        ([_pax(SPARSE_01), _member("pkg/s", b"x")], "GNU.sparse.size"),
        ([_pax({"GNU.sparse.name": "pkg/x"}), _member("pkg/s", b"x")], "GNU.sparse.name"),
        # 9 extended headers before one member (tarfile reads them recursively: thousands
        # were a RecursionError)
        ([_pax({"comment": "c"})] * 9 + [_member("pkg/a")], "9 extended headers in a row"),
        ([_pax({"comment": "c"})] * 3000 + [_member("pkg/a")], "9 extended headers in a row"),
        # digits only: no record (Python < 3.11.10's tarfile searches it in quadratic time)
        ([_header("././@PaxHeader", tarfile.XHDTYPE, 60000), _padded(b"1" * 60000),
          _member("pkg/a")], "malformed pax record at byte 0"),  # fmt: skip
        ([_pax({"comment": "c"}), _padded(b"x"), _member("pkg/a")], "not a valid tar"),
        ([_pax({f"k{i}": "v" for i in range(257)}), _member("pkg/a")], "more than 256 records"),
        # global records last for the whole archive: 64 KiB of them at most
        ([_pax({"comment": "a" * 40000}, tarfile.XGLTYPE), _member("pkg/a"),
          _pax({"comment": "b" * 40000}, tarfile.XGLTYPE), _member("pkg/b")],
         "pax global headers of more than 65536 bytes"),  # fmt: skip
        ([_pax({f"g{i}": "v" for i in range(200)}, tarfile.XGLTYPE), _member("pkg/a"),
          _pax({f"h{i}": "v" for i in range(200)}, tarfile.XGLTYPE), _member("pkg/b")],
         "more than 256 records"),  # fmt: skip
    ],
    ids=["gnu-sparse", "pax-sparse-1.0", "pax-sparse-0.1", "pax-sparse-name", "chain-9",
         "chain-3000", "digits", "bad-next-header", "records", "global-bytes", "global-records"],
)  # fmt: skip
def test_tar_headers_past_the_bounds_are_refused(
    tmp_path: Path, parts: list[bytes], reason: str
) -> None:
    refused(_tgz(*parts, END), tmp_path, reason)


def test_eight_extended_headers_in_a_row_are_read(tmp_path: Path) -> None:
    parts = [_pax({"comment": f"c{i}"}) for i in range(7)] + [_pax({"path": "pkg/long"})]
    assert unpack_archive(_tgz(*parts, _member("pkg/a", b"xyz"), END), tmp_path) == 3
    assert (tmp_path / "pkg" / "long").read_bytes() == b"xyz"


def test_pax_records_of_many_members_are_not_kept(tmp_path: Path) -> None:
    """tarfile keeps every member it read, with its pax records: 500 members with a 60 KB
    record each (30 MB) must not stay in memory together."""
    one = _pax({"comment": "a" * 60000})
    source = _tgz(*(one + _member(f"pkg/f{i}") for i in range(500)), END)
    tracemalloc.start()
    try:
        assert unpack_archive(source, tmp_path) == 0
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 16 << 20, f"peak {peak / 2**20:.1f} MiB"
    assert len(list((tmp_path / "pkg").iterdir())) == 500


def test_the_decompressed_tar_stream_is_bounded(tmp_path: Path) -> None:
    """Headers within their bounds still count towards the whole stream's budget (1 MiB
    unpacked + 4 KiB per entry + 1 MiB): 8 headers of 60 KB before each of 10 members."""
    chain = _pax({"comment": "a" * 60000}) * 8
    parts = [chain + _member(f"pkg/f{i}") for i in range(10)]
    refused(_tgz(*parts, END), tmp_path, "decompressed tar stream", max_unpacked_bytes=1 << 20,
            max_files=10)  # fmt: skip


def test_pax_and_gnu_archives_with_long_and_non_ascii_names_unpack(tmp_path: Path) -> None:
    """What tar writes for names beyond ustar's 100 bytes, non-ASCII names and sub-second
    times (pax records; GNU long-name headers), and a global header as git archive writes
    it: unpacked, names and contents intact."""
    long_name = "pkg/" + "/".join(["d" * 200] * 4) + "/mesh.stl"  # 817 bytes
    files = {long_name: b"long", "pkg/méshes/ü.stl": b"accents", "pkg/plain.txt": b"plain"}
    for fmt, root in ((tarfile.PAX_FORMAT, "pax"), (tarfile.GNU_FORMAT, "gnu")):
        buf = io.BytesIO()
        pax = {"comment": "4b825dc642cb6eb9a060e54bf8d69288fbee4904"}  # git archive's
        with tarfile.open(fileobj=buf, mode="w:gz", format=fmt, pax_headers=pax) as tf:
            for name, data in files.items():
                info = tarfile.TarInfo(name)
                info.size, info.mtime = len(data), 1700000000.25
                tf.addfile(info, io.BytesIO(data))
        (tmp_path / root).mkdir()
        assert unpack_archive(io.BytesIO(buf.getvalue()), tmp_path / root) == 16
        for name, data in files.items():
            assert (tmp_path / root / name).read_bytes() == data


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
