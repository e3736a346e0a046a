#!/usr/bin/env python3
"""Runs presets over several seeds (resuming any that were interrupted) and
prints the results table of docs/results.md.

    scripts/results.py PRESET:SEEDS [PRESET:SEEDS ...] [--runs-dir DIR] [--workers K]

e.g. scripts/results.py miconi2006-small:1-5 chaumont2007-walker-small:1-3

For each run: the final best fitness; the best creature re-simulated exactly
(its run's config and evaluation seed): distance and body lengths. Whether
its gait goes on is check's sustained column (below).

For every run also `bestiary check` of its best: its fitness re-simulated
under 5 other physics seeds (the median ratio to the scored fitness: an
elite's mean or least over its evaluations, evolution.elite_evaluations and
task.trial_score), at dt/2
and dt/4 (and twice the solver iterations, under QuickStep), with its motors
lagging 10 ms more and its brain at half its rate (a buzzer collapses under
them), with every effector clamped to its mean and with every joint held still
by its motor, for locomotion its last third's travel over its first in a run
twice as long (sustained), each active effector's dominant frequency, the
largest joint separation, and the verdict (its gates are the run's [check]
config keys, or --check-set's).

For a throwing run (chaumont2007's catapults) instead: the best fitness of the
first and last generation; the best creature re-simulated exactly: its throw
distance D_p, its target miss D_t (aim task), its release time from the
throw's start (the drop, or its rest with throwing.start = "settled"; the
mechanism fires 0.5 s after it, earlier means the body fired it), its projectile's size; the
median throw of the same creature over evaluation seeds 1-5 (throws are
chaotic: this says how much of the best was luck); and the explosion and
speed discards (5.4) as a share of the evaluations of the first generation,
the last generation and the whole run. Then how the best threw (its replay,
the first trial; see throw_profile): the body's parts, height and mass over
the projectile's, the release's height, the projectile's top speed, its
flight to the first touch of the ground, its roll from there to rest, and the
kick (above 1: something struck it on the ground, as in a drop-kick); and
the share of the first and last generation's new individuals whose body fires
the release before the mechanism's delay (each simulated once, seed 1).

For a lessin2015 locomotion run also its best's speed (the scored one: the
lesser of the measured time's halves, task.windows), efficiency and muscle
work over the measured time (the task's named metrics).

For every run but the river crossing's also `bestiary crosscheck` of its
best (docs/export.md): its ODE evaluation's motor commands replayed open loop
in MuJoCo under four contact settings, each as its distance's ratio to ODE's
and how many degrees its heading is off, their medians and the verdict (the
same way: within 45 degrees and 0.5-2x); for a throw the projectile's, from
its release to its rest, and its flight to its landing in a table of its own;
and the task's score in ODE and (the median) in MuJoCo, the same task scoring
the replay;
a creature MuJoCo cannot replay says why.

For a run of several stages (an ESP syllabus) instead: per stage, its
generations, its best in its first and last generation, and `bestiary check`
of that last best on its own stage's task.

For a river crossing run (Stanton & Channon 2015) instead of distances: its
tournaments, best fitness, and per level the share of its final 1000
tournaments' evaluations that completed the level (the generation_metric
table), food eaten and the torso's travel in its first and last report
interval (whether evolution got going), the mean progress toward the
resources (metric 'approach') in them, its Fig. 5 curve (`bestiary plot RUN --metric completed`, written as
RUN/levels.svg); then over all its seeds the paper's Table 1: per level, the
share of runs with more than 0% and at least 20/40/60/80% of those
evaluations completing it, beside the paper's.
"""
import argparse, json, math, os, re, sqlite3, subprocess, sys, tempfile, tomllib

# $BESTIARY overrides (e.g. a frozen copy while the build tree changes)
BESTIARY = os.environ.get("BESTIARY") or os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "build", "bestiary")


def sh(args, **kw):
    return subprocess.run([BESTIARY] + args, capture_output=True, text=True, **kw)


def seeds(spec):
    a, _, b = spec.partition("-")
    return range(int(a), int(b or a) + 1)


def stages(run_dir):
    """A run of several stages (a syllabus): [(name, generations)] in order;
    [] for a run of one."""
    cfg = tomllib.loads(open(os.path.join(run_dir, "config.toml")).read())
    base = cfg.get("evolution", {})
    out = []
    for st in cfg.get("stage", []):
        e = dict(base, **st.get("evolution", {}))
        if e.get("algorithm", "generational") == "generational":
            out.append((st["name"], e.get("generations", 0)))
        else:
            # a steady state stores its first generation, then one per report interval
            every = e.get("report_every") or e.get("population", 1)
            out.append((st["name"], 1 + math.ceil(e.get("evaluations", 0) / every)))
    return out


