// MUSHRA (ITU-R BS.1534): 0-100 quality against the open reference; the hidden reference and the
// anchors are among the lettered sounds.
import graded from './graded.js';

export default function mushra(trial) {
  return graded(trial, {
    prompt: 'Rate the quality of each sound compared with the reference. Click another sound while one plays to switch at the same moment.',
    labels: ['Excellent', 'Good', 'Fair', 'Poor', 'Bad'], min: 0, max: 100, step: 1, start: 0, decimals: 0,
  });
}
