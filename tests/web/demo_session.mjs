// A whole protocols/demo.yaml session in a real browser: `modalstudy serve` on a free loopback port,
// Debian's chromium headless driven by playwright-core through every page with clicks and keys, a
// reload in the middle (the session resumes where it was), the adjust trial's sliders released with
// the mouse (release to the new sound's start, measured in the page, at most 100 ms), the experimenter
// page (completion, a download), then `modalstudy export` of the store: one response per trial, in one
// session, and the download equal to the export's file.
import { join } from 'node:path';
import { readFileSync, rmSync } from 'node:fs';

import { Participant, exportStore, fail, loadChromium, median, serverTimes, source, startServe, workDir } from './browser_driver.mjs';

const kAdjustBudgetMs = 100;
const browser = await loadChromium();
const work = workDir();
const serve = await startServe(work, join(source, 'protocols', 'demo.yaml'), 1, 'demo');

const page = await browser.newPage();
// Release to sound: every range input's change (fired on release) and every AudioBufferSourceNode start,
// the latter at the time it is scheduled to sound (start(when) on the audio clock).
await page.addInitScript(() => {
  window.adjustTimes = { releases: [], starts: [] };
  document.addEventListener('change', (e) => {
    if (e.target.type === 'range') window.adjustTimes.releases.push(performance.now());
  }, true);
  const start = AudioBufferSourceNode.prototype.start;
  AudioBufferSourceNode.prototype.start = function (when = 0, ...rest) {
    const ahead = Math.max(0, when - this.context.currentTime) * 1000;
    window.adjustTimes.starts.push(performance.now() + ahead);
    return start.call(this, when, ...rest);
  };
});
const p = new Participant(page);
await page.goto(serve.links[0]);

// Releases the adjust trial's first slider at `fractions` of its track (each a new value), one after another;
// returns the milliseconds from each release to the start of the sound it made.
async function releaseToSound(fractions) {
  const slider = page.locator('#view input[type=range]').first();
  await slider.scrollIntoViewIfNeeded();
  const box = await slider.boundingBox();
  const took = [];
  for (const f of fractions) {
    const before = await page.evaluate(() => window.adjustTimes.starts.length);
    await slider.click({ position: { x: box.width * f, y: box.height / 2 } });  // press and release at f
    await page.waitForFunction((n) => window.adjustTimes.starts.length > n &&
                                      document.querySelector('#resynth-status').textContent === '', before, { timeout: 30000 });
    took.push(await page.evaluate(() => {
      const t = window.adjustTimes;
      return t.starts[t.starts.length - 1] - t.releases[t.releases.length - 1];
    }));
  }
  return took;
}

const mushraNames = ['full', 'lp5', 'plate', '~lp'];
let answered = 0, total = 0, reloaded = false, staircaseSteps = 0, adjustMs = [];
const sawTypes = new Set();
try {
  for (let screens = 0; screens < 400; ++screens) {
    const s = await p.nextScreen();
    if (s.kind === 'finished') break;
    if (s.kind === 'error') fail(`the page says: ${s.text}`);
    if (s.kind === 'message') { await p.next(); continue; }  // feedback or a break: Continue
    total = Number(s.progress.split('/')[1]);
    sawTypes.add(s.type);
    if (!reloaded && s.type === 'ab' && answered >= 4) {  // in the middle of the ABX block
      const before = s.progress;
      await page.reload();
      const again = await p.nextScreen();
      if (again.progress !== before) fail(`after a reload the page shows ${again.progress}, not ${before}`);
      reloaded = true;
    }
    if (s.type === 'mushra') {
      const html = await page.content();
      for (const n of mushraNames) if (html.includes(n)) fail(`the MUSHRA page names the stimulus '${n}'`);
    }
    if (s.type === 'adjust') {
      adjustMs = await releaseToSound([0.5, 0.8, 0.35, 0.65, 0.9]);  // the slider starts at 19
      await p.hearAll();
    } else {
      await p.answer(s);
    }
    await p.next();
    if (s.type === 'staircase' || s.type === 'tokens') ++staircaseSteps; else ++answered;
  }
  if (p.errors.length) fail(`errors in the page: ${p.errors.join('; ')}`);
} catch (e) {
  const shown = await p.describe();
  await page.screenshot({ path: join(work, 'failure.png') }).catch(() => {});
  await browser.close();
  await serve.stop();
  fail(`${e.message.split('\n')[0]}\n  page: ${shown}\n  page errors: ${p.errors.join('; ')}\n  screenshot: ${join(work, 'failure.png')}` +
       `\n  server log (last lines): ${serve.log().split('\n').slice(-12).join('\n    ')}`);
}

