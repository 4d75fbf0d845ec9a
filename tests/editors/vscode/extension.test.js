// The extension's activation under plain node, with a recording stand-in for VS Code.
const assert = require("node:assert/strict");
const path = require("path");
const test = require("node:test");
const { install } = require("./stub_vscode");
const { manifest, tempDir, writeExecutable } = require("./helpers");

function withPath(t, dir) {
  const saved = process.env.PATH;
  process.env.PATH = dir;
  t.after(() => (process.env.PATH = saved));
}

function activate(t, settings) {
  const stub = install(settings);
  t.after(stub.restore);
  const extension = stub.require("extension");
  return { stub, done: extension.activate({ subscriptions: [] }) };
}

test("starts crt-lsp found on PATH by default, with the settings as initializationOptions", async (t) => {
  const bin = tempDir(t);
  const server = writeExecutable(path.join(bin, "crt-lsp"), "#!/bin/sh\n");
  withPath(t, bin);
  const { stub, done } = activate(t, {
    "crt.includePaths": ["/scenes/include"],
    "crt.assetRoots": ["/scenes/assets"],
    "crt.allowRead": [],
    "crt.maxSteps": 1000,
    "crt.timeBudgetMs": 250,
    "crt.maxEntities": null,
  });
  await done;
  assert.equal(stub.calls.clients.length, 1);
  const client = stub.calls.clients[0];
  assert.equal(stub.calls.started, 1);
  assert.deepEqual(client.serverOptions.run, { command: server });
  assert.deepEqual(client.clientOptions.documentSelector, [{ scheme: "file", language: "crt" }]);
  // Unset and empty settings are left to the server's defaults.
  assert.deepEqual(client.clientOptions.initializationOptions, {
    includeDirs: ["/scenes/include"],
    assetRoots: ["/scenes/assets"],
    maxSteps: 1000,
    timeBudgetMs: 250,
  });
  assert.deepEqual(stub.calls.errors, []);
});

test("crt.server.path names the server by path", async (t) => {
  const server = writeExecutable(path.join(tempDir(t), "my-crt-lsp"), "#!/bin/sh\n");
  withPath(t, "");
  const { stub, done } = activate(t, { "crt.server.path": server });
  await done;
  assert.equal(stub.calls.clients[0].serverOptions.run.command, server);
});

test("a missing server gives a message naming it and the setting, and no client", async (t) => {
  withPath(t, tempDir(t));
  const { stub, done } = activate(t, {});
  await done;
  assert.equal(stub.calls.clients.length, 0);
  assert.equal(stub.calls.errors.length, 1);
  assert.match(stub.calls.errors[0], /'crt-lsp' was not found/);
  assert.match(stub.calls.errors[0], /crt\.server\.path/);
  // The commands still work without the server.
  assert.equal(stub.calls.commands.length, manifest.contributes.commands.length);
});

test("registers every command and the task type the manifest declares", async (t) => {
  withPath(t, "");
  const { stub, done } = activate(t, {});
  await done;
  assert.deepEqual(
    stub.calls.commands.map((c) => c.id).sort(),
    manifest.contributes.commands.map((c) => c.command).sort(),
  );
  assert.deepEqual(
    stub.calls.taskProviders.map((p) => p.type),
    manifest.contributes.taskDefinitions.map((d) => d.type),
  );
});

test("a workspace whose tasks.json runs a crt task activates the extension", () => {
  // Languages and commands activate it by themselves; a task type needs its event.
  for (const { type } of manifest.contributes.taskDefinitions)
    assert.ok(manifest.activationEvents.includes(`onTaskType:${type}`), `onTaskType:${type}`);
});

test("every server setting in the manifest is passed, under its server name", (t) => {
  const stub = install({});
  t.after(stub.restore);
  const { INITIALIZATION_OPTIONS } = stub.require("server_options");
  const settings = Object.keys(manifest.contributes.configuration.properties)
    .map((key) => key.replace(/^crt\./, ""))
    .filter((key) => !key.endsWith(".path"));
  assert.deepEqual(settings.sort(), Object.keys(INITIALIZATION_OPTIONS).sort());
  assert.deepEqual(Object.values(INITIALIZATION_OPTIONS).sort(), [
    "allowRead", "assetRoots", "includeDirs", "maxEntities", "maxPrimitives", "maxSteps", "timeBudgetMs",
  ]);
});

test("CRT: Render saves the script and runs crtc on it with the crtc problem matcher", async (t) => {
  withPath(t, "");
  const { stub, done } = activate(t, { "crt.crtc.path": "/opt/crt/bin/crtc" });
  await done;
  let saved = false;
  stub.vscode.window.activeTextEditor = {
    document: { languageId: "crt", uri: { fsPath: "/scenes/ball.crt" }, save: async () => (saved = true) },
  };
  await stub.calls.commands.find((c) => c.id === "crt.render").callback();
  assert.ok(saved);
  assert.equal(stub.calls.executed.length, 1);
  const task = stub.calls.executed[0];
  assert.equal(task.execution.process, "/opt/crt/bin/crtc");
  assert.deepEqual(task.execution.args, ["/scenes/ball.crt"]);
  assert.deepEqual(task.problemMatchers, ["$crtc"]);
  assert.ok(manifest.contributes.problemMatchers.some((m) => `$${m.name}` === "$crtc"));
});

test("CRT: Render refuses without a CRT script", async (t) => {
  withPath(t, "");
  const { stub, done } = activate(t, {});
  await done;
  stub.vscode.window.activeTextEditor = { document: { languageId: "plaintext" } };
  await stub.calls.commands.find((c) => c.id === "crt.render").callback();
  assert.equal(stub.calls.executed.length, 0);
  assert.match(stub.calls.errors.at(-1), /needs a \.crt script/);
});

test("a tasks.json entry resolves to crtc with its options before the file", async (t) => {
  withPath(t, "");
  const { stub, done } = activate(t, {});
  await done;
  const { provider } = stub.calls.taskProviders[0];
  const resolved = provider.resolveTask({ definition: { type: "crt", file: "/s/a.crt", args: ["--width", "64"] } });
  assert.equal(resolved.execution.process, "crtc");
  assert.deepEqual(resolved.execution.args, ["--width", "64", "/s/a.crt"]);
  assert.equal(provider.resolveTask({ definition: { type: "crt" } }), undefined);
});

test("the extension's version is the project's (CMakeLists.txt)", () => {
  const cmake = require("fs").readFileSync(path.join(__dirname, "../../../CMakeLists.txt"), "utf8");
  assert.equal(manifest.version, /project\(crt VERSION (\S+)/.exec(cmake)[1]);
});
