// Two participants at once in a real browser: one `modalstudy serve`, two browser contexts (two people,
// no shared storage), their answers interleaved screen by screen. Then the store holds both complete
// sessions: every scheduled trial answered once (no answer lost, none duplicated), each participant's
// answers in their own session, and the experimenter page says both finished.
import { rmSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

import { Participant, exportStore, fail, loadChromium, source, startServe, workDir } from './browser_driver.mjs';

const browser = await loadChromium();
const work = workDir();
const sets = join(source, 'stimuli');
const protocol = join(work, 'two.yaml');
writeFileSync(protocol, `study: two-at-once
title: Two at once
sample_rate: 44100
seed: 7
stimuli:
  metal: {paramset: ${sets}/bar/sterling-steel.yaml}
  glass: {paramset: ${sets}/plate/sterling-glass.yaml}
  full:  {paramset: ${sets}/examples/plate-pruned-a16.yaml, set: {prune: {method: energy}}}
  plate: {paramset: ${sets}/examples/plate-pruned-a16.yaml, prune: {threshold_db: 24}}
blocks:
  - {type: instructions, id: welcome, text: "Two of you at once."}
  - {type: ab, id: abx, mode: abx, pairs: [[full, plate], [metal, glass]]}
  - {type: mushra, id: mushra, reference: full, conditions: [plate], anchors: auto}
  - {type: identify, id: material, stimuli: [metal, glass], labels: [metal, glass], repeats: 2}
  - type: questionnaire
    id: about
    questions: ["Any comments?", {id: hand, text: "Which hand?", options: [left, right]}]
`);
const serve = await startServe(work, protocol, 2, 'two', ['--allow-outside']);

const people = [];
for (const link of serve.links) {
  const context = await browser.newContext();
  const person = new Participant(await context.newPage());
  await person.page.goto(link);
  people.push(person);
}
const totals = [0, 0];
const screens = [0, 0];
try {
  // Round robin: each person in turn answers one screen, so the server interleaves two sessions.
  for (let round = 0; round < 200 && people.some((p) => !p.done); ++round) {
    for (const [i, p] of people.entries()) {
      if (p.done) continue;
      const s = await p.nextScreen();
      if (s.kind === 'finished') { p.done = true; continue; }
      if (s.kind === 'error') fail(`participant ${i + 1}'s page says: ${s.text}`);
      if (s.kind === 'trial') {
        totals[i] = Number(s.progress.split('/')[1]);
        await p.answer(s);
        ++screens[i];
      }
      await p.next();
    }
  }
  if (!people.every((p) => p.done)) fail('the sessions did not finish within 200 rounds');
  for (const [i, p] of people.entries()) if (p.errors.length) fail(`errors in participant ${i + 1}'s page: ${p.errors.join('; ')}`);
} catch (e) {
  const shown = await Promise.all(people.map((p) => p.describe()));
  await browser.close();
  await serve.stop();
  fail(`${e.message.split('\n')[0]}\n  pages: ${shown.join('\n         ')}\n  server log: ${serve.log().split('\n').slice(-12).join('\n    ')}`);
}
const completion = await (await people[0].page.request.get(serve.experimenter.replace('/x/', '/xapi/') + '/completion')).json();
await browser.close();
await serve.stop();

const exported = exportStore(serve.db, join(work, 'export'));
const col = (name) => {
  const k = exported.header.indexOf(name);
  if (k < 0) fail(`responses.csv has no column ${name}`);
  return k;
};
const [participant, session, block, trial] = ['participant', 'session', 'block', 'trial'].map(col);
const keys = new Set();
const bySession = new Map();
for (const line of exported.lines) {
  const cells = line.split(',');
  const key = [cells[session], cells[block], cells[trial]].join('/');
  if (keys.has(key)) fail(`the answer to session ${cells[session]} block ${cells[block]} trial ${cells[trial]} is stored twice`);
  keys.add(key);
  const who = bySession.get(cells[session]) || { participant: cells[participant], n: 0 };
  if (who.participant !== cells[participant]) fail(`session ${cells[session]} holds answers of two participants`);
  ++who.n;
  bySession.set(cells[session], who);
}
if (bySession.size !== 2) fail(`the store holds ${bySession.size} sessions, not 2`);
const stored = [...bySession.values()].sort((a, b) => a.participant.localeCompare(b.participant));
for (const [i, who] of stored.entries())
  if (who.n !== totals[i] || screens[i] !== totals[i])
    fail(`${who.participant}: ${who.n} answers stored, ${screens[i]} given, ${totals[i]} scheduled`);
for (const row of completion.participants)
  if (row.state !== 'finished' || row.answered !== row.scheduled)
    fail(`the experimenter page shows ${row.participant} ${row.state} ${row.answered}/${row.scheduled}`);
console.log(`two participants at once: ${stored.map((w) => `${w.participant} ${w.n}/${totals[stored.indexOf(w)]}`).join(', ')} ` +
            `answers stored in ${bySession.size} sessions, none lost or duplicated; experimenter page: both finished`);
rmSync(work, { recursive: true, force: true });
