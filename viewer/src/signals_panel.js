// The signals panel: between brain and body, one group each for the
// effectors' signals, the sensors' readings and the joints' angles, each
// group a list of traces (sparklines.js) that opens and closes.
import { el } from './dom.js';
import { signalGroups } from './signals.js';
import { createTraceList } from './sparklines.js';

/**
 * The panel for `replay` in `container`: { rows: {effectors, sensors,
 * joints} (traces drawn per group), setTime(t), dispose() }.
 */
export function createSignalsPanel(container, replay) {
  container.replaceChildren(el('h2', {}, 'Signals'));
  const lists = [];
  const rows = {};
  for (const g of signalGroups(replay)) {
    const constant = g.series.filter((s) => s.constant).length;
    const summary = el('summary', {},
      el('span', { class: 'group-title' }, `${g.title} (${g.series.length})`),
      constant ? el('span', { class: 'badge constant', title: `${constant} of them constant` }, `${constant} constant`) : null,
      el('span', { class: 'group-note' }, g.axis));
    const group = el('details', { class: 'group', 'data-group': g.key, open: true }, summary);
    rows[g.key] = 0;
    if (g.missing) {
      group.append(el('p', { class: 'muted' }, 'not in this replay (written before replays recorded them)'));
    } else if (g.series.length === 0) {
      group.append(el('p', { class: 'muted' }, `This creature has no ${g.key === 'joints' ? 'joints that move' : g.key}.`));
    } else {
      const list = createTraceList(g.series, replay.frames);
      group.append(list.element);
      lists.push(list);
      rows[g.key] = list.rows;
    }
    container.append(group);
  }
  lists.forEach((l) => l.redraw());
  return {
    rows,
    setTime(t) { for (const l of lists) l.setTime(t); },
    dispose() { for (const l of lists) l.dispose(); },
  };
}
