"""Times lint on heavy USD stages and the batch matcher on many paths, in one run
(docs/benchmarks.md, "Lint at scale"):

1. `lpe.lint(stage)` against a `Usd.PrimRange` traversal of the same stage that finds
   its RenderVars (`p.GetTypeName() == "RenderVar"`), with the part of it that reads
   the stage (`lpe._stage_facts`, the traversal collecting what lint reads) and the
   memory lint takes: the Python heap's peak (tracemalloc) and the process's resident
   peak over its start;
2. `lpe-check lint` on the stage exported as `.usda`, against the file's size (MB/s)
   and with its peak resident memory (GNU time's `%M`: `/usr/bin/time` is needed);
3. `lpe-check match --batch` (`--engine fast` and `--engine reference`) against
   `AovSet.match_many` on the same paths (match_many.py's draw and expression);
4. `lpe-check match --batch`, `--engine fast` against `--engine reference`, on lines
   whose expressions do not repeat (every line its own expression: a counted
   repetition, which the fast engine's full DFA pays for, and a label of its own).

Usage: python lint_scale.py LPE_CHECK [--sizes PRIMS:POINTS,...] [--paths N] [--parts]
(default sizes: 1000:100000, 1000:10000000, 100000:100000, 100000:10000000; paths:
1 000 000). `--parts` also times each pxr query of lint's reading on its own, per prim
(CPU time, best of three): the traversal into a list, the type names, the authored
property names, and the attribute handles and values of the attributes lint reads.

Each stage holds PRIMS meshes sharing POINTS points between them (one triangle list
each), every mesh with a Karma object group, one RectLight with a light group, a
RenderSettings with a partition, a RenderProduct and three LPE RenderVars. Times are
the best of three runs (lint's memory is measured on a fourth); a single run on a
shared host gives ratios, not a controlled benchmark. The traversal, lint(stage) and its
reading are timed in this process's CPU time (`time.process_time`): on a shared host a
wall clock counts the time other processes hold the cores, which at these durations
(a millisecond at 10^3 prims) can be most of it; the `lpe-check` processes are timed
by the wall clock.
"""

import argparse
import collections
import os
import subprocess
import sys
import tempfile
import time
import tracemalloc

from pxr import Gf, Sdf, Usd, Vt

import lpe

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import match_many  # noqa: E402  (the same draw of paths and expression)

SIZES = [(10**3, 10**5), (10**3, 10**7), (10**5, 10**5), (10**5, 10**7)]
VARS = {"diffuse": "C<RD>[<L.'key'>O]", "specular": "C<RS>[<L.'key'>O]", "rest": "C[^<RD><RS>].*[LO]"}


