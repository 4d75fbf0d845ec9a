// What the extension hands crt-lsp, computed from the settings alone (no vscode API), so the
// tests can call it from plain node.
const fs = require("fs");
const path = require("path");

// Setting (under "crt.") -> the server's initializationOptions key. Only settings the user
// set are passed: the server's defaults stay the server's.
const INITIALIZATION_OPTIONS = {
  includePaths: "includeDirs",
  assetRoots: "assetRoots",
  allowRead: "allowRead",
  maxSteps: "maxSteps",
  maxEntities: "maxEntities",
  maxPrimitives: "maxPrimitives",
  timeBudgetMs: "timeBudgetMs",
};

/** The initializationOptions for crt-lsp from a configuration with get(key). */
function initializationOptions(config) {
  const options = {};
  for (const [setting, key] of Object.entries(INITIALIZATION_OPTIONS)) {
    const value = config.get(setting);
    if (value === undefined || value === null) continue;
    if (Array.isArray(value) && value.length === 0) continue;
    options[key] = value;
  }
  return options;
}

/**
 * The file an executable setting names: a path (absolute, or with a slash: taken as is) or a
 * name looked up on PATH. undefined when there is none.
 */
function findExecutable(name, env = process.env) {
  const isExecutable = (file) => {
    try {
      fs.accessSync(file, fs.constants.X_OK);
      return fs.statSync(file).isFile();
    } catch {
      return false;
    }
  };
  if (name.includes("/") || name.includes(path.sep)) return isExecutable(name) ? name : undefined;
  const extensions = process.platform === "win32" ? (env.PATHEXT || ".EXE").split(";") : [""];
  for (const dir of (env.PATH || "").split(path.delimiter)) {
    if (!dir) continue;
    for (const extension of extensions) {
      const candidate = path.join(dir, name + extension);
      if (isExecutable(candidate)) return candidate;
    }
  }
  return undefined;
}

/** The message shown when the server cannot be found. */
function missingServerMessage(setting) {
  return (
    `CRT: the language server '${setting}' was not found. Install crt (crt-lsp on PATH) ` +
    `or set "crt.server.path" to the crt-lsp executable.`
  );
}

module.exports = { INITIALIZATION_OPTIONS, initializationOptions, findExecutable, missingServerMessage };
