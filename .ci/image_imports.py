"""image_imports.py: which installed distributions the service never imports, run INSIDE a
throwaway container of the image (container-check.sh's "imports" step, as root: it adds a
recording hook to the image's site-packages, which the image itself never has).

    podman run --rm --network=none -u 0 -v .ci:/probe:ro IMAGE \
        python /probe/image_imports.py /probe/image-allowlist.txt

1. Installs ``_import_probe.pth`` in site-packages: every Python process of the venv started
   afterwards (the uvicorn workers, the work pool's and map builds' processes, and the
   ``python -I`` children that read uploads: ``-I`` skips PYTHONPATH but not ``.pth``
   files) sends each module name it looks up, and the names already in ``sys.modules`` when
   the hook starts, to the probe's datagram socket (a socket, not a file: the upload
   children may not write files).
2. Starts ``python -m app`` (the image's CMD and settings; data in a temporary directory)
   and sends a representative set of requests: every exchange of the OpenAPI examples
   (``app/api/examples/exchanges.json`` of the installed package: each operation, uploads
   of DH, URDF and a package with a mesh, a reachability build, error answers), then FK,
   IK, Jacobian and collisions on the Panda and the UR5, a batch IK, a Cartesian path with
   timing, a catalog mesh file, an MJCF package, a xacro package, the viewer and the docs
   pages, and a WebSocket stream with an FK and an IK message.
3. Reads the shared libraries mapped by every live process (``/proc/*/maps``), stops the
   server (SIGTERM), and maps each installed distribution (``importlib.metadata``, its
   RECORD) to the top-level modules and the shared libraries it installs. A distribution
   is *used* when one of its top-level modules was imported or one of its libraries
   mapped; every other one must be named, with a reason, in the allowlist file (``name  #
   reason`` per line). Entries of site-packages that no distribution owns are reported the
   same way.

Prints one line per distribution (MB, used by what, or kept for what reason) and exits 1
when a distribution is never imported and not listed, or a listed name is not installed.
"""

from __future__ import annotations

import base64
import glob
import importlib.metadata as md
import json
import os
import re
import signal
import socket
import struct
import subprocess
import sys
import sysconfig
import tempfile
import threading
import time
import urllib.error
import urllib.request
import uuid
import zipfile
from io import BytesIO
from pathlib import Path

SOCKET = Path(os.environ.get("PROBE_SOCKET", "/tmp/import-probe.sock"))
PORT = int(os.environ.get("PROBE_PORT", "18765"))
URL = f"http://127.0.0.1:{PORT}"
SITE = Path(sysconfig.get_paths()["purelib"])

HOOK = '''"""Written by .ci/image_imports.py into a throwaway container: records imports."""
import os
import socket
import sys

_SOCKET = "{socket}"


class _Recorder:
    """Sends each module name looked up to the probe's datagram socket (not a file: the
    upload children may write no file, RLIMIT_FSIZE 0)."""

    def __init__(self):
        self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_DGRAM)
        self.sock.connect(_SOCKET)
        self.sent = False

    def find_spec(self, name, path=None, target=None):
        try:
            if not self.sent:  # what was imported before this hook
                self.sent = True
                for early in list(sys.modules):
                    self.sock.send(early.encode())
            self.sock.send(name.encode())
        except OSError:
            pass
        return None


if os.path.exists(_SOCKET):
    try:
        sys.meta_path.insert(0, _Recorder())
    except OSError:
        pass
'''

