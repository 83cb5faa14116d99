// The experimenter's page: completion per participant and the export's files as downloads, both read
// from the server's store on every refresh. The token is the page's own path segment.
import { el } from './views/common.js';

const token = location.pathname.split('/')[2] || '';
const base = `/xapi/${token}`;

async function getJson(path) {
  const response = await fetch(`${base}/${path}`, { cache: 'no-store' });
  const value = await response.json();
  if (!response.ok) throw new Error(value.error || `the server answered ${response.status}`);
  return value;
}

function showCompletion(c) {
  document.getElementById('title').textContent = `${c.title} — experimenter`;
  document.title = `${c.study}: experimenter`;
  document.getElementById('summary').textContent =
    `${c.finished} of ${c.participants.length} finished · ${c.answered} / ${c.scheduled} trials answered`;
  const rows = c.participants.map((p) => el('tr', { 'data-participant': p.participant, 'data-state': p.state },
    el('td', { text: p.participant }), el('td', { text: p.state }), el('td', { class: 'answered', text: String(p.answered) }),
    el('td', { class: 'scheduled', text: String(p.scheduled) }), el('td', { text: String(p.sessions) })));
  document.querySelector('#participants tbody').replaceChildren(...rows);
}

function showDownloads(list) {
  const items = list.files.map((name) => el('li', {}, el('a', { href: `${base}/export/${name}`, download: name, text: name })));
  if (!items.length) items.push(el('li', { class: 'note', text: 'Nothing to export yet.' }));
  for (const n of list.notices) items.push(el('li', { class: 'note', text: n }));
  document.getElementById('downloads').replaceChildren(...items);
}

async function refresh() {
  const error = document.getElementById('error');
  try {
    showCompletion(await getJson('completion'));
    showDownloads(await getJson('export'));
    error.hidden = true;
  } catch (e) {
    error.textContent = e.message;
    error.hidden = false;
  }
  document.body.dataset.loaded = '1';
}

document.getElementById('refresh').addEventListener('click', refresh);
refresh();
