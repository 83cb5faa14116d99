// BS.1116 (double-blind triple-stimulus with hidden reference): A and B, one of them the reference
// itself, graded on the continuous impairment scale 1.0-5.0 with one decimal.
import graded from './graded.js';

export default function bs1116(trial) {
  return graded(trial, {
    prompt: 'One of A and B is the reference itself. Grade how much each differs from the reference (5.0 = no difference heard).',
    labels: ['5 Imperceptible', '4 Perceptible, not annoying', '3 Slightly annoying', '2 Annoying', '1 Very annoying'],
    min: 1, max: 5, step: 0.1, start: 5, decimals: 1,
  });
}