#: A binary STL tetrahedron (MuJoCo reads binary STL only).
_TETRA = [(0, 0, 0), (0.1, 0, 0), (0, 0.1, 0), (0, 0, 0.1)]
STL = (
    b"\0" * 80
    + struct.pack("<I", 4)
    + b"".join(
        struct.pack("<12fH", 0, 0, 0, *_TETRA[a], *_TETRA[b], *_TETRA[c], 0)
        for a, b, c in ((0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3))
    )
)
MJCF = """<mujoco model="mini">
  <compiler angle="radian" meshdir="assets"/>
  <asset><mesh name="tri" file="tri.stl"/></asset>
  <worldbody>
    <body name="base">
      <geom type="mesh" mesh="tri"/>
      <body name="upper" pos="0 0 0.2">
        <joint name="shoulder" axis="0 1 0" range="-2 2"/>
        <geom type="capsule" fromto="0 0 0 0 0 0.3" size="0.03"/>
        <body name="fore" pos="0 0 0.3">
          <joint name="elbow" axis="0 1 0" range="-2 2"/>
          <site name="tcp" pos="0 0 0.2"/>
        </body>
      </body>
    </body>
  </worldbody>
</mujoco>
"""
XACRO = """<?xml version="1.0"?>
<robot xmlns:xacro="http://wiki.ros.org/xacro" name="xrr">
  <xacro:property name="len" value="0.4"/>
  <xacro:macro name="arm_link" params="name">
    <link name="${name}"><collision><geometry><box size="0.05 0.05 ${len}"/></geometry>
    </collision></link>
  </xacro:macro>
  <link name="base"/>
  <xacro:arm_link name="l1"/>
  <link name="tool"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="l1"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="l1"/><child link="tool"/>
    <origin xyz="${len} 0 0"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
</robot>
"""


# ---------------------------------------------------------------------------- requests
def request(
    method: str,
    path: str,
    body: bytes | None = None,
    headers: dict[str, str] | None = None,
    timeout: float = 120.0,
) -> tuple[int, bytes]:
    """(status, body) of one HTTP request to the server (4xx and 5xx included)."""
    req = urllib.request.Request(URL + path, data=body, method=method, headers=headers or {})
    try:
        with urllib.request.urlopen(req, timeout=timeout) as resp:
            return resp.status, resp.read()
    except urllib.error.HTTPError as err:
        return err.code, err.read()
    except (urllib.error.URLError, ConnectionError):
        return -1, b""  # no answer: the server closed the connection


def post_json(path: str, payload: object) -> tuple[int, bytes]:
    return request("POST", path, json.dumps(payload).encode(), {"content-type": "application/json"})


def multipart(form: dict[str, str], files: dict[str, tuple[str, str, bytes]]) -> tuple[bytes, str]:
    """A multipart/form-data body and its content type."""
    boundary = uuid.uuid4().hex
    out = BytesIO()
    for name, value in form.items():
        out.write(f'--{boundary}\r\nContent-Disposition: form-data; name="{name}"\r\n\r\n'.encode())
        out.write(value.encode() + b"\r\n")
    for field, (filename, media, data) in files.items():
        out.write(
            f'--{boundary}\r\nContent-Disposition: form-data; name="{field}"; '
            f'filename="{filename}"\r\nContent-Type: {media}\r\n\r\n'.encode()
        )
        out.write(data + b"\r\n")
    out.write(f"--{boundary}--\r\n".encode())
    return out.getvalue(), f"multipart/form-data; boundary={boundary}"


def zip_bytes(files: dict[str, bytes]) -> bytes:
    buf = BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zf:
        for name, data in files.items():
            zf.writestr(name, data)
    return buf.getvalue()


def fill(value: object, bound: dict[str, str]) -> object:
    """``{name}`` placeholders of the examples' JSON filled from ``bound``."""
    if isinstance(value, str):
        for k, v in bound.items():
            value = value.replace("{" + k + "}", v)
        return value
    if isinstance(value, dict):
        return {k: fill(v, bound) for k, v in value.items()}
    if isinstance(value, list):
        return [fill(v, bound) for v in value]
    return value


