// Adaptive token series, one comparison per page: the reference token, then the next one (the same
// sound with fewer modes, never named); do they sound different? The series ends after the last token.
import { sameOrDifferentStep } from './common.js';

export default function tokens(trial) {
  return sameOrDifferentStep(trial, {
    task: 'Listen to the reference, then to the next sound. Do they sound different?',
    sequence: '▶ Play the reference, then the next sound',
    step: `Comparison ${trial.page.step + 1} of ${trial.page.comparisons} — the series ends with the simplest sound.`,
  });
}
