#!/usr/bin/env python3
"""Open every USD fixture with Pixar's USD library and check that the LPE RenderVars it
reads (prim path, sourceName, sourceType) are exactly those `lpe-check lint --format
json` reads. Usage: check_usd_fixtures.py LPE_CHECK FIXTURE...  Exit 1 on any mismatch."""

import json
import subprocess
import sys

from pxr import Usd


def pixar_vars(path):
    stage = Usd.Stage.Open(path)
    out = []
    for prim in stage.Traverse():
        if prim.GetTypeName() != "RenderVar":
            continue
        source_type = prim.GetAttribute("sourceType").Get()
        # The schema fallback for an unauthored sourceType is "raw".
        if str(source_type or "raw") != "lpe":
            continue
        name = prim.GetAttribute("sourceName").Get()
        out.append((str(prim.GetPath()), str(name or ""), str(source_type)))
    return out


def lint_vars(lpe_check, path):
    run = subprocess.run(
        [lpe_check, "lint", "--format", "json", path],
        capture_output=True,
        text=True,
        check=False,
    )
    if run.returncode not in (0, 1):
        sys.exit(f"{path}: lpe-check lint exited {run.returncode}: {run.stderr}")
    report = json.loads(run.stdout)
    return [
        (a["location"]["prim"], a["source"], a["source_type"])
        for a in report["aovs"]
        if a["file"] == path
    ]


def main():
    lpe_check, fixtures = sys.argv[1], sys.argv[2:]
    if not fixtures:
        sys.exit("no fixtures given")
    failed = False
    for path in fixtures:
        want, got = pixar_vars(path), lint_vars(lpe_check, path)
        if want != got:
            failed = True
            print(f"MISMATCH {path}\n  usd-core: {want}\n  lint:     {got}")
        else:
            print(f"ok {path}: {len(want)} LPE RenderVars")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
