#!/usr/bin/env python3
"""Read Bestiary run folders from Python (docs/run-database.md, "From Python").

Standard library only (sqlite3, json, subprocess); pandas, where installed
(Debian: python3-pandas), turns any table into a DataFrame.

    import sys; sys.path.insert(0, "scripts")
    from bestiary_runs import Run
    run = Run("runs/quick-DATE")
    run.facts["seed"]                 # the run's facts: name, seed, build, ...
    gens = run.generations()          # one dict a generation: generation, stage, evaluations, best, ...
    inds = run.individuals()          # one dict a creature born (without its genome)
    run.metrics()                     # the task's named measures per generation
    run.genome(15)                    # individual 15's genome, as parsed JSON
    run.resimulate(15)                # `bestiary simulate RUN:15 --json`: its evaluation again
    run.frame("generations")          # a pandas DataFrame (needs pandas)

As a command, `scripts/bestiary_runs.py RUN_DIR...` prints one line a run:
its name, seed, generations, evaluations, first and last best.
"""
import json
import os
import sqlite3
import subprocess
import sys


class Run:
    """One run folder, its database opened read-only (a run going on can be read)."""

    def __init__(self, path):
        self.path = path
        db = os.path.join(path, "run.sqlite")
        if not os.path.isfile(db):
            raise FileNotFoundError(f"{path}: no run database (run.sqlite) there")
        self.db = sqlite3.connect(f"file:{db}?mode=ro", uri=True)
        self.db.row_factory = sqlite3.Row
        self.facts = {r["key"]: r["value"] for r in self.db.execute("SELECT key, value FROM run")}

    def _rows(self, sql, args=()):
        return [dict(r) for r in self.db.execute(sql, args)]

    def _has_table(self, name):
        return bool(self._rows("SELECT 1 FROM sqlite_schema WHERE type = 'table' AND name = ?", (name,)))

    def generations(self):
        """One dict a generation (steady state: a report interval), with its stage's name."""
        stage = ("COALESCE((SELECT name FROM stage WHERE first_gen <= g.gen ORDER BY first_gen DESC LIMIT 1), '')"
                 if self._has_table("stage") else "''")
        return self._rows(f"SELECT g.gen AS generation, {stage} AS stage, g.evaluations, g.best, g.mean, "
                          "g.median, g.best_id, g.rejected, g.failed FROM generation g ORDER BY g.gen")

    def individuals(self):
        """One dict a creature born, without its genome (genome(id) reads that)."""
        return self._rows("SELECT id, gen AS generation, fitness, distance, evaluations, parent1, parent2, "
                          "operator, failure, seed, kind FROM individual ORDER BY id")

    def metrics(self):
        """The task's named measures: one dict per generation and measure."""
        return self._rows("SELECT gen AS generation, name AS metric, mean, nonzero AS nonzero_share "
                          "FROM generation_metric ORDER BY gen, name")

    def genome(self, ident):
        """Individual `ident`'s genome (its kind's JSON form), parsed."""
        rows = self._rows("SELECT genome FROM individual WHERE id = ?", (ident,))
        if not rows:
            raise KeyError(f"{self.path}: no individual {ident}")
        return json.loads(rows[0]["genome"])

    def resimulate(self, ident, bestiary=None):
        """Individual `ident` evaluated again by the bestiary command, on the run's
        config and its own seed: `simulate RUN:ID --json` parsed (its fitness is the
        stored one, bit for bit)."""
        exe = bestiary or os.environ.get("BESTIARY", os.path.join(os.path.dirname(__file__), "..", "build", "bestiary"))
        out = subprocess.run([exe, "simulate", f"{self.path}:{ident}", "--json"],
                             capture_output=True, text=True, check=True)
        return json.loads(out.stdout)

    def frame(self, table):
        """generations, individuals or metrics as a pandas DataFrame."""
        import pandas  # Debian: python3-pandas
        return pandas.DataFrame(getattr(self, table)())


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print("usage: bestiary_runs.py RUN_DIR...  (one line a run; import it for tables)", file=sys.stderr)
        return 2
    for path in argv[1:]:
        try:
            run = Run(path)
        except (FileNotFoundError, sqlite3.Error) as e:
            print(f"bestiary_runs.py: {e}", file=sys.stderr)
            return 2
        g = run.generations()
        if not g:
            print(f"{path}: {run.facts.get('name', '?')} seed {run.facts.get('seed', '?')}: no generation yet")
            continue
        print(f"{path}: {run.facts.get('name', '?')} seed {run.facts.get('seed', '?')}: {len(g)} generations, "
              f"{g[-1]['evaluations']} evaluations, best {g[0]['best']:.4g} -> {g[-1]['best']:.4g}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
