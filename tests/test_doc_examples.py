"""Every example of README.md and docs/*.md runs against a live server and answers as shown.

The convention (blocks that run, answers, ``<!-- not run: why -->``, tolerances, elision) is
in :mod:`tests.doc_examples`. One server (``uvicorn``, a free port, stopped by its PID)
serves the whole module; each document's ``sh`` examples run in order in one ``bash``
session, in a scratch folder holding :func:`scratch_files`. docs/clients.md is left out
here: its Python and TypeScript blocks are run by the clients' own tests
(:data:`OWN_TESTS`).
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import time
from pathlib import Path

import pytest

from tests.doc_examples import (
    ELIDED,
    Block,
    Example,
    check_answer,
    mismatches,
    parse_answer,
    plan,
    session_script,
)
from tests.helpers import ROOT, serve
from tests.packages import panda_files

#: Documents whose blocks another test runs (document → that test).
OWN_TESTS: dict[str, str] = {}
DOCS = ["README.md"] + sorted(
    p.relative_to(ROOT).as_posix()
    for p in (ROOT / "docs").glob("*.md")
    if p.relative_to(ROOT).as_posix() not in OWN_TESTS
)

#: A two-link planar arm without meshes (docs/robots.md, "A URDF document").
TWO_LINK = """<?xml version="1.0"?>
<robot name="two_link">
  <link name="base"/>
  <link name="upper"/>
  <link name="fore"/>
  <link name="tip"/>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="upper"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="10" velocity="2"/>
  </joint>
  <joint name="elbow" type="revolute">
    <parent link="upper"/><child link="fore"/><origin xyz="0.5 0 0"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="10" velocity="2"/>
  </joint>
  <joint name="tip_joint" type="fixed">
    <parent link="fore"/><child link="tip"/><origin xyz="0.4 0 0"/>
  </joint>
</robot>
"""

#: A lab's xacro wrapper around the Panda: a tool whose length is an argument.
WRAPPER = """<?xml version="1.0"?>
<robot name="lab_panda" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="tool_length" default="0.1"/>
  <xacro:include filename="$(find lab_panda)/urdf/panda.urdf"/>
  <link name="tool_tip"/>
  <joint name="tool_joint" type="fixed">
    <parent link="panda_hand"/><child link="tool_tip"/>
    <origin xyz="0 0 $(arg tool_length)"/>
  </joint>
</robot>
"""


def scratch_files() -> dict[str, bytes]:
    """The files the examples name, by path in their working folder: ``two_link.urdf`` and
    ``lab_panda/`` (the Panda as a lab ships it: package.xml, urdf/panda.urdf with relative
    mesh paths, urdf/lab_panda.urdf.xacro, srdf/panda.srdf, meshes/collision/)."""
    files = {"two_link.urdf": TWO_LINK.encode()}
    # The collision meshes serve as visual meshes too: 0.1 MB to upload instead of 11 MB.
    panda = panda_files(top="lab_panda/")
    urdf = panda.pop("lab_panda/urdf/panda.urdf").decode()
    urdf = re.sub(r"meshes/visual/(\w+)\.dae", r"meshes/collision/\1.stl", urdf)
    files |= {k: v for k, v in panda.items() if "/meshes/visual/" not in k}
    files["lab_panda/urdf/panda.urdf"] = urdf.encode()
    files["lab_panda/urdf/lab_panda.urdf.xacro"] = WRAPPER.encode()
    return files


def _fill(folder: Path) -> None:
    for name, data in scratch_files().items():
        path = folder / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(data)


def test_every_block_runs_answers_or_is_marked() -> None:
    """No block escapes: each one runs, answers the example above it, or says why not."""
    problems = [p for doc in DOCS for p in plan(doc, (ROOT / doc).read_text()).problems]
    assert not problems, "\n".join(problems)


@pytest.fixture(scope="module")
def server(tmp_path_factory: pytest.TempPathFactory):
    with serve(tmp_path_factory.mktemp("doc-data")) as live:
        yield live


def _run_python(example: Example, port: int, cwd: Path) -> list[str]:
    code = example.block.text.replace("127.0.0.1:8000", f"127.0.0.1:{port}")
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    proc = subprocess.run(
        [sys.executable, "-c", code], cwd=cwd, env=env, capture_output=True, text=True, timeout=120
    )
    if proc.returncode != 0:
        return [f"{example.block.where}: exited {proc.returncode}: {proc.stderr[-2000:]}"]
    return check_answer(example, proc.stdout)


def _run_document(doc: str, port: int, work: Path) -> tuple[int, int, list[str]]:
    """Run one document's examples in the folder ``work``; (examples run, blocks marked not
    run, failures)."""
    found = plan(doc, (ROOT / doc).read_text())
    cwd = work
    out = work / ".answers" / doc.replace("/", "_")
    out.mkdir(parents=True)
    failures = list(found.problems)
    shell = [ex for ex in found.examples if ex.block.lang == "sh"]
    if shell:
        script = out / "session.sh"
        script.write_text(session_script(shell, port, out))
        proc = subprocess.run(
            ["bash", str(script)], cwd=cwd, capture_output=True, text=True, timeout=300
        )
        if proc.returncode != 0:
            failures.append(f"{doc}: the shell session failed: {proc.stderr[-2000:]}")
        for i, ex in enumerate(shell):
            rc = (out / f"{i}.rc").read_text().strip() if (out / f"{i}.rc").exists() else "?"
            stdout = (out / f"{i}.out").read_text() if (out / f"{i}.out").exists() else ""
            if rc != "0":
                err = (out / f"{i}.err").read_text()[-2000:] if (out / f"{i}.err").exists() else ""
                failures.append(f"{ex.block.where}: exited {rc}: {err}")
                continue
            failures += check_answer(ex, stdout)
    for ex in found.examples:
        if ex.block.lang == "python":
            failures += _run_python(ex, port, cwd)
    return len(found.examples), len(found.not_run), failures


def test_doc_examples_answer_as_shown(server, tmp_path: Path) -> None:
    """Each document's examples run against the live server and answer what they show."""
    port = int(server.url.rsplit(":", 1)[1])
    _fill(tmp_path)
    failures: list[str] = []
    counts = []
    for doc in DOCS:
        start = time.monotonic()
        ran, marked, problems = _run_document(doc, port, tmp_path)
        took = time.monotonic() - start
        counts.append(f"{doc}: {ran} run, {marked} marked not run ({took:.1f} s)")
        failures += problems
    print("\n".join(counts))
    assert not failures, "\n\n".join(failures)