def replay_examples() -> list[tuple[str, int]]:
    """Every exchange of the installed OpenAPI examples that runs on the started service."""
    import app

    path = Path(app.__file__).parent / "api" / "examples" / "exchanges.json"
    out, bound = [], {}
    for exchange in json.loads(path.read_text())["exchanges"]:
        spec = exchange["request"]
        if "app" in spec:  # needs a differently configured service (token, not started)
            continue
        headers = dict(spec.get("headers", {}))
        body = None
        if "json" in spec:
            body = json.dumps(fill(spec["json"], bound)).encode()
            headers["content-type"] = "application/json"
        elif "text" in spec:
            body = spec["text"].encode()
            headers["content-type"] = spec["content_type"]
        elif "files" in spec:
            files = {f: (n, m, base64.b64decode(d)) for f, (n, m, d) in spec["files"].items()}
            body, headers["content-type"] = multipart(spec["form"], files)
        elif "filler" in spec:
            body = b" " * spec["filler"]
        target = str(fill(spec["path"], bound))
        status, data = request(spec["method"], target, body, headers)
        if status == -1 and "filler" in spec:
            status = 413  # a body over the limit: answered, or the connection closed early
        until = spec.get("until")
        for _ in range(3000):
            if not until or json.loads(data).get(until["field"]) == until["value"]:
                break
            time.sleep(0.02)
            status, data = request(spec["method"], target, body, headers)
        for var, key in spec.get("bind", {}).items():
            bound[var] = str(json.loads(data)[key])
        out.append((f"{spec['method']} {target}", status))
    return out


def stream_round_trip(robot: str, messages: list[dict]) -> list[dict]:
    """Send ``messages`` as text frames on WS /robots/{robot}/stream; their answers."""
    sock = socket.create_connection(("127.0.0.1", PORT), timeout=60)
    key = base64.b64encode(os.urandom(16)).decode()
    sock.sendall(
        (
            f"GET /robots/{robot}/stream HTTP/1.1\r\nHost: 127.0.0.1:{PORT}\r\n"
            "Upgrade: websocket\r\nConnection: Upgrade\r\n"
            f"Sec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n"
        ).encode()
    )
    head = b""
    while b"\r\n\r\n" not in head:
        head += sock.recv(4096)
    head, rest = head.split(b"\r\n\r\n", 1)
    if not head.startswith(b"HTTP/1.1 101"):
        raise SystemExit(f"image_imports: no WebSocket upgrade: {head[:200]!r}")
    buf = bytearray(rest)

    def recv_exact(n: int) -> bytes:
        while len(buf) < n:
            chunk = sock.recv(65536)
            if not chunk:
                raise SystemExit("image_imports: the stream closed")
            buf.extend(chunk)
        data = bytes(buf[:n])
        del buf[:n]
        return data

    answers = []
    for message in messages:
        payload = json.dumps(message).encode()
        mask = os.urandom(4)
        n = len(payload)
        header = bytes([0x81]) + (
            bytes([0x80 | n])
            if n < 126
            else bytes([0x80 | 126]) + struct.pack(">H", n)
            if n < 65536
            else bytes([0x80 | 127]) + struct.pack(">Q", n)
        )
        sock.sendall(header + mask + bytes(b ^ mask[i % 4] for i, b in enumerate(payload)))
        b0, b1 = recv_exact(2)
        length = b1 & 0x7F
        if length == 126:
            (length,) = struct.unpack(">H", recv_exact(2))
        elif length == 127:
            (length,) = struct.unpack(">Q", recv_exact(8))
        answers.append(json.loads(recv_exact(length)))
    sock.sendall(bytes([0x88, 0x82]) + b"\0\0\0\0" + struct.pack(">H", 1000))
    sock.close()
    return answers


