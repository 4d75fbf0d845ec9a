// Drives crtc --preview's page in headless chromium, as a user would, and checks what the
// page and the API show after each step.
//   node preview_browser_test.mjs URL SCRIPT OUTPUT_DIR   (PUPPETEER_DIR: where puppeteer-core is)
import { createRequire } from "node:module";
import { readFileSync, writeFileSync } from "node:fs";
import assert from "node:assert/strict";
import http from "node:http";

const require = createRequire(process.env.PUPPETEER_DIR + "/");
const puppeteer = require("puppeteer-core");

const [url, script, out] = process.argv.slice(2);
const base = new URL(url);
const api = (path) => new URL("api/" + path + base.search, base).href;
const getJson = async (path) => (await fetch(api(path))).json();
const timeout = 60000;
let shot = 0;

function step(text) { console.log(`- ${text}`); }

/// The status of a GET of `path` (with `query`) sent with the given headers.
function statusOf(path, query, headers) {
  return new Promise((resolve, reject) => {
    const request = http.get({ host: "127.0.0.1", port: base.port, path: "/" + path + query, headers }, (response) => {
      response.resume();
      resolve(response.statusCode);
    });
    request.on("error", reject);
  });
}

/// Statistics of an image the page shows (by default the camera's view), read back through
/// a canvas.
async function imageStats(page, selector = "#view") {
  return page.evaluate((selector) => {
    const img = document.querySelector(selector);
    const canvas = document.createElement("canvas");
    canvas.width = img.naturalWidth;
    canvas.height = img.naturalHeight;
    const context = canvas.getContext("2d");
    context.drawImage(img, 0, 0);
    const data = context.getImageData(0, 0, canvas.width, canvas.height).data;
    let sum = 0, sumSquares = 0, hash = 0;
    for (let i = 0; i < data.length; i += 4) {
      const v = data[i] + data[i + 1] + data[i + 2];
      sum += v;
      sumSquares += v * v;
      hash = (hash * 31 + data[i] * 7 + data[i + 1] * 3 + data[i + 2]) >>> 0;
    }
    const n = data.length / 4;
    const centre = ((canvas.height >> 1) * canvas.width + (canvas.width >> 1)) * 4;
    return {
      width: canvas.width, height: canvas.height, frame: Number(img.dataset.frame),
      variance: sumSquares / n - (sum / n) ** 2, hash,
      centre: [data[centre], data[centre + 1], data[centre + 2]],
    };
  }, selector);
}

/// Waits until the page shows the last pass of an image newer than `after`.
async function waitForFinalImage(page, after) {
  await page.waitForFunction((after) => {
    const img = document.getElementById("view");
    return Number(img.dataset.frame) > after && img.dataset.final === "true" && img.complete && img.naturalWidth > 0;
  }, { timeout }, after);
  return imageStats(page);
}

async function screenshot(page, name) {
  const file = `${out}/${String(++shot).padStart(2, "0")}-${name}.png`;
  await page.screenshot({ path: file });
  return file;
}

