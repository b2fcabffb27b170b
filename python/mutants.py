#!/usr/bin/env python3
"""Mutation testing of the Python bindings' Rust side (python/src) against pytest.

cargo-mutants generates the mutants but can only run `cargo test`; the bindings' tests
are pytest on the built extension module. This script asks cargo-mutants for the
mutants (with their diffs), and for each one: applies it, rebuilds the extension module
incrementally (`cargo build --release -p lpe-python --features extension-module`),
copies it over the installed `lpe/_lpe.abi3.so` of a test venv, runs pytest (stopping
at the first failure), and restores python/src with git. Outcomes go to a JSON-lines
file (one object per mutant: name, outcome, seconds, the first failing test) that a
rerun resumes from; the per-file counts are printed at the end.

It edits python/src in place: run it in a scratch worktree (`git worktree add`), never
in a checkout you are editing. Setup and usage: docs/testing.md, "Mutants on the
Python bindings".
"""

import argparse
import collections
import glob
import json
import os
import pathlib
import shutil
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
BUILD = ["cargo", "build", "--release", "-p", "lpe-python", "--features", "extension-module", "--lib"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--venv", required=True, help="a venv with the lpe wheel, pytest and usd-core installed")
    ap.add_argument("--out", default="target/python-mutants.jsonl", help="outcomes, one JSON object per line")
    ap.add_argument("--names", help="a file of mutant names (one per line): test only those")
    ap.add_argument("--file", action="append", default=[], help="only mutants of this file (repeatable)")
    ap.add_argument("--timeout", type=float, default=120, help="seconds for one pytest run")
    args = ap.parse_args()

    sites = glob.glob(os.path.join(args.venv, "lib", "python3*", "site-packages", "lpe"))
    if not sites:
        sys.exit(f"error: {args.venv} has no installed lpe package (pip install the wheel first)")
    module = os.path.join(sites[0], "_lpe.abi3.so")
    python = os.path.join(args.venv, "bin", "python")
    target = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    built = target / "release" / "lib_lpe.so"
    env = dict(os.environ, CARGO_PROFILE_RELEASE_INCREMENTAL="true")
    env.setdefault("LPE_CHECK", str(target / "release" / "lpe-check"))
    if not os.path.exists(env["LPE_CHECK"]):
        # test_usd.py fails without it, which would count every mutant as caught.
        sys.exit(f"error: no lpe-check at {env['LPE_CHECK']}: build it (cargo build --release -p lpe-cli) or set LPE_CHECK")

    listing = ["cargo", "mutants", "--list", "--json", "--diff", "-d", "python"]
    for f in args.file:
        listing += ["--file", f]
    mutants = json.loads(subprocess.run(listing, cwd=ROOT, capture_output=True, text=True, check=True).stdout)
    only = {l.strip() for l in open(args.names) if l.strip()} if args.names else None
    done = {}
    if os.path.exists(args.out):
        records = (json.loads(l) for l in open(args.out) if l.strip())
        done = {r["name"]: r for r in records}
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)

    def build_and_install():
        b = subprocess.run(BUILD, cwd=ROOT, env=env, capture_output=True, text=True)
        if b.returncode == 0:
            shutil.copyfile(built, module)
        return b.returncode == 0

    def pytest():
        return subprocess.run(
            [python, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider", "python/tests"],
            cwd=ROOT, env=env, capture_output=True, text=True, timeout=args.timeout,
        )

    # The baseline: the unmutated module must pass, or every mutant would count as caught.
    if not build_and_install():
        sys.exit("error: the unmutated extension module does not build")
    base = pytest()
    if base.returncode != 0:
        sys.exit(f"error: pytest fails on the unmutated module:\n{base.stdout[-2000:]}")

    try:
        for i, m in enumerate(mutants):
            name = m["name"]
            if name in done or (only is not None and name not in only):
                continue
            t0 = time.time()
            failed = []
            p = subprocess.run(["patch", "-s", m["file"]], input=m["diff"], cwd=ROOT, text=True, capture_output=True)
            if p.returncode != 0:
                outcome = "patch-failed"
            elif not build_and_install():
                outcome = "unviable"
            else:
                try:
                    t = pytest()
                    outcome = "missed" if t.returncode == 0 else "caught"
                    failed = [l for l in t.stdout.splitlines() if l.startswith(("FAILED", "ERROR"))][:1]
                except subprocess.TimeoutExpired:
                    outcome = "timeout"
            subprocess.run(["git", "checkout", "--", "python/src"], cwd=ROOT, check=True)
            rec = {"name": name, "outcome": outcome, "secs": round(time.time() - t0, 1), "by": failed}
            done[name] = rec
            with open(args.out, "a") as f:
                f.write(json.dumps(rec) + "\n")
            print(f"{i + 1}/{len(mutants)} {outcome:8} {rec['secs']:6}s {name}", flush=True)
    finally:
        # Whatever happened, leave the sources and the installed module unmutated.
        subprocess.run(["git", "checkout", "--", "python/src"], cwd=ROOT, check=True)
        build_and_install()

    counts = collections.Counter((r["name"].split(":")[0], r["outcome"]) for r in done.values())
    for f in sorted({f for f, _ in counts}):
        row = ", ".join(f"{o} {counts[(f, o)]}" for o in ("caught", "missed", "unviable", "timeout", "patch-failed") if counts[(f, o)])
        print(f"{f}: {row}")
    for r in done.values():
        if r["outcome"] in ("missed", "timeout"):
            print(f"{r['outcome'].upper()} {r['name']}")


if __name__ == "__main__":
    main()