def finished(run_dir):
    db = os.path.join(run_dir, "run.sqlite")
    if not os.path.exists(db):
        return False
    con = sqlite3.connect(db)
    staged = stages(run_dir)
    if staged:
        return con.execute("select count(*) from generation").fetchone()[0] >= sum(g for _, g in staged)
    cfg = dict(con.execute("select key, value from run"))["config"]
    n = con.execute("select count(*), max(evaluations) from generation").fetchone()
    alg = re.search(r'^algorithm = "(\w+)"', cfg, re.M).group(1)
    pop = int(re.search(r"^population = (\d+)", cfg, re.M).group(1))
    if alg == "generational":
        return n[0] >= int(re.search(r"^generations = (\d+)", cfg, re.M).group(1))
    # a steady state's budget counts creatures born (tournaments): the checkpoint's next id
    state = con.execute("select state from checkpoint").fetchone()
    born = json.loads(state[0])["next_id"] if state else 0
    return born >= pop + int(re.search(r"^evaluations = (\d+)", cfg, re.M).group(1))


def row(preset, seed, run_dir):
    con = sqlite3.connect(os.path.join(run_dir, "run.sqlite"))
    first, last = con.execute("select min(gen), max(gen) from generation").fetchone()
    best0 = con.execute("select best from generation where gen = ?", (first,)).fetchone()[0]
    best, failed, rejected, evals = con.execute(
        "select best, (select sum(failed) from generation), (select sum(rejected) from generation), evaluations "
        "from generation where gen = ?", (last,)).fetchone()
    out = os.path.join(run_dir, "best.json")
    b = sh(["best", run_dir, "--out", out])
    cmd = ["simulate"] + re.search(r"exactly: \S+ simulate (.*)$", b.stderr, re.M).group(1).split()
    one = json.loads(sh(cmd + ["--json"]).stdout)
    d1, bl = one["distance"], one["body_length"]
    text = (f"| {preset} | {seed} | {evals} | {best0:.4g} | {best:.4g} | {one['parts']} | {d1:.2f} | "
            f"{d1 / bl:.1f} | {failed} | {rejected} |")
    # lessin2015's fitness measures its speed and efficiency (named metrics)
    m = one.get("metrics", {})
    muscles = None
    if "efficiency" in m:
        muscles = (f"| {preset} | {seed} | {m['speed']:.4f} | {m['efficiency']:.3f} | {m['muscle_work']:.1f} | "
                   f"{one['parts']} | {one['fitness']:.4g} |")
    return text, muscles


def check_row(preset, seed, run_dir, check_set=()):
    """`bestiary check` of the run's best: ratios to the scored fitness."""
    r = sh(["check", run_dir, "--json"] + [x for kv in check_set for x in ("--set", kv)])
    if r.returncode not in (0, 1):
        sys.exit(r.stderr)
    c = json.loads(r.stdout)
    # "dt/2 (median of 5 seeds)" under check.converge_seeds > 1 counts as "dt/2"
    # and "held (no effectors)" as "held"
    ratio = {v["name"].split(" (")[0]: v for v in c["variants"]}
    # "motor lag +10 ms" and "brain at 30 Hz" by what they are
    for v in c["variants"]:
        name = v["name"].split(" (")[0]
        if name.startswith("motor lag"):
            ratio["lag"] = v
        elif name.startswith("brain at"):
            ratio["half rate"] = v
    cell = lambda n: ("failed" if ratio[n]["failed"] else f"{ratio[n]['ratio']:.2f}") if n in ratio else "-"
    verdict = "pass" if c["passed"] else "FAIL: " + "; ".join(c["failures"])
    if c.get("notes"):
        verdict += " (" + "; ".join(c["notes"]) + ")"
    active = [k for k, sd in enumerate(c["effector_sd"]) if sd >= 0.1]
    hz = ", ".join(f"{c['effector_hz'][k]:.3g}" for k in active) if c.get("effector_hz") else ""
    sustained = f"{c['sustained']['ratio']:.2f}" if "sustained" in c else "-"
    # the fitness selection saw: under elite_evaluations the mean (or least) of several evaluations
    scored = c.get("scored_fitness", c["fitness"])
    return (f"| {preset} | {seed} | {scored:.4g} | {c['other_seeds']:.2f} | {cell('dt/2')} | "
            f"{cell('dt/4')} | {cell('lag')} | {cell('half rate')} | {cell('clamped')} | {cell('held')} | "
            f"{sustained} | {len(active)}/{len(c['effector_sd'])} | {hz or '-'} | {100 * c['max_joint_gap']:.1f} | "
            f"{verdict} |")