# ------------------------------------------------------------------ the comparison itself
def _answer(text: str, note: str = "") -> Example:
    block = Block("doc.md", 1, "sh", "true")
    answer = Block("doc.md", 3, "json", text, {"answer": note} if note else {})
    return Example(block, answer)


def test_answers_compare_by_the_stated_rules() -> None:
    """Each rule can fail: a changed number, string, boolean, missing key, list length."""
    shown = '{"a": 1.0, "b": "x", "c": [1, 2], "d": true, ...}'
    assert (
        check_answer(_answer(shown), '{"a": 1.0, "b": "x", "c": [1, 2], "d": true, "e": 0}') == []
    )
    assert check_answer(_answer(shown), '{"a": 1.001, "b": "x", "c": [1, 2], "d": true}')
    assert (
        check_answer(
            _answer(shown, "tolerance 1e-2"), '{"a": 1.001, "b": "x", "c": [1, 2], "d": true}'
        )
        == []
    )
    assert check_answer(_answer(shown), '{"a": 1.0, "b": "y", "c": [1, 2], "d": true}')
    assert check_answer(_answer(shown), '{"a": 1.0, "b": "x", "c": [1, 2, 3], "d": true}')
    assert check_answer(_answer(shown), '{"a": 1.0, "b": "x", "c": [1, 2], "d": 1}')
    assert check_answer(_answer(shown), '{"a": 1.0, "b": "x", "c": [1, 2]}')
    assert check_answer(_answer(shown), "not json")


def test_elision_matches_what_it_stands_for() -> None:
    """``...`` in a list: head and tail matched, any count between; as a value: anything;
    at a string's end: a prefix."""
    shown = parse_answer('{"l": [1, ..., 9], "v": ..., "s": "free at ..."}')
    assert shown == {"l": [1, ELIDED, 9], "v": ELIDED, "s": "free at ..."}
    assert mismatches(shown, {"l": [1, 5, 6, 9], "v": [3], "s": "free at 2 m"}, 1e-9) == []
    assert mismatches(shown, {"l": [1, 9], "v": None, "s": "free at"}, 1e-9) == [
        "$.s: shown 'free at ...', answered 'free at'"
    ]
    assert mismatches(shown, {"l": [2, 5, 9], "v": 0, "s": "free at 2"}, 1e-9)
    assert mismatches(shown, {"l": [1], "v": 0, "s": "free at 2"}, 1e-9)


SAMPLE = """# A page

<!-- not run: a diagram -->
```
box
```

```sh
curl -s http://127.0.0.1:8000/health
```

```json
{"status": "ok"}
```

```sh
curl -s http://localhost:8000/health
```

Prose between an example and a block: that block is no answer.

```json
{"status": "ok"}
```

<!-- not run: -->
```sh
make run
```
"""


def test_blocks_that_neither_run_nor_answer_nor_are_marked_are_problems() -> None:
    """The plan of a page: one example with its answer; a foreign address, a missing
    answer, a json block after prose and a reasonless mark are each reported."""
    found = plan("page.md", SAMPLE)
    assert [(ex.block.line, ex.answer.line if ex.answer else None) for ex in found.examples] == [
        (8, 12),
        (16, None),
    ]
    assert [b.line for b in found.not_run] == [4, 27]
    assert found.problems == [
        "page.md:16: names ['localhost:8000'], not 127.0.0.1:8000",
        "page.md:16: a sh example without its answer block",
        "page.md:22: a ```json block that neither runs (sh, python), answers the example above "
        "it, nor is marked <!-- not run: reason -->",
        "page.md:27: 'not run' without a reason",
    ]
