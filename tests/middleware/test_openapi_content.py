"""Binary answers are declared as binary strings in the served document (what client
generators read as files), and nothing else is touched."""

from __future__ import annotations

from app.middleware.openapi_content import BINARY, binary_responses


def _contents(schema: dict) -> dict[tuple[str, str, str, str], dict]:
    return {
        (path, method, status, media): content
        for path, item in schema["paths"].items()
        for method, op in item.items()
        if isinstance(op, dict)
        for status, response in op.get("responses", {}).items()
        for media, content in response.get("content", {}).items()
    }


def test_the_png_heat_map_and_package_files_are_binary(client) -> None:
    contents = _contents(client.get("/openapi.json").json())
    png = ("/robots/{robot_id}/reachability/maps/{map_id}/slice.png", "get", "200", "image/png")
    files = ("/robots/{robot_id}/files/{path}", "get", "200", "application/octet-stream")
    assert contents[png]["schema"] == BINARY
    assert contents[files]["schema"] == BINARY
    binary = [k for k, c in contents.items() if c.get("schema") == BINARY]
    partial = ("/robots/{robot_id}/files/{path}", "get", "206", "application/octet-stream")
    assert sorted(binary) == sorted([png, files, partial])
    # JSON answers keep their models; the URDF stays text.
    fk = contents[("/robots/{robot_id}/fk", "post", "200", "application/json")]
    assert fk["schema"] == {"$ref": "#/components/schemas/FKResponse"}
    urdf = contents[("/robots/{robot_id}/urdf", "get", "200", "application/xml")]
    assert urdf["schema"] == {"type": "string"}


def test_only_image_and_octet_stream_bodies_change() -> None:
    doc = {
        "paths": {
            "/a": {
                "parameters": [],
                "get": {
                    "responses": {
                        "200": {"content": {"image/jpeg": {}, "text/plain": {}}},
                        "206": {"description": "no content"},
                        "400": {"content": {"application/problem+json": {"schema": {"x": 1}}}},
                    }
                },
            }
        }
    }
    out = binary_responses(doc)
    assert out is doc
    content = doc["paths"]["/a"]["get"]["responses"]
    assert content["200"]["content"] == {"image/jpeg": {"schema": BINARY}, "text/plain": {}}
    assert content["400"]["content"]["application/problem+json"] == {"schema": {"x": 1}}
    assert content["206"] == {"description": "no content"}
