// Descending method of limits, one pair per page: the reference, then the second sound (the stimulus
// at the series' level, never named); does the second sound differ? The series ends at a "different".
import { sameOrDifferentStep } from './common.js';

export default function limits(trial) {
  return sameOrDifferentStep(trial, {
    task: 'Listen to the reference, then to the second sound. Do you hear a change?',
    sequence: '▶ Play reference, then the second sound',
    step: `Pair ${trial.page.step + 1} of this series — the series ends when you hear a change.`,
  });
}
