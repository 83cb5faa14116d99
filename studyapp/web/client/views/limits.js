// Descending method of limits, one pair per page: the reference, then the second sound (the stimulus
// at the series' level, never named); does the second sound differ? The series ends at a "different".
import { choices, el, prompt, soundButtons } from './common.js';

export default function limits(trial) {
  const page = trial.page;
  prompt(trial, 'Listen to the reference, then to the second sound. Do you hear a change?');
  const sequence = el('button', { type: 'button', id: 'play-sequence', text: '▶ Play reference, then the second sound' });
  sequence.addEventListener('click', async () => {
    for (let i = 0; i < 2; ++i) {
      await trial.player.play(i);
      await new Promise((done) => setTimeout(done, trial.player.buffers[i].duration * 1000 + 400));
      if (trial.closed) return;
    }
  });
  trial.root.append(sequence);
  soundButtons(trial, [0, 1]);
  const pick = choices(trial, page.choices);
  trial.root.append(el('p', { class: 'note', id: 'step',
    text: `Pair ${page.step + 1} of this series — the series ends when you hear a change.` }));
  return { answer: () => pick.value(), complete: () => pick.value() !== null };
}
