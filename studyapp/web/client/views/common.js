// Building blocks every view uses: elements, the prompt, sound buttons, a row of exclusive choices.
export function el(tag, attrs = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === 'class') e.className = v;
    else if (k === 'text') e.textContent = v;
    else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c);
  return e;
}

export function prompt(trial, fallback) {
  trial.root.append(el('p', { class: 'prompt', text: trial.page.prompt || fallback }));
}

export function note(trial, text) { trial.root.append(el('p', { class: 'note', text })); }

// One button per sound index; a click plays it (or, while another plays, switches at the same moment
// when `switching`). Buttons show heard and playing; trial.refresh() keeps them current.
export function soundButtons(trial, indices, { switching = false, parent = null } = {}) {
  const row = el('div', { class: 'sounds' });
  for (const i of indices) {
    const b = el('button', { type: 'button', class: 'sound', id: `play-${i}`, text: `▶ ${trial.page.sounds[i].label}` });
    b.addEventListener('click', () => (switching && trial.player.playingIndex() >= 0 ? trial.player.switchTo(i) : trial.player.play(i)));
    trial.soundButtons[i] = b;
    row.append(b);
  }
  if (switching) row.append(el('button', { type: 'button', id: 'stop', text: '■ Stop', onclick: () => trial.player.stop() }));
  (parent || trial.root).append(row);
  return row;
}

// A button playing the sounds `indices` in order, 400 ms apart; it stops when the trial closes.
export function sequenceButton(trial, indices, text) {
  const b = el('button', { type: 'button', id: 'play-sequence', text });
  b.addEventListener('click', async () => {
    for (const i of indices) {
      await trial.player.play(i);
      await new Promise((done) => setTimeout(done, trial.player.buffers[i].duration * 1000 + 400));
      if (trial.closed) return;
    }
  });
  trial.root.append(b);
  return b;
}

// One step of a series run inside its trial (limits, tokens): the reference and the second sound, a
// button playing them in order, Same / Different (the page's choices) and where the series is.
export function sameOrDifferentStep(trial, { task, sequence, step }) {
  prompt(trial, task);
  sequenceButton(trial, [0, 1], sequence);
  soundButtons(trial, [0, 1]);
  const pick = choices(trial, trial.page.choices);
  trial.root.append(el('p', { class: 'note', id: 'step', text: step }));
  return { answer: () => pick.value(), complete: () => pick.value() !== null };
}

// Exclusive choices [{value, label}]; returns () => the chosen value or null.
export function choices(trial, list, parent = null) {
  let chosen = null;
  const row = el('div', { class: 'choices', role: 'radiogroup' });
  for (const c of list) {
    const b = el('button', { type: 'button', class: 'choice', 'data-value': String(c.value), 'aria-pressed': 'false', text: c.label });
    b.addEventListener('click', () => {
      chosen = c.value;
      for (const other of row.children) other.setAttribute('aria-pressed', String(other === b));
      trial.refresh();
    });
    row.append(b);
  }
  (parent || trial.root).append(row);
  return { value: () => chosen, reset: () => { chosen = null; for (const b of row.children) b.setAttribute('aria-pressed', 'false'); } };
}

export const allIndices = (page) => page.sounds.map((_, i) => i);