def cross_row(preset, seed, run_dir):
    """`bestiary crosscheck` of the run's best: its motor commands replayed open
    loop in MuJoCo under four contact settings, against ODE (docs/export.md)."""
    r = sh(["crosscheck", run_dir, "--json"])
    if r.returncode != 0:
        why = r.stderr.strip().split(": cannot replay it in MuJoCo: ")[-1]
        return f"| {preset} | {seed} | - | - | - | - | - | - | - | not replayed: {why} |", None
    c = json.loads(r.stdout)
    ode = math.hypot(c["ode"][0], c["ode"][1])
    heading = math.degrees(math.atan2(c["ode"][1], c["ode"][0]))
    cells = [f"{v['distance_ratio']:.2f} / {v['heading_difference_deg']:.0f}" for v in c["variants"]]
    verdict = ("moves less than a tenth of its length" if not c["moved"] else
               "the same way" if c["agrees"] else "NOT the same way")
    score = f"{c['ode_fitness']:.4g} / {c['mujoco_fitness']:.4g}"
    row = (f"| {preset} | {seed} | {ode:.2f} m at {heading:.0f} | " + " | ".join(cells) +
           f" | {c['distance_ratio']:.2f} / {c['heading_difference_deg']:.0f} | {score} | {verdict} |")
    return row, flight_row(preset, seed, c)


def flight_row(preset, seed, c):
    """A thrown part's flight, from its release to its landing, in ODE and in
    MuJoCo under each contact setting (None when the task scores no part)."""
    if "ode_flight" not in c:
        return None
    f = c["ode_flight"]
    cells = [f"{v['flight_ratio']:.2f} / {v['flight_heading_difference_deg']:.0f}" for v in c["variants"]]
    return (f"| {preset} | {seed} | {math.hypot(f[0], f[1]):.2f} m at "
            f"{math.degrees(math.atan2(f[1], f[0])):.0f}, landing at {c['landing']:.2f} s | " + " | ".join(cells) +
            f" | {c['flight_ratio']:.2f} / {c['flight_heading_difference_deg']:.0f} |")


CROSS_HEADER = ("\n| preset | seed | ODE: distance at heading (deg) | MuJoCo as exported: ratio / degrees off "
                "| stiffest | elliptic cone | stiffest, elliptic cone | median | task score: ODE / MuJoCo (median) "
                "| MuJoCo |\n|" + "---|" * 10)
FLIGHT_HEADER = ("\n| preset | seed | ODE: flight at heading (deg) | MuJoCo as exported: ratio / degrees off "
                 "| stiffest | elliptic cone | stiffest, elliptic cone | median |\n|" + "---|" * 8)


def stage_rows(preset, seed, run_dir, staged, check_set=()):
    """A syllabus run, a row per stage: its generations, its best in its
    first and last generation, and `bestiary check` of that last best (its
    stage's task and config)."""
    con = sqlite3.connect(os.path.join(run_dir, "run.sqlite"))
    firsts = [g for (g,) in con.execute("select first_gen from stage order by idx")]
    out = []
    for k, (name, _) in enumerate(staged):
        if k >= len(firsts):
            break
        g0 = firsts[k]
        g1 = firsts[k + 1] - 1 if k + 1 < len(firsts) else con.execute("select max(gen) from generation").fetchone()[0]
        b0 = con.execute("select best from generation where gen = ?", (g0,)).fetchone()[0]
        b1, best_id = con.execute("select best, best_id from generation where gen = ?", (g1,)).fetchone()
        r = sh(["check", f"{run_dir}:{best_id}", "--json"] + [x for kv in check_set for x in ("--set", kv)])
        if r.returncode not in (0, 1):
            sys.exit(r.stderr)
        c = json.loads(r.stdout)
        verdict = "pass" if c["passed"] else "FAIL: " + "; ".join(c["failures"])
        # their median or mean, against the held-out fitness where the run measured one
        others = f"{c['other_seeds']:.2f} ({c['other_seeds_statistic']}"
        others += f", of held out {c['held_out']['fitness']:.4g})" if "held_out" in c else ")"
        out.append(f"| {preset} | {seed} | {k + 1} {name} | {g1 - g0 + 1} | {b0:.4g} | {b1:.4g} | {best_id} | "
                   f"{others} | {verdict} |")
    return out


