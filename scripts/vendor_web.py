"""Refresh the browser libraries vendored into ``app/static/vendor`` from the npm registry.

    python scripts/vendor_web.py            (what ``make viewer-vendor`` runs; needs npm)

The service serves every page offline, with no CDN and no Node on a user's machine: the
built files of the pinned npm packages below are copied into the package, each with its
license, and ``app/static/vendor/manifest.json`` records name, version, the registry's
integrity hash and the files taken. Change a version here, run the target, commit the
result.

- three (MIT): the ES-module build and the addons the viewer imports (orbit and transform
  controls; the STL, Collada and OBJ mesh loaders).
- urdf-loader (Apache-2.0): the URDF loader for three.js. Its npm package ships no
  LICENSE file; the Apache-2.0 text is taken from swagger-ui-dist's (the same license).
- swagger-ui-dist (Apache-2.0) and redoc (MIT): the assets of ``/docs`` and ``/redoc``.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
import tarfile
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
VENDOR = ROOT / "app" / "static" / "vendor"

#: npm package → (pinned version, files to copy, relative to the package root).
PACKAGES: dict[str, tuple[str, list[str]]] = {
    "three": (
        "0.187.0",
        [
            "LICENSE",
            "build/three.module.js",
            "build/three.core.js",
            "examples/jsm/controls/OrbitControls.js",
            "examples/jsm/controls/TransformControls.js",
            "examples/jsm/loaders/STLLoader.js",
            "examples/jsm/loaders/OBJLoader.js",
            "examples/jsm/loaders/ColladaLoader.js",
            "examples/jsm/loaders/TGALoader.js",
            "examples/jsm/loaders/collada/ColladaParser.js",
            "examples/jsm/loaders/collada/ColladaComposer.js",
        ],
    ),
    "urdf-loader": ("0.13.1", ["src/URDFLoader.js", "src/URDFClasses.js"]),
    "swagger-ui-dist": (
        "5.35.0",
        [
            "LICENSE",
            "NOTICE",
            "swagger-ui-bundle.js",
            "swagger-ui-bundle.js.LICENSE.txt",
            "swagger-ui.css",
            "favicon-32x32.png",
        ],
    ),
    "redoc": (
        "2.5.2",
        ["LICENSE", "bundles/redoc.standalone.js", "bundles/redoc.standalone.js.LICENSE.txt"],
    ),
}


def pack(name: str, version: str, workdir: Path) -> tuple[Path, dict]:
    """``npm pack`` one pinned package into ``workdir``; its unpacked root and npm's record."""
    out = subprocess.run(
        ["npm", "pack", f"{name}@{version}", "--json", "--pack-destination", str(workdir)],
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    record = json.loads(out)[0]
    if record["version"] != version:
        sys.exit(f"{name}: npm gave {record['version']}, pinned {version}")
    root = workdir / name
    with tarfile.open(workdir / record["filename"]) as tar:
        tar.extractall(root, filter="data")
    return root / "package", record


def main() -> None:
    if shutil.which("npm") is None:
        sys.exit("npm not found: `make viewer-vendor` refreshes the vendored files from npm")
    entries = []
    with tempfile.TemporaryDirectory() as tmp:
        unpacked = {}
        for name, (version, files) in PACKAGES.items():
            root, record = pack(name, version, Path(tmp))
            unpacked[name] = root
            manifest = json.loads((root / "package.json").read_text())
            entries.append(
                {
                    "name": name,
                    "version": version,
                    "license": manifest.get("license"),
                    "integrity": record["integrity"],
                    "files": files,
                }
            )
        shutil.rmtree(VENDOR, ignore_errors=True)
        for entry in entries:
            root = unpacked[entry["name"]]
            for rel in entry["files"]:
                dest = VENDOR / entry["name"] / rel
                dest.parent.mkdir(parents=True, exist_ok=True)
                shutil.copyfile(root / rel, dest)
        note = (
            "urdf-loader is licensed Apache-2.0 (its package.json; Copyright Garrett "
            "Johnson). Its npm package ships no LICENSE file; the license text follows.\n\n"
        )
        apache = (unpacked["swagger-ui-dist"] / "LICENSE").read_text()
        (VENDOR / "urdf-loader" / "LICENSE").write_text(note + apache)
        next(e for e in entries if e["name"] == "urdf-loader")["files"].append("LICENSE")
    (VENDOR / "manifest.json").write_text(json.dumps({"packages": entries}, indent=2) + "\n")
    for entry in entries:
        print(f"{entry['name']} {entry['version']}: {len(entry['files'])} files")


if __name__ == "__main__":
    main()
