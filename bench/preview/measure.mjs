// Measures one running preview (see run.sh): save-to-image latency and orbit frame rate.
//   node measure.mjs URL SCRIPT NAME   → one Markdown table row
import { readFileSync, writeFileSync } from "node:fs";

const [url, script, name] = process.argv.slice(2);
const base = new URL(url);
const saves = 5, orbitSeconds = 3;
const api = (path) => new URL("api/" + path + base.search, base).href;

/// Frame events as they come, each with the time it arrived.
const frames = [];
let notify = () => {};
async function listen() {
  const response = await fetch(api("events"));
  const decoder = new TextDecoder();
  let buffer = "";
  for await (const chunk of response.body) {
    buffer += decoder.decode(chunk, { stream: true });
    let end;
    while ((end = buffer.indexOf("\n\n")) >= 0) {
      const block = buffer.slice(0, end);
      buffer = buffer.slice(end + 2);
      if (!block.startsWith("event: frame")) continue;
      frames.push({ at: performance.now(), ...JSON.parse(block.split("\ndata: ")[1]) });
      notify();
    }
  }
}
/// The first frame after index `from` that `match` accepts.
async function frameAfter(from, match) {
  for (;;) {
    const found = frames.slice(from).find(match);
    if (found) return found;
    await new Promise((resolve) => { notify = resolve; setTimeout(resolve, 60000); });
  }
}
const median = (values) => values.sort((a, b) => a - b)[Math.floor(values.length / 2)];

listen().catch(() => {});
await frameAfter(0, (f) => f.final);
const original = readFileSync(script, "utf8");
const first = [], full = [];
for (let i = 0; i < saves; ++i) {
  const from = frames.length;
  const saved = performance.now();
  writeFileSync(script, original + `\n-- edit ${i}\n`);
  first.push((await frameAfter(from, () => true)).at - saved);
  full.push((await frameAfter(from, (f) => f.final)).at - saved);
}
writeFileSync(script, original);
await frameAfter(frames.length, (f) => f.final);

// Orbit: a move as soon as the previous one's frame is in, as a dragging mouse would.
let count = 0;
const start = performance.now();
while (performance.now() - start < orbitSeconds * 1000) {
  const from = frames.length;
  await fetch(api("camera/move"), { method: "POST", body: JSON.stringify({ orbitX: 2, interactive: true }) });
  await frameAfter(from, (f) => !f.final);
  ++count;
}
const fps = count / ((performance.now() - start) / 1000);
await fetch(api("quit"), { method: "POST", body: "{}" });
console.log(`| ${name} | ${median(first).toFixed(0)} | ${median(full).toFixed(0)} | ${fps.toFixed(1)} |`);
process.exit(0);
