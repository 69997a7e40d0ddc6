"""Files a client uploaded never run as pages of the service's origin (stored XSS).

A package may hold any file: an XHTML ``.xml``, an SVG, an HTML page, a COLLADA ``.dae``
or a ``.urdf``/``.xacro``/``.srdf`` whose root holds an XHTML ``<script>``; an uploaded
URDF (POST /robots/urdf) may hold one too. Served from the service's origin and rendered,
such a script reads what the viewer's origin keeps and sends it anywhere. Each script
here, if it ran, would leave a trace in the origin: a request to ``/stolen/<name>`` (in
the browser and in the server's access log), keys in ``localStorage`` and
``sessionStorage``, the document's title, a message to its opener or parent.

Each file is opened every way a browser may render it: a tab navigated to it, an
``<iframe>``, an ``<object>`` and a ``window.open`` popup of the viewer's page. None of
them may leave a trace. The viewer itself still draws the package's mesh, byte for byte
the uploaded file.
"""

from __future__ import annotations

import hashlib
from collections.abc import Iterator

import httpx
import pytest
from playwright.sync_api import Error as PlaywrightError

from tests.browser.tools import WAIT_MS, Tab, wait_idle
from tests.helpers import Server
from tests.packages import zip_bytes

ROBOT = "scripted"


def payload(name: str) -> str:
    """JavaScript that leaves every trace it can in the origin it runs in, tagged ``name``."""
    return (
        f"(function () {{ var n = 'stolen-{name}';"
        " try { fetch('/stolen/' + n.slice(7)); } catch (e) {}"
        " try { localStorage.setItem(n, '1'); } catch (e) {}"
        " try { sessionStorage.setItem(n, '1'); } catch (e) {}"
        " try { document.title = n; } catch (e) {}"
        " try { (window.opener || window.parent).postMessage(n, '*'); } catch (e) {}"
        " })();"
    )


def xhtml_script(name: str) -> str:
    """An XHTML ``<script>`` element, as an XML document of any other root may hold it."""
    return (
        f'<h:script xmlns:h="http://www.w3.org/1999/xhtml"><![CDATA[{payload(name)}]]></h:script>'
    )


TETRA_OBJ = b"""o tetra
v 0 0 0
v 0.1 0 0
v 0 0.1 0
v 0 0 0.1
f 1 3 2
f 1 2 4
f 1 4 3
f 2 3 4
"""

ARM_URDF = b"""<?xml version="1.0"?>
<robot name="scripted">
  <link name="base"/>
  <link name="arm">
    <visual><geometry><mesh filename="../meshes/tetra.obj"/></geometry></visual>
  </link>
  <joint name="j1" type="revolute">
    <parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1.5" upper="1.5" effort="1" velocity="1"/>
  </joint>
</robot>
"""

#: The scripted files of the package: path → (trace name, content).
SCRIPTED = {
    "evil/page.xml": (
        "xml",
        f'<html xmlns="http://www.w3.org/1999/xhtml"><head><title>t</title></head><body>'
        f"<script><![CDATA[{payload('xml')}]]></script></body></html>",
    ),
    "evil/page.xhtml": (
        "xhtml",
        f'<html xmlns="http://www.w3.org/1999/xhtml"><body>'
        f"<script><![CDATA[{payload('xhtml')}]]></script></body></html>",
    ),
    "evil/picture.svg": (
        "svg",
        f'<svg xmlns="http://www.w3.org/2000/svg"><script><![CDATA[{payload("svg")}]]>'
        "</script></svg>",
    ),
    "evil/page.html": (
        "html",
        f"<!doctype html><title>t</title><script>{payload('html')}</script>",
    ),
    "evil/mesh.dae": (
        "dae",
        f'<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">'
        f"{xhtml_script('dae')}</COLLADA>",
    ),
    "evil/robot.urdf": ("urdf", f'<robot name="x">{xhtml_script("urdf")}<link name="a"/></robot>'),
    "evil/robot.xacro": ("xacro", f'<robot name="x">{xhtml_script("xacro")}</robot>'),
    "evil/robot.srdf": ("srdf", f'<robot name="x">{xhtml_script("srdf")}</robot>'),
}
FILES: dict[str, bytes] = {
    "package.xml": b'<package format="3"><name>scripted</name><version>1.0.0</version></package>',
    "urdf/arm.urdf": ARM_URDF,
    "meshes/tetra.obj": TETRA_OBJ,
    **{path: text.encode() for path, (_, text) in SCRIPTED.items()},
}
#: An uploaded URDF (POST /robots/urdf) with a script of its own, served by GET .../urdf.
URDF_ROBOT = "scripted_urdf"
SCRIPTED_URDF = (
    '<?xml version="1.0"?><robot name="u"><link name="base"/>'
    f"{xhtml_script('uploaded')}"
    '<link name="arm"/><joint name="j1" type="revolute"><parent link="base"/>'
    '<child link="arm"/><axis xyz="0 0 1"/>'
    '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>'
)

