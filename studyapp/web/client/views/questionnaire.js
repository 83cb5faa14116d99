// Questionnaire: free-text questions and questions with options (those must be answered).
import { choices, el } from './common.js';

export default function questionnaire(trial) {
  const answers = {};
  for (const q of trial.page.questions) {
    trial.root.append(el('label', { class: 'question', for: `q-${q.id}`, text: q.text }));
    if (q.options.length) {
      const pick = choices(trial, q.options.map((o) => ({ value: o, label: o })));
      answers[q.id] = () => pick.value();
    } else {
      const area = el('textarea', { id: `q-${q.id}`, maxlength: '2000' });
      area.addEventListener('input', () => trial.refresh());
      trial.root.append(area);
      answers[q.id] = () => area.value;
    }
  }
  return {
    answer: () => Object.fromEntries(Object.entries(answers).map(([k, f]) => [k, f() ?? ''])),
    complete: () => trial.page.questions.every((q) => !q.options.length || answers[q.id]() !== null),
    missing: 'Answer every question that has choices.',
  };
}
