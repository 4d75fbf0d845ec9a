// Checks an unpacked .vsix (the folder given): the files it holds, and that the bundled
// client loads with nothing but the `vscode` module from outside.
const assert = require("node:assert/strict");
const fs = require("fs");
const Module = require("module");
const path = require("path");

const root = process.argv[2];
const files = [];
(function walk(dir) {
  for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
    const file = path.join(dir, entry.name);
    if (entry.isDirectory()) walk(file);
    else files.push(path.relative(root, file));
  }
})(root);
assert.deepEqual(files.sort(), [
  "[Content_Types].xml",
  "extension.vsixmanifest",
  "extension/LICENSE.txt",
  "extension/dist/extension.js",
  "extension/images/glass_and_textures.png",
  "extension/images/icon.png",
  "extension/language-configuration.json",
  "extension/package.json",
  "extension/readme.md",
  "extension/syntaxes/crt.tmLanguage.json",
]);

const manifest = JSON.parse(fs.readFileSync(path.join(root, "extension/package.json"), "utf8"));
assert.equal(manifest.main, "./dist/extension.js");
assert.match(fs.readFileSync(path.join(root, "extension/LICENSE.txt"), "utf8"), /MIT/);

// Any `vscode` member is a do-nothing function: loading must not need more than that.
const anything = new Proxy(function () {}, { get: (target, key) => (key === "prototype" ? {} : anything) });
const load = Module._load;
Module._load = function (request, ...rest) {
  if (request === "vscode") return anything;
  return load.call(this, request, ...rest);
};
const extension = require(path.resolve(root, "extension", manifest.main));
assert.equal(typeof extension.activate, "function");
assert.equal(typeof extension.deactivate, "function");
console.log(`package check: ${files.length} files, the bundle loads`);