def extras() -> list[tuple[str, int]]:
    """The catalog's 6R and 7R arms, timing, meshes, MJCF, xacro, pages, the stream."""
    out = []

    def note(name: str, result: tuple[int, bytes]) -> bytes:
        out.append((name, result[0]))
        return result[1]

    starts = {
        "panda": [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785, 0.02],
        "ur5": [0.3, -1.1, 1.4, -0.6, 1.2, 0.4],
    }
    for robot, q0 in starts.items():
        fk = post_json(f"/robots/{robot}/fk", {"q": q0})
        pose = json.loads(note(f"{robot} fk", fk))["poses"]
        tip = next(iter(pose.values()))
        target = {"position": tip["position"], "orientation": tip["orientation"]}
        ik = {"target": target, "seed": q0, "random_seed": 0}
        note(f"{robot} ik", post_json(f"/robots/{robot}/ik", ik))
        note(f"{robot} jacobian", post_json(f"/robots/{robot}/jacobian", {}))
        ball = {"name": "b", "shape": "sphere", "radius": 0.05, "pose": {"position": [0.3, 0, 0.5]}}
        note(f"{robot} collisions", post_json(f"/robots/{robot}/collisions", {"obstacles": [ball]}))
        batch = {"targets": [target] * 64, "random_seed": 0}
        note(f"{robot} ik batch", post_json(f"/robots/{robot}/ik/batch", batch))
        x, y, z = tip["position"]
        moved = {"position": [x, y + 0.05, z - 0.05], "orientation": tip["orientation"]}
        path = {"start": q0, "waypoints": [moved], "random_seed": 0, "timing": {}}
        answer = json.loads(note(f"{robot} ik path", post_json(f"/robots/{robot}/ik/path", path)))
        timed = answer.get("fraction") == 1.0 and answer.get("timing") is not None
        out.append((f"{robot} path timed to its end", 200 if timed else 0))
        urdf = note(f"{robot} urdf", request("GET", f"/robots/{robot}/urdf")).decode()
        mesh = re.search(r'filename="package://[^"]*?/robots/[^/]+/([^"]+)"', urdf)
        if mesh:
            note(f"{robot} mesh", request("GET", f"/robots/{robot}/files/{mesh[1]}"))
        answers = stream_round_trip(
            robot, [{"id": 1, "op": "fk"}, {"id": 2, "op": "ik", "target": target}]
        )
        out.append((f"{robot} stream fk+ik", 200 if all("error" not in a for a in answers) else 0))
    mjcf = zip_bytes({"mini/mini.xml": MJCF.encode(), "mini/assets/tri.stl": STL})
    body, media = multipart(
        {"name": "mini", "description": "mini/mini.xml"},
        {"archive": ("mini.zip", "application/zip", mjcf)},
    )
    note("MJCF package", request("POST", "/robots/package", body, {"content-type": media}))
    note("MJCF robot fk", post_json("/robots/mini/fk", {}))
    xacro = zip_bytes({"xrr/urdf/xrr.urdf.xacro": XACRO.encode()})
    body, media = multipart(
        {"name": "xrr", "description": "xrr/urdf/xrr.urdf.xacro"},
        {"archive": ("xrr.zip", "application/zip", xacro)},
    )
    note("xacro package", request("POST", "/robots/package", body, {"content-type": media}))
    for page in ("/viewer", "/viewer/panda", "/docs", "/redoc", "/openapi.json", "/metrics"):
        note(f"GET {page}", request("GET", page))
    return out


# ---------------------------------------------------------------------------- analysis
def module_name(path: Path, roots: list[Path]) -> str | None:
    """The top-level module that ``path`` (a .py or extension file) belongs to, if any."""
    for root in roots:
        try:
            rel = path.relative_to(root)
        except ValueError:
            continue
        if "__pycache__" in rel.parts or rel.parts[0].endswith((".dist-info", ".egg-info")):
            return None
        if len(rel.parts) == 1 and not rel.name.endswith((".py", ".so")):
            return None
        return rel.parts[0].split(".")[0]
    return None


def bytecode_share(modules: set[str], roots: list[Path]) -> str:
    """How much of site-packages' bytecode (``.pyc``) belongs to modules never imported
    (information: the image keeps every module's, so that none compiles at start-up)."""
    total = unused = 0
    for pyc in SITE.rglob("*.pyc"):
        root = next((r for r in roots if r in pyc.parents), None)
        if root is None or pyc.parent.name != "__pycache__":
            continue
        parts = list(pyc.parent.parent.relative_to(root).parts)
        stem = pyc.name.split(".")[0]
        name = ".".join(parts if stem == "__init__" else [*parts, stem])
        size = pyc.stat().st_size
        total += size
        unused += size * (name not in modules)
    return (
        f"bytecode: {total / 1e6:.1f} MB of .pyc, {unused / 1e6:.1f} MB of it for modules "
        "never imported"
    )