def is_river(run_dir):
    cfg = open(os.path.join(run_dir, "config.toml")).read()
    return re.search(r'^kind = "river"', cfg, re.M) is not None


RIVER_LEVELS = 6
# Table 1 of the paper: share of 20 runs with >0/20/40/60/80% of their final
# 1000 tournaments completing each level
PAPER_TABLE1 = {1: (100, 100, 100, 100, 100), 2: (100, 100, 100, 100, 100), 3: (100, 100, 100, 100, 95),
                4: (85, 85, 85, 30, 10), 5: (85, 65, 50, 20, 0), 6: (65, 20, 0, 0, 0)}
COVERS = (0, 20, 40, 60, 80)


def final_shares(run_dir, tournaments=1000):
    """Per level, the share of the final `tournaments` tournaments' evaluations
    that completed it: the last report intervals covering them, weighted by
    their evaluations."""
    con = sqlite3.connect(os.path.join(run_dir, "run.sqlite"))
    # a run of stages: its last stage's tournaments only (an earlier stage's
    # evaluations may be too short to complete a level, rivercrossing-small's
    # walk); a tournament births one child, so each interval's births count them
    first_gen = first_id = 0
    if stages(run_dir):
        first_gen, first_id = con.execute(
            "select first_gen, first_id from stage order by first_gen desc limit 1").fetchone()
    born = con.execute("select gen, count(*) from individual where id >= ? and gen > ? group by gen order by gen desc",
                       (first_id, first_gen)).fetchall()
    take, span = [], 0
    for g, n in born:
        if span >= tournaments:
            break
        take.append(g)
        span += n
    evals = dict(con.execute("select gen, evaluations - lag(evaluations) over (order by gen) from generation"))
    shares = {}
    for level in range(1, RIVER_LEVELS + 1):
        num = den = 0.0
        for g in take:
            v = con.execute("select nonzero from generation_metric where gen = ? and name = ?",
                            (g, f"level {level} completed")).fetchone()
            w = evals.get(g) or 0
            num += (v[0] if v else 0) * w
            den += w
        shares[level] = 100 * num / den if den else 0
    return shares, span


def river_row(preset, seed, run_dir):
    con = sqlite3.connect(os.path.join(run_dir, "run.sqlite"))
    best, evals = con.execute("select best, evaluations from generation order by gen desc limit 1").fetchone()
    state = json.loads(con.execute("select state from checkpoint").fetchone()[0])
    pop = int(re.search(r"^population = (\d+)", open(os.path.join(run_dir, "config.toml")).read(), re.M).group(1))
    shares, span = final_shares(run_dir)
    svg = os.path.join(run_dir, "levels.svg")
    sh(["plot", run_dir, "--metric", "completed", "--out", svg])
    cells = " | ".join(f"{shares[k]:.1f}" for k in range(1, RIVER_LEVELS + 1))
    # whether evolution got going: food and travel in the first and the last report interval
    first, last = con.execute("select min(gen), max(gen) from generation").fetchone()
    def food(g):
        v = con.execute("select nonzero from generation_metric where gen = ? and name = 'food eaten'", (g,)).fetchone()
        return 100 * v[0] if v else 0
    def travel(g):
        v = con.execute("select avg(distance) from individual where gen = ? and evaluations > 0", (g,)).fetchone()
        return v[0] or 0
    def approach(g):
        v = con.execute("select mean from generation_metric where gen = ? and name = 'approach'", (g,)).fetchone()
        return f"{100 * v[0]:.1f}%" if v else "-"
    start = (f"{food(first):.1f}% → {food(last):.1f}% | {approach(first)} → {approach(last)} | "
             f"{100 * travel(first):.1f} → {100 * travel(last):.1f}")
    # every stage's first generation is a population of its own (random, or the last stage's copied)
    tournaments = state['next_id'] - pop * max(1, len(stages(run_dir)))
    # the best where selection never looked (evolution.held_out_evaluations), if measured
    h = con.execute("select value from run where key = 'held_out'").fetchone()
    held = f"{json.loads(h[0])['fitness']:.4g} ({len(json.loads(h[0])['by_seed'])})" if h else "-"
    return (f"| {preset} | {seed} | {tournaments} | {evals} | {best:.4g} | {held} | {start} | {cells} | {svg} |",
            shares, span)


