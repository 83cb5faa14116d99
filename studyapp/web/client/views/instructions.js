// Instructions: the text, then Next.
import { el } from './common.js';

export default function instructions(trial) {
  trial.root.append(el('p', { class: 'instructions', text: trial.page.text || '' }));
  return { answer: () => 'ok', complete: () => true };
}
