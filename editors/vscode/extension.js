// Starts crt-lsp for .crt files. All the language logic is in the server.
const vscode = require("vscode");
const { LanguageClient } = require("vscode-languageclient/node");

let client;

function activate(context) {
  const config = vscode.workspace.getConfiguration("crt");
  const command = config.get("server.path", "crt-lsp");
  const serverOptions = { run: { command }, debug: { command } };
  const clientOptions = {
    documentSelector: [{ scheme: "file", language: "crt" }],
    initializationOptions: { includeDirs: config.get("server.includeDirs", []) },
  };
  client = new LanguageClient("crt", "CRT language server", serverOptions, clientOptions);
  client.start();
  context.subscriptions.push({ dispose: () => client && client.stop() });
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
