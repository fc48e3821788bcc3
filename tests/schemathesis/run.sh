#!/usr/bin/env bash
# Property-based contract test: schemathesis generates requests from api/openapi.yaml and sends
# them to a running `strata serve`, failing on any 5xx and on any answer whose status code,
# content type or body the specification does not allow.
#
# The server runs on a free loopback port with a temporary data directory and an admin token;
# a world (with an authored region, a subsurface and an uploaded image) and an export job are
# created first, so
# the hooks (hooks.py) can send path parameters that resolve. Schemathesis is installed, pinned, into a
# virtual environment under the build directory. The budget is bounded by --max-examples per
# operation (SCHEMATHESIS_MAX_EXAMPLES, default 60: a few thousand cases in all).
#
# One worker: with two, a CI run on a loaded 2-core machine once stopped in the coverage phase
# of POST /v1/worlds with schemathesis's "Inconsistent results" (a case that failed once and
# passed on its replay, its first failure not printed), which a local run of the same commit
# never showed; one worker keeps the requests in a fixed order and costs about a minute.
#
# Usage: tests/schemathesis/run.sh (after `cargo build`; STRATA_BIN picks another binary).
set -euo pipefail
cd "$(dirname "$0")/../.."

SCHEMATHESIS_VERSION=4.32.5
target="${CARGO_TARGET_DIR:-target}"
bin="${STRATA_BIN:-$target/debug/strata}"
max_examples="${SCHEMATHESIS_MAX_EXAMPLES:-60}"

if [ ! -x "$bin" ]; then
  cargo build --locked --bin strata
fi

venv="$target/schemathesis-venv"
if ! "$venv/bin/schemathesis" --version 2>/dev/null | grep -qF "$SCHEMATHESIS_VERSION"; then
  python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet --disable-pip-version-check "schemathesis==$SCHEMATHESIS_VERSION"
fi

work="$(mktemp -d)"
server_pid=""
cleanup() {
  if [ -n "$server_pid" ]; then
    kill "$server_pid" 2>/dev/null || true
    wait "$server_pid" 2>/dev/null || true
  fi
  rm -rf "$work"
}
trap cleanup EXIT

port="$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
base="http://127.0.0.1:$port"
admin="schemathesis-admin-$(python3 -c 'import secrets; print(secrets.token_hex(16))')"

"$bin" serve --addr "127.0.0.1:$port" --data "$work/data" --backend cpu --web web/dist \
  --admin-token "$admin" >"$work/server.log" 2>&1 &
server_pid=$!
for _ in $(seq 1 100); do
  curl -fs "$base/healthz" >/dev/null 2>&1 && break
  kill -0 "$server_pid" 2>/dev/null || { cat "$work/server.log"; exit 1; }
  sleep 0.2
done
curl -fs "$base/healthz" >/dev/null

json_field() { python3 -c "import json, sys; print(json.load(sys.stdin)$1)"; }
auth=(-H "Authorization: Bearer $admin")
world="$(curl -fs -XPOST "$base/v1/worlds" "${auth[@]}" -H 'Content-Type: application/json' \
  -d '{"seed": 42, "public": true}' | json_field '["id"]')"
curl -fs -XPOST "$base/v1/worlds/$world/edits" "${auth[@]}" \
  -H 'Content-Type: application/json-patch+json' \
  -d '[{"op":"add","path":"/regions/-","value":{"id":"peak","bbox":{"min":[0,0],"max":[256,256]},"samples":65,"ops":[{"op":"elevation","shape":{"point":[128,128]},"elevation_m":400,"radius_m":6}]}},{"op":"add","path":"/strata/-","value":{"id":"rock","bbox":{"min":[-500,-500],"max":[500,500]},"preset":"B3"}}]' \
  >/dev/null
# A 1 × 1 PNG for the image routes (uploadWorldImage, getWorldImage).
python3 -c 'import struct, sys, zlib
def chunk(t, d): return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d))
sys.stdout.buffer.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 1, 1, 8, 6, 0, 0, 0))
  + chunk(b"IDAT", zlib.compress(b"\x00\x40\x80\xc0\xff")) + chunk(b"IEND", b""))' >"$work/pixel.png"
image="$(curl -fs -XPOST "$base/v1/worlds/$world/images" "${auth[@]}" -H 'Content-Type: image/png' \
  --data-binary @"$work/pixel.png" | json_field '["image"]')"
job="$(curl -fs -XPOST "$base/v1/worlds/$world/exports" "${auth[@]}" -H 'Content-Type: application/json' \
  -d '{"lod":4,"region":[0,0,1,1],"products":["tiles"],"formats":["bin"]}' | json_field '["job"]')"

status=0
STRATA_WORLD_ID="$world" STRATA_REGION_ID=peak STRATA_JOB_ID="$job" STRATA_IMAGE_HASH="$image" \
  SCHEMATHESIS_HOOKS=tests/schemathesis/hooks.py \
  "$venv/bin/schemathesis" --no-color run api/openapi.yaml \
  --url "$base" \
  --header "Authorization: Bearer $admin" \
  --checks not_a_server_error,status_code_conformance,content_type_conformance,response_schema_conformance \
  --phases examples,coverage,fuzzing \
  --max-examples "$max_examples" \
  --seed 18 \
  --workers 1 \
  --request-timeout 60 \
  --suppress-health-check all \
  --generation-database none \
  --report junit --report-junit-path "$work/junit.xml" || status=$?

if grep -q 'panicked' "$work/server.log"; then
  echo "the server panicked during the schemathesis run:"
  grep -A3 'panicked' "$work/server.log" | head -40
  status=1
fi
if [ "$status" -ne 0 ]; then
  echo "schemathesis failed (exit $status); the server log's last lines:"
  tail -20 "$work/server.log"
fi
exit "$status"
