// CRT: Open Preview: crtc --preview's first line, the webview page, and the process's life.
const assert = require("node:assert/strict");
const fs = require("fs");
const path = require("path");
const test = require("node:test");
const { install } = require("./stub_vscode");
const { tempDir, fakePreviewCrtc, waitForFile } = require("./helpers");

const URL_LINE = "preview: http://127.0.0.1:8123/?token=abc";

function modules(t) {
  const stub = install({});
  t.after(stub.restore);
  return { stub, process: stub.require("preview_process"), panel: stub.require("preview_panel") };
}

test("the preview line gives the URL and its port; anything else is not it", (t) => {
  const { process } = modules(t);
  assert.deepEqual(process.parsePreviewLine(URL_LINE + "\r"), {
    url: "http://127.0.0.1:8123/?token=abc",
    port: 8123,
  });
  assert.equal(process.parsePreviewLine("preview: http://example.com:80/"), undefined);
  assert.equal(process.parsePreviewLine("rendering ball.crt"), undefined);
});

test("the page frames the preview's origin and allows nothing else", (t) => {
  const { process } = modules(t);
  const html = process.previewHtml("http://127.0.0.1:8123/?token=a&b", "Preview <x>.crt");
  assert.match(html, /content="default-src 'none'; frame-src http:\/\/127\.0\.0\.1:8123; style-src 'unsafe-inline';"/);
  assert.match(html, /<iframe src="http:\/\/127\.0\.0\.1:8123\/\?token=a&amp;b"/);
  assert.match(html, /<title>Preview &lt;x>\.crt<\/title>/);
});

test("opens the URL crtc prints in a panel beside the editor; closing it stops crtc", async (t) => {
  const dir = tempDir(t);
  const crtc = fakePreviewCrtc(dir, URL_LINE);
  const script = path.join(dir, "ball.crt");
  fs.writeFileSync(script, "Scene { }\n");
  const { stub, panel } = modules(t);
  stub.vscode.window.activeTextEditor = {
    document: { languageId: "crt", uri: { fsPath: script }, save: async () => true },
  };
  const opened = await panel.openPreview(() => crtc);
  assert.deepEqual(stub.calls.errors, []);
  assert.equal(stub.calls.panels.length, 1);
  assert.equal(opened.column, stub.vscode.ViewColumn.Beside);
  assert.deepEqual(opened.options.portMapping, [{ webviewPort: 8123, extensionHostPort: 8123 }]);
  assert.match(opened.webview.html, /<iframe src="http:\/\/127\.0\.0\.1:8123\/\?token=abc"/);
  assert.equal(fs.readFileSync(path.join(dir, "args"), "utf8"), `--preview\n${script}\n`);
  // A second request shows the same panel, with no second crtc.
  assert.equal(await panel.openPreview(() => crtc), opened);
  assert.equal(stub.calls.panels.length, 1);
  opened.dispose();
  await waitForFile(path.join(dir, "stopped"));
});

test("crtc that prints something else, fails, or is missing: an error message, no panel", async (t) => {
  const dir = tempDir(t);
  const script = path.join(dir, "ball.crt");
  fs.writeFileSync(script, "Scene { }\n");
  const cases = [
    [fakePreviewCrtc(dir, "hello"), /printed 'hello', not its URL/],
    [path.join(dir, "absent-crtc"), /cannot run '.*absent-crtc'/],
  ];
  const failing = path.join(dir, "failing-crtc");
  fs.writeFileSync(failing, "#!/bin/sh\necho 'crtc: unknown option --preview' >&2\nexit 2\n", { mode: 0o755 });
  cases.push([failing, /exit status 2\) before printing its URL\ncrtc: unknown option --preview/]);
  for (const [crtc, message] of cases) {
    const { stub, panel } = modules(t);
    stub.vscode.window.activeTextEditor = {
      document: { languageId: "crt", uri: { fsPath: script }, save: async () => true },
    };
    assert.equal(await panel.openPreview(() => crtc), undefined);
    assert.equal(stub.calls.panels.length, 0);
    assert.match(stub.calls.errors[0], message);
  }
  // The one that printed "hello" was stopped, not left running.
  await waitForFile(path.join(dir, "stopped"));
});
