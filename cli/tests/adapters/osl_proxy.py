"""An OSL-dialect external matcher for the tests of `lpe-check diff --external --dialect osl`.

It answers through `LPE_CHECK match --dialect osl --engine reference --batch` (one
process per request), so it agrees with lpe unless a bug is planted:

    python3 osl_proxy.py LPE_CHECK [--forget-registration]

`--forget-registration` parses every set as if nothing were registered, the mistake of
an adapter that drops the `registered` field of `compile`: expressions using a
registered label are rejected where lpe accepts them.
"""

import json
import subprocess
import sys

LPE_CHECK = sys.argv[1]
FORGET = "--forget-registration" in sys.argv[2:]


def registration(reg):
    """The `registered` object as lpe-check's REGISTERED column."""
    if FORGET or reg is None:
        return "-"
    parts = [f"{k}={','.join(reg[k])}" for k in ("events", "scatters") if reg.get(k)]
    return ";".join(parts) or "-"


def batch(lines):
    """lpe-check's answer line per `EXPR<TAB>REGISTERED<TAB>PATH` line."""
    out = subprocess.run(
        [LPE_CHECK, "match", "--dialect", "osl", "--engine", "reference", "--batch"],
        input="".join(l + "\n" for l in lines),
        capture_output=True,
        text=True,
    )
    answers = out.stdout.splitlines()
    if len(answers) != len(lines):
        sys.exit(f"lpe-check answered {len(answers)} of {len(lines)} lines: {out.stderr}")
    return answers


aovs, reg = [], "-"
for line in sys.stdin:
    req = json.loads(line)
    rid, op = req["id"], req["op"]
    reply = {"id": rid, "ok": True}
    if op == "hello":
        if req.get("dialect") != "osl":
            reply = {"id": rid, "ok": False, "unsupported": "only the osl dialect"}
        else:
            reply["protocol"] = 1
    elif op == "compile":
        aovs = [(a["name"], a["expr"]) for a in req["aovs"]]
        reg = registration(req.get("registered"))
        # Any path will do: the answer line says whether the expression parses.
        answers = batch([f"{e}\t{reg}\tC,_ L,_" for _, e in aovs]) if aovs else []
        for i, a in enumerate(answers):
            if a.startswith("error"):
                aovs = []
                reply = {"id": rid, "ok": False, "error": {"message": a, "aov": i}}
                break
    elif op == "match":
        lines = [f"{e}\t{reg}\t{p}" for p in req["paths"] for _, e in aovs]
        answers = iter(batch(lines)) if lines else iter(())
        reply["matches"] = [
            [name for name, _ in aovs if next(answers) == "match"] for _ in req["paths"]
        ]
    print(json.dumps(reply), flush=True)
    if op == "quit":
        break