def import_roots() -> list[Path]:
    """The import roots inside site-packages (it, and cmeel.prefix's from its .pth), deepest
    first: pinocchio lives in cmeel.prefix/lib/python3.11/site-packages."""
    site = SITE.resolve()
    paths = {Path(p).resolve() for p in sys.path if p and Path(p).is_dir()}
    return sorted((r for r in paths if r == site or site in r.parents), key=lambda r: -len(r.parts))


def mapped_libraries() -> set[Path]:
    """Files mapped by any live process (its shared libraries)."""
    out = set()
    for maps in glob.glob("/proc/[0-9]*/maps"):
        try:
            lines = Path(maps).read_text().splitlines()
        except OSError:
            continue
        for line in lines:
            parts = line.split(None, 5)
            if len(parts) == 6 and parts[5].startswith("/"):
                out.add(Path(parts[5].strip()))
    return out


class Collector(threading.Thread):
    """Receives the module names the hook sends, from every process, until stopped."""

    def __init__(self) -> None:
        super().__init__(daemon=True)
        SOCKET.unlink(missing_ok=True)
        self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_DGRAM)
        self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4 << 20)
        self.sock.bind(str(SOCKET))
        self.names: set[str] = set()
        self.modules: set[str] = set()
        self.messages = 0

    def run(self) -> None:
        while True:
            data = self.sock.recv(4096)
            if data == b"\0stop":
                return
            self.messages += 1
            self.modules.add(data.decode(errors="replace"))
            self.names.add(data.decode(errors="replace").split(".")[0])

    def stop(self) -> set[str]:
        with socket.socket(socket.AF_UNIX, socket.SOCK_DGRAM) as s:
            s.sendto(b"\0stop", str(SOCKET))
        self.join(timeout=30)
        return self.names


def read_allowlist(path: Path) -> dict[str, str]:
    """{distribution: reason} of ``name  # reason`` lines (blank lines and comments skipped)."""
    out = {}
    for line in path.read_text().splitlines():
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        name, _, reason = line.partition("#")
        if not reason.strip():
            raise SystemExit(f"image_imports: {path.name}: no reason given for {name.strip()!r}")
        out[canonical(name.strip())] = reason.strip()
    return out


def canonical(name: str) -> str:
    return re.sub(r"[-_.]+", "-", name).lower()


