// Adaptive staircase, one step per page: the reference, then A and B (one of them the reference again,
// the other the stimulus at the track's level); which of A and B is the same as the reference?
import { choices, el, prompt, sequenceButton, soundButtons } from './common.js';

export default function staircase(trial) {
  const page = trial.page;
  prompt(trial, 'Listen to the reference, then to A and B. Which of A and B is the same as the reference?');
  sequenceButton(trial, [0, 1, 2], '▶ Play reference, A, B');
  soundButtons(trial, [0, 1, 2]);
  const pick = choices(trial, page.choices);
  trial.root.append(el('p', { class: 'note', id: 'step',
    text: `Step ${page.step + 1} of at most ${page.max_steps} · ${page.reversals} of ${page.max_reversals} turning points — this part ends after ${page.max_reversals} turning points.` }));
  return { answer: () => pick.value(), complete: () => pick.value() !== null };
}
