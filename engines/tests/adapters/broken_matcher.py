#!/usr/bin/env python3
"""An external matcher that breaks the protocol on purpose, one way per mode (argv[1]):

crash     exits with status 3 on every `match` (after a line on stderr)
hang      never answers a `match` (after a line on stderr)
garbage   answers `match` with a line that is not JSON
count     answers `match` with one list fewer than paths
extra     answers `compile` twice
wrongid   answers `match` with another request's id
reject    rejects every expression (a compile error at byte 0 of AOV 0)

Everything else it answers correctly enough: `match` says no AOV matches. The harness
must turn each misbehaviour into a finding and finish its run.
"""

import json
import sys
import time

MODE = sys.argv[1]


def send(obj):
    print(json.dumps(obj), flush=True)


for line in sys.stdin:
    req = json.loads(line)
    rid, op = req["id"], req["op"]
    if op == "hello":
        send({"id": rid, "ok": True, "protocol": 1, "name": "broken-" + MODE})
    elif op == "compile":
        if MODE == "reject":
            send({"id": rid, "ok": False,
                  "error": {"message": "rejects everything", "aov": 0, "position": 0}})
            continue
        send({"id": rid, "ok": True})
        if MODE == "extra":
            send({"id": rid, "ok": True})
    elif op == "match":
        n = len(req["paths"])
        if MODE == "crash":
            print("boom: mode crash", file=sys.stderr, flush=True)
            sys.exit(3)
        if MODE == "hang":
            print("waiting: mode hang", file=sys.stderr, flush=True)
            time.sleep(3600)
        if MODE == "garbage":
            print("}{ this is not JSON", flush=True)
            continue
        if MODE == "count":
            n -= 1
        send({"id": rid - 1 if MODE == "wrongid" else rid, "ok": True,
              "matches": [[] for _ in range(n)]})
    elif op == "quit":
        send({"id": rid, "ok": True})
        break
