// A/B trials: same/different, preference, ABX ("X is A" / "X is B"), 2AFC and the bipolar -3..+3 scale.
import { allIndices, choices, el, note, prompt, soundButtons } from './common.js';

const kPrompts = {
  same_different: 'Are A and B the same or different?',
  preference: 'Which sound do you prefer?',
  abx: 'Is X the same as A or the same as B?',
  '2afc': 'Which of the two sounds is the different one (the target)?',
};

export default function ab(trial) {
  const page = trial.page;
  const bipolarPrompt = page.with_reference ? 'Which of A and B is closer to the reference? (-3: A much closer … +3: B much closer)'
                                            : 'Compared with A, how is B? (-3 much worse … +3 much better)';
  prompt(trial, page.bipolar ? bipolarPrompt : kPrompts[page.mode] || 'Choose A or B.');
  if (page.with_reference && !page.bipolar) note(trial, 'The reference plays after A and B.');
  soundButtons(trial, allIndices(page));
  if (page.bipolar) {
    const points = [];
    for (let v = -3; v <= 3; ++v) points.push({ value: v, label: v > 0 ? `+${v}` : String(v) });
    const row = el('div', { class: 'scale' });
    trial.root.append(row);
    const pick = choices(trial, points, row);
    return { answer: () => pick.value(), complete: () => pick.value() !== null };
  }
  const pick = choices(trial, page.choices);
  return { answer: () => pick.value(), complete: () => pick.value() !== null };
}