const browser = await puppeteer.launch({
  executablePath: "/usr/bin/chromium",
  headless: true,
  args: ["--no-sandbox", "--disable-gpu", "--window-size=1100,700"],
  defaultViewport: { width: 1100, height: 700 },
});
try {
  const context = browser.defaultBrowserContext();
  await context.overridePermissions(base.origin, ["clipboard-read", "clipboard-write", "clipboard-sanitized-write"]);
  const page = await browser.newPage();
  const pageErrors = [];
  page.on("pageerror", (error) => pageErrors.push(error.message));

  step("requests without the token, or from another Host or Origin, are refused");
  const own = { Host: base.host };
  assert.equal(await statusOf("api/state", base.search, own), 200);
  assert.equal(await statusOf("api/state", "", own), 403);
  assert.equal(await statusOf("api/state", "?token=0123", own), 403);
  assert.equal(await statusOf("", base.search, { Host: `rebound.example:${base.port}` }), 403);
  assert.equal(await statusOf("api/state", base.search, { ...own, Origin: "http://evil.example" }), 403);

  step("the page loads and shows a rendered, non-uniform image");
  await page.goto(url);
  let image = await waitForFinalImage(page, 0);
  assert.equal(image.width, 320);
  assert.ok(image.variance > 100, `the image looks uniform (variance ${image.variance})`);
  assert.match(await page.$eval("#progress", (e) => e.textContent), /done/);
  await screenshot(page, "loaded");

  step("a drag orbits the camera around the point looked at, and the image follows");
  const before = await getJson("camera");
  const box = await (await page.$("#view")).boundingBox();
  const centre = { x: box.x + box.width / 2, y: box.y + box.height / 2 };
  await page.mouse.move(centre.x, centre.y);
  await page.mouse.down();
  for (let i = 1; i <= 10; ++i) await page.mouse.move(centre.x + i * 8, centre.y + i * 2);
  await page.mouse.up();
  let after = await getJson("camera");
  for (let i = 0; i < 50 && JSON.stringify(after) === JSON.stringify(before); ++i) {
    await new Promise((resolve) => setTimeout(resolve, 100));
    after = await getJson("camera");
  }
  assert.notDeepEqual(after.position, before.position, "the camera did not move");
  assert.deepEqual(after.pointing, before.pointing, "an orbit keeps the point looked at");
  const moved = await waitForFinalImage(page, image.frame);
  assert.notEqual(moved.hash, image.hash, "the image did not change with the camera");
  image = moved;
  await screenshot(page, "orbited");

  step("copy camera puts a CRT Camera literal of the current camera on the clipboard");
  const current = await getJson("camera");
  await page.click("#copy");
  await page.waitForFunction(() => /camera/.test(document.getElementById("message").textContent), { timeout });
  const copied = await page.evaluate(async () => {
    const box = document.getElementById("cameraText");
    try { return await navigator.clipboard.readText(); } catch { return box.value; }
  });
  assert.match(copied, /^Camera \{ position -> vec3\(/);
  assert.ok(copied.includes(`pointing -> vec3(0.0, 0.8, 0.0)`), copied);
  assert.ok(copied.includes(current.position[0].toFixed(6).replace(/0+$/, "").replace(/\.$/, ".0")), copied);

  step("saving the script re-renders it");
  const original = readFileSync(script, "utf8");
  writeFileSync(script, original.replace("rgb(0.9, 0.2, 0.2)", "rgb(0.1, 0.8, 0.2)"));
  const green = await waitForFinalImage(page, image.frame);
  assert.ok(green.centre[1] > green.centre[0], `the sphere is not green: ${green.centre}`);
  image = green;
  await screenshot(page, "edited");

  step("a broken edit shows its diagnostic and keeps the last good image");
  const broken = original.replace("radius -> 1.0", "radius -> ");
  writeFileSync(script, broken);
  await page.waitForFunction(() => !document.getElementById("diagnostics").hidden, { timeout });
  const diagnostics = await page.$eval("#diagnostics", (e) => e.textContent);
  assert.match(diagnostics, /scene\.crt:\d+:\d+: error: /);
  assert.equal((await imageStats(page)).hash, image.hash, "the last good image is no longer shown");
  await screenshot(page, "diagnostic");
  writeFileSync(script, original);
  await page.waitForFunction(() => document.getElementById("diagnostics").hidden, { timeout });
  image = await waitForFinalImage(page, image.frame);

  step("the animation slider evaluates another frame");
  assert.equal(await page.$eval("#animation", (e) => e.hidden), false);
  await page.$eval("#frame", (slider) => {
    slider.value = "2";
    slider.dispatchEvent(new Event("input"));
  });
  for (let i = 0; i < 100 && (await getJson("state")).time !== 2; ++i) await new Promise((r) => setTimeout(r, 100));
  assert.equal((await getJson("state")).time, 2);
  const frame2 = await waitForFinalImage(page, image.frame);
  assert.notEqual(frame2.hash, image.hash, "frame 2 looks like frame 0");
  image = frame2;
  await screenshot(page, "frame2");

  step("a click names the object under the mouse and where the script built it");
  const sphereLine = original.split("\n").findIndex((line) => line.trim().startsWith("Sphere {")) + 1;
  const shown = await (await page.$("#view")).boundingBox();
  await page.mouse.click(shown.x + shown.width / 2, shown.y + shown.height / 2);
  await page.waitForFunction(() => document.getElementById("pick").textContent !== "", { timeout });
  const picked = await page.$eval("#pick", (e) => e.textContent);
  assert.match(picked, new RegExp(`^Sphere at .*scene\\.crt:${sphereLine}:\\d+`), picked);
  await screenshot(page, "picked");

  step("the side views show the scene from the top, the front and the side");
  await page.waitForFunction(() => [...document.querySelectorAll(".port img")].every(
    (img) => Number(img.dataset.loaded) > 0 && img.complete && img.naturalWidth === 240), { timeout });
  for (const view of ["top", "front", "side"]) {
    const seen = await imageStats(page, `.port[data-view=${view}] img`);
    assert.ok(seen.variance > 10, `the ${view} view looks uniform (variance ${seen.variance})`);
  }
  await screenshot(page, "side_views");

  step("dragging the camera in the top view moves it there, and the main view follows");
  const placedBefore = await getJson("camera");
  const topView = await (await page.$(".port[data-view=top] canvas")).boundingBox();
  // Where the page draws the camera, and the scene units a pixel of the top view spans.
  const drawn = await page.evaluate(() => {
    const port = ports.find((p) => p.view === "top");
    return { at: toPixel(port, camera.position), unitsPerPixel: port.width / 240 };
  });
  const grab = { x: topView.x + drawn.at[0], y: topView.y + drawn.at[1] };
  await page.mouse.move(grab.x, grab.y);
  await page.mouse.down();
  for (let i = 1; i <= 10; ++i) await page.mouse.move(grab.x + i * 3, grab.y - i * 2);
  await page.mouse.up();
  let placed = await getJson("camera");
  for (let i = 0; i < 50 && Math.abs(placed.position[0] - placedBefore.position[0] - 30 * drawn.unitsPerPixel) > 1e-9; ++i) {
    await new Promise((resolve) => setTimeout(resolve, 100));
    placed = await getJson("camera");
  }
  // Right in the top view is +x, up is +z; the height and the aim stay.
  assert.ok(Math.abs(placed.position[0] - (placedBefore.position[0] + 30 * drawn.unitsPerPixel)) < 1e-9, JSON.stringify(placed));
  assert.ok(Math.abs(placed.position[2] - (placedBefore.position[2] + 20 * drawn.unitsPerPixel)) < 1e-9, JSON.stringify(placed));
  assert.equal(placed.position[1], placedBefore.position[1]);
  assert.deepEqual(placed.pointing, placedBefore.pointing);
  const fromAbove = await waitForFinalImage(page, image.frame);
  assert.notEqual(fromAbove.hash, image.hash, "the main view did not follow the camera");
  image = fromAbove;
  await screenshot(page, "camera_placed");

  step("the theme follows the system's preference, and can be chosen");
  const background = () => page.evaluate(() => getComputedStyle(document.body).backgroundColor);
  await page.emulateMediaFeatures([{ name: "prefers-color-scheme", value: "light" }]);
  assert.equal(await background(), "rgb(244, 245, 247)");
  await page.emulateMediaFeatures([{ name: "prefers-color-scheme", value: "dark" }]);
  assert.equal(await background(), "rgb(29, 31, 33)");
  await page.select("#themeChoice", "light");
  assert.equal(await background(), "rgb(244, 245, 247)", "the light theme was not applied");
  await screenshot(page, "light_theme");
  await page.select("#themeChoice", "system");
  assert.equal(await background(), "rgb(29, 31, 33)");

  step("write camera to script replaces the Settings camera in the file");
  const camera = await getJson("camera");
  await page.$eval("#message", (e) => { e.textContent = ""; });
  await page.click("#write");
  await page.waitForFunction(() => /camera/.test(document.getElementById("message").textContent), { timeout });
  assert.match(await page.$eval("#message", (e) => e.textContent), /^replaced the camera at .*scene\.crt:5:/);
  const written = readFileSync(script, "utf8");
  assert.ok(written.includes("camera -> Camera { position -> vec3(" + camera.position[0].toFixed(6).replace(/0+$/, "")),
            written);
  assert.equal(written.split("\n").length, original.split("\n").length, "the rest of the script changed");

  step("a path-traced image gains paths pass after pass while the camera is still");
  await page.evaluate(() => {
    window.pathsShown = [];
    const img = document.getElementById("view");
    new MutationObserver(() => { if (img.dataset.paths) window.pathsShown.push(Number(img.dataset.paths)); })
      .observe(img, { attributes: true, attributeFilter: ["data-paths"] });
  });
  writeFileSync(script, readFileSync(script, "utf8").replace("supersampling -> 2", 'integrator -> "path" samples -> 64'));
  // (The camera just written may still be re-rendering: wait for the path-traced end.)
  await page.waitForFunction(() => {
    const img = document.getElementById("view");
    return img.dataset.final === "true" && img.dataset.paths === "64.00" && img.complete;
  }, { timeout });
  const traced = await imageStats(page);
  assert.ok(traced.variance > 100, `the path-traced image looks uniform (variance ${traced.variance})`);
  const shownPaths = await page.evaluate(() => window.pathsShown);
  assert.equal(shownPaths.at(-1), 64, `the last image has not every path: ${shownPaths}`);
  assert.ok(shownPaths.length >= 2 && shownPaths[0] < 64, `no image before the last pass was shown: ${shownPaths}`);
  for (let i = 1; i < shownPaths.length; ++i)
    assert.ok(shownPaths[i] >= shownPaths[i - 1], `the paths went down: ${shownPaths}`);
  assert.match(await page.$eval("#progress", (e) => e.textContent), /64 paths\/pixel, error \d+\.\d+ % .* — done/);
  await screenshot(page, "path_traced");

  assert.deepEqual(pageErrors, [], "the page had script errors");
  step("the stop button ends crtc");
  await page.click("#quit");
  await page.waitForFunction(() => /stopped/.test(document.getElementById("progress").textContent), { timeout });
} finally {
  await browser.close();
}
