// CRT: Open Preview: crtc --preview for the active script, shown in a webview beside the
// editor; closing the panel stops crtc (SIGTERM).
const path = require("path");
const vscode = require("vscode");
const { startPreview, previewHtml } = require("./preview_process");

const panels = new Map(); // script path -> its open panel

async function openPreview(crtcPath) {
  const editor = vscode.window.activeTextEditor;
  if (!editor || editor.document.languageId !== "crt") {
    vscode.window.showErrorMessage("CRT: Open Preview needs a .crt script in the active editor.");
    return undefined;
  }
  const file = editor.document.uri.fsPath;
  if (panels.has(file)) {
    panels.get(file).reveal(vscode.ViewColumn.Beside);
    return panels.get(file);
  }
  await editor.document.save();
  let preview;
  try {
    preview = await startPreview(crtcPath(), file);
  } catch (error) {
    vscode.window.showErrorMessage(`CRT: ${error.message}`);
    return undefined;
  }
  // The iframe reaches crtc's port through the webview's port mapping (and, in remote
  // set-ups, the forwarded address asExternalUri gives).
  const external = await vscode.env.asExternalUri(vscode.Uri.parse(preview.url));
  const title = `Preview ${path.basename(file)}`;
  const panel = vscode.window.createWebviewPanel("crt.preview", title, vscode.ViewColumn.Beside, {
    enableScripts: true,
    retainContextWhenHidden: true,
    portMapping: [{ webviewPort: preview.port, extensionHostPort: preview.port }],
  });
  panel.webview.html = previewHtml(external.toString(true), title);
  panels.set(file, panel);
  panel.onDidDispose(() => {
    panels.delete(file);
    preview.process.kill("SIGTERM");
  });
  return panel;
}

function disposePreviews() {
  for (const panel of [...panels.values()]) panel.dispose();
}

module.exports = { openPreview, disposePreviews };
