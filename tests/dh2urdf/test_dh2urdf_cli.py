"""The dh2urdf command line, end to end (subprocess) and in process (main())."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pinocchio as pin
import pytest

from dh2urdf.cli import main
from dh2urdf.table import DHTable
from dh2urdf.urdf import to_urdf

REPO = Path(__file__).resolve().parents[2]
ARMAR = REPO / "robots" / "dh" / "armar1_arm.yaml"
PYTHON = sys.executable


def run(*args: str, stdin: str | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [PYTHON, "-m", "dh2urdf", *args],
        cwd=REPO,
        input=stdin,
        capture_output=True,
        text=True,
        timeout=60,
    )


def test_stdout_end_to_end() -> None:
    result = run(str(ARMAR))
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    assert result.stdout == to_urdf(DHTable.from_file(ARMAR))
    model = pin.buildModelFromXML(result.stdout)
    assert model.nq == 7 and model.existFrame("tool")


def test_output_file_end_to_end(tmp_path: Path) -> None:
    out = tmp_path / "robot.urdf"
    result = run(str(ARMAR), "-o", str(out))
    assert result.returncode == 0, result.stderr
    assert result.stdout == "" and result.stderr == ""
    assert out.read_text(encoding="utf-8") == to_urdf(DHTable.from_file(ARMAR))


BAD_FILES = {
    "missing_field.yaml": (
        "name: bad\nconvention: standard\njoints:\n  - {a: 0, alpha: 0, d: 0, theta: 0}\n"
        "  - {a: 0, d: 0, theta: 0}\n",
        "joints[1].alpha: field required",
    ),
    "bad_yaml.yaml": ("name: [unclosed\n", "invalid YAML: line 2, column 1: "),
    "bad_json.json": ('{"name": "x",', "invalid JSON: "),
    "bad_limits.json": (
        json.dumps(
            {
                "name": "bad",
                "convention": "modified",
                "joints": [
                    {
                        "type": "prismatic",
                        "a": 0,
                        "alpha": 0,
                        "d": 0,
                        "theta": 0,
                        "lower": 10,
                        "upper": 5,
                    }
                ],
            }
        ),
        "joints[0].lower: lower (10) > upper (5)",
    ),
    "table.txt": ("name: x\n", "unsupported file extension '.txt'"),
}


@pytest.mark.parametrize("filename", ["missing_field.yaml", "bad_yaml.yaml", "bad_json.json"])
def test_bad_input_exit_2_one_line(tmp_path: Path, filename: str) -> None:
    """End to end: exit status 2, one line on stderr, no traceback, no output file."""
    text, reason = BAD_FILES[filename]
    path = tmp_path / filename
    path.write_text(text)
    result = run(str(path), "-o", str(tmp_path / "out.urdf"))
    assert result.returncode == 2
    assert result.stdout == ""
    assert "Traceback" not in result.stderr
    assert result.stderr.count("\n") == 1
    assert result.stderr.startswith(f"dh2urdf: error: {path}: {reason}"), result.stderr
    assert not (tmp_path / "out.urdf").exists()


@pytest.mark.parametrize("filename", sorted(BAD_FILES))
def test_main_bad_input_exit_2_one_line(
    tmp_path: Path, filename: str, capsys: pytest.CaptureFixture[str]
) -> None:
    text, reason = BAD_FILES[filename]
    path = tmp_path / filename
    path.write_text(text)
    assert main([str(path), "-o", str(tmp_path / "out.urdf")]) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert err.count("\n") == 1
    assert err.startswith(f"dh2urdf: error: {path}: {reason}"), err
    assert not (tmp_path / "out.urdf").exists()


def test_missing_file_exit_2(tmp_path: Path) -> None:
    path = tmp_path / "nope.yaml"
    result = run(str(path))
    assert result.returncode == 2
    assert result.stderr == f"dh2urdf: error: {path}: cannot read: No such file or directory\n"


# ----------------------------------------------------------------- in process (fast)


def test_main_stdout_and_json(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    table = DHTable.from_file(ARMAR)
    path = tmp_path / "armar.json"
    path.write_text(json.dumps(table.to_dict()))
    assert main([str(path)]) == 0
    out = capsys.readouterr().out
    assert out == to_urdf(table)


def test_main_stdin(monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    import io

    monkeypatch.setattr("sys.stdin", io.StringIO(ARMAR.read_text()))
    assert main(["-"]) == 0
    assert capsys.readouterr().out == to_urdf(DHTable.from_file(ARMAR))
    monkeypatch.setattr("sys.stdin", io.StringIO("name: x\n"))
    assert main(["-"]) == 2
    assert capsys.readouterr().err == "dh2urdf: error: <stdin>: convention: field required\n"


def test_main_format_override(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "table.txt"
    path.write_text(ARMAR.read_text())
    assert main([str(path), "--format", "yaml"]) == 0
    assert capsys.readouterr().out.startswith("<?xml")


def test_main_directory_and_binary_input(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    folder = tmp_path / "dir.yaml"
    folder.mkdir()
    assert main([str(folder)]) == 2
    assert capsys.readouterr().err.startswith(f"dh2urdf: error: {folder}: cannot read: ")
    binary = tmp_path / "bin.yaml"
    binary.write_bytes(b"\xff\xfe\x00name")
    assert main([str(binary)]) == 2
    assert capsys.readouterr().err.startswith(f"dh2urdf: error: {binary}: not UTF-8 text")


def test_main_unwritable_output_exit_1(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    target = tmp_path / "missing_dir" / "robot.urdf"
    assert main([str(ARMAR), "-o", str(target)]) == 1
    err = capsys.readouterr().err
    assert err == f"dh2urdf: error: {target}: cannot write: No such file or directory\n"


def test_main_usage_error_exit_2(capsys: pytest.CaptureFixture[str]) -> None:
    assert main([]) == 2
    err = capsys.readouterr().err
    assert err.startswith("dh2urdf: error: the following arguments are required: table")
    assert err.count("\n") == 1
    assert main(["a.yaml", "--format", "xml"]) == 2
    assert "invalid choice: 'xml'" in capsys.readouterr().err


def test_main_help_exit_0(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["--help"]) == 0
    assert "usage: dh2urdf" in capsys.readouterr().out


def test_package_never_imports_app() -> None:
    """dh2urdf is usable without the service: importing it must not load ``app``."""
    code = (
        "import sys, dh2urdf, dh2urdf.cli, dh2urdf.geometry, dh2urdf.math, dh2urdf.urdf;"
        "assert not any(m == 'app' or m.startswith('app.') for m in sys.modules), 'app loaded'"
    )
    result = subprocess.run([PYTHON, "-c", code], cwd=REPO, capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    for source in (REPO / "dh2urdf").glob("*.py"):
        text = source.read_text()
        assert "import app" not in text and "from app" not in text, source
