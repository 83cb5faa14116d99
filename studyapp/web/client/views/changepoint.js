// Change points over one sweep: the sounds in their fixed order, each with a play button and, from the
// second on, a "Changed here" toggle that works once that sound was heard; any number of marks (or
// none) once every sound was heard (the server's gate has the last word).
import { allIndices, el, prompt, sequenceButton } from './common.js';

export default function changepoint(trial) {
  const page = trial.page;
  prompt(trial, 'The sounds are one object whose material changes little by little. Listen to them in order and ' +
                'mark each sound at which, in your opinion, the material changed (any number, or none).');
  sequenceButton(trial, allIndices(page), '▶ Play all in order');
  const marks = [];
  // Down two columns, three for long sweeps, so a sweep of 19 fits a 1024x600 screen with Next in sight
  // (set through the CSSOM: the page's CSP refuses style attributes).
  const list = el('div', { class: 'sweep' });
  const columns = page.sounds.length > 12 ? 3 : 2;
  list.style.gridTemplateColumns = `repeat(${columns}, minmax(0, 1fr))`;
  list.style.gridTemplateRows = `repeat(${Math.ceil(page.sounds.length / columns)}, auto)`;
  for (const i of allIndices(page)) {
    const play = el('button', { type: 'button', class: 'sound', id: `play-${i}`, text: `▶ ${i + 1}`,
                                'aria-label': page.sounds[i].label });
    play.addEventListener('click', () => trial.player.play(i));
    trial.soundButtons[i] = play;
    const row = el('div', { class: 'sweep-row' }, play);
    if (i > 0) {
      const mark = el('button', { type: 'button', class: 'mark', id: `mark-${i}`, 'aria-pressed': 'false', text: 'Changed here' });
      mark.disabled = true;
      mark.addEventListener('click', () => {
        mark.setAttribute('aria-pressed', String(mark.getAttribute('aria-pressed') !== 'true'));
        trial.refresh();
      });
      marks[i] = mark;
      row.append(mark);
    }
    list.append(row);
  }
  trial.root.append(list);
  trial.onRefresh = () => {
    for (const [i, mark] of Object.entries(marks)) if (mark) mark.disabled = !trial.heard.has(Number(i));
  };
  const marked = () => marks.flatMap((m, i) => (m && m.getAttribute('aria-pressed') === 'true' ? [i] : []));
  return { answer: () => ({ marks: marked() }), complete: () => true };
}
