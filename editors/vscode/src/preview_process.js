// Runs `crtc --preview FILE` and waits for the URL it prints as its first line of output
// ("preview: http://127.0.0.1:PORT/?token=..."). No vscode API: the tests run it with node.
const { spawn } = require("child_process");
const path = require("path");

const PREVIEW_LINE = /^preview: (http:\/\/(?:127\.0\.0\.1|localhost|\[::1\]):(\d+)\/\S*)$/;

/** { url, port } from crtc's first line, or undefined when it is not the preview line. */
function parsePreviewLine(line) {
  const match = PREVIEW_LINE.exec(line.trim());
  return match ? { url: match[1], port: Number(match[2]) } : undefined;
}

/**
 * Starts the preview server. Resolves with { url, port, process } once the first line is
 * read; rejects (and stops the process) when that line is something else, or the process
 * ends or cannot start first. Standard error is kept for the message.
 */
function startPreview(crtc, file) {
  return new Promise((resolve, reject) => {
    const child = spawn(crtc, ["--preview", file], {
      cwd: path.dirname(file),
      stdio: ["ignore", "pipe", "pipe"],
    });
    let stdout = "";
    let stderr = "";
    let settled = false;
    const fail = (message) => {
      if (settled) return;
      settled = true;
      child.kill("SIGTERM");
      reject(new Error(stderr.trim() ? `${message}\n${stderr.trim()}` : message));
    };
    child.stderr.on("data", (chunk) => (stderr += chunk));
    child.stdout.on("data", (chunk) => {
      if (settled) return;
      stdout += chunk;
      const end = stdout.indexOf("\n");
      if (end < 0) return;
      const preview = parsePreviewLine(stdout.slice(0, end));
      if (!preview) return fail(`crtc --preview printed '${stdout.slice(0, end)}', not its URL`);
      settled = true;
      resolve({ ...preview, process: child });
    });
    child.on("error", (error) => fail(`cannot run '${crtc}': ${error.message}`));
    // "close", not "exit": by then standard error has been read to its end.
    child.on("close", (code, signal) =>
      fail(`crtc --preview ended (${signal || `exit status ${code}`}) before printing its URL`),
    );
  });
}

/** The webview's page: the preview in a full-size iframe, allowed by the CSP and nothing else. */
function previewHtml(frameUrl, title) {
  const origin = new URL(frameUrl).origin;
  const escape = (text) => text.replace(/&/g, "&amp;").replace(/"/g, "&quot;").replace(/</g, "&lt;");
  return `<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="default-src 'none'; frame-src ${origin}; style-src 'unsafe-inline';">
<title>${escape(title)}</title>
<style>html, body, iframe { margin: 0; padding: 0; border: 0; width: 100%; height: 100%; overflow: hidden; }</style>
</head>
<body><iframe src="${escape(frameUrl)}" title="${escape(title)}"></iframe></body>
</html>
`;
}

module.exports = { parsePreviewLine, startPreview, previewHtml };