// The experimenter's page: the participant finished, every scheduled trial answered; a download.
const xpage = await browser.newPage({ acceptDownloads: true });
await xpage.goto(serve.experimenter);
await xpage.waitForFunction(() => document.body.dataset.loaded === '1' && document.querySelector('#downloads a'));
const row = await xpage.evaluate(() => {
  const tr = document.querySelector('#participants tr[data-participant="web-001"]');
  return tr && { state: tr.dataset.state, answered: Number(tr.querySelector('.answered').textContent),
                 scheduled: Number(tr.querySelector('.scheduled').textContent) };
});
const [download] = await Promise.all([xpage.waitForEvent('download'), xpage.locator('#downloads a', { hasText: 'responses.csv' }).click()]);
const downloaded = join(work, 'downloaded-responses.csv');
await download.saveAs(downloaded);
const wrongToken = await (await xpage.request.get(serve.experimenter.replace(/\/x\/[0-9a-f]+$/, `/x/${'0'.repeat(32)}`))).status();
await browser.close();
await serve.stop();

if (!reloaded) fail('the session never reached the reload point');
for (const t of ['instructions', 'ab', 'mushra', 'bs1116', 'magnitude', 'identify', 'rating', 'adjust', 'staircase', 'limits',
                 'tokens', 'changepoint', 'questionnaire'])
  if (!sawTypes.has(t)) fail(`no ${t} page was shown`);
const exported = exportStore(serve.db, join(work, 'export'));
if (exported.lines.length !== total) fail(`the store holds ${exported.lines.length} responses, the session had ${total} trials`);
const sessions = new Set(exported.lines.map((r) => r.split(',')[exported.header.indexOf('session')]));
if (sessions.size !== 1) fail(`the responses come from ${sessions.size} sessions, not one (the reload must resume)`);
// MUSHRA switches happened at a position inside the sound, logged with the audio clock's time.
const events = exported.text('events.csv').split(/\r?\n/);
const switches = events.filter((l) => l.includes(',mushra,') && l.includes(',switch,'));
const positions = switches.map((l) => Number((l.match(/position_s"":([0-9.eE+-]+)/) || [])[1]));
if (!switches.length || !positions.every((x) => x > 0)) fail(`MUSHRA switches without a position: ${switches.length} switches`);
if (!row || row.state !== 'finished' || row.answered !== total || row.scheduled !== total)
  fail(`the experimenter page shows ${JSON.stringify(row)}, not finished with ${total}/${total}`);
if (readFileSync(downloaded, 'utf8') !== exported.text('responses.csv'))
  fail('the experimenter page\'s responses.csv differs from modalstudy export\'s');
if (wrongToken !== 404) fail(`the experimenter page with a wrong token answered ${wrongToken}, not 404`);
const sorted = [...adjustMs].sort((a, b) => a - b);
if (sorted.length !== 5) fail(`adjust: ${sorted.length} release-to-sound times measured, not 5`);
if (sorted.at(-1) > kAdjustBudgetMs) fail(`adjust: release to sound ${sorted.map((x) => x.toFixed(1)).join(', ')} ms; over ${kAdjustBudgetMs} ms`);

const answers = serverTimes(serve.log(), 'answer'), renders = serverTimes(serve.log(), 'render');
console.log(`adjust in the browser: slider release to AudioBufferSourceNode start p50 ${median(sorted).toFixed(1)} ms, ` +
            `max ${sorted.at(-1).toFixed(1)} ms (n=${sorted.length}, budget ${kAdjustBudgetMs} ms)`);
console.log(`server: answer committed + next trial p50 ${median(answers)} ms (max ${answers.at(-1)} ms, n=${answers.length}); ` +
            `adjust render p50 ${median(renders)} ms (n=${renders.length}); ${switches.length} MUSHRA switches at positions > 0`);
console.log(`browser session: ${total} trials answered (${staircaseSteps} staircase and token-series steps), reload resumed, ` +
            `${exported.lines.length} responses exported from one session; experimenter page: finished ${row.answered}/${row.scheduled}, ` +
            'responses.csv download identical to the export');
rmSync(work, { recursive: true, force: true });
