#!/usr/bin/env python3
"""Runs presets over several seeds (resuming any that were interrupted) and
prints the results table of docs/results.md.

    scripts/results.py PRESET:SEEDS [PRESET:SEEDS ...] [--runs DIR] [--workers K]

e.g. scripts/results.py miconi2006-small:1-5 chaumont2007-walker-small:1-3

For each run: the final best fitness; the best creature re-simulated exactly
(its run's config and evaluation seed): distance and body lengths; and the
same creature simulated for twice the task's time: the gait counts as
sustained when, in that run, the centre of mass moves (in the plane) over the
second half at least half as far as over the first half, and more than half a
body length.
"""
import argparse, json, os, re, sqlite3, subprocess, sys

BESTIARY = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "bestiary")


def sh(args, **kw):
    return subprocess.run([BESTIARY] + args, capture_output=True, text=True, **kw)


def seeds(spec):
    a, _, b = spec.partition("-")
    return range(int(a), int(b or a) + 1)


def finished(run_dir):
    db = os.path.join(run_dir, "run.sqlite")
    if not os.path.exists(db):
        return False
    con = sqlite3.connect(db)
    cfg = dict(con.execute("select key, value from run"))["config"]
    n = con.execute("select count(*), max(evaluations) from generation").fetchone()
    alg = re.search(r'algorithm = "(\w+)"', cfg).group(1)
    pop = int(re.search(r"population = (\d+)", cfg).group(1))
    if alg == "generational":
        return n[0] >= int(re.search(r"generations = (\d+)", cfg).group(1))
    return (n[1] or 0) >= pop + int(re.search(r"evaluations = (\d+)", cfg).group(1))


def row(preset, seed, run_dir):
    con = sqlite3.connect(os.path.join(run_dir, "run.sqlite"))
    first, last = con.execute("select min(gen), max(gen) from generation").fetchone()
    best0 = con.execute("select best from generation where gen = ?", (first,)).fetchone()[0]
    best, failed, rejected, evals = con.execute(
        "select best, (select sum(failed) from generation), (select sum(rejected) from generation), evaluations "
        "from generation where gen = ?", (last,)).fetchone()
    out = os.path.join(run_dir, "best.json")
    b = sh(["best", run_dir, "--out", out])
    cmd = ["simulate"] + re.search(r"bestiary simulate (.*)$", b.stderr, re.M).group(1).split()
    one = json.loads(sh(cmd + ["--json"]).stdout)
    cfg = open(os.path.join(run_dir, "config.toml")).read()
    seconds = float(re.search(r"^seconds = ([0-9.e+-]+)", cfg, re.M).group(1))
    rep = os.path.join(run_dir, "best-2x.replay.json")
    two = json.loads(sh(cmd + ["--json", "--seconds", str(2 * seconds), "--replay", rep]).stdout)
    d1, d2, bl = one["distance"], two["distance"], one["body_length"]
    # sustained: over twice the time, the second half moves the centre of mass (in the
    # plane) at least half as far as the first half does
    frames = json.load(open(rep))["frames"]
    com = [f["com"] for f in frames]
    mid, end = com[len(com) // 2], com[-1]
    planar = lambda a, b: ((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2) ** 0.5
    first, second = planar(com[0], mid), planar(mid, end)
    sustained = "yes" if second >= 0.5 * first and second > 0.5 * bl else "no"
    return (f"| {preset} | {seed} | {evals} | {best0:.4g} | {best:.4g} | {one['parts']} | {d1:.2f} | "
            f"{d1 / bl:.1f} | {d2:.2f} | {sustained} | {failed} | {rejected} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+", help="PRESET:SEEDS, seeds as N or A-B")
    ap.add_argument("--runs-dir", default="runs/results")
    ap.add_argument("--workers", default="2")
    a = ap.parse_args()
    rows = []
    for spec in a.runs:
        preset, _, s = spec.partition(":")
        for seed in seeds(s or "1"):
            run_dir = os.path.join(a.runs_dir, f"{preset}-s{seed}")
            if not finished(run_dir):
                args = (["resume", run_dir] if os.path.exists(run_dir) else
                        ["run", preset, "--out", run_dir, "--seed", str(seed)])
                print(f"running {' '.join(args)}", file=sys.stderr, flush=True)
                r = sh(args + ["--workers", a.workers, "--quiet"])
                if r.returncode != 0:
                    sys.exit(r.stderr)
            rows.append(row(preset, seed, run_dir))
            print(rows[-1], flush=True)
    print("\n| preset | seed | evaluations | best, first generation | best, last | parts | distance (m) "
          "| body lengths | distance, 2x time (m) | sustained | failed | rejected |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    print("\n".join(rows))


if __name__ == "__main__":
    main()
