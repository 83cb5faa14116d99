// Pictures of the browser client for the README: the demo study in Debian's chromium at 1024x600
// (docs/images/web-*.png) and at a device scale of 1.5 (build/web-shots-150/), one per block type, a
// whole 19-sound sweep of the change-point replication, a sound-variation trial and the experimenter
// page. Not a test; run by hand after a build:
//   MODALSTUDY_BIN=build/bin/modalstudy node tests/web/screenshots.mjs [OUTDIR]
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';

import { Participant, fail, loadChromium, source, startServe, workDir } from './browser_driver.mjs';

const out = process.argv[2] || join(source, 'docs', 'images');
const browser = await loadChromium();
for (const [scale, dir] of [[1, out], [1.5, join(source, 'build', 'web-shots-150')]]) {
  mkdirSync(dir, { recursive: true });
  const work = workDir();
  const serve = await startServe(work, join(source, 'protocols', 'demo.yaml'), 1, 'demo');
  const context = await browser.newContext({ viewport: { width: 1024, height: 600 }, deviceScaleFactor: scale });
  const page = await context.newPage();
  const p = new Participant(page);
  await page.goto(serve.links[0]);
  const shot = new Set();
  for (let screens = 0; screens < 400; ++screens) {
    const s = await p.nextScreen();
    if (s.kind === 'finished') break;
    if (s.kind === 'error') fail(`the page shows an error: ${s.text}`);
    if (s.kind === 'message') { await p.next(); continue; }
    const wanted = !shot.has(s.type) && ['mushra', 'bs1116', 'ab', 'adjust', 'limits', 'staircase', 'tokens', 'changepoint'].includes(s.type);
    const answeredFirst = s.type === 'changepoint';  // its picture shows the sounds heard and a change marked
    if (wanted && !answeredFirst) await page.screenshot({ path: join(dir, `web-${s.type}.png`) });
    await p.answer(s);
    if (wanted && answeredFirst) await page.screenshot({ path: join(dir, `web-${s.type}.png`) });
    if (wanted) shot.add(s.type);
    await p.next();
  }
  // A whole Q sweep of the change-point replication (19 sounds): it fits with Next in sight.
  const sweepServe = await startServe(workDir(), join(source, 'protocols', 'skandalou2017_changepoint.yaml'), 1, 'sweep');
  const sweepPage = await context.newPage();
  const sweeper = new Participant(sweepPage);
  await sweepPage.goto(sweepServe.links[0]);
  for (let screens = 0; screens < 4; ++screens) {
    const s = await sweeper.nextScreen();
    if (s.kind === 'trial' && s.type === 'changepoint') {
      await sweeper.answer(s);
      await sweepPage.locator('#mark-12').click();
      await sweepPage.evaluate(() => window.scrollTo(0, 0));
      await sweepPage.screenshot({ path: join(dir, 'web-changepoint-sweep.png') });
      break;
    }
    await sweeper.answer(s);
    await sweeper.next();
  }
  await sweepServe.stop();
  // A sound-variation trial (Skandalou & Ireland 2017, Exp. 2): two bounce sequences, both heard, +1 chosen.
  const variationServe = await startServe(workDir(), join(source, 'protocols', 'skandalou2017_variation.yaml'), 1, 'variation');
  const variationPage = await context.newPage();
  const listener = new Participant(variationPage);
  await variationPage.goto(variationServe.links[0]);
  for (let screens = 0; screens < 4; ++screens) {
    const s = await listener.nextScreen();
    if (s.kind === 'trial' && s.type === 'ab') {
      await listener.hearAll();
      await variationPage.locator('#view button.choice[data-value="1"]').click();
      await variationPage.evaluate(() => window.scrollTo(0, 0));
      await variationPage.screenshot({ path: join(dir, 'web-ab-variation.png') });
      break;
    }
    await listener.answer(s);
    await listener.next();
  }
  await variationServe.stop();
  const x = await context.newPage();
  await x.goto(serve.experimenter);
  await x.waitForSelector('#participants tr[data-participant="web-001"]');
  await x.screenshot({ path: join(dir, 'web-experimenter.png') });
  await context.close();
  await serve.stop();
  console.log(`${dir}: ${[...shot].map((t) => `web-${t}.png`).join(' ')} web-changepoint-sweep.png web-ab-variation.png web-experimenter.png`);
}
await browser.close();