def analyse(allow: dict[str, str], imported: set[str], mapped: set[Path]) -> list[str]:
    """Prints the distributions by size, used or not and why; the names that fail."""
    roots = import_roots()
    mapped = {p.resolve() for p in mapped if p.exists()}
    owned: set[str] = set()
    bad, kept_mb = [], 0.0
    installed = set()
    rows = []
    for dist in md.distributions(path=[str(SITE)]):
        name = canonical(dist.metadata["Name"])
        installed.add(name)
        modules, libs, size = set(), set(), 0
        for f in dist.files or []:
            path = Path(dist.locate_file(f))
            owned.add(f.parts[0])
            if not path.exists() or path.is_symlink():
                continue
            size += path.stat().st_size
            real = path.resolve()
            mod = module_name(real, roots)
            if mod and (real.suffix == ".py" or ".so" in real.name):
                modules.add(mod)
            if ".so" in real.name and real in mapped:
                libs.add(real.name)
        used = sorted(modules & imported)
        mb = size / 1e6
        if used or libs:
            why = "imports " + ", ".join(used) if used else ""
            if libs:
                why += (
                    "; " if why else ""
                ) + f"maps {len(libs)} librar{'y' if len(libs) == 1 else 'ies'}"
            rows.append((name, mb, "used", why))
            if name in allow:
                rows[-1] = (name, mb, "used", why + f" (listed as kept: {allow[name]})")
        elif name in allow:
            rows.append((name, mb, "kept", allow[name]))
            kept_mb += mb
        else:
            rows.append((name, mb, "NEVER IMPORTED", f"top-level modules {sorted(modules)}"))
            bad.append(name)
    unowned = sorted(
        e.name
        for e in SITE.iterdir()
        if e.name not in owned
        and e.name != "__pycache__"
        and not e.name.startswith("_import_probe")
    )
    for entry in unowned:
        if canonical(entry) in allow:
            rows.append((entry, 0.0, "kept", allow[canonical(entry)]))
        else:
            rows.append((entry, 0.0, "NOT OWNED", "no installed distribution lists it"))
            bad.append(entry)
    missing = sorted(set(allow) - installed - {canonical(e) for e in unowned})
    for name in missing:
        rows.append((name, 0.0, "LISTED, NOT INSTALLED", allow[name]))
        bad.append(name)
    for name, mb, status, why in sorted(rows, key=lambda r: (r[2] == "used", -r[1])):
        print(f"image_imports: {mb:7.1f} MB  {name:28s} {status}: {why}")
    total = sum(r[1] for r in rows)
    print(
        f"image_imports: {len(rows)} distributions, {total:.0f} MB; kept unimported "
        f"{kept_mb:.1f} MB; never imported and unlisted: {', '.join(bad) or 'none'}"
    )
    return bad


def main() -> int:
    allow = read_allowlist(Path(sys.argv[1]))
    collector = Collector()
    collector.start()
    (SITE / "_import_probe_hook.py").write_text(HOOK.format(socket=SOCKET))
    (SITE / "_import_probe.pth").write_text("import _import_probe_hook\n")
    data = Path(tempfile.mkdtemp(prefix="probe-data-"))
    env = {**os.environ, "DENAVIT_DATA_DIR": str(data), "DENAVIT_PORT": str(PORT),
           "DENAVIT_HOST": "127.0.0.1"}  # fmt: skip
    log = open(data.parent / "probe-server.log", "wb")
    server = subprocess.Popen([sys.executable, "-m", "app"], env=env, stdout=log, stderr=log)
    try:
        for _ in range(600):
            try:
                if request("GET", "/ready", timeout=2)[0] == 200:
                    break
            except OSError:
                pass
            if server.poll() is not None:
                raise SystemExit("image_imports: the server exited: " + log.name)
            time.sleep(0.2)
        examples = replay_examples()
        extra = extras()
        results = examples + extra
        # The examples answer what they recorded (errors included); each extra must succeed.
        failed = [(what, status) for what, status in examples if status >= 500 or status <= 0]
        failed += [(what, status) for what, status in extra if not 200 <= status < 300]
        for what, status in extra:
            print(f"image_imports: request {status} {what}")
        print(f"image_imports: {len(results)} requests, statuses "
              f"{sorted({s for _, s in results})}; failed: {failed or 'none'}")  # fmt: skip
        mapped = mapped_libraries()
    finally:
        server.send_signal(signal.SIGTERM)
        try:
            server.wait(timeout=30)
        except subprocess.TimeoutExpired:
            server.kill()
        os.unlink(SITE / "_import_probe.pth")
    imported = collector.stop()
    print(f"image_imports: {len(imported)} top-level module names looked up "
          f"({collector.messages} lookups, every process of the service)")  # fmt: skip
    print("image_imports: " + bytecode_share(collector.modules, import_roots()))
    bad = analyse(allow, imported, mapped)
    verdict = "ok" if not (bad or failed) else "FAIL"
    print(f"image_imports: verdict {verdict}: never imported and unlisted: "
          f"{', '.join(bad) or 'none'}; failed requests: {len(failed)}")  # fmt: skip
    return 0 if verdict == "ok" else 1


if __name__ == "__main__":
    sys.exit(main())
