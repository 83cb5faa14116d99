// Method of adjustment: one 0-100 slider per protocol slider between its end labels. A release (or a
// key) asks the server for the sound at the sliders' positions, which then plays; moves during a render
// are coalesced into one more render. The answer is the values of the sound last made (and heard).
import { el, prompt, soundButtons } from './common.js';
import { render } from '../api.js';

export default function adjust(trial) {
  const page = trial.page;
  prompt(trial, page.target
    ? 'Move the sliders until your sound matches the target sound. Each change plays the new sound; play the target as often as you like.'
    : 'Move the sliders until the sound seems right to you. Each change plays the new sound.');
  const inputs = [];
  for (const s of page.sliders) {
    const row = el('div', { class: 'slider-row' });
    const input = el('input', { type: 'range', min: '0', max: '100', step: '1', value: String(s.start), id: `adjust-${s.key}`,
                                'aria-label': s.label });
    const shown = el('span', { class: 'note' });
    row.append(el('b', { text: s.label }), el('span', { text: s.low || '' }), input, el('span', { text: s.high || '' }), shown);
    input.addEventListener('change', () => request());
    trial.root.append(row);
    inputs.push(input);
  }
  soundButtons(trial, page.sounds.map((_, i) => i));
  const status = el('p', { class: 'note', id: 'resynth-status' });
  trial.root.append(status);
  let values = page.values;
  let busy = false;
  let dirty = false;

  async function request() {
    if (busy) { dirty = true; trial.refresh(); return; }
    busy = true;
    dirty = false;
    status.textContent = 'Making the new sound…';
    trial.refresh();
    try {
      const made = await render({ trial: page.trial, step: page.step, positions: inputs.map((i) => Number(i.value)) });
      if (trial.closed) return;
      await trial.player.replace(page.adjusted, made.sound.id);
      page.sounds[page.adjusted].id = made.sound.id;
      trial.heard.delete(page.adjusted);  // the new version has not been heard
      values = made.values;
      status.textContent = '';
      busy = false;
      if (dirty) return request();
      await trial.player.play(page.adjusted);
    } catch (e) {
      status.textContent = e.message;
      busy = false;
    }
    trial.refresh();
  }

  return {
    answer: () => values,
    complete: () => !busy && !dirty,
    missing: 'Making the new sound…',
  };
}
