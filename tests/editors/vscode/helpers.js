// Shared by the extension's tests: the manifest, temporary folders and fake executables.
const fs = require("fs");
const os = require("os");
const path = require("path");

const extensionDir = path.resolve(__dirname, "../../../editors/vscode");
const manifest = JSON.parse(fs.readFileSync(path.join(extensionDir, "package.json"), "utf8"));

function tempDir(t) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), "crt-vscode-test-"));
  t.after(() => fs.rmSync(dir, { recursive: true, force: true }));
  return dir;
}

function writeExecutable(file, script) {
  fs.writeFileSync(file, script, { mode: 0o755 });
  return file;
}

// A stand-in for `crtc --preview`: prints FIRST_LINE, records its arguments and the
// SIGTERM that must stop it.
function fakePreviewCrtc(dir, firstLine) {
  return writeExecutable(
    path.join(dir, "fake-crtc"),
    `#!/usr/bin/env bash
printf '%s\\n' "$@" > "${dir}/args"
trap 'touch "${dir}/stopped"; exit 0' TERM
echo "${firstLine}"
while :; do sleep 0.05; done
`,
  );
}

async function waitForFile(file, timeoutMs = 10000) {
  const start = Date.now();
  while (!fs.existsSync(file)) {
    if (Date.now() - start > timeoutMs) throw new Error(`${file} did not appear`);
    await new Promise((resolve) => setTimeout(resolve, 20));
  }
}

module.exports = { extensionDir, manifest, tempDir, writeExecutable, fakePreviewCrtc, waitForFile };
