"""The committed clients are what their generators make of docs/openapi.json today.

- clients/python: ``clients/generate.py --check`` regenerates the package into a temporary
  directory (the pinned openapi-python-client, the committed configuration, the project's
  ruff) and compares every generated file; the hand-written modules are not generated.
- clients/typescript: ``generate.mjs`` (openapi-typescript, the pinned version) writes the
  types into a temporary file, compared with src/schema.d.ts.
- Optional security: an operation whose ``security`` admits anonymous access (``{}``) takes a
  plain ``Client``; one that demands the bearer scheme, an ``AuthenticatedClient``.

Offline and deterministic (no network: the generators read the local document).
"""

from __future__ import annotations

import importlib.util
import json
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
TS_DIR = ROOT / "clients" / "typescript"
PACKAGE = ROOT / "clients" / "python" / "denavit_client"


def _generator():
    spec = importlib.util.spec_from_file_location("clients_generate", ROOT / "clients/generate.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _client_type(module_text: str) -> str:
    """The type of the ``client`` argument of a generated operation's ``sync_detailed``."""
    sync = module_text[module_text.index("\ndef sync_detailed(") :]
    found = re.search(r"client: ([^,\n]+),", sync)
    assert found, sync[:400]
    return found.group(1)


def test_the_python_client_is_generated_from_the_committed_document() -> None:
    done = subprocess.run(
        [sys.executable, "clients/generate.py", "--check"], cwd=ROOT, capture_output=True, text=True
    )
    assert done.returncode == 0, done.stdout + done.stderr


def test_the_typescript_types_are_generated_from_the_committed_document(tmp_path) -> None:
    assert (TS_DIR / "node_modules").is_dir(), "run `make typescript` (npm ci) first"
    out = tmp_path / "schema.d.ts"
    done = subprocess.run(
        ["node", "generate.mjs", str(out)], cwd=TS_DIR, capture_output=True, text=True
    )
    assert done.returncode == 0, done.stdout + done.stderr
    committed = (TS_DIR / "src" / "schema.d.ts").read_text()
    assert out.read_text() == committed, "clients/typescript is out of date: run `make clients`"


def test_request_fields_with_defaults_stay_optional_in_typescript() -> None:
    """generate.mjs's defaultNonNullable false: an IK request needs its target only."""
    types = (TS_DIR / "src" / "schema.d.ts").read_text()
    ik = types[types.index("        IKRequest: {") :]
    ik = ik[: ik.index("\n        };")]
    required = re.findall(r"^            (\w+): ", ik, flags=re.MULTILINE)
    assert required == ["target"], required


def test_operations_with_optional_security_take_a_plain_client(tmp_path) -> None:
    """The generator demands an AuthenticatedClient wherever ``security`` is set; clients/
    generate.py drops ``security`` where it admits anonymous access (``{}``)."""
    gen = _generator()
    scheme = {"bearerAuth": {"type": "http", "scheme": "bearer"}}
    answer = {"204": {"description": "done"}}
    document = {
        "openapi": "3.1.0",
        "info": {"title": "t", "version": "1"},
        "paths": {
            f"/{name}": {"post": {"operationId": name, "responses": answer, **security}}
            for name, security in {
                "optional_token": {"security": [{}, {"bearerAuth": []}]},
                "token": {"security": [{"bearerAuth": []}]},
                "anyone": {"security": []},
            }.items()
        },
        "components": {"securitySchemes": scheme},
    }
    unchanged = json.dumps(document)
    gen.generate(tmp_path / "denavit_client", document)
    assert json.dumps(document) == unchanged  # the caller's document is not changed
    api = tmp_path / "denavit_client" / "api" / "default"
    assert _client_type((api / "optional_token.py").read_text()) == "AuthenticatedClient | Client"
    assert _client_type((api / "token.py").read_text()) == "AuthenticatedClient"
    assert _client_type((api / "anyone.py").read_text()) == "AuthenticatedClient | Client"


def test_the_committed_client_takes_the_clients_the_document_allows() -> None:
    """Every operation of docs/openapi.json: a plain Client where no token or an optional one
    is declared, an AuthenticatedClient where the bearer scheme is required."""
    document = json.loads((ROOT / "docs" / "openapi.json").read_text())
    seen = 0
    for item in document["paths"].values():
        for op in item.values():
            security = op.get("security", [])
            tag = op["tags"][0].replace(" ", "_")
            text = (PACKAGE / "api" / tag / f"{op['operationId']}.py").read_text()
            demands_token = bool(security) and {} not in security
            expected = "AuthenticatedClient" if demands_token else "AuthenticatedClient | Client"
            assert _client_type(text) == expected, op["operationId"]
            seen += 1
    assert seen == sum(len(item) for item in document["paths"].values())
