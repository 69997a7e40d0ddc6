"""Trim the image's virtualenv to what the service runs (the Dockerfile's build stage).

    python deploy/slim_venv.py VENV CATALOG [--dry-run]

VENV is the virtualenv the locked runtime dependencies were installed into, CATALOG the
robot catalog (``robots/example_robot_data.yaml``). Removed, each with the reason it is
safe; everything else is left as installed:

- ``cmeel.prefix``'s build-time files: C++ headers (``include/``, Boost's alone is 185 MB),
  CMake and pkg-config files, static archives, command-line tools, man pages and docs.
  Nothing is compiled against them in the image.
- ``example-robot-data`` packages the catalog does not name (33 of 39, ~330 MB of meshes):
  the service loads example-robot-data robots only through the catalog.
- Copies of one shared library under its link names: wheels cannot hold symlinks, so
  ``libassimp.so``, ``libassimp.so.6`` and ``libassimp.so.6.0.5`` are three 14 MB files.
  The copies become relative symlinks to the fully-versioned file (same bytes, same path).
- Debug and local symbols of the shared libraries built with them (``strip
  --strip-unneeded``; the dynamic symbols that loading and ctypes use stay): Pinocchio's
  and Coal's Python modules and libraries, llvmlite and uvloop (~68 MB). Libraries that
  auditwheel grafted in (``*.libs/``, rewritten by patchelf) are left alone.
- The test suites that NumPy, SciPy and Numba ship inside their packages.
- ``pip`` and ``setuptools`` (run last in the build stage): the image installs nothing.

Prints one line per category with the bytes it frees, and the total.
"""

from __future__ import annotations

import argparse
import hashlib
import os
import shutil
import subprocess
import sys
from collections import defaultdict
from collections.abc import Iterable, Iterator
from pathlib import Path

import yaml

#: Build-time parts of the cmeel prefix (paths relative to it).
CMEEL_BUILD_FILES = ("include", "bin", "lib/cmake", "lib/pkgconfig", "share/cmake")
CMEEL_DOCS = ("share/doc", "share/man")
#: Packages whose in-package test suites are not imported at run time.
TESTED_PACKAGES = ("numpy", "scipy", "numba")
#: Packages whose shared libraries are stripped (none is patchelf-rewritten).
STRIPPED_PACKAGES = ("cmeel.prefix", "llvmlite", "uvloop")
#: Tools that only install things (site-packages entries).
INSTALLERS = (
    "pip", "pip-*.dist-info", "setuptools", "setuptools-*.dist-info", "pkg_resources",
    "_distutils_hack", "distutils-precedence.pth",
)  # fmt: skip


def site_packages(venv: Path) -> Path:
    """The one ``lib/python3.X/site-packages`` directory of ``venv``."""
    found = sorted(venv.glob("lib/python3*/site-packages"))
    if len(found) != 1:
        raise SystemExit(f"slim_venv: expected one site-packages under {venv}, found {found}")
    return found[0]


def catalog_packages(catalog: Path) -> set[str]:
    """The example-robot-data package directories the catalog's URDF and SRDF paths use."""
    robots = yaml.safe_load(catalog.read_text())["robots"]
    return {
        Path(entry[key]).parts[0] for entry in robots for key in ("urdf", "srdf") if entry.get(key)
    }


def size(path: Path) -> int:
    """Bytes held by ``path`` (a file, or a tree; symlinks count as nothing)."""
    if path.is_symlink():
        return 0
    if path.is_file():
        return path.stat().st_size
    return sum(p.lstat().st_size for p in path.rglob("*") if p.is_file() and not p.is_symlink())


def duplicate_libraries(lib: Path) -> Iterator[tuple[Path, Path]]:
    """(copy, original) for each shared library in ``lib`` that is a byte-for-byte copy of
    another under a longer name (``libX.so`` and ``libX.so.6`` of ``libX.so.6.0.5``)."""
    groups: dict[tuple[int, str], list[Path]] = defaultdict(list)
    for path in sorted(lib.iterdir()):
        if path.is_file() and not path.is_symlink() and ".so" in path.name:
            digest = hashlib.sha256(path.read_bytes()).hexdigest()
            groups[(path.stat().st_size, digest)].append(path)
    for paths in groups.values():
        if len(paths) > 1:
            original = max(paths, key=lambda p: (len(p.name), p.name))
            for copy in paths:
                if copy != original and copy.name.startswith(original.name.split(".so")[0]):
                    yield copy, original


