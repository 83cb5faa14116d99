// Graded sounds against an open reference (MUSHRA, BS.1116): the reference first, then per lettered
// sound a play button and a vertical slider beside the scale's five labels; clicking a sound while one
// plays switches at the same moment; the sounds loop. Keys: 1 plays the reference, 2..9 the lettered
// sounds. A slider shows no grade until moved (an untouched slider is not a grade). The answer is keyed
// by the sounds' opaque ids: the page never knows which is the hidden reference or an anchor.
import { el, prompt, soundButtons } from './common.js';

export default function graded(trial, scale) {
  const page = trial.page;
  prompt(trial, scale.prompt);
  trial.player.setLoop(true);
  soundButtons(trial, [0], { switching: true });
  const grid = el('div', { class: 'graded' });
  grid.append(el('div', { class: 'labels' }, ...scale.labels.map((q) => el('span', { text: q }))));
  const moved = new Set();
  const sliders = [];
  for (let i = 1; i < page.sounds.length; ++i) {
    const column = el('div', { class: 'column' });
    const slider = el('input', { type: 'range', min: String(scale.min), max: String(scale.max), step: String(scale.step),
                                 value: String(scale.start), id: `rate-${i}`, 'aria-label': `Grade of ${page.sounds[i].label}` });
    const value = el('output', { text: '\u2013' });
    slider.addEventListener('input', () => {
      moved.add(i);
      value.textContent = Number(slider.value).toFixed(scale.decimals);
      trial.refresh();
    });
    column.append(slider, value);
    soundButtons(trial, [i], { switching: true, parent: column });
    sliders.push([i, slider]);
    grid.append(column);
  }
  trial.root.append(grid);
  trial.keys = (key) => {
    const n = Number(key);
    if (n >= 1 && n <= page.sounds.length) {
      const i = n - 1;
      trial.player.playingIndex() >= 0 ? trial.player.switchTo(i) : trial.player.play(i);
    }
  };
  const left = () => sliders.length - moved.size;
  return {
    answer: () => Object.fromEntries(sliders.map(([i, s]) => [page.sounds[i].id, Number(Number(s.value).toFixed(scale.decimals))])),
    moved: () => [...moved].map((i) => page.sounds[i].id),
    complete: () => left() === 0,
    missing: () => `Rate every sound: move each slider at least once (${left()} ${left() === 1 ? 'is' : 'are'} not rated yet).`,
  };
}
