// A whole protocols/demo.yaml session in a real browser: `modalstudy serve` on a free loopback port,
// Debian's chromium headless driven by playwright-core through every page with clicks and keys, a
// reload in the middle (the session resumes where it was), then `modalstudy export` of the store: one
// response per trial, in one session. Exits 77 (CTest: skipped) with the reason when chromium, node
// or playwright-core is missing.
import { spawn, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const skip = (why) => { console.log(`SKIP: ${why}`); process.exit(77); };
const fail = (why) => { console.error(`FAIL: ${why}`); process.exit(1); };

const chromiumPath = process.env.CHROMIUM || '/usr/bin/chromium';
if (!existsSync(chromiumPath)) skip(`no chromium at ${chromiumPath} (scripts/setup.sh installs Debian's chromium)`);
let chromium;
try {
  ({ chromium } = await import(join(here, 'node_modules', 'playwright-core', 'index.mjs')));
} catch {
  skip('playwright-core is not installed in tests/web/node_modules (scripts/setup.sh runs npm ci there)');
}
const bin = process.env.MODALSTUDY_BIN;
const source = process.env.MODALSTUDY_SOURCE_DIR || join(here, '..', '..');
if (!bin || !existsSync(bin)) fail('MODALSTUDY_BIN does not name the modalstudy binary');

const work = mkdtempSync(join(tmpdir(), 'modalstudy-web-'));
const db = join(work, 'demo.sqlite');
const server = spawn(bin, ['serve', join(source, 'protocols', 'demo.yaml'), '--db', db, '--port', '0',
                           '--participants', '1', '--cache', join(work, 'cache')], { stdio: ['ignore', 'pipe', 'pipe'] });
let serverLog = '';
server.stderr.on('data', (d) => { serverLog += d; });
const link = await new Promise((resolve, reject) => {
  let out = '';
  server.stdout.on('data', (d) => {
    out += d;
    const m = out.match(/^web-001 (http:\/\/\S+)$/m);
    if (m) resolve(m[1]);
  });
  server.on('exit', (code) => reject(new Error(`serve exited with ${code}: ${serverLog}`)));
  setTimeout(() => reject(new Error('serve printed no link within 120 s')), 120000);
});
const stopServer = () => new Promise((resolve) => { server.once('exit', resolve); server.kill('SIGINT'); });

const browser = await chromium.launch({ executablePath: chromiumPath, headless: true,
                                        args: ['--no-sandbox', '--autoplay-policy=no-user-gesture-required'] });
const page = await browser.newPage();
const pageErrors = [];
page.on('pageerror', (e) => pageErrors.push(e.message));
await page.goto(link);

// Waits until the page shows something new after `marker`: a trial, feedback or the end page.
async function nextScreen() {
  await page.waitForFunction(() => {
    const t = document.querySelector('#view .trial');
    return document.querySelector('#finished') || document.querySelector('#message') || document.querySelector('#error') ||
           (t && !t.dataset.seen);
  }, null, { timeout: 60000 });
  return page.evaluate(() => {
    const t = document.querySelector('#view .trial');
    if (t) t.dataset.seen = '1';
    if (document.querySelector('#finished')) return { kind: 'finished' };
    if (document.querySelector('#message')) return { kind: 'message' };
    if (document.querySelector('#error')) return { kind: 'error', text: document.querySelector('#error').textContent };
    return { kind: 'trial', type: t.dataset.type, progress: document.querySelector('#progress').textContent };
  });
}

async function hearAll() {
  const buttons = page.locator('#view button.sound');
  for (let i = 0; i < await buttons.count(); ++i) {
    await page.waitForFunction((k) => !document.querySelectorAll('#view button.sound')[k].disabled, i);
    await buttons.nth(i).click();
    await page.waitForFunction((k) => document.querySelectorAll('#view button.sound')[k].classList.contains('heard'), i);
  }
}

async function next() {
  await page.waitForFunction(() => !document.querySelector('#next').disabled, null, { timeout: 30000 });
  await page.keyboard.press('Enter');
}

const mushraNames = ['full', 'lp5', 'plate', '~lp'];
let answered = 0, total = 0, reloaded = false, sawTypes = new Set(), staircaseSteps = 0;
try {
for (let screens = 0; screens < 400; ++screens) {
  const s = await nextScreen();
  if (s.kind === 'finished') break;
  if (s.kind === 'error') fail(`the page says: ${s.text}`);
  if (s.kind === 'message') { await next(); continue; }  // feedback or a break: Continue
  total = Number(s.progress.split('/')[1]);
  sawTypes.add(s.type);
  if (!reloaded && s.type === 'ab' && answered >= 4) {  // in the middle of the ABX block
    const before = s.progress;
    await page.reload();
    const again = await nextScreen();
    if (again.progress !== before) fail(`after a reload the page shows ${again.progress}, not ${before}`);
    reloaded = true;
  }
  switch (s.type) {
    case 'instructions': break;
    case 'ab': case 'identify': case 'staircase':
      await hearAll();
      await page.locator('#view button.choice').first().click();
      break;
    case 'mushra': {
      const html = await page.content();
      for (const n of mushraNames) if (html.includes(n)) fail(`the MUSHRA page names the stimulus '${n}'`);
      await hearAll();
      const sliders = page.locator('#view input[type=range]');
      for (let i = 0; i < await sliders.count(); ++i) {
        await sliders.nth(i).focus();
        for (let k = 0; k <= i * 10 + 20; ++k) await page.keyboard.press('ArrowUp');
      }
      break;
    }
    case 'magnitude':
      await hearAll();
      await page.locator('#magnitude').fill('');
      await page.locator('#magnitude').pressSequentially('62,5');  // a decimal comma, as the window reads it
      break;
    case 'rating':
      await hearAll();
      for (const row of await page.locator('#view .scale').all()) await row.locator('button.choice').nth(4).click();
      break;
    case 'adjust': {
      const slider = page.locator('#view input[type=range]').first();
      await slider.focus();
      await page.keyboard.press('ArrowRight');  // a key makes and plays the new sound
      await page.waitForFunction(() => document.querySelector('#resynth-status').textContent === '', null, { timeout: 30000 });
      await hearAll();
      break;
    }
    case 'questionnaire':
      await page.locator('#view textarea').first().fill('Fine.');
      await page.locator('#view button.choice').first().click();
      break;
    default: fail(`no driver for the block type ${s.type}`);
  }
  await next();
  if (s.type === 'staircase') ++staircaseSteps; else ++answered;
}
} catch (e) {
  const shown = await page.evaluate(() => `${document.querySelector('#progress').textContent} | hint: ` +
    `${document.querySelector('#hint').textContent} | ${document.querySelector('#view').innerText.slice(0, 400)}`).catch(() => '');
  await page.screenshot({ path: join(work, 'failure.png') }).catch(() => {});
  await browser.close();
  await stopServer();
  fail(`${e.message.split('\n')[0]}\n  page: ${shown}\n  page errors: ${pageErrors.join('; ')}\n  screenshot: ${join(work, 'failure.png')}` +
       `\n  server log (last lines): ${serverLog.split('\n').slice(-12).join('\n    ')}`);
}
await browser.close();
await stopServer();
if (pageErrors.length) fail(`errors in the page: ${pageErrors.join('; ')}`);
if (!reloaded) fail('the session never reached the reload point');
for (const t of ['instructions', 'ab', 'mushra', 'magnitude', 'identify', 'rating', 'adjust', 'staircase', 'questionnaire'])
  if (!sawTypes.has(t)) fail(`no ${t} page was shown`);

const out = join(work, 'export');
const exported = spawnSync(bin, ['export', db, '-o', out], { encoding: 'utf8' });
if (exported.status !== 0) fail(`modalstudy export: ${exported.stderr}`);
const rows = readFileSync(join(out, 'responses.csv'), 'utf8').trim().split(/\r?\n/).slice(1);
if (rows.length !== total) fail(`the store holds ${rows.length} responses, the session had ${total} trials`);
const header = readFileSync(join(out, 'responses.csv'), 'utf8').split(/\r?\n/)[0].split(',');
const sessions = new Set(rows.map((r) => r.split(',')[header.indexOf('session')]));
if (sessions.size !== 1) fail(`the responses come from ${sessions.size} sessions, not one (the reload must resume)`);
// MUSHRA switches happened at a position inside the sound, logged with the audio clock's time.
const events = readFileSync(join(out, 'events.csv'), 'utf8').split(/\r?\n/);
const switches = events.filter((l) => l.includes(',mushra,') && l.includes(',switch,'));
const positions = switches.map((l) => Number((l.match(/position_s"":([0-9.eE+-]+)/) || [])[1]));
if (!switches.length || !positions.every((p) => p > 0)) fail(`MUSHRA switches without a position: ${switches.length} switches`);
// How long the server took, from its request log: an answer committed and the next trial made; an adjust render.
const took = (what) => [...serverLog.matchAll(new RegExp(`POST /api/\\*/${what} 200 ([0-9.]+) ms`, 'g'))].map((m) => Number(m[1])).sort((a, b) => a - b);
const median = (v) => (v.length ? v[Math.floor(v.length / 2)] : NaN);
const answers = took('answer'), renders = took('render');
console.log(`server: answer committed + next trial p50 ${median(answers)} ms (max ${answers.at(-1)} ms, n=${answers.length}); ` +
            `adjust render p50 ${median(renders)} ms (n=${renders.length}); ${switches.length} MUSHRA switches at positions > 0`);
console.log(`browser session: ${total} trials answered (${staircaseSteps} staircase steps), reload resumed, ` +
            `${rows.length} responses exported from one session`);
rmSync(work, { recursive: true, force: true });