def river_tables(rows):
    out = [f"\nLevel k: the share (%) of the final {rows[0][2]} tournaments' evaluations that completed level k.",
           "Food: the share of evaluations that ate any, in the first and the last report interval; travel: "
           "the torso's mean travel (cm) per evaluation of the individuals born in them (their latest evaluation); "
           "approach: the mean, over those evaluations, of the levels' progress toward their resources (metric "
           "'approach': a completed level 1, the current one 1 - closest / start distance; runs made before it: -).",
           "Held out: the best's fitness in layouts no evaluation of the run used (evolution.held_out_evaluations; "
           "how many in brackets), where its best fitness is the most of many means that selection kept.",
           "\n| preset | seed | tournaments | evaluations | best fitness | held out | food | approach | travel (cm) | "
           + " | ".join(f"level {k}" for k in range(1, RIVER_LEVELS + 1)) + " | Fig. 5 curve |",
           "|" + "---|" * (10 + RIVER_LEVELS)]
    out += [r[0] for r in rows]
    span = rows[0][2]
    out.append(f"\nTable 1 over these {len(rows)} runs (share of runs whose final {span} tournaments' evaluations "
               "complete the level in more than 0% / at least 20, 40, 60, 80% of them), ours / the paper's (20 runs):")
    out.append("\n| level | " + " | ".join(("> 0%" if c == 0 else f"{c}%") for c in COVERS) + " |")
    out.append("|" + "---|" * (1 + len(COVERS)))
    for level in range(1, RIVER_LEVELS + 1):
        cells = []
        for i, c in enumerate(COVERS):
            n = sum(1 for r in rows if (r[1][level] > 0 if c == 0 else r[1][level] >= c))
            cells.append(f"{100 * n / len(rows):.0f}% / {PAPER_TABLE1[level][i]}%")
        out.append(f"| {level} | " + " | ".join(cells) + " |")
    return "\n".join(out)


def is_throwing(run_dir):
    cfg = open(os.path.join(run_dir, "config.toml")).read()
    return re.search(r'^kind = "throwing"', cfg, re.M) is not None


def half_height(pose, size):
    """Half a box's vertical extent: its half extents projected on the
    vertical (the third row of its rotation matrix)."""
    w, qx, qy, qz = pose[3:7]
    row = (2 * (qx * qz - w * qy), 2 * (qy * qz + w * qx), 1 - 2 * (qx * qx + qy * qy))
    return sum(abs(r) * h / 2 for r, h in zip(row, size))


def throw_of(replay):
    """The projectile's part and the release's time (None: never released),
    from the replay's scene record (its "projectile" part and "release"
    marker; files before the record held them as replay["throw"])."""
    if "throw" in replay:
        return replay["throw"]["projectile"], replay["throw"]["release_t"]
    record = replay["scene"]["record"]
    p = next(q["part"] for q in record["parts"] if q["name"] == "projectile")
    rel = next((m["t"] for m in record.get("markers", []) if m["name"] == "release"), None)
    return p, rel


