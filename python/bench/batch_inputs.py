"""Times `lpe-check match --batch` with `--engine fast` against `--engine reference` on
inputs of several shapes, checks that both print the same answers, and prints the CPU-time
ratio per input (docs/benchmarks.md, "match --batch: fast against the reference").

Usage: python batch_inputs.py LPE_CHECK [--lines N] [--reps R] [--only NAME[,NAME...]]

Each input is `EXPR<TAB>PATH` lines, the paths drawn with a fixed seed as
`match_many.py` draws them (a camera, 0 to 6 scattering vertices, a light or an emissive
object), except where an input says otherwise. The inputs:

- `repeated`: one expression (`indirectDiffuse`) on every line: compiled once in full;
- `distinct-counted`: every line its own expression `(C.{k}[LO])|(C<RD'l<i>'>.*L)`
  (k = i mod 200): counted repetition that an automaton unrolls;
- `distinct-matching`: `C<RD'l<i>'>?.{k}[LO]` with k = i mod 7, which matches about one
  line in seven;
- `distinct-alternatives`: a `[...]` of 40 labelled triples per line, starred;
- `hundreds`: 97 expressions of the `distinct-alternatives` kind, each on about 200
  lines;
- `thousands`: 20 of them, each on about 1 000 lines: each is compiled again for some
  paths (the fast engine's lazy DFA) at its 256th line;
- `distinct-nested`: nested counted repetition, `C((<R[DS]>|<T.>){1,3}){1,4}[<L.'l<i>'>O]`
  with its counts varied per line;
- `distinct-algebra`: set algebra, `C.*[LO] - C.*<.D'l<i>'>.*[LO]`;
- `distinct-long`: paths of 60 to 120 vertices (past one machine word of positions)
  against `(C.*<.S>.{k}[LO])|(C<RD'l<i>'>.*L)`, k = i mod 50;
- `tens`: 2 000 expressions of the `distinct-matching` kind, each on 10 lines in a row:
  the cache hits, no expression reaches its full compile.

The CPU time is the child process's user + system time (resource.getrusage), the best of
R runs: on a shared host wall time is mostly other processes' turns.
"""

import random
import resource
import subprocess
import sys
import tempfile

from match_many import paths


def long_paths(n, seed=2):
    rng = random.Random(seed)
    out = []
    for _ in range(n):
        middle = [
            f"{rng.choice('RT')}{rng.choice('DS')}{rng.randint(1, 4)}"
            for _ in range(rng.randint(58, 118))
        ]
        out.append(" ".join(["C", *middle, "L"]))
    return out


def alternatives(i, labels):
    items = " ".join(f"<R{'DS'[j % 2]}'a{(i + j) % labels}'>" for j in range(40))
    return f"C[{items}]*.[LO]"


def inputs(n):
    ps = paths(n)
    return {
        "repeated": [("indirectDiffuse", p) for p in ps],
        "distinct-counted": [
            (f"(C.{{{i % 200}}}[LO])|(C<RD'l{i}'>.*L)", p) for i, p in enumerate(ps)
        ],
        "distinct-matching": [
            (f"C<RD'l{i}'>?.{{{i % 7}}}[LO]", p) for i, p in enumerate(ps)
        ],
        "distinct-alternatives": [(alternatives(i, n + 40), p) for i, p in enumerate(ps)],
        "hundreds": [(alternatives(i, 97), p) for i, p in enumerate(ps)],
        "thousands": [(alternatives(i, 20), p) for i, p in enumerate(ps)],
        "distinct-nested": [
            (
                f"C((<R[DS]>|<T.>){{1,{1 + i % 3}}}){{{i % 2},{1 + i % 4}}}[<L.'l{i}'>O]",
                p,
            )
            for i, p in enumerate(ps)
        ],
        "distinct-algebra": [
            (f"C.*[LO] - C.*<.D'l{i}'>.*[LO]", p) for i, p in enumerate(ps)
        ],
        "distinct-long": [
            (f"(C.*<.S>.{{{i % 50}}}[LO])|(C<RD'l{i}'>.*L)", p)
            for i, p in enumerate(long_paths(n // 10))
        ],
        "tens": [
            (f"C<RD'l{i // 10}'>?.{{{(i // 10) % 7}}}[LO]", p)
            for i, p in enumerate(ps)
        ],
    }


def cpu_run(lpe_check, engine, tsv):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(tsv) as stdin:
        run = subprocess.run(
            [lpe_check, "match", "--batch", "--engine", engine],
            stdin=stdin, capture_output=True, text=True, check=False,
        )
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if run.returncode not in (0, 2):
        sys.exit(f"--engine {engine} exited {run.returncode}: {run.stderr[:500]}")
    return cpu, run.stdout


def main():
    args = sys.argv[1:]
    opts = {"--lines": "20000", "--reps": "3", "--only": ""}
    for k in opts:
        if k in args:
            i = args.index(k)
            opts[k] = args[i + 1]
            del args[i : i + 2]
    lpe_check = args[0]
    n, reps = int(opts["--lines"]), int(opts["--reps"])
    only = [o for o in opts["--only"].split(",") if o]
    print(f"| input ({n} lines; distinct-long {n // 10}) | fast CPU | reference CPU "
          f"| fast / reference | lines matched |")
    print("|---|---|---|---|---|")
    for name, lines in inputs(n).items():
        if only and name not in only:
            continue
        with tempfile.NamedTemporaryFile("w", suffix=".tsv", delete=False) as f:
            for expr, path in lines:
                f.write(f"{expr}\t{path}\n")
            tsv = f.name
        best = {}
        outs = {}
        for _ in range(reps):
            for engine in ("fast", "reference"):
                cpu, out = cpu_run(lpe_check, engine, tsv)
                best[engine] = min(best.get(engine, cpu), cpu)
                outs[engine] = out
        if outs["fast"] != outs["reference"]:
            sys.exit(f"{name}: the engines' answers differ")
        answers = outs["fast"].splitlines()
        errors = [a for a in answers if a.startswith("error")]
        if errors:
            sys.exit(f"{name}: {len(errors)} error lines, first: {errors[0]}")
        matched = sum(a == "match" for a in answers)
        f, r = best["fast"], best["reference"]
        print(f"| {name} | {f:.3f} s | {r:.3f} s | {f / r:.2f}x | {matched} |")


if __name__ == "__main__":
    main()
