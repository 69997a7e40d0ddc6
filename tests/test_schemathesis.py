"""API quality gate: schemathesis fuzzes every operation of the app's own OpenAPI schema,
in-process (ASGI), and checks that no response is a 5xx and that every response's status
code, media type, headers and body conform to the schema.

Bounded: 25 examples per operation, derandomised (the same examples on every run), an app
whose IK budget cap is 50 ms and largest batch 32 items. Excluded, as long-running:
``build_reachability_map`` (POST /robots/{robot_id}/reachability starts a background job
that samples the joint space for seconds to minutes); its job and map routes are fuzzed.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import schemathesis
from hypothesis import HealthCheck, settings
from schemathesis.checks import (
    content_type_conformance,
    not_a_server_error,
    response_headers_conformance,
    response_schema_conformance,
    status_code_conformance,
)

from app.main import create_app
from app.settings import Settings

EXCLUDED = ("build_reachability_map",)
CHECKS = [
    not_a_server_error,
    status_code_conformance,
    content_type_conformance,
    response_headers_conformance,
    response_schema_conformance,
]

_data = Path(tempfile.mkdtemp(prefix="denavit-fuzz-")) / "data"
APP = create_app(Settings(data_dir=_data, ik_max_timeout_ms=50, max_batch=32, access_log=False))

schema = schemathesis.openapi.from_asgi("/openapi.json", APP)
for operation_id in EXCLUDED:
    schema = schema.exclude(operation_id=operation_id)


@schema.parametrize()
@settings(
    max_examples=25,
    deadline=None,
    derandomize=True,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)
def test_api_conforms_to_its_schema(case) -> None:
    case.call_and_validate(checks=CHECKS)


def test_exclusions_name_real_operations() -> None:
    ops = {
        op.get("operationId")
        for item in APP.openapi()["paths"].values()
        for op in item.values()
        if isinstance(op, dict)
    }
    assert set(EXCLUDED) <= ops
