"""An OSL-dialect external matcher for the tests of `lpe-check diff --external --dialect osl`.

It answers through `LPE_CHECK match --dialect osl --engine reference --batch` (one
process per request), so it agrees with lpe unless a bug is planted:

    python3 osl_proxy.py LPE_CHECK [--forget-registration] [--forget-renderer] [--miss-counted] [--crash-on-zero]

`--forget-registration` parses every set as if nothing were registered, the mistake of
an adapter that drops the `registered` field of `compile`: expressions using a
registered label are rejected where lpe accepts them. `--forget-renderer` drops the
`renderer` field of `compile` the same way: a renderer's built-in names and prefixes are
then rejected.

`--miss-counted` answers "no AOV" for every path of a set whose expressions hold a
counted repetition `{…}`: a bug that shows only under counts, so that minimizing one
walks the counts down towards `{0}`, which OSL's grammar accepts only among the leading
items. `--crash-on-zero` exits (a crash) when asked to compile a `{0}` count.
`--crash-after K` answers the first K `compile` requests of the process and exits (a
crash) on the next: a crash on a schedule, every process alike.
`--flaky` makes `--miss-counted` a flaky bug: it shows only the first time a set is
compiled, so a case asked again agrees.
"""

import json
import subprocess
import sys

LPE_CHECK = sys.argv[1]
FORGET = "--forget-registration" in sys.argv[2:]
FORGET_RENDERER = "--forget-renderer" in sys.argv[2:]
MISS_COUNTED = "--miss-counted" in sys.argv[2:]
CRASH_ON_ZERO = "--crash-on-zero" in sys.argv[2:]
FLAKY = "--flaky" in sys.argv[2:]
compiled = set()
CRASH_AFTER = (
    int(sys.argv[sys.argv.index("--crash-after") + 1]) if "--crash-after" in sys.argv else None
)
compiles = 0
buggy = False


def registration(reg):
    """The `registered` object as lpe-check's REGISTERED column."""
    if FORGET or reg is None:
        return "-"
    parts = [f"{k}={','.join(reg[k])}" for k in ("events", "scatters") if reg.get(k)]
    return ";".join(parts) or "-"


def batch(lines):
    """lpe-check's answer line per `EXPR<TAB>REGISTERED<TAB>PATH` line, under the
    renderer the last `compile` named."""
    named = ["--renderer", renderer] if renderer else ["--dialect", "osl"]
    out = subprocess.run(
        [LPE_CHECK, "match", *named, "--engine", "reference", "--batch"],
        input="".join(l + "\n" for l in lines),
        capture_output=True,
        text=True,
    )
    answers = out.stdout.splitlines()
    if len(answers) != len(lines):
        sys.exit(f"lpe-check answered {len(answers)} of {len(lines)} lines: {out.stderr}")
    return answers


aovs, reg, renderer = [], "-", None
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
        compiles += 1
        if CRASH_AFTER is not None and compiles > CRASH_AFTER:
            sys.exit(f"planted crash on compile {compiles}")
        key = tuple(e for _, e in aovs)
        buggy = MISS_COUNTED and not (FLAKY and key in compiled)
        compiled.add(key)
        if CRASH_ON_ZERO and any("{0}" in e or "{0,0}" in e for _, e in aovs):
            sys.exit("planted crash on a {0} count")
        reg = registration(req.get("registered"))
        renderer = None if FORGET_RENDERER else req.get("renderer")
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
        if buggy and any("{" in e for _, e in aovs):
            reply["matches"] = [[] for _ in req["paths"]]
    print(json.dumps(reply), flush=True)
    if op == "quit":
        break
