// A run's line of descent: each individual's first parent, back to
// generation 0 (the first parent is the one the child is a copy of; the run
// page's gathering, src/io/run_page.cpp, says why it follows that one).

/** The run's members by id. */
export function membersById(run) {
  return new Map(run.members.map((m) => [m.id, m]));
}

/**
 * Individual `id` and its first parents back to generation 0, as members,
 * newest first. Stops at an ancestor the page does not hold.
 */
export function lineageOf(byId, id) {
  const out = [];
  const seen = new Set();
  for (let m = byId.get(id); m && !seen.has(m.id); m = byId.get(m.parent1)) {
    seen.add(m.id);
    out.push(m);
  }
  return out;
}

/** The member whose replay is `replayIndex` (null for none). */
export function memberOfReplay(run, replayIndex) {
  return run.members.find((m) => m.replay_index === replayIndex) ?? null;
}

/** The generations whose best individual `id` is, in order. */
export function bestOf(run, id) {
  return run.generations.filter((g) => g.best_id === id).map((g) => g.gen);
}

/** "3", "3-10" or "3, 5-7": generations as short ranges. */
export function generationRanges(gens) {
  const parts = [];
  for (let i = 0; i < gens.length;) {
    let j = i;
    while (j + 1 < gens.length && gens[j + 1] === gens[j] + 1) ++j;
    parts.push(j > i ? `${gens[i]}-${gens[j]}` : String(gens[i]));
    i = j + 1;
  }
  return parts.join(', ');
}
