// What the real-browser tests share: `modalstudy serve` started on a free loopback port (its links
// and experimenter page read from what it prints), Debian's chromium headless through playwright-core,
// and a participant driver that answers whatever screen its page shows with clicks and keys, as a
// person would. Missing chromium, node or playwright-core exits 77 (CTest: skipped) with the reason.
import { spawn, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
export const skip = (why) => { console.log(`SKIP: ${why}`); process.exit(77); };
export const fail = (why) => { console.error(`FAIL: ${why}`); process.exit(1); };

export const chromiumPath = process.env.CHROMIUM || '/usr/bin/chromium';
export const bin = process.env.MODALSTUDY_BIN;
export const source = process.env.MODALSTUDY_SOURCE_DIR || join(here, '..', '..');

export async function loadChromium() {
  if (!existsSync(chromiumPath)) skip(`no chromium at ${chromiumPath} (scripts/setup.sh installs Debian's chromium)`);
  let chromium;
  try {
    ({ chromium } = await import(join(here, 'node_modules', 'playwright-core', 'index.mjs')));
  } catch {
    skip('playwright-core is not installed in tests/web/node_modules (scripts/setup.sh runs npm ci there)');
  }
  if (!bin || !existsSync(bin)) fail('MODALSTUDY_BIN does not name the modalstudy binary');
  return chromium.launch({ executablePath: chromiumPath, headless: true,
                           args: ['--no-sandbox', '--autoplay-policy=no-user-gesture-required'] });
}

export const workDir = () => mkdtempSync(join(tmpdir(), 'modalstudy-web-'));

// Runs `modalstudy serve PROTOCOL --participants N [more]` into work/<name>.sqlite; resolves when every
// link is printed: { links: [url], experimenter: url, db, log(), stop() }.
export async function startServe(work, protocol, participants, name = 'study', more = []) {
  const db = join(work, `${name}.sqlite`);
  const server = spawn(bin, ['serve', protocol, '--db', db, '--port', '0', '--participants', String(participants),
                             '--cache', join(work, 'cache'), ...more], { stdio: ['ignore', 'pipe', 'pipe'] });
  let log = '';
  server.stderr.on('data', (d) => { log += d; });
  const printed = await new Promise((resolve, reject) => {
    let out = '';
    server.stdout.on('data', (d) => {
      out += d;
      const links = [...out.matchAll(/^web-\d+ (http:\/\/\S+)$/mg)].map((m) => m[1]);
      const experimenter = (out.match(/^experimenter (http:\/\/\S+)$/m) || [])[1];
      if (links.length === participants && experimenter) resolve({ links, experimenter });
    });
    server.on('exit', (code) => reject(new Error(`serve exited with ${code}: ${log}`)));
    setTimeout(() => reject(new Error('serve printed no links within 120 s')), 120000);
  });
  const stop = () => new Promise((resolve) => {
    if (server.exitCode !== null) return resolve();
    server.once('exit', resolve);
    server.kill('SIGINT');
  });
  return { ...printed, db, log: () => log, stop };
}

// `modalstudy export DB -o work/export`: { header: [columns], rows: [[cells]], text(file) }.
export function exportStore(db, out) {
  const exported = spawnSync(bin, ['export', db, '-o', out], { encoding: 'utf8' });
  if (exported.status !== 0) fail(`modalstudy export: ${exported.stderr}`);
  const text = (file) => readFileSync(join(out, file), 'utf8');
  const lines = text('responses.csv').trim().split(/\r?\n/);
  return { header: lines[0].split(','), lines: lines.slice(1), text };
}

// One participant's page: waits for the next screen and answers it as a person would.
export class Participant {
  constructor(page) {
    this.page = page;
    this.errors = [];
    page.on('pageerror', (e) => this.errors.push(e.message));
  }

  // Waits until the page shows something new: a trial, feedback or a break, the end page, an error.
  async nextScreen() {
    await this.page.waitForFunction(() => {
      const t = document.querySelector('#view .trial');
      return document.querySelector('#finished') || document.querySelector('#message') || document.querySelector('#error') ||
             (t && !t.dataset.seen);
    }, null, { timeout: 60000 });
    return this.page.evaluate(() => {
      const t = document.querySelector('#view .trial');
      if (t) t.dataset.seen = '1';
      if (document.querySelector('#finished')) return { kind: 'finished' };
      if (document.querySelector('#message')) return { kind: 'message' };
      if (document.querySelector('#error')) return { kind: 'error', text: document.querySelector('#error').textContent };
      return { kind: 'trial', type: t.dataset.type, progress: document.querySelector('#progress').textContent };
    });
  }

  async hearAll() {
    const page = this.page;
    const buttons = page.locator('#view button.sound');
    for (let i = 0; i < await buttons.count(); ++i) {
      await page.waitForFunction((k) => !document.querySelectorAll('#view button.sound')[k].disabled, i);
      await buttons.nth(i).click();
      await page.waitForFunction((k) => document.querySelectorAll('#view button.sound')[k].classList.contains('heard'), i);
    }
  }

  // Next (Enter) once the page allows it.
  async next() {
    await this.page.waitForFunction(() => !document.querySelector('#next').disabled, null, { timeout: 30000 });
    await this.page.keyboard.press('Enter');
  }

  // Answers the trial on screen (`s` from nextScreen) without pressing Next.
  async answer(s) {
    const page = this.page;
    switch (s.type) {
      case 'instructions': break;
      case 'ab': case 'identify': case 'staircase':
        await this.hearAll();
        await page.locator('#view button.choice').first().click();
        break;
      case 'limits':  // "different": the series ends at this pair
        await this.hearAll();
        await page.locator('#view button.choice').last().click();
        break;
      case 'tokens':  // "same": the reference stays; the series still ends after the last token
        await this.hearAll();
        await page.locator('#view button.choice').first().click();
        break;
      case 'changepoint':  // a change marked at the third sound, which works only once it was heard
        if (!await page.locator('#mark-2').isDisabled()) fail('a change could be marked before its sound was heard');
        await this.hearAll();
        await page.locator('#mark-2').click();
        break;
      case 'mushra': {
        await this.hearAll();
        const sliders = page.locator('#view input[type=range]');
        for (let i = 0; i < await sliders.count(); ++i) {
          await sliders.nth(i).focus();
          for (let k = 0; k <= i * 10 + 20; ++k) await page.keyboard.press('ArrowUp');
        }
        break;
      }
      case 'bs1116': {
        await this.hearAll();
        const sliders = page.locator('#view input[type=range]');
        for (let i = 0; i < await sliders.count(); ++i) {
          await sliders.nth(i).focus();
          for (let k = 0; k <= i * 7 + 2; ++k) await page.keyboard.press('ArrowDown');  // from 5.0 down
        }
        break;
      }
      case 'magnitude':
        await this.hearAll();
        await page.locator('#magnitude').fill('');
        await page.locator('#magnitude').pressSequentially('62,5');  // a decimal comma, as the window reads it
        break;
      case 'rating':
        await this.hearAll();
        for (const row of await page.locator('#view .scale').all()) await row.locator('button.choice').nth(4).click();
        break;
      case 'adjust': {
        const slider = page.locator('#view input[type=range]').first();
        await slider.focus();
        await page.keyboard.press('ArrowRight');  // a key makes and plays the new sound
        await page.waitForFunction(() => document.querySelector('#resynth-status').textContent === '', null, { timeout: 30000 });
        await this.hearAll();
        break;
      }
      case 'questionnaire':
        await page.locator('#view textarea').first().fill('Fine.');
        await page.locator('#view button.choice').first().click();
        break;
      default: fail(`no driver for the block type ${s.type}`);
    }
  }

  // What the page shows now, for a failure message.
  async describe() {
    return this.page.evaluate(() => `${document.querySelector('#progress').textContent} | hint: ` +
      `${document.querySelector('#hint').textContent} | ${document.querySelector('#view').innerText.slice(0, 400)}`).catch(() => '');
  }
}

// Sorted request times of one API call from serve's request log ("POST /api/*/answer 200 3.1 ms").
export function serverTimes(log, what) {
  return [...log.matchAll(new RegExp(`POST /api/\\*/${what} 200 ([0-9.]+) ms`, 'g'))].map((m) => Number(m[1])).sort((a, b) => a - b);
}
export const median = (v) => (v.length ? v[Math.floor(v.length / 2)] : NaN);
