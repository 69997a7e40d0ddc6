#!/usr/bin/env bash
# container-startup.sh: how fast a fresh container of the image serves (docs/deployment.md).
# Root with podman, after `make container-check` (its podman settings and its image).
#
#   bash bench/container-startup.sh [RUNS]
#
# Per run, a new container (new anonymous /data, no state): milliseconds from `podman run`
# to the first 200 of GET /health, then the first IK request sent the moment /health
# answered (Panda, full pose, the kernels from the image's Numba cache and the robot not
# yet loaded in the worker that answers), then a second IK request. Prints one line per run
# and the median and worst of each column.
set -uo pipefail
RUNS=${1:-5}
IMAGE=${IMAGE:-denavit}
PORT=${PORT:-18335}
export CONTAINERS_CONF=${CONTAINERS_CONF:-${TMPDIR:-/tmp}/container-check/containers.conf}
URL=http://127.0.0.1:$PORT
NAME=denavit-startup-$$
IK='{"target": {"position": [0.4, 0.1, 0.5], "orientation": [1, 0, 0, 0]}, "timeout_ms": 50}'
now_ms() { echo $(( ${EPOCHREALTIME/./} / 1000 )); }
trap 'podman rm -f -t 0 "$NAME" >/dev/null 2>&1' EXIT

printf '%-4s %10s %14s %14s %s\n' run health_ms first_ik_ms second_ik_ms "first IK status"
rows=()
for ((r = 1; r <= RUNS; r++)); do
    podman rm -f -t 0 "$NAME" >/dev/null 2>&1
    t0=$(now_ms)
    podman run -d --name "$NAME" -p "127.0.0.1:$PORT:8000" "$IMAGE" >/dev/null 2>&1 \
        || { echo "podman run failed"; exit 1; }
    until [ "$(curl -s -m 2 -o /dev/null -w '%{http_code}' "$URL/health")" = 200 ]; do
        sleep 0.02
    done
    t1=$(now_ms)
    code=$(curl -s -m 60 -o /dev/null -w '%{http_code}' -X POST "$URL/robots/panda/ik" \
        -H 'content-type: application/json' -d "$IK")
    t2=$(now_ms)
    curl -s -m 60 -o /dev/null -X POST "$URL/robots/panda/ik" -H 'content-type: application/json' -d "$IK"
    t3=$(now_ms)
    printf '%-4s %10d %14d %14d %s\n' "$r" $((t1 - t0)) $((t2 - t1)) $((t3 - t2)) "$code"
    rows+=("$((t1 - t0)) $((t2 - t1)) $((t3 - t2))")
done
printf '%s\n' "${rows[@]}" | awk '
    { for (c = 1; c <= 3; c++) v[c, NR] = $c }
    END {
        n = NR
        for (c = 1; c <= 3; c++) {
            for (i = 1; i <= n; i++) a[i] = v[c, i]
            for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
            med[c] = (n % 2) ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2; max[c] = a[n]
        }
        printf "median %10d %14d %14d\nworst  %10d %14d %14d\n", med[1], med[2], med[3], max[1], max[2], max[3]
    }'
