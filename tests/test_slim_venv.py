"""deploy/slim_venv.py, the image's virtualenv trim, on a small fake virtualenv: what goes,
what stays, copies turned into symlinks to the same bytes, stripped libraries still ELF.
The real trim is exercised by the container check (the image must serve FK, IK and DH)."""

from __future__ import annotations

import importlib.util
import shutil
import sys
from pathlib import Path

import httptools.parser.parser as httptools_parser
import pytest

from app.robots.catalog import erd_share_dir

ROOT = Path(__file__).resolve().parents[1]
CATALOG = ROOT / "robots" / "example_robot_data.yaml"

spec = importlib.util.spec_from_file_location("slim_venv", ROOT / "deploy" / "slim_venv.py")
slim_venv = importlib.util.module_from_spec(spec)
sys.modules["slim_venv"] = slim_venv
spec.loader.exec_module(slim_venv)


def write(path: Path, data: bytes = b"x") -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data)
    return path


@pytest.fixture
def venv(tmp_path) -> Path:
    root = tmp_path / "venv"
    site = root / "lib" / "python3.11" / "site-packages"
    prefix = site / "cmeel.prefix"
    write(prefix / "include" / "boost" / "config.hpp", b"#pragma once\n" * 100)
    write(prefix / "lib" / "cmake" / "x" / "xConfig.cmake")
    write(prefix / "lib" / "libboost_exception.a", b"!<arch>\n")
    write(prefix / "share" / "doc" / "README")
    lib = b"LIB" + bytes(range(256)) * 40  # not ELF: not stripped
    for name in ("libfoo.so", "libfoo.so.6", "libfoo.so.6.0.5"):
        write(prefix / "lib" / name, lib)
    write(prefix / "lib" / "libbar.so.2", b"LIB other")
    real = Path(httptools_parser.__file__)  # a real, unstripped extension module
    shutil.copy(real, (prefix / "lib" / real.name))
    robots = prefix / "share" / "example-robot-data" / "robots"
    for package in slim_venv.catalog_packages(CATALOG) | {"romeo_description"}:
        write(robots / package / "meshes" / "m.stl", b"solid" * 100)
    write(prefix / "share" / "example-robot-data" / "package.xml")
    write(site / "numpy" / "_core" / "tests" / "test_x.py")
    write(site / "numpy" / "testing" / "__init__.py")
    write(site / "numpy" / "__init__.py")
    for name in ("pip/__init__.py", "pip-23.2.1.dist-info/RECORD", "setuptools/__init__.py",
                 "setuptools-80.9.0.dist-info/RECORD", "pkg_resources/__init__.py",
                 "_distutils_hack/__init__.py", "distutils-precedence.pth",
                 "pipx_like/__init__.py"):  # fmt: skip
        write(site / name)
    write(root / "bin" / "pip3")
    write(root / "bin" / "python")
    return root


def test_slim_removes_what_the_service_does_not_run(venv) -> None:
    site = venv / "lib" / "python3.11" / "site-packages"
    prefix = site / "cmeel.prefix"
    real_so = next((prefix / "lib").glob("parser*.so"))
    unstripped = real_so.stat().st_size
    freed = slim_venv.slim(venv, CATALOG)

    assert not (prefix / "include").exists() and not (prefix / "lib" / "cmake").exists()
    assert not list((prefix / "lib").glob("*.a")) and not (prefix / "share" / "doc").exists()
    robots = prefix / "share" / "example-robot-data" / "robots"
    assert {p.name for p in robots.iterdir()} == slim_venv.catalog_packages(CATALOG)
    assert (prefix / "share" / "example-robot-data" / "package.xml").exists()
    # Link names now point at the fully-versioned file; distinct libraries are untouched.
    for name in ("libfoo.so", "libfoo.so.6"):
        link = prefix / "lib" / name
        assert link.is_symlink() and link.readlink() == Path("libfoo.so.6.0.5")
        assert link.read_bytes() == (prefix / "lib" / "libfoo.so.6.0.5").read_bytes()
    assert not (prefix / "lib" / "libbar.so.2").is_symlink()
    # Stripped, still an ELF object, smaller.
    assert real_so.read_bytes()[:4] == b"\x7fELF" and real_so.stat().st_size < unstripped
    assert not (site / "numpy" / "_core" / "tests").exists()
    assert (site / "numpy" / "testing" / "__init__.py").exists()
    for gone in ("pip", "pip-23.2.1.dist-info", "setuptools", "pkg_resources",
                 "_distutils_hack", "distutils-precedence.pth"):  # fmt: skip
        assert not (site / gone).exists(), gone
    assert (site / "pipx_like").exists() and (venv / "bin" / "python").exists()
    assert not (venv / "bin" / "pip3").exists()
    assert freed["example-robot-data packages outside the catalog"] == 500
    assert freed["shared-library copies (now symlinks)"] == 2 * (3 + 256 * 40)
    assert freed["debug symbols (strip --strip-unneeded)"] == unstripped - real_so.stat().st_size


def test_dry_run_changes_nothing(venv) -> None:
    before = sorted(str(p) for p in venv.rglob("*"))
    freed = slim_venv.slim(venv, CATALOG, dry_run=True)
    assert sorted(str(p) for p in venv.rglob("*")) == before
    assert freed["cmeel headers and build files"] > 0


def test_a_catalog_package_that_is_not_installed_stops_the_build(venv) -> None:
    robots = venv / "lib/python3.11/site-packages/cmeel.prefix/share/example-robot-data/robots"
    shutil.rmtree(robots / "panda_description")
    with pytest.raises(SystemExit, match="panda_description"):
        slim_venv.slim(venv, CATALOG)
    assert (robots / "romeo_description").exists(), "nothing removed before the check"


def test_catalog_packages_are_the_ones_the_registry_loads() -> None:
    """Every catalog robot's URDF and SRDF lies in a kept package, and each kept package
    exists in the installed example-robot-data."""
    import yaml

    keep = slim_venv.catalog_packages(CATALOG)
    robots_dir = erd_share_dir() / "example-robot-data" / "robots"
    for entry in yaml.safe_load(CATALOG.read_text())["robots"]:
        for key in ("urdf", "srdf"):
            if entry.get(key):
                assert Path(entry[key]).parts[0] in keep
                assert (robots_dir / entry[key]).is_file()
    assert keep == {"panda_description", "ur_description", "kinova_description",
                    "xarm_description", "z1_description", "so_arm_description"}  # fmt: skip
