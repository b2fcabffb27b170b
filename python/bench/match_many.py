"""Times matching N paths (default 1 000 000) from Python through `AovSet.match_many`
against `lpe-check match --batch` on the same paths, checks that both give the same
answers, and prints the ratio (docs/benchmarks.md, "Python: match_many").

Usage: python match_many.py LPE_CHECK [N] [--engine ENGINE[,ENGINE...]]
(default engines: reference, the fastest for --batch, whose every line names its own
expression: the automaton engines build a matcher per line; and fast)

The paths are drawn with a fixed seed: a camera, 0 to 6 scattering vertices (R or T,
D1-D4 or S1-S8, a label one time in four), then a light (a light group one time in two)
or an emissive object. The expression is `indirectDiffuse` (C<RD>.+[<L.>O]).
`lpe-check match --batch` reads `EXPR<TAB>PATH` lines and writes one answer line each;
its time is the whole process (reading, matching, writing). The Python time is one
`match_many` call on a list of path strings, building the list of results; the
per-path form (`[s.match(p) for p in paths]`) is timed too.
"""

import os
import random
import subprocess
import sys
import tempfile
import time

import lpe

EXPR = "indirectDiffuse"


def paths(n, seed=1):
    rng = random.Random(seed)
    labels = ["floor", "glass", "wall"]
    groups = ["key", "fill", "rim"]
    out = []
    for _ in range(n):
        vs = ["C"]
        for _ in range(rng.randint(0, 6)):
            kind = rng.choice("DS")
            lobe = rng.randint(1, 4 if kind == "D" else 8)
            label = f"'{rng.choice(labels)}'" if rng.random() < 0.25 else ""
            vs.append(f"{rng.choice('RT')}{kind}{lobe}{label}")
        if rng.random() < 0.8:
            vs.append(f"L'{rng.choice(groups)}'" if rng.random() < 0.5 else "L")
        else:
            vs.append("O")
        out.append(" ".join(vs))
    return out


def main():
    args = sys.argv[1:]
    engines = ["reference", "fast"]
    if "--engine" in args:
        i = args.index("--engine")
        engines = args[i + 1].split(",")
        del args[i : i + 2]
    lpe_check = args[0]
    n = int(args[1]) if len(args) > 1 else 1_000_000
    ps = paths(n)

    with tempfile.NamedTemporaryFile("w", suffix=".tsv", delete=False) as f:
        for p in ps:
            f.write(f"{EXPR}\t{p}\n")
        tsv = f.name
    timed = []
    answers = {}
    for engine in engines:
        with open(tsv) as stdin:
            t0 = time.perf_counter()
            run = subprocess.run(
                [lpe_check, "match", "--batch", "--engine", engine],
                stdin=stdin, capture_output=True, text=True, check=False,
            )
            timed.append((engine, time.perf_counter() - t0))
        if run.returncode != 0:
            sys.exit(f"lpe-check exited {run.returncode}: {run.stderr[:500]}")
        answers[engine] = [line == "match" for line in run.stdout.splitlines()]
    os.unlink(tsv)

    s = lpe.AovSet({"e": EXPR})
    t0 = time.perf_counter()
    got = s.match_many(ps)
    t_py = time.perf_counter() - t0
    py = [bool(g) for g in got]
    t0 = time.perf_counter()
    one = [s.match(p) for p in ps]
    t_one = time.perf_counter() - t0
    if [tuple(o) for o in one] != got:
        sys.exit("match and match_many differ")

    for engine, cli in answers.items():
        if cli != py:
            bad = next((i for i, (a, b) in enumerate(zip(cli, py)) if a != b), -1)
            sys.exit(f"--engine {engine}: answers differ (first at {bad}: {ps[bad] if bad >= 0 else 'lengths'})")
    matched = sum(py)
    print(f"{n} paths, {matched} match {EXPR}; answers agree")
    for engine, t_cli in timed:
        print(f"lpe-check match --batch --engine {engine}: {t_cli:.2f} s ({t_cli / n * 1e9:.0f} ns/path)")
    print(f"AovSet.match_many: {t_py:.2f} s ({t_py / n * 1e9:.0f} ns/path)")
    print(f"AovSet.match, one call per path: {t_one:.2f} s ({t_one / n * 1e9:.0f} ns/path)")
    for engine, t_cli in timed:
        print(f"ratio lpe-check --engine {engine} / match_many: {t_cli / t_py:.1f}")


if __name__ == "__main__":
    main()
