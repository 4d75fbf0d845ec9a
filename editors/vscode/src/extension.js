// Starts crt-lsp for .crt files (all the language logic is in the server) and adds the
// CRT: Render task and CRT: Open Preview.
const vscode = require("vscode");
const { LanguageClient } = require("vscode-languageclient/node");
const { initializationOptions, findExecutable, missingServerMessage } = require("./server_options");
const { TASK_TYPE, renderTaskProvider, runRender } = require("./render_task");
const { openPreview, disposePreviews } = require("./preview_panel");

let client;

function crtcPath() {
  return vscode.workspace.getConfiguration("crt").get("crtc.path") || "crtc";
}

/** The language client for the current settings, or undefined (after saying why). */
function createClient() {
  const config = vscode.workspace.getConfiguration("crt");
  const setting = config.get("server.path") || "crt-lsp";
  const command = findExecutable(setting);
  if (!command) {
    vscode.window.showErrorMessage(missingServerMessage(setting));
    return undefined;
  }
  const serverOptions = { run: { command }, debug: { command } };
  const clientOptions = {
    documentSelector: [{ scheme: "file", language: "crt" }],
    initializationOptions: initializationOptions(config),
  };
  return new LanguageClient("crt", "CRT language server", serverOptions, clientOptions);
}

async function restartClient() {
  try {
    if (client) await client.stop();
    client = createClient();
    if (client) await client.start();
  } catch (error) {
    vscode.window.showErrorMessage(`CRT: crt-lsp could not start: ${error.message}`);
  }
}

function activate(context) {
  context.subscriptions.push(
    vscode.commands.registerCommand("crt.render", () => runRender(crtcPath)),
    vscode.commands.registerCommand("crt.openPreview", () => openPreview(crtcPath)),
    vscode.tasks.registerTaskProvider(TASK_TYPE, renderTaskProvider(crtcPath)),
    vscode.workspace.onDidChangeConfiguration((event) => {
      // The server reads its options once, at initialize: a change needs a new server.
      if (event.affectsConfiguration("crt") && !event.affectsConfiguration("crt.crtc")) {
        restartClient();
      }
    }),
    { dispose: disposePreviews },
  );
  return restartClient();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate, createClient };