def throw_profile(replay):
    """How a catapult threw, from its replay (the first trial): the release's
    height and the projectile's top speed after it; the flight (release to the
    projectile's first touch of the ground) and the roll (first touch to rest)
    as horizontal distances; the kick, the projectile's largest horizontal
    speed after it touched the ground over its speed at the touch (above 1
    means something hit it on the ground: a drop-kick, chaumont2007 4.3); the
    body's height at the start (its parts' highest corner) and its mass over
    the projectile's."""
    parts, frames = replay["parts"], replay["frames"]
    p, rel = throw_of(replay)
    size = parts[p]["size"]
    top = max(f[2] + half_height(f, parts[i]["size"])
              for i, f in enumerate(frames[0]["poses"]) if i != p)
    mass = sum(q["mass"] for i, q in enumerate(parts) if i != p) / parts[p]["mass"]
    out = {"height": top, "mass": mass}
    if rel is None:
        return out
    after = [f for f in frames if f["t"] >= rel - 1e-9]
    xy = lambda f: f["poses"][p][:2]
    dist = lambda a, b: ((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2) ** 0.5
    speed = [dist(xy(a), xy(b)) / (b["t"] - a["t"]) for a, b in zip(after, after[1:])]
    vz = [(b["poses"][p][2] - a["poses"][p][2]) / (b["t"] - a["t"]) for a, b in zip(after, after[1:])]
    grounded = lambda f: f["poses"][p][2] - half_height(f["poses"][p], size) < 0.01
    touch = next((k for k, f in enumerate(after) if grounded(f)), len(after) - 1)
    out["release_z"] = after[0]["poses"][p][2]
    out["top_speed"] = max((math.hypot(a, b) for a, b in zip(speed, vz)), default=0)
    out["flight"] = dist(xy(after[0]), xy(after[touch]))
    out["roll"] = dist(xy(after[touch]), xy(after[-1]))
    at = speed[touch - 1] if 0 < touch <= len(speed) else 0
    out["kick"] = max(speed[touch:], default=0) / max(at, 1e-3)
    return out


def early_releases(run_dir, gen):
    """Share of a generation's new individuals whose body fires the release
    before the mechanism's delay (simulated once, evaluation seed 1)."""
    con = sqlite3.connect(os.path.join(run_dir, "run.sqlite"))
    cfg = os.path.join(run_dir, "config.toml")
    text = open(cfg).read()
    dt = float(re.search(r"^dt = ([0-9.e+-]+)", text, re.M).group(1))
    rate = float(re.search(r"^rate_hz = ([0-9.e+-]+)", text, re.M).group(1))
    early = n = 0
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "genome.json")
        for (genome,) in con.execute("select genome from individual where gen = ?", (gen,)):
            open(path, "w").write(genome)
            r = sh(["simulate", path, "--config", cfg, "--json"])
            if r.returncode != 0:
                continue
            one = json.loads(r.stdout)
            marks = one.get("markers", {})  # the task's moments (s)
            t, begin = marks.get("release"), marks.get("begin", 0)
            t = t - begin if t is not None else t  # from the throw's beginning
            steps = json.loads(genome)["catapult"].get("release", {}).get("delay_steps", 30)
            delay = steps / rate  # brain steps at brain.rate_hz
            n += 1
            early += t is not None and 0 <= t < delay - dt / 2
    return f"{100.0 * early / n:.0f}%" if n else "-"


