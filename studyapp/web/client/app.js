// The participant's page: shows the trial the server sends, offers its sounds, sends what was played
// and the answer; the server commits the answer before it returns the next trial. Reloading the page
// resumes at the first unanswered trial. The server checks everything again (the answer gate too).
import * as api from './api.js';
import { Player } from './audio.js';
import { el } from './views/common.js';
import { views } from './views/index.js';

const view = document.getElementById('view');
const next = document.getElementById('next');
const hint = document.getElementById('hint');
const progress = document.getElementById('progress');
let trial = null;
let waiting = null;  // resolves when Continue is pressed (feedback, break)

const player = new Player((kind, index, atMs, positionS) => {
  if (!trial) return;
  if (kind !== 'stop') trial.heard.add(index);
  const { page } = trial;
  api.sendEvent({ trial: page.trial, step: page.step, kind, sound: page.sounds[index].id, at_ms: atMs, position_s: positionS })
    .catch((e) => { hint.textContent = e.message; });
  refresh();
}, () => refresh());

// What the participant still has to do, as the window says it; the server's gate has the last word.
function missing() {
  const { page } = trial;
  const listening = page.type !== 'instructions' && page.type !== 'questionnaire';
  const heard = page.sounds.filter((_, i) => trial.heard.has(i)).length;
  if (listening && page.listen_all && heard < page.sounds.length) {
    return page.sounds.length === 1 ? 'Listen to the sound before answering.'
                                    : `Listen to every sound before answering (${heard} of ${page.sounds.length} heard).`;
  }
  if (!trial.view.complete()) {
    const m = trial.view.missing;
    return (typeof m === 'function' ? m() : m) || 'Choose an answer.';
  }
  return '';
}

function refresh() {
  if (waiting) return;
  if (!trial || !trial.view) { next.disabled = true; return; }
  const playing = player.playingIndex();
  for (const [i, b] of Object.entries(trial.soundButtons)) {
    b.classList.toggle('heard', trial.heard.has(Number(i)));
    b.classList.toggle('playing', playing === Number(i));
  }
  if (trial.onRefresh) trial.onRefresh();
  const why = missing();
  next.disabled = why !== '';
  hint.textContent = why;
}

function pause(message, cls) {
  view.append(el('p', { class: `feedback ${cls}`, id: 'message', text: message }));
  next.textContent = 'Continue ⏎';
  next.disabled = false;
  hint.textContent = '';
  return new Promise((resolve) => { waiting = resolve; });
}

async function show(page) {
  if (trial) trial.closed = true;
  player.stop(false);
  trial = null;
  next.textContent = 'Next ⏎';
  view.replaceChildren();
  if (page.finished) {
    progress.textContent = '';
    view.append(el('p', { id: 'finished', text: 'Thank you! You have finished the study. You may close this page.' }));
    next.hidden = true;
    hint.textContent = '';
    return;
  }
  progress.textContent = `${page.position} / ${page.total}`;
  hint.textContent = page.sounds.length ? 'Loading the sounds…' : '';
  await player.load(page.sounds);
  player.setLoop(false);
  const root = el('div', { class: `trial ${page.type}`, 'data-type': page.type, 'data-trial': String(page.trial) });
  trial = { page, player, root, heard: new Set(), soundButtons: {}, shownAt: performance.now(), refresh };
  trial.view = views[page.type](trial);
  view.append(root);
  refresh();
}

async function submit() {
  if (waiting) { const resolve = waiting; waiting = null; resolve(); return; }
  if (!trial || next.disabled) return;
  next.disabled = true;
  player.stop();
  const { page, view: v } = trial;
  const body = { trial: page.trial, step: page.step, answer: v.answer(), rt_ms: performance.now() - trial.shownAt };
  if (v.moved) body.moved = v.moved();
  let reply;
  try {
    reply = await api.sendAnswer(body);
  } catch (e) {
    hint.textContent = e.message;
    next.disabled = false;
    return;
  }
  if (reply.feedback) await pause(reply.feedback.message, reply.feedback.correct ? 'right' : 'wrong');
  if (reply.break) {
    view.replaceChildren();
    await pause('Take a short break. Continue when you are ready.', 'break');
  }
  await show(reply.page);
}

next.addEventListener('click', submit);
document.addEventListener('keydown', (e) => {
  if (e.key === 'Enter' && e.target.tagName !== 'TEXTAREA') { e.preventDefault(); submit(); return; }
  if (trial && trial.keys && e.target.tagName !== 'INPUT' && e.target.tagName !== 'TEXTAREA') trial.keys(e.key);
});

api.getTrial().then((r) => {
  document.getElementById('title').textContent = r.title;
  document.title = r.title;
  return show(r.page);
}).catch((e) => { view.replaceChildren(el('p', { id: 'error', text: e.message })); });
