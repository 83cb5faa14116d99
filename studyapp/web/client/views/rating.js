// Rating: one k-point scale per attribute, between its low and high labels.
import { allIndices, choices, el, prompt, soundButtons } from './common.js';

export default function rating(trial) {
  prompt(trial, 'Listen to the sound, then rate it on every scale.');
  soundButtons(trial, allIndices(trial.page));
  const picks = {};
  for (const a of trial.page.attributes) {
    trial.root.append(el('p', { class: 'question', text: a.name }));
    const row = el('div', { class: 'scale', 'data-attribute': a.name });
    row.append(el('span', { class: 'note', text: a.low || '' }));
    trial.root.append(row);
    const points = Array.from({ length: a.points }, (_, i) => ({ value: i + 1, label: String(i + 1) }));
    picks[a.name] = choices(trial, points, row);
    row.append(el('span', { class: 'note', text: a.high || '' }));
  }
  const values = () => Object.fromEntries(Object.entries(picks).map(([k, p]) => [k, p.value()]));
  return {
    answer: values,
    complete: () => Object.values(picks).every((p) => p.value() !== null),
    missing: 'Choose a point on every scale.',
  };
}
