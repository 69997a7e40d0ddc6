"""GET /viewer, /viewer/{robot_id} and the static files they load (no browser needed).

The page must load only files the service serves itself: every import of the import map
and of the viewer's modules answers 200 here, no module names an outside URL, and the
vendored libraries each carry their license and the files their manifest lists.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from app.api.static_files import STATIC_DIR
from tests.helpers import problem

VIEWER = STATIC_DIR / "viewer"


def test_viewer_page_starts_on_the_first_robot(client) -> None:
    resp = client.get("/viewer")
    assert resp.status_code == 200
    assert resp.headers["content-type"].startswith("text/html")
    assert 'data-robot-id=""' in resp.text
    assert '<script type="importmap">' in resp.text


def test_viewer_page_for_a_robot(client) -> None:
    resp = client.get("/viewer/ur5")
    assert resp.status_code == 200
    assert 'data-robot-id="ur5"' in resp.text


def test_unknown_robot_is_a_404_problem_naming_it(client) -> None:
    body = problem(client.get("/viewer/ur55"), 404, "robot_id")
    assert "ur5" in body["detail"]  # the close match is suggested


@pytest.mark.parametrize("robot_id", ["x" * 65, "%3Cscript%3Ealert(1)%3C%5Cscript%3E"])
def test_hostile_robot_ids_are_4xx_problems_never_html(client, robot_id: str) -> None:
    resp = client.get(f"/viewer/{robot_id}")
    assert 400 <= resp.status_code < 500
    # JSON, never a page: an id echoed in the problem cannot run as markup.
    assert resp.headers["content-type"].startswith("application/problem+json")
    assert resp.json()["field"] == "robot_id"


def test_viewer_routes_are_not_in_the_openapi_document(client) -> None:
    paths = client.get("/openapi.json").json()["paths"]
    assert not [p for p in paths if p.startswith(("/viewer", "/static"))]


def test_writing_to_the_viewer_is_a_405_problem(client) -> None:
    problem(client.post("/viewer/panda", json={}), 405)


def _imports(text: str) -> list[str]:
    return re.findall(r"""(?:from|import)\s*['"]([^'"]+)['"]""", text)


def test_every_module_the_page_loads_is_served(client) -> None:
    page = client.get("/viewer/panda").text
    importmap = json.loads(re.search(r'<script type="importmap">(.*?)</script>', page, re.S)[1])
    urls = set(re.findall(r'(?:src|href)="(/static/[^"]+)"', page))
    prefixes = {name: url for name, url in importmap["imports"].items() if name.endswith("/")}
    urls |= {url for name, url in importmap["imports"].items() if name not in prefixes}
    for module in VIEWER.glob("*.js"):
        for spec in _imports(module.read_text()):
            if spec.startswith("./"):
                urls.add(f"/static/viewer/{spec[2:]}")
            elif spec in importmap["imports"]:
                continue
            else:
                prefix = next(p for p in prefixes if spec.startswith(p))  # else: unmapped
                urls.add(prefixes[prefix] + spec[len(prefix) :])
    assert len(urls) > 10
    for url in sorted(urls):
        resp = client.get(url)
        assert resp.status_code == 200, url
        kind = "text/javascript" if url.endswith(".js") else "text/css"
        assert resp.headers["content-type"].startswith(kind), url


def test_viewer_names_no_outside_url() -> None:
    for path in VIEWER.iterdir():
        text = path.read_text()
        assert not re.search(r"https?://", text), f"{path.name} names an outside URL"


def test_static_files_refuse_traversal_and_unknown_files(client) -> None:
    assert client.get("/static/viewer/nope.js").status_code == 404
    for url in ["/static/../main.py", "/static/%2e%2e/main.py", "/static/viewer/..%2f..%2fmain.py"]:
        resp = client.get(url)
        assert resp.status_code == 404, url
        assert "create_app" not in resp.text


def test_vendored_libraries_carry_licenses_and_their_manifest_files() -> None:
    manifest = json.loads((STATIC_DIR / "vendor" / "manifest.json").read_text())
    names = {entry["name"] for entry in manifest["packages"]}
    assert names == {"three", "urdf-loader", "swagger-ui-dist", "redoc"}
    for entry in manifest["packages"]:
        assert re.fullmatch(r"\d+\.\d+\.\d+", entry["version"]), entry  # pinned
        assert entry["integrity"].startswith("sha512-")
        folder = STATIC_DIR / "vendor" / entry["name"]
        assert "LICENSE" in entry["files"]
        for rel in entry["files"]:
            assert (folder / rel).is_file(), (entry["name"], rel)
        listed = {Path(rel) for rel in entry["files"]}
        present = {p.relative_to(folder) for p in folder.rglob("*") if p.is_file()}
        assert present == listed, entry["name"]  # nothing unlisted was vendored
