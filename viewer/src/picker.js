// The choice of creature. A run's page offers each generation's best, and
// the lineage of the creature chosen that way: its first parents back to
// generation 0, each playable when the page holds its replay. A page of
// several replays without a run lists them by label; a page of one has none.
import { el } from './dom.js';
import { generationChoices } from './curves.js';
import { fitness } from './format.js';

/** How a lineage member's row reads: generation, id, how it was made, fitness. */
export function lineageText(m) {
  const parents = m.parent2 === null ? '' : ` with #${m.parent2}`;
  return `gen ${m.gen} · #${m.id} · ${m.operator || '?'}${parents} · ${fitness(m.fitness)}`;
}

/**
 * The picker in `container` for the page data `data`. For a run,
 * `on.generation(gen)` and `on.member(id)` report the user's choice; for a
 * page without a run, `on.replay(i)`. `setCurrent({index, gen, anchor,
 * lineage, member})` shows what is on the stage.
 */
export function createPicker(container, data, on) {
  container.replaceChildren();
  if (!data.run) {
    container.hidden = data.replays.length < 2;
    const select = el('select', { id: 'replay', 'aria-label': 'creature' },
      ...data.replays.map((r, i) => el('option', { value: String(i) }, r.label)));
    select.addEventListener('change', () => on.replay(Number(select.value)));
    container.append(el('label', { class: 'row' }, 'Creature ', select));
    return { setCurrent({ index }) { select.value = String(index); } };
  }

  container.hidden = false;
  const choices = generationChoices(data.run);
  // a lineage member that is no generation's best leaves the list on "-"
  const select = el('select', { id: 'generation', 'aria-label': 'best of generation' },
    el('option', { value: '', disabled: true }, '-'),
    ...choices.map((c) => el('option', { value: String(c.gen), disabled: c.replayIndex === null },
      `${c.gen}: #${c.id} · ${fitness(c.best)}` + (c.id === data.run.best_id ? ' (overall best)' : '') +
      (c.replayIndex === null ? ' (not replayed)' : ''))));
  select.addEventListener('change', () => on.generation(Number(select.value)));
  const title = el('h3', {});
  const list = el('ol', { class: 'lineage-list' });
  container.append(
    el('h2', {}, 'Creatures'),
    el('label', { class: 'row' }, 'Best of generation ', select),
    title,
    list);

  return {
    setCurrent({ gen, anchor, lineage, member }) {
      select.value = gen === null ? '' : String(gen);
      title.textContent = `Lineage of #${anchor}: first parents back to generation 0`;
      list.replaceChildren(...lineage.map((m) => {
        const playable = m.replay_index !== null;
        const button = el('button', {
          type: 'button', class: 'lineage-item', 'data-id': String(m.id), disabled: !playable,
          'aria-current': m === member ? 'true' : null,
          title: playable ? `play #${m.id}` : `#${m.id} is not replayed on this page (at most ${data.run.replay_cap} replays)`,
        }, lineageText(m), playable ? null : el('span', { class: 'not-replayed' }, ' not replayed'));
        button.addEventListener('click', () => on.member(m.id));
        return el('li', {}, button);
      }));
    },
  };
}