#: Every URL a script hides in: the package's files and the uploaded URDF.
URLS = [f"/robots/{ROBOT}/files/{path}" for path in SCRIPTED] + [f"/robots/{URDF_ROBOT}/urdf"]
NAMES = [name for name, _ in SCRIPTED.values()] + ["uploaded"]


@pytest.fixture(scope="module")
def uploaded(live: Server) -> Iterator[Server]:
    """The live server with the scripted package and the scripted URDF robot."""
    with httpx.Client(base_url=live.url, timeout=60) as http:
        resp = http.post(
            "/robots/package",
            data={"name": ROBOT, "description": "urdf/arm.urdf"},
            files={"archive": ("p.zip", zip_bytes(FILES))},
        )
        assert resp.status_code == 201, resp.text
        resp = http.post("/robots/urdf", json={"name": URDF_ROBOT, "urdf": SCRIPTED_URDF})
        assert resp.status_code == 201, resp.text
    yield live


class Opened:
    """What became of each URL the browser was asked to open: a download or a document."""

    def __init__(self, tab: Tab, live: Server) -> None:
        self.tab, self.live = tab, live
        self.log_start = len(live.log_lines())  # the server's log lines of this test follow
        self.downloads: list[str] = []
        self.requests: list[str] = []
        context = tab.page.context
        context.on("request", lambda r: self.requests.append(r.url))
        tab.page.on("download", lambda d: self.downloads.append(d.url))
        context.on("page", lambda p: p.on("download", lambda d: self.downloads.append(d.url)))

    def settle(self, url: str, pages: list) -> str:
        """Wait until ``url`` is downloaded or shown (loaded) in a frame of ``pages``.

        A shown document must not have run its script: read its storage and title
        (an opaque origin, as a CSP sandbox gives it, has no storage: that is fine).
        """
        page = self.tab.page
        for _ in range(WAIT_MS // 20):
            if url in self.downloads:
                return "download"
            frames = [f for p in pages if not p.is_closed() for f in p.frames if f.url == url]
            if frames:
                frames[0].wait_for_load_state("load")
                seen = frames[0].evaluate(
                    """() => { try {
                         return [document.title, Object.keys(localStorage),
                                 Object.keys(sessionStorage)].flat().join(' ');
                       } catch (e) { return 'opaque: ' + e.name; } }"""
                )
                assert "stolen" not in seen, f"{url}: its script ran ({seen})"
                return f"document ({seen})"
            page.wait_for_timeout(20)
        raise AssertionError(f"{url} was neither downloaded nor shown")


def open_viewer_page(tab: Tab, live: Server) -> Opened:
    """The viewer on the scripted robot (the origin has a page and storage), recording."""
    opened = Opened(tab, live)
    tab.goto(f"/viewer/{ROBOT}")
    wait_idle(tab)
    tab.page.evaluate(
        "window.__messages = []; addEventListener('message', (e) => __messages.push(e.data))"
    )
    return opened


def assert_no_trace(tab: Tab, opened: Opened) -> None:
    page = tab.page
    seen = page.evaluate(
        "[document.title, Object.keys(localStorage), Object.keys(sessionStorage), "
        "__messages, document.cookie].flat().join(' ')"
    )
    assert "stolen" not in seen, seen
    assert not [u for u in opened.requests if "/stolen/" in u]
    logged = opened.live.log_lines()[opened.log_start :]
    assert not [line for line in logged if "/stolen/" in str(line.get("path"))]


def strip_header(tab: Tab, name: str) -> None:
    """Drop header ``name`` from every answer of the robots' routes the tab's pages get."""

    def without(route) -> None:
        response = route.fetch()
        headers = {k: v for k, v in response.headers.items() if k.lower() != name}
        route.fulfill(response=response, headers=headers)

    tab.page.route("**/robots/**", without)  # after the Tab's own route: it comes first
    tab.page.context.route("**/robots/**", without)  # new tabs and popups


def open_every_file(tab: Tab, opened: Opened, how: str) -> dict[str, str]:
    """Open each scripted URL ``how``; what became of each (see :meth:`Opened.settle`)."""
    outcomes = {}
    for path in URLS:
        url = tab.url + path
        if how == "tab":
            other = tab.page.context.new_page()
            try:
                other.goto(url, wait_until="load")
            except PlaywrightError as exc:
                if "Download is starting" not in str(exc):
                    raise
                opened.downloads.append(url)
            outcomes[path] = opened.settle(url, [other])
            other.close()
        elif how == "popup":
            with tab.page.context.expect_page() as info:
                tab.page.evaluate("(u) => { window.open(u); }", path)
            outcomes[path] = opened.settle(url, [info.value])
        else:
            attribute = "data" if how == "object" else "src"
            tab.page.evaluate(
                """([tag, attribute, u]) => { const e = document.createElement(tag);
                     e[attribute] = u; document.body.append(e); }""",
                [how, attribute, path],
            )
            outcomes[path] = opened.settle(url, [tab.page])
    return outcomes


@pytest.mark.parametrize("how", ["tab", "iframe", "object", "popup"])
def test_scripts_in_uploaded_files_never_run(page: Tab, uploaded: Server, how: str) -> None:
    opened = open_viewer_page(page, uploaded)
    outcomes = open_every_file(page, opened, how)
    # Saved, never shown: no document of the service's origin holds what a client sent.
    assert set(outcomes.values()) == {"download"}, outcomes
    # The viewer's own page, the browser's requests and the server's log hold no trace.
    assert_no_trace(page, opened)
    assert page.page_errors == [] and page.external == []


@pytest.mark.parametrize("how", ["tab", "iframe"])
@pytest.mark.parametrize("dropped", ["content-disposition", "content-security-policy"])
def test_each_header_alone_keeps_the_scripts_from_running(
    page: Tab, uploaded: Server, how: str, dropped: str
) -> None:
    """Two layers, each enough on its own: a client that loses one header is still safe.

    Without ``Content-Disposition`` (a browser or a proxy that ignores or drops it), the
    XML documents are shown, but in the opaque origin of the CSP sandbox: no storage, no
    script. Without the CSP, the attachment alone keeps every file from being shown.
    """
    strip_header(page, dropped)
    opened = open_viewer_page(page, uploaded)
    outcomes = open_every_file(page, opened, how)
    if dropped == "content-disposition":
        shown = {p: o for p, o in outcomes.items() if o != "download"}
        assert shown, "nothing was shown: the sandbox was not put to the test"
        assert set(shown.values()) == {"document (opaque: SecurityError)"}, shown
    else:
        assert set(outcomes.values()) == {"download"}, outcomes
    assert_no_trace(page, opened)


def sha256_in_page(tab: Tab, path: str) -> str:
    return tab.page.evaluate(
        """async (u) => { const b = await (await fetch(u)).arrayBuffer();
             const d = new Uint8Array(await crypto.subtle.digest('SHA-256', b));
             return Array.from(d, (x) => x.toString(16).padStart(2, '0')).join(''); }""",
        path,
    )


def test_viewer_draws_the_package_and_files_are_unchanged(page: Tab, uploaded: Server) -> None:
    headers: dict[str, dict[str, str]] = {}
    page.page.on("response", lambda r: headers.setdefault(r.url, r.headers))
    open_viewer_page(page, uploaded)
    stats = page.page.evaluate("denavit.viewer.robot.stats")
    assert (stats["meshes"], stats["loaded"], stats["failed"]) == (1, 1, 0), stats
    triangles = page.page.evaluate(
        """(() => { let n = 0; denavit.viewer.robot.root.traverse((o) => {
             if (o.isMesh) n += o.geometry.attributes.position.count / 3; }); return n; })()"""
    )
    assert triangles == 4
    # The mesh was loaded from the files route with its headers as served.
    mesh = headers[f"{page.url}/robots/{ROBOT}/files/meshes/tetra.obj"]
    assert mesh["content-type"] == "model/obj"
    # Every file, as the page fetches it and as a client gets it, is the uploaded bytes.
    for path, data in FILES.items():
        url = f"/robots/{ROBOT}/files/{path}"
        assert sha256_in_page(page, url) == hashlib.sha256(data).hexdigest(), path
        assert page.http.get(url).content == data, path
    page.shot("scripted-package")
    assert page.errors() == []