def elf_libraries(root: Path) -> Iterator[Path]:
    """Regular ``*.so*`` files under ``root`` that are ELF objects."""
    for path in sorted(root.rglob("*.so*")):
        if path.is_file() and not path.is_symlink():
            with path.open("rb") as f:
                if f.read(4) == b"\x7fELF":
                    yield path


class Slimmer:
    """Collects removals by category; applies them unless ``dry_run``."""

    def __init__(self, dry_run: bool) -> None:
        self.dry_run = dry_run
        self.freed: dict[str, int] = defaultdict(int)

    def remove(self, category: str, paths: Iterable[Path]) -> None:
        for path in paths:
            if not (path.exists() or path.is_symlink()):
                continue
            self.freed[category] += size(path)
            if self.dry_run:
                continue
            if path.is_dir() and not path.is_symlink():
                shutil.rmtree(path)
            else:
                path.unlink()

    def strip(self, category: str, paths: Iterable[Path]) -> None:
        for path in paths:
            before = size(path)
            if self.dry_run:
                continue
            subprocess.run(["strip", "--strip-unneeded", str(path)], check=True)
            self.freed[category] += before - size(path)

    def link(self, category: str, copy: Path, original: Path) -> None:
        self.freed[category] += size(copy)
        if not self.dry_run:
            copy.unlink()
            os.symlink(original.name, copy)


def slim(venv: Path, catalog: Path, *, strip: bool = True, dry_run: bool = False) -> dict[str, int]:
    """Trim ``venv`` (see the module docstring); bytes freed by category."""
    site = site_packages(venv)
    prefix = site / "cmeel.prefix"
    out = Slimmer(dry_run)

    out.remove("cmeel headers and build files", (prefix / p for p in CMEEL_BUILD_FILES))
    out.remove("cmeel headers and build files", (prefix / "lib").glob("*.a"))
    out.remove("cmeel docs", (prefix / p for p in CMEEL_DOCS))

    robots = prefix / "share" / "example-robot-data" / "robots"
    keep = catalog_packages(catalog)
    missing = sorted(p for p in keep if not (robots / p).is_dir())
    if missing:
        raise SystemExit(f"slim_venv: the catalog names packages not installed: {missing}")
    out.remove(
        "example-robot-data packages outside the catalog",
        (p for p in sorted(robots.iterdir()) if p.is_dir() and p.name not in keep),
    )

    for copy, original in list(duplicate_libraries(prefix / "lib")):
        out.link("shared-library copies (now symlinks)", copy, original)

    if strip:
        out.strip(
            "debug symbols (strip --strip-unneeded)",
            (lib for pkg in STRIPPED_PACKAGES for lib in elf_libraries(site / pkg)),
        )
    out.remove(
        "in-package test suites",
        (t for pkg in TESTED_PACKAGES for t in sorted((site / pkg).rglob("tests")) if t.is_dir()),
    )
    out.remove(
        "pip and setuptools",
        (p for pattern in INSTALLERS for p in sorted(site.glob(pattern))),
    )
    out.remove("pip and setuptools", sorted((venv / "bin").glob("pip*")))
    return dict(out.freed)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("venv", type=Path)
    parser.add_argument("catalog", type=Path)
    parser.add_argument("--no-strip", action="store_true", help="leave symbols alone")
    parser.add_argument("--dry-run", action="store_true", help="report, change nothing")
    args = parser.parse_args(argv)
    freed = slim(args.venv, args.catalog, strip=not args.no_strip, dry_run=args.dry_run)
    for category, n in freed.items():
        print(f"slim_venv: {n / 1e6:8.1f} MB  {category}")
    print(f"slim_venv: {sum(freed.values()) / 1e6:8.1f} MB  in all")
    return 0


if __name__ == "__main__":
    sys.exit(main())