def throw_row(preset, seed, run_dir):
    con = sqlite3.connect(os.path.join(run_dir, "run.sqlite"))
    gens = con.execute("select gen, evaluations, best, failed from generation order by gen").fetchall()
    # evaluations is cumulative: each generation's own are the difference
    per_gen, prev = [], 0
    for g, ev, best, failed in gens:
        per_gen.append((g, ev - prev, best, failed))
        prev = ev
    share = lambda f, n: f"{100.0 * f / n:.1f}%" if n else "-"
    first, last = per_gen[0], per_gen[-1]
    total_failed = sum(x[3] for x in per_gen)
    out = os.path.join(run_dir, "best.json")
    b = sh(["best", run_dir, "--out", out])
    cmd = ["simulate"] + re.search(r"exactly: \S+ simulate (.*)$", b.stderr, re.M).group(1).split()
    replay = os.path.join(run_dir, "best.replay.json")
    one = json.loads(sh(cmd + ["--json", "--replay", replay]).stdout)
    prof = throw_profile(json.load(open(replay)))
    opt = lambda k, f="{:.2f}": f.format(prof[k]) if k in prof else "-"
    genome = json.load(open(out))
    size = genome["nodes"][genome["catapult"]["projectile"]]["size"]
    # the same creature under other evaluation seeds (drop the exact one)
    base = cmd[:cmd.index("--seed")] if "--seed" in cmd else cmd
    others = sorted(json.loads(sh(base + ["--seed", str(k), "--json"]).stdout)["distance"] for k in range(1, 6))
    miss = one.get("metrics", {}).get("target miss")  # the aim task's metric (m)
    early0, early1 = early_releases(run_dir, first[0]), early_releases(run_dir, last[0])
    marks = one.get("markers", {})  # the task's moments (s)
    release = marks.get("release")
    if release is not None:
        release -= marks.get("begin", 0)  # from the throw's beginning (its rest)
    head = f"| {preset} | {seed} | "
    result = (head + f"{gens[-1][1]} | {first[2]:.3g} | {last[2]:.3g} | "
              f"{one['distance']:.2f} | {'-' if miss is None else f'{miss:.2f}'} | {others[2]:.2f} | "
              f"{share(first[3], first[1])} | {share(last[3], last[1])} | {share(total_failed, gens[-1][1])} |")
    how = (head + f"{one['parts']} | {prof['height']:.2f} | {prof['mass']:.3g} | "
           f"{' x '.join(f'{v:.3g}' for v in size)} | "
           f"{'never' if release is None or release < 0 else f'{release:.3f}'} | {opt('release_z')} | "
           f"{opt('top_speed', '{:.1f}')} | {opt('flight')} | {opt('roll')} | {opt('kick', '{:.1f}')} | "
           f"{early0} | {early1} |")
    return result, how


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+", help="PRESET:SEEDS, seeds as N or A-B")
    ap.add_argument("--runs-dir", default="runs/results")
    ap.add_argument("--workers", default="2")
    ap.add_argument("--check-set", action="append", default=[], metavar="KEY=VALUE",
                    help="a [check] key for `bestiary check` (repeatable), e.g. check.converge_seeds=5 "
                         "for runs made before their preset set it")
    a = ap.parse_args()
    rows, throws, checks, rivers, speeds, syllabus, crosses = [], [], [], [], [], [], []
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
            staged = stages(run_dir)
            if staged:
                rows_of_run = stage_rows(preset, seed, run_dir, staged, a.check_set)
                syllabus.extend(rows_of_run)
                print("\n".join(rows_of_run), flush=True)
                if is_river(run_dir):
                    # its last stage's statistics (Table 1 over its final report intervals)
                    rivers.append(river_row(preset, seed, run_dir))
                    print(rivers[-1][0], flush=True)
                continue
            checks.append(check_row(preset, seed, run_dir, a.check_set))
            print(checks[-1], flush=True)
            if not is_river(run_dir):
                crosses.append(cross_row(preset, seed, run_dir))
                print("\n".join(r for r in crosses[-1] if r), flush=True)
            if is_river(run_dir):
                rivers.append(river_row(preset, seed, run_dir))
                print(rivers[-1][0], flush=True)
                continue
            if is_throwing(run_dir):
                throws.append(throw_row(preset, seed, run_dir))
                print("\n".join(throws[-1]), flush=True)
                continue
            text, muscles = row(preset, seed, run_dir)
            rows.append(text)
            print(rows[-1], flush=True)
            if muscles:
                speeds.append(muscles)
                print(muscles, flush=True)
    if throws:
        print("\n| preset | seed | evaluations | best, first generation | best, last | throw (m) | target miss (m) "
              "| median throw, seeds 1-5 (m) | discarded, first generation | discarded, last | discarded, run |")
        print("|" + "---|" * 11)
        print("\n".join(t[0] for t in throws))
        print("\n| preset | seed | parts | height (m) | body / projectile mass | projectile (m) | release (s after the start) "
              "| release height (m) | top speed (m/s) | flight (m) | roll (m) | kick "
              "| early release, first generation | early release, last |")
        print("|" + "---|" * 14)
        print("\n".join(t[1] for t in throws))
    if checks:
        print("\n| preset | seed | best (scored) | other seeds (median) | dt/2 | dt/4 | motor lag +10 ms "
              "| brain at half rate | clamped | held | sustained | active effectors (s.d. >= 0.1) "
              "| their frequencies (Hz) | largest joint gap (cm) | check |")
        print("|" + "---|" * 15)
        print("\n".join(checks))
    if crosses:
        print(CROSS_HEADER)
        print("\n".join(row for row, _ in crosses))
        flights = [f for _, f in crosses if f]
        if flights:
            print(FLIGHT_HEADER)
            print("\n".join(flights))
    if syllabus:
        print("\n| preset | seed | stage | generations | best, first generation | best, last | its id "
              "| other seeds | check |")
        print("|" + "---|" * 9)
        print("\n".join(syllabus))
    if rivers:
        print(river_tables(rivers))
    if not rows:
        return
    print("\n| preset | seed | evaluations | best, first generation | best, last | parts | distance (m) "
          "| body lengths | failed | rejected |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    print("\n".join(rows))
    if speeds:
        print("\n| preset | seed | speed (m/s, the lesser half's) | efficiency | muscle work (J) | parts | fitness |")
        print("|" + "---|" * 7)
        print("\n".join(speeds))


if __name__ == "__main__":
    main()
