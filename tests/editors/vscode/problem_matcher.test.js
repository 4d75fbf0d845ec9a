// The "crtc" problem matcher of package.json against what the real crtc prints.
const assert = require("node:assert/strict");
const { spawnSync } = require("child_process");
const fs = require("fs");
const path = require("path");
const test = require("node:test");
const { manifest, tempDir } = require("./helpers");

const crtc = process.env.CRTC;

test("reads crtc's errors, warnings and notes", { skip: !crtc && "CRTC is not set" }, (t) => {
  const dir = tempDir(t);
  const script = path.join(dir, "scene.crt");
  fs.writeFileSync(
    script,
    ["max = 2", "bump = Macro (n) {", "    n / 0", "}", "Scene { Sphere { center -> vec3(0, 0, 0) radius -> max } }", "bump(1)", ""].join("\n"),
  );
  const run = spawnSync(crtc, ["--check", "--color", "never", script], { encoding: "utf8" });
  assert.equal(run.status, 1, run.stderr);
  const matcher = manifest.contributes.problemMatchers.find((m) => m.name === "crtc");
  const pattern = new RegExp(matcher.pattern.regexp);
  const problems = run.stderr
    .split("\n")
    .map((line) => pattern.exec(line))
    .filter(Boolean)
    .map((m) => [m[matcher.pattern.file], Number(m[matcher.pattern.line]), Number(m[matcher.pattern.column]),
      m[matcher.pattern.severity], m[matcher.pattern.message]]);
  assert.deepEqual(problems, [
    [script, 1, 1, "warning", "'max' shadows the built-in of the same name"],
    [script, 3, 7, "error", "integer division by zero"],
    [script, 6, 1, "note", "in the macro called here"],
  ], run.stderr); // and the source lines and carets between them are not problems
});
