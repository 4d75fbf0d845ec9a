// CRT: Render as a task: crtc on the active script, its diagnostics read by the "crtc"
// problem matcher (file:line:col: error|warning|note: message) declared in package.json.
const vscode = require("vscode");

const TASK_TYPE = "crt";

function renderTask(crtc, file, args = []) {
  const definition = { type: TASK_TYPE, file, args };
  const task = new vscode.Task(
    definition,
    vscode.TaskScope.Workspace,
    `render ${require("path").basename(file)}`,
    "crt",
    new vscode.ProcessExecution(crtc, [...args, file]),
    ["$crtc"],
  );
  task.group = vscode.TaskGroup.Build;
  return task;
}

/** The task provider: tasks.json entries { "type": "crt", "file": "${file}" } resolve here. */
function renderTaskProvider(crtcPath) {
  return {
    provideTasks() {
      const editor = vscode.window.activeTextEditor;
      if (!editor || editor.document.languageId !== "crt") return [];
      return [renderTask(crtcPath(), editor.document.uri.fsPath)];
    },
    resolveTask(task) {
      const { file, args } = task.definition;
      if (!file) return undefined;
      const resolved = renderTask(crtcPath(), file, args || []);
      resolved.definition = task.definition; // VS Code matches the resolved task by it
      return resolved;
    },
  };
}

async function runRender(crtcPath) {
  const editor = vscode.window.activeTextEditor;
  if (!editor || editor.document.languageId !== "crt") {
    vscode.window.showErrorMessage("CRT: Render needs a .crt script in the active editor.");
    return undefined;
  }
  await editor.document.save();
  return vscode.tasks.executeTask(renderTask(crtcPath(), editor.document.uri.fsPath));
}

module.exports = { TASK_TYPE, renderTask, renderTaskProvider, runRender };
