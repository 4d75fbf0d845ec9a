// A recording stand-in for the `vscode` module and for vscode-languageclient/node, so the
// extension's own code runs under plain node. install() routes require() to them.
const Module = require("module");
const path = require("path");

function createStub(settings = {}) {
  const calls = { commands: [], taskProviders: [], errors: [], clients: [], started: 0, executed: [], panels: [] };
  class Task {
    constructor(definition, scope, name, source, execution, problemMatchers) {
      Object.assign(this, { definition, scope, name, source, execution, problemMatchers });
    }
  }
  class ProcessExecution {
    constructor(process, args) {
      Object.assign(this, { process, args });
    }
  }
  const vscode = {
    Task,
    ProcessExecution,
    TaskScope: { Workspace: "workspace" },
    TaskGroup: { Build: "build" },
    ViewColumn: { Beside: -2 },
    Uri: { parse: (text) => ({ toString: () => text }) },
    env: { asExternalUri: async (uri) => uri },
    window: {
      activeTextEditor: undefined,
      showErrorMessage: (message) => calls.errors.push(message),
      createWebviewPanel: (viewType, title, column, options) => {
        const disposeListeners = [];
        const panel = {
          viewType, title, column, options,
          webview: { html: "" },
          reveal() {},
          onDidDispose: (listener) => disposeListeners.push(listener),
          dispose: () => disposeListeners.forEach((listener) => listener()),
        };
        calls.panels.push(panel);
        return panel;
      },
    },
    workspace: {
      getConfiguration: (section) => ({
        get: (key, fallback) => {
          const value = settings[`${section}.${key}`];
          return value === undefined ? fallback : value;
        },
      }),
      onDidChangeConfiguration: () => ({ dispose() {} }),
    },
    commands: {
      registerCommand: (id, callback) => {
        calls.commands.push({ id, callback });
        return { dispose() {} };
      },
    },
    tasks: {
      registerTaskProvider: (type, provider) => {
        calls.taskProviders.push({ type, provider });
        return { dispose() {} };
      },
      executeTask: async (task) => calls.executed.push(task),
    },
  };
  class LanguageClient {
    constructor(id, name, serverOptions, clientOptions) {
      Object.assign(this, { id, name, serverOptions, clientOptions });
      calls.clients.push(this);
    }
    async start() {
      calls.started += 1;
    }
    async stop() {}
  }
  return { vscode, languageClient: { LanguageClient }, calls };
}

// Fresh stubs and a fresh copy of the extension's modules for each test.
function install(settings) {
  const stub = createStub(settings);
  const source = path.resolve(__dirname, "../../../editors/vscode/src");
  for (const key of Object.keys(require.cache)) {
    if (key.startsWith(source)) delete require.cache[key];
  }
  const originalLoad = Module._load;
  Module._load = function (request, parent, isMain) {
    if (request === "vscode") return stub.vscode;
    if (request === "vscode-languageclient/node") return stub.languageClient;
    return originalLoad.call(this, request, parent, isMain);
  };
  stub.restore = () => (Module._load = originalLoad);
  stub.require = (name) => require(path.join(source, name));
  return stub;
}

module.exports = { install };
