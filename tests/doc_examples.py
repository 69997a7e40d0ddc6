"""The examples of README.md and docs/*.md: how they are found, run and compared.

The convention (also in docs/architecture.md, "Where things go"):

- Every fenced block of a document is an **example that runs**, the **answer** of the
  example above it, or **marked** as not run with its reason: ``<!-- not run: why -->`` on
  the line(s) just above the fence. A block that is none of these fails the test, so no
  example can escape.
- A ``sh`` block is run by ``bash`` (``pipefail``); all ``sh`` blocks of one document run in
  order in **one** shell session (a variable set by one block, such as ``JOB``, is seen by
  the next), in a scratch folder holding the files the examples name (``scratch_files``
  in tests/test_doc_examples.py). Every URL in it is ``http://127.0.0.1:8000`` (the
  address of ``make run``); the test swaps in its live server's port. Each block must
  exit 0.
- A ``python`` block runs in its own interpreter (the project's), same folder, same port
  swap; it must exit 0. Its checks are its own ``assert``\\ s, or an answer block.
- The block right after an example (nothing but blank lines and comments between them) is
  its **answer** when it is ``json`` or ``text``: the example's standard output,
  compared. Every ``sh`` example has one (an answer without a body is shown with
  ``curl -s -o /dev/null -w '%{http_code}\\n'`` and a ``text`` block).
- ``text``: equal after stripping surrounding white space.
- ``json``: the shown value must *match* the answer (:func:`mismatches`): an object's keys
  shown ⊆ the keys answered (keys may be left out; a trailing ``...`` in an object says
  so to the reader); lists of the same length, unless one element is ``...`` (then the
  elements before it match the answer's first ones, those after it its last ones, and
  any number may be between); ``...`` as a value matches anything, a string ending in
  ``...`` matches every string that starts with the rest; strings, booleans and null
  equal; numbers within the block's tolerance: ``<!-- answer: tolerance 1e-6 -->``
  above the answer block (|shown − answered| ≤ tol·(1 + |shown|)), else
  :data:`DEFAULT_TOLERANCE`.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass, field
from pathlib import Path

#: Tolerance of a number in a json answer block that states none.
DEFAULT_TOLERANCE = 1e-9
#: The address every example names; the test swaps in its server's port.
ADDRESS = "127.0.0.1:8000"
#: The elision marker (bare ``...`` in a json answer block).
ELIDED = "..."
#: Languages of blocks that run, and of blocks that are answers.
RUNS = ("sh", "python")
ANSWERS = ("json", "text")

_FENCE = re.compile(r"^(\s*)(```+|~~~+)\s*([\w+-]*)\s*$")
_COMMENT = re.compile(r"^\s*<!--\s*(.*?)\s*-->\s*$")
_URL = re.compile(r"\b(?:https?|wss?)://([^/\s'\"`]+)")


@dataclass
class Block:
    """One fenced block: its document, first line (1-based, the fence), language, text and
    the ``<!-- key: value -->`` comments just above it."""

    doc: str
    line: int
    lang: str
    text: str
    notes: dict[str, str] = field(default_factory=dict)
    #: Whether prose stands between the previous block and this one.
    after_prose: bool = True

    @property
    def where(self) -> str:
        return f"{self.doc}:{self.line}"


@dataclass
class Example:
    """A block that runs, with its answer block (or none)."""

    block: Block
    answer: Block | None


@dataclass
class Plan:
    """What one document holds: examples that run, blocks marked not run, and problems
    (blocks that are neither)."""

    examples: list[Example] = field(default_factory=list)
    not_run: list[Block] = field(default_factory=list)
    problems: list[str] = field(default_factory=list)


def blocks(doc: str, text: str) -> list[Block]:
    """The fenced blocks of a Markdown text, in order."""
    lines = text.splitlines()
    out: list[Block] = []
    i = 0
    prose = True
    while i < len(lines):
        m = _FENCE.match(lines[i])
        if not m:
            if lines[i].strip() and not _COMMENT.match(lines[i]):
                prose = True
            i += 1
            continue
        fence = m.group(2)
        start = i
        j = i + 1
        while j < len(lines) and not lines[j].strip().startswith(fence):
            j += 1
        notes: dict[str, str] = {}
        k = start - 1
        while k >= 0 and (not lines[k].strip() or _COMMENT.match(lines[k])):
            c = _COMMENT.match(lines[k])
            if c and ":" in c.group(1):
                key, _, value = c.group(1).partition(":")
                notes.setdefault(key.strip(), value.strip())
            k -= 1
        body = "\n".join(lines[start + 1 : j])
        out.append(Block(doc, start + 1, m.group(3).lower(), body, notes, prose))
        prose = False
        i = j + 1
    return out


def plan(doc: str, text: str) -> Plan:
    """Sort a document's blocks into examples, answers, marked blocks and problems."""
    result = Plan()
    found = blocks(doc, text)
    i = 0
    while i < len(found):
        b = found[i]
        if "not run" in b.notes:
            if not b.notes["not run"]:
                result.problems.append(f"{b.where}: 'not run' without a reason")
            result.not_run.append(b)
            i += 1
            continue
        if b.lang not in RUNS:
            result.problems.append(
                f"{b.where}: a ```{b.lang} block that neither runs (sh, python), answers the "
                "example above it, nor is marked <!-- not run: reason -->"
            )
            i += 1
            continue
        hosts = {h for h in _URL.findall(b.text)}
        if hosts - {ADDRESS}:
            result.problems.append(f"{b.where}: names {sorted(hosts - {ADDRESS})}, not {ADDRESS}")
        nxt = found[i + 1] if i + 1 < len(found) else None
        answer = None
        if nxt is not None and nxt.lang in ANSWERS and not nxt.after_prose:
            answer = nxt if "not run" not in nxt.notes else None
        if b.lang == "sh" and answer is None:
            result.problems.append(f"{b.where}: a sh example without its answer block")
        result.examples.append(Example(b, answer))
        i += 2 if answer is not None else 1
    return result