def build(prims, points):
    """The stage: `prims` meshes of `points // prims` points each (module docs)."""
    stage = Usd.Stage.CreateInMemory()
    layer = stage.GetRootLayer()
    per = max(3, points // prims // 3 * 3)
    pts = Vt.Vec3fArray([Gf.Vec3f(i * 0.001, -i * 0.002, (i % 97) * 0.5) for i in range(per)])
    counts = Vt.IntArray([3] * (per // 3))
    indices = Vt.IntArray(list(range(per)))
    with Sdf.ChangeBlock():
        world = Sdf.CreatePrimInLayer(layer, "/World")
        world.specifier = Sdf.SpecifierDef
        world.typeName = "Xform"
        for m in range(prims):
            mesh = Sdf.PrimSpec(world, f"m{m}", Sdf.SpecifierDef, "Mesh")
            for name, ty, value in (
                ("points", Sdf.ValueTypeNames.Point3fArray, pts),
                ("faceVertexCounts", Sdf.ValueTypeNames.IntArray, counts),
                ("faceVertexIndices", Sdf.ValueTypeNames.IntArray, indices),
                ("primvars:karma:object:lpetag", Sdf.ValueTypeNames.String, "floor"),
            ):
                Sdf.AttributeSpec(mesh, name, ty).default = value
        light = Sdf.PrimSpec(world, "key", Sdf.SpecifierDef, "RectLight")
        Sdf.AttributeSpec(light, "inputs:karma:light:lpetag", Sdf.ValueTypeNames.String).default = "key"
        render = Sdf.CreatePrimInLayer(layer, "/Render")
        render.specifier = Sdf.SpecifierDef
        settings = Sdf.PrimSpec(render, "settings", Sdf.SpecifierDef, "RenderSettings")
        part = Sdf.AttributeSpec(settings, "lpe:partition", Sdf.ValueTypeNames.String)
        part.custom = True
        part.default = ",".join(VARS)
        product = Sdf.PrimSpec(render, "product", Sdf.SpecifierDef, "RenderProduct")
        rel = Sdf.RelationshipSpec(product, "orderedVars")
        for name, source in VARS.items():
            var = Sdf.PrimSpec(render, name, Sdf.SpecifierDef, "RenderVar")
            Sdf.AttributeSpec(var, "sourceType", Sdf.ValueTypeNames.Token,
                              variability=Sdf.VariabilityUniform).default = "lpe"
            Sdf.AttributeSpec(var, "sourceName", Sdf.ValueTypeNames.String,
                              variability=Sdf.VariabilityUniform).default = source
            rel.targetPathList.explicitItems.append(f"/Render/{name}")
    return stage


def best(f, runs=3, clock=time.perf_counter):
    times = []
    for _ in range(runs):
        t0 = clock()
        out = f()
        times.append(clock() - t0)
    return min(times), out


def status_kb(field):
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith(field + ":"):
                return int(line.split()[1])
    return 0


def lint_memory(stage):
    """The Python heap's peak during one lint, and the resident peak over the resident
    size before it (the kernel's high-water mark reset through clear_refs)."""
    tracemalloc.start()
    lpe.lint(stage)
    heap = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    try:
        with open("/proc/self/clear_refs", "w") as f:
            f.write("5")
        before = status_kb("VmRSS")
        lpe.lint(stage)
        rss = (status_kb("VmHWM") - before) * 1024
    except OSError:
        rss = float("nan")
    return heap, rss


def run_child(argv, stdin=None, stdout=subprocess.DEVNULL):
    """Wall time and peak resident bytes of one process. The peak is GNU time's `%M`:
    a child forked from this process would count this process's pages in its own
    `ru_maxrss` (the high-water mark survives exec), GNU time's child is small."""
    t0 = time.perf_counter()
    run = subprocess.run(["/usr/bin/time", "-f", "%M", *argv], stdin=stdin,
                         stdout=stdout, stderr=subprocess.PIPE, check=False)
    took = time.perf_counter() - t0
    *err, peak = run.stderr.decode(errors="replace").rstrip("\n").split("\n")
    return took, int(peak) * 1024, run.returncode, run.stdout, "\n".join(err)


def stage_row(lpe_check, prims, points, tmp):
    t = time.perf_counter()
    stage = build(prims, points)
    built = time.perf_counter() - t

    def traverse():
        return sum(1 for p in Usd.PrimRange.Stage(stage) if p.GetTypeName() == "RenderVar")

    cpu = time.process_time
    t_trav, nvars = best(traverse, clock=cpu)
    t_lint, report = best(lambda: lpe.lint(stage), clock=cpu)
    # The reading part of lint(stage): the traversal that collects what lint reads.
    t_facts, _ = best(lambda: lpe._stage_facts(stage), clock=cpu)
    assert nvars == len(VARS) and len(report.aovs) == len(VARS), (nvars, report.aovs)
    heap, rss = lint_memory(stage)

    path = os.path.join(tmp, f"stage_{prims}_{points}.usda")
    stage.GetRootLayer().Export(path)
    size = os.path.getsize(path)
    del stage
    runs = [run_child([lpe_check, "lint", "--format", "json", path]) for _ in range(3)]
    for _, _, code, _, err in runs:
        if code not in (0, 1):
            sys.exit(f"lpe-check lint {path} exited {code}: {err[:500]!r}")
    t_cli = min(r[0] for r in runs)
    rss_cli = max(r[1] for r in runs)
    os.unlink(path)
    return {
        "prims": prims, "points": points, "built": built,
        "trav": t_trav, "lint": t_lint, "facts": t_facts, "heap": heap, "rss": rss,
        "size": size, "cli": t_cli, "cli_rss": rss_cli,
    }


def reading_parts(prims, points):
    """The CPU time per prim of each pxr query of `lpe._stage_facts`, on its own: its
    results are dropped as they come, as the reading's `map`s consume them."""
    stage = build(prims, points)
    cpu = time.process_time
    ps = list(stage.Traverse())
    at, wanted = lpe._lpe.StageReading(
        map(Usd.Prim.GetTypeName, ps), map(Usd.Prim.GetAuthoredPropertyNames, ps)).wanted()
    attrs = list(map(Usd.Prim.GetAttribute, map(ps.__getitem__, at), wanted))

    def drop(results):
        collections.deque(results, maxlen=0)

    parts = [
        ("PrimRange traversal with GetTypeName (the reference)", len(ps), lambda: sum(
            1 for p in Usd.PrimRange.Stage(stage) if p.GetTypeName() == "RenderVar")),
        ("list(stage.Traverse())", len(ps), lambda: list(stage.Traverse())),
        ("GetTypeName", len(ps), lambda: drop(map(Usd.Prim.GetTypeName, ps))),
        ("GetAuthoredPropertyNames", len(ps), lambda: drop(map(Usd.Prim.GetAuthoredPropertyNames, ps))),
        ("GetAttribute (attributes lint reads)", len(at),
         lambda: drop(map(Usd.Prim.GetAttribute, map(ps.__getitem__, at), wanted))),
        ("Attribute.Get (attributes lint reads)", len(at), lambda: drop(map(Usd.Attribute.Get, attrs))),
    ]
    return [(name, best(f, clock=cpu)[0], n) for name, n, f in parts]


def match_rows(lpe_check, n, tmp):
    ps = match_many.paths(n)
    tsv = os.path.join(tmp, "batch.tsv")
    with open(tsv, "w") as f:
        for p in ps:
            f.write(f"{match_many.EXPR}\t{p}\n")
    s = lpe.AovSet({"e": match_many.EXPR})
    t_many, got = best(lambda: s.match_many(ps))
    want = [bool(g) for g in got]
    rows = [("AovSet.match_many", t_many)]
    for engine in ("fast", "reference"):
        t, out = time_batch(lpe_check, tsv, engine)
        if [line == b"match" for line in out.splitlines()] != want:
            sys.exit(f"match --batch --engine {engine} and match_many answer differently")
        rows.append((f"lpe-check match --batch --engine {engine}", t))
    os.unlink(tsv)
    return rows


def time_batch(lpe_check, tsv, engine):
    """The best of three `match --batch --engine ENGINE < TSV` runs, and its output."""
    times = []
    for _ in range(3):
        with open(tsv) as stdin:
            t, _, code, out, err = run_child(
                [lpe_check, "match", "--batch", "--engine", engine], stdin=stdin,
                stdout=subprocess.PIPE)
        if code != 0:
            sys.exit(f"match --batch --engine {engine} exited {code}: {err[:500]!r}")
        times.append(t)
    return min(times), out


def distinct_rows(lpe_check, n, tmp):
    """`--batch` on N lines that each bring their own expression, over the first N paths
    of the draw: both engines must give the same answers (`batch_inputs.py` times more
    shapes of input)."""
    ps = match_many.paths(n)
    tsv = os.path.join(tmp, "distinct.tsv")
    with open(tsv, "w") as f:
        for i, p in enumerate(ps):
            f.write(f"(C.{{{i % 200}}}[LO])|(C<RD'l{i}'>.*L)\t{p}\n")
    rows, answers = [], []
    for engine in ("fast", "reference"):
        t, out = time_batch(lpe_check, tsv, engine)
        answers.append(out)
        rows.append((f"lpe-check match --batch --engine {engine}", t))
    if answers[0] != answers[1]:
        sys.exit("match --batch: the engines answer the distinct lines differently")
    os.unlink(tsv)
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("lpe_check")
    ap.add_argument("--sizes", default=",".join(f"{a}:{b}" for a, b in SIZES))
    ap.add_argument("--paths", type=int, default=1_000_000)
    ap.add_argument("--parts", action="store_true")
    args = ap.parse_args()
    sizes = [tuple(int(x) for x in s.split(":")) for s in args.sizes.split(",")]
    mb = 1e6
    with tempfile.TemporaryDirectory(prefix="lpe-bench-") as tmp:
        print("| prims | points | PrimRange traversal (CPU) | lint(stage) (CPU) | ratio | of which reading | lint heap peak | lint RSS growth | .usda size | lpe-check lint | MB/s | lpe-check peak RSS |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|")
        for prims, points in sizes:
            r = stage_row(args.lpe_check, prims, points, tmp)
            print(
                f"| {prims:,} | {points:,} | {r['trav'] * 1e3:.1f} ms | {r['lint'] * 1e3:.1f} ms "
                f"| {r['lint'] / r['trav']:.2f}x | {r['facts'] * 1e3:.1f} ms ({r['facts'] / r['trav']:.2f}x) "
                f"| {r['heap'] / mb:.1f} MB | {r['rss'] / mb:.1f} MB "
                f"| {r['size'] / mb:.1f} MB | {r['cli']:.2f} s | {r['size'] / mb / r['cli']:.0f} "
                f"| {r['cli_rss'] / mb:.1f} MB |",
                flush=True,
            )
        print()
        for prims, points in sizes if args.parts else []:
            print(f"| {prims:,} prims, {points:,} points: query over all prims | CPU time | per prim |")
            print("|---|---|---|")
            for name, t, n in reading_parts(prims, points):
                print(f"| {name} | {t * 1e3:.1f} ms | {t / max(n, 1) * 1e6:.2f} µs |")
            print()
        rows = match_rows(args.lpe_check, args.paths, tmp)
        base = rows[0][1]
        print(f"| {args.paths:,} paths (`{match_many.EXPR}`) | time | per path | / match_many |")
        print("|---|---|---|---|")
        for name, t in rows:
            print(f"| {name} | {t:.2f} s | {t / args.paths * 1e9:.0f} ns | {t / base:.2f}x |")
        print()
        n = min(args.paths, 20_000)
        rows = distinct_rows(args.lpe_check, n, tmp)
        base = rows[1][1]
        print(f"| {n:,} lines, each its own expression | time | per line | / reference |")
        print("|---|---|---|---|")
        for name, t in rows:
            print(f"| {name} | {t:.2f} s | {t / n * 1e6:.1f} µs | {t / base:.2f}x |")


if __name__ == "__main__":
    main()
