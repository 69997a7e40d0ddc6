"""API quality gate: schemathesis fuzzes every operation of the app's own OpenAPI schema,
in-process (ASGI), and checks that no response is a 5xx, that every response's status
code, media type, headers and body conform to the schema, that schema-invalid requests are
refused and schema-valid ones are not refused as malformed, and that methods the schema
does not list answer 405 with a truthful ``Allow``.

Bounded: 80 examples per operation, derandomised (the same examples on every run), an app
whose IK budget cap is 50 ms and largest batch 32 items; ``robot_id`` is ``planar2``.
Excluded, as long-running: ``build_reachability_map`` (POST /robots/{robot_id}/reachability
starts a background job that samples the joint space for seconds to minutes); its job and
map routes are fuzzed. And ``get_robot_stream``, the WebSocket's plain-HTTP face: every
plain request is answered 426 by design (tests/test_openapi_statuses.py checks it).

Reads and computations are fuzzed on an app without a token. The write operations (those
the schema marks with the bearer ``security`` requirement) are fuzzed on an app with
``DENAVIT_API_TOKEN`` set, schemathesis sending the token: without one the service is open
by design, so it would ignore the declared requirement. There ``ignored_auth`` replays
requests without the token and with a wrong one, which must not succeed.

A stateful test follows the links schemathesis infers (create a scene or robot, then read,
use and delete it) and adds the checks that need such sequences: ``use_after_free`` (a
deleted resource answers 404) and ``ensure_resource_availability`` (a created one is
there).
"""

from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Any

import schemathesis
from fastapi.testclient import TestClient
from hypothesis import HealthCheck, settings
from schemathesis.checks import (
    CHECKS,
    allow_header_conformance,
    content_type_conformance,
    ensure_resource_availability,
    ignored_auth,
    max_response_time,
    missing_required_header,
    negative_data_rejection,
    not_a_server_error,
    object_level_authorization,
    positive_data_acceptance,
    response_headers_conformance,
    response_schema_conformance,
    status_code_conformance,
    unsupported_method,
    use_after_free,
)
from schemathesis.config import SchemathesisConfig

from app.main import create_app
from app.middleware.openapi import BEARER, guarded_operations
from app.operations.settings import Settings

EXCLUDED = ("build_reachability_map", "get_robot_stream")
TOKEN = "fuzz-token-0123456789"
MAX_EXAMPLES = 80

CHECKS_USED = [
    not_a_server_error,
    status_code_conformance,
    content_type_conformance,
    response_headers_conformance,
    response_schema_conformance,
    # Requests the schema forbids (wrong types, missing fields, out-of-range numbers) get 4xx.
    negative_data_rejection,
    # Requests the schema allows are not refused as malformed (400, 413, 415...). 422 is
    # expected too: the schema cannot state that `q` has one value per joint of this robot,
    # that a frame exists, or that exactly one of `wrench`/`torques` is given.
    positive_data_acceptance,
    # Methods the schema does not list: 405 with an Allow header naming the listed ones.
    unsupported_method,
    allow_header_conformance,
    # Authorization is the only required header (guarded app): its absence must be a 401.
    missing_required_header,
    # Guarded operations refuse requests without a valid token.
    ignored_auth,
]
#: Checks not run, and why.
CHECKS_NOT_USED = {
    # Wall-clock limits fail on a busy CI machine (project rule: no wall-clock budgets);
    # latency is measured by `make bench` instead.
    max_response_time: "wall-clock budget",
    # Needs two principals (user A's resource read with user B's credentials): the service
    # has one shared token and no per-user resources.
    object_level_authorization: "single principal",
}

#: Checks that compare a response with an earlier one of the same sequence (a DELETE then a
#: GET of the same resource; a POST that created it then a GET): run by the stateful test.
STATEFUL_CHECKS = [use_after_free, ensure_resource_availability]

POSITIVE_STATUSES = ["2xx", "401", "403", "404", "409", "422"]


