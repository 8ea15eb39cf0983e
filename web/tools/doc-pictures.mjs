// Takes docs/web.md's pictures: the page on a desktop, and one frame of the
// emulated Quest 3's session at a pose in the default layout's hall
// (`node web/tools/doc-pictures.mjs` after scripts/web-build.sh).
import path from 'node:path';
import { openPage, repoRoot } from './browser.mjs';

const images = path.join(repoRoot, 'docs', 'images');
const desktop = await openPage({ width: 1280, height: 520 });
await desktop.page.waitForTimeout(1500);
await desktop.page.screenshot({ path: path.join(images, 'web-page.png') });
await desktop.close();

const headset = await openPage({ xr: true, width: 1280, height: 640 });
await headset.page.evaluate(async () => {
  const { xr, api } = window.impossible;
  const info = JSON.parse(api.layoutInfo());
  const p = xr.layoutToFloor(info.start, [0.6, 1.6, 1.2, 20, -8, 0]);
  window.emulatedHeadset.position.set(...p.position);
  window.emulatedHeadset.quaternion.set(...p.orientation);
  await xr.enter();
  await new Promise((r) => setTimeout(r, 1500));
});
await (await headset.page.$('#impossible-gl')).screenshot({ path: path.join(images, 'web-xr.png') });
await headset.close();
