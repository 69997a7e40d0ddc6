#!/usr/bin/env bash
# compose-check.sh: start compose.yaml with podman-compose (pinned in requirements-dev.lock)
# on the image `make container-check` built, check it, take it down. Root on Debian, after
# container-check (it reuses that script's podman settings: runc, rlimits; see its header).
#
#   make container-check && make compose-check
#
# Checks: the file parses and the "metrics" profile stays off by default; /health; the
# token comes from the env file (a write is 401 without it, 201 with it); the write lands
# in the named volume; the compose healthcheck runs healthy; /metrics serves what the
# Prometheus example scrapes; `down` stops the service gracefully (exit code 0).
# Prints one line and exits 0 only when all pass.
set -uo pipefail
cd "$(dirname "$0")/.."

WORK=${WORK:-${TMPDIR:-/tmp}/compose-check}
export CONTAINERS_CONF=${CONTAINERS_CONF:-${TMPDIR:-/tmp}/container-check/containers.conf}
PROJECT=denavit-compose-check-$$
PORT=${PORT:-18334}
URL=http://127.0.0.1:$PORT
LOG=$WORK/podman-compose.log
mkdir -p "$WORK"
: >"$LOG"

PASSED=0; FAILED=0; FAILS=()
check() {  # check NAME OK(0/1) DETAIL
    if [ "$2" = 0 ]; then PASSED=$((PASSED + 1)); echo "   PASS $1: $3"
    else FAILED=$((FAILED + 1)); FAILS+=("$1"); echo "   FAIL $1: $3"; fi
}
finish() {
    local verdict=PASS
    { [ "$FAILED" -gt 0 ] || [ "$PASSED" -eq 0 ]; } && verdict=FAIL
    echo "compose-check: $verdict $PASSED/$((PASSED + FAILED)) checks${FAILS[*]:+; failed: ${FAILS[*]}}${1:+; $1}"
    [ "$verdict" = PASS ]
}
die() { FAILED=$((FAILED + 1)); FAILS+=("$1"); finish "$2"; exit 1; }

[ -f "$CONTAINERS_CONF" ] || die setup "no $CONTAINERS_CONF: run make container-check first"
command -v podman-compose >/dev/null || die setup "podman-compose is not on PATH (make install)"
podman image exists denavit || die setup "no image denavit: run make container-check first"

TOKEN=$(od -An -tx1 -N16 /dev/urandom | tr -d ' \n')
printf 'DENAVIT_API_TOKEN=%s\nDENAVIT_LOG_LEVEL=info\n' "$TOKEN" >"$WORK/denavit.env"
export DENAVIT_ENV_FILE=$WORK/denavit.env DENAVIT_PUBLISH_PORT=$PORT
compose() { podman-compose --project-name "$PROJECT" -f compose.yaml "$@"; }
cleanup() { compose --profile metrics down -v -t 15 >>"$LOG" 2>&1 || true; }
trap cleanup EXIT
http() {  # http BODY_FILE METHOD PATH [curl args...]: the status code (000: no answer)
    local out=$1 method=$2 path=$3; shift 3
    curl -s -m 30 -o "$out" -w '%{http_code}' -X "$method" "$URL$path" "$@" 2>/dev/null || true
}

compose config >"$WORK/config.yaml" 2>>"$LOG"; rc=$?
services=$(awk '/^services:/ { s = 1; next } s && /^[^ ]/ { s = 0 } s && /^  [a-z]/ { sub(":", ""); print $1 }' \
    "$WORK/config.yaml" | sort | tr '\n' ' ')
check config "$([ $rc = 0 ] && [ "$services" = "denavit " ]; echo $?)" \
    "podman-compose config -> rc $rc; services without a profile: ${services:-none}"

compose up -d >>"$LOG" 2>&1 || die up "podman-compose up failed: $(tail -2 "$LOG" | tr '\n' ' ')"
container=$(podman ps -q --filter "label=io.podman.compose.project=$PROJECT" \
    --filter "label=com.docker.compose.service=denavit" | head -1)
[ -n "$container" ] || die up "no denavit container in project $PROJECT"
for ((i = 0; i < 240; i++)); do
    [ "$(http /dev/null GET /health)" = 200 ] && break
    sleep 0.5
done
code=$(http "$WORK/body" GET /health)
check health "$([ "$code" = 200 ]; echo $?)" "GET /health -> $code"

DH='{"name": "compose_probe", "convention": "standard", "units": {"length": "m", "angle": "deg"},
  "joints": [{"name": "j1", "type": "revolute", "a": 0.5, "alpha": 0, "d": 0, "theta": 0,
              "lower": -180, "upper": 180}]}'
anon=$(http "$WORK/body" POST /robots/dh -H 'content-type: application/json' -d "$DH")
authed=$(http "$WORK/body" POST /robots/dh -H 'content-type: application/json' \
    -H "authorization: Bearer $TOKEN" -d "$DH")
check token_from_env_file "$([ "$anon" = 401 ] && [ "$authed" = 201 ]; echo $?)" \
    "POST /robots/dh without the token -> $anon, with the env file's token -> $authed"

volume=$(podman inspect -f '{{range .Mounts}}{{if eq .Destination "/data"}}{{.Name}}{{end}}{{end}}' \
    "$container" 2>>"$LOG")
files=$(podman exec "$container" find /data -path '*compose_probe*' -type f 2>>"$LOG" | wc -l)
check named_volume "$([ "$volume" = "${PROJECT}_denavit-data" ] && [ "$files" -gt 0 ]; echo $?)" \
    "/data is volume ${volume:-none}, $files file(s) of the new robot in it"

hc_out=$(podman healthcheck run "$container" 2>&1); hc_rc=$?
hc_test=$(podman inspect -f '{{json .Config.Healthcheck.Test}}' "$container" 2>>"$LOG")
check healthcheck "$([ $hc_rc = 0 ]; echo $?)" "podman healthcheck run -> rc $hc_rc ${hc_out}; test $hc_test"

code=$(http "$WORK/metrics" GET /metrics)
check metrics "$([ "$code" = 200 ] && grep -q '^denavit_http_requests_total' "$WORK/metrics"; echo $?)" \
    "GET /metrics (the Prometheus example's target) -> $code"

compose stop -t 15 >>"$LOG" 2>&1
exit_code=$(podman inspect -f '{{.State.ExitCode}}' "$container" 2>/dev/null)
compose down -t 15 >>"$LOG" 2>&1
left=$(podman volume ls -q --filter "name=${PROJECT}_denavit-data" | wc -l)
check stop_and_down "$([ "$exit_code" = 0 ] && [ "$left" = 1 ]; echo $?)" \
    "podman-compose stop -> exit code ${exit_code:-?}; down keeps the volume: $left"

finish