def _config(**extra: Any) -> SchemathesisConfig:
    """Deterministic generation; every ``robot_id`` is the built-in 2-DoF DH arm ``planar2``,
    so generated bodies reach the kinematics (a random id only ever gets a 404), and a
    two-value ``q`` is short enough for the generator to hit often."""
    return SchemathesisConfig.from_dict(
        {
            "generation": {"deterministic": True, **extra.pop("generation", {})},
            "checks": {"positive_data_acceptance": {"expected-statuses": POSITIVE_STATUSES}},
            "parameters": {"robot_id": "planar2"},
            **extra,
        }
    )


def _app(**settings_: object):
    data = Path(tempfile.mkdtemp(prefix="denavit-fuzz-")) / "data"
    return create_app(
        Settings(data_dir=data, ik_max_timeout_ms=50, max_batch=32, access_log=False, **settings_)
    )


APP = _app()
GUARDED_APP = _app(api_token=TOKEN)

GUARDED = sorted(guarded_operations(APP))

schema = schemathesis.openapi.from_asgi("/openapi.json", APP, config=_config()).exclude(
    operation_id=[*EXCLUDED, *GUARDED]
)
guarded_schema = schemathesis.openapi.from_asgi(
    "/openapi.json",
    GUARDED_APP,
    config=_config(auth={"openapi": {BEARER: {"bearer": TOKEN}}}),
).include(operation_id=[op for op in GUARDED if op not in EXCLUDED])

#: Stateful: sequences along the links schemathesis infers from the schema (POST /scenes →
#: GET/DELETE /scenes/{name}, POST /robots/dh → GET/DELETE /robots/{robot_id} and the
#: computations on the new robot...), valid data only (invalid data is the job of the
#: per-operation tests), on the guarded app.
STATEFUL_APP = _app(api_token=TOKEN)
stateful_schema = schemathesis.openapi.from_asgi(
    "/openapi.json",
    STATEFUL_APP,
    config=_config(auth={"openapi": {BEARER: {"bearer": TOKEN}}}, generation={"mode": "positive"}),
).exclude(operation_id=list(EXCLUDED))

FUZZ = settings(
    max_examples=MAX_EXAMPLES,
    deadline=None,
    derandomize=True,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)


@schema.parametrize()
@FUZZ
def test_api_conforms_to_its_schema(case) -> None:
    case.call_and_validate(checks=CHECKS_USED)


@guarded_schema.parametrize()
@FUZZ
def test_write_operations_conform_to_their_schema_with_a_token(case) -> None:
    case.call_and_validate(checks=CHECKS_USED)


class Workflows(stateful_schema.as_state_machine()):  # type: ignore[misc]
    """Each example starts from the same state: what one created is deleted after it (else
    a later example's POST answers 409 and hypothesis sees a different sequence on replay)."""

    def teardown(self) -> None:
        client = TestClient(STATEFUL_APP)
        auth = {"Authorization": f"Bearer {TOKEN}"}
        for robot in client.get("/robots").json()["robots"]:
            if robot["source"] != "example-robot-data":
                client.delete(f"/robots/{robot['id']}", headers=auth)  # 403: built in
        for scene in client.get("/scenes").json()["scenes"]:
            assert client.delete(f"/scenes/{scene['name']}", headers=auth).status_code == 204
        super().teardown()

    def validate_response(self, response, case, additional_checks=None, **kwargs) -> None:
        case.validate_response(
            response,
            checks=[*CHECKS_USED, *STATEFUL_CHECKS],
            transport_kwargs=kwargs or None,
            recorder=self.recorder,
        )


def test_stateful_workflows_conform_to_the_schema() -> None:
    Workflows.run(settings=settings(FUZZ, max_examples=30, stateful_step_count=6))


def test_exclusions_name_real_operations() -> None:
    assert GUARDED
    ops = {
        op.get("operationId")
        for item in APP.openapi()["paths"].values()
        for op in item.values()
        if isinstance(op, dict)
    }
    assert set(EXCLUDED) <= ops


def test_every_schemathesis_check_is_used_or_explained() -> None:
    """A check added by a schemathesis upgrade is noticed, not silently left out."""
    available = {check.__name__ for check in CHECKS.get_all()}
    used = {check.__name__ for check in [*CHECKS_USED, *STATEFUL_CHECKS]}
    explained = {check.__name__ for check in CHECKS_NOT_USED}
    assert not used & explained
    assert available <= used | explained, available - (used | explained)
