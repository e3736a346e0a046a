// The choice between the page's replays by label, when it holds more than one.
import { el } from './dom.js';

/** A replay list in `container`; hidden for a single replay. */
export function createPicker(container, replays, onChoose) {
  container.replaceChildren();
  container.hidden = replays.length < 2;
  const select = el('select', { id: 'replay', 'aria-label': 'creature' },
    ...replays.map((r, i) => el('option', { value: String(i) }, r.label)));
  select.addEventListener('change', () => onChoose(Number(select.value)));
  container.append(el('label', { class: 'row' }, 'Creature ', select));
  return {
    setCurrent(i) {
      select.value = String(i);
    },
  };
}
