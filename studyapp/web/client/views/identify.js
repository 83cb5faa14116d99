// Identification: the sound, then one of the block's labels.
import { allIndices, choices, prompt, soundButtons } from './common.js';

export default function identify(trial) {
  prompt(trial, 'Listen to the sound, then choose what it is.');
  soundButtons(trial, allIndices(trial.page));
  const pick = choices(trial, trial.page.labels.map((l) => ({ value: l, label: l })));
  return { answer: () => pick.value(), complete: () => pick.value() !== null };
}