def parse_answer(text: str) -> object:
    """A json answer block as a value: bare ``...`` becomes :data:`ELIDED`; a ``...`` member
    of an object (``{"a": 1, ...}``) is dropped (keys may be left out anyway)."""
    out = []
    in_string = escaped = False
    i = 0
    while i < len(text):
        ch = text[i]
        if in_string:
            out.append(ch)
            if escaped:
                escaped = False
            elif ch == "\\":
                escaped = True
            elif ch == '"':
                in_string = False
        elif ch == '"':
            in_string = True
            out.append(ch)
        elif text.startswith("...", i):
            out.append(json.dumps(ELIDED))
            i += 3
            continue
        else:
            out.append(ch)
        i += 1
    marked = "".join(out)
    member = re.escape(json.dumps(ELIDED))
    marked = re.sub(r",\s*" + member + r"\s*}", "}", marked)
    marked = re.sub(r"{\s*" + member + r"\s*}", "{}", marked)
    marked = re.sub(r"{\s*" + member + r"\s*,", "{", marked)
    return json.loads(marked)


def mismatches(shown: object, got: object, tol: float, path: str = "$") -> list[str]:
    """Where the answer ``got`` differs from the ``shown`` one (rules: module doc)."""
    if shown == ELIDED:
        return []
    if isinstance(shown, dict):
        if not isinstance(got, dict):
            return [f"{path}: shown an object, answered {json.dumps(got)[:200]}"]
        out: list[str] = []
        for key, value in shown.items():
            if key not in got:
                out.append(f"{path}.{key}: shown, not in the answer (keys: {sorted(got)})")
            else:
                out += mismatches(value, got[key], tol, f"{path}.{key}")
        return out
    if isinstance(shown, list):
        if not isinstance(got, list):
            return [f"{path}: shown a list, answered {json.dumps(got)[:200]}"]
        if ELIDED in shown:
            cut = shown.index(ELIDED)
            head, tail = shown[:cut], shown[cut + 1 :]
            if len(got) < len(head) + len(tail):
                return [
                    f"{path}: shown at least {len(head) + len(tail)} items, answered {len(got)}"
                ]
            pairs = list(zip(head, got, strict=False))
            pairs += list(zip(tail, got[len(got) - len(tail) :], strict=True))
            offsets = list(range(len(head))) + list(range(len(got) - len(tail), len(got)))
        else:
            if len(got) != len(shown):
                return [f"{path}: shown {len(shown)} items, answered {len(got)}"]
            pairs = list(zip(shown, got, strict=True))
            offsets = list(range(len(shown)))
        out = []
        for k, (s, g) in zip(offsets, pairs, strict=True):
            out += mismatches(s, g, tol, f"{path}[{k}]")
        return out
    if isinstance(shown, str) and shown.endswith(ELIDED) and isinstance(got, str):
        ok = got.startswith(shown[: -len(ELIDED)])
        return [] if ok else [f"{path}: shown {shown!r}, answered {got!r}"]
    if isinstance(shown, bool) or shown is None or isinstance(shown, str):
        ok = type(got) is type(shown) and got == shown
        return [] if ok else [f"{path}: shown {json.dumps(shown)}, answered {json.dumps(got)}"]
    if isinstance(shown, int | float):
        ok = isinstance(got, int | float) and not isinstance(got, bool)
        if ok and abs(float(got) - float(shown)) <= tol * (1 + abs(float(shown))):
            return []
        return [f"{path}: shown {shown}, answered {json.dumps(got)} (tolerance {tol:g})"]
    return [f"{path}: cannot compare {shown!r}"]


def tolerance(answer: Block) -> float:
    """The answer block's tolerance (``<!-- answer: tolerance X -->``), else the default."""
    note = answer.notes.get("answer", "")
    m = re.fullmatch(r"tolerance\s+(\S+)", note)
    if note and not m:
        raise ValueError(f"{answer.where}: unreadable note 'answer: {note}'")
    return float(m.group(1)) if m else DEFAULT_TOLERANCE


def check_answer(example: Example, stdout: str) -> list[str]:
    """Problems of one example's output against its answer block."""
    answer = example.answer
    if answer is None:
        return []
    where = f"{example.block.where} (answer {answer.line})"
    if answer.lang == "text":
        if stdout.strip() != answer.text.strip():
            return [f"{where}: shown {answer.text.strip()!r}, answered {stdout.strip()[:500]!r}"]
        return []
    try:
        shown = parse_answer(answer.text)
    except ValueError as exc:
        return [f"{where}: the answer block is no JSON: {exc}"]
    try:
        got = json.loads(stdout)
    except ValueError:
        return [f"{where}: the example answered no JSON: {stdout[:500]!r}"]
    found = [f"{where}: {m}" for m in mismatches(shown, got, tolerance(answer))]
    if found:
        found.append(f"{where}: the answer was {stdout[:1500]}")
    return found


def session_script(examples: list[Example], port: int, out_dir: Path) -> str:
    """One bash script running a document's sh examples in order, each one's stdout, stderr
    and exit status into ``out_dir/<i>.{out,err,rc}``."""
    parts = ["set -o pipefail"]
    for i, ex in enumerate(examples):
        body = ex.block.text.replace(ADDRESS, f"127.0.0.1:{port}")
        parts.append(
            "{\n" + body + f"\n}} > {out_dir}/{i}.out 2> {out_dir}/{i}.err\n"
            f"echo $? > {out_dir}/{i}.rc"
        )
    return "\n".join(parts) + "\n"
