-- Driven by run.sh: opens a .crt file with an error in headless Neovim, attached to crt-lsp,
-- and checks diagnostics, hover, definition, completion, document symbols and an edit.
local lsp_path = os.getenv("CRT_LSP")
local file = os.getenv("CRT_FILE")

local function fail(message)
  io.stderr:write("nvim e2e: FAIL: " .. message .. "\n")
  vim.cmd("cquit! 1")
end

local function step(name)
  io.stdout:write("nvim e2e: " .. name .. "\n")
end

-- The editors/nvim glue: filetype detection, syntax and the client setup.
vim.opt.runtimepath:append(os.getenv("CRT_EDITORS_NVIM"))
vim.cmd("runtime! ftdetect/crt.vim")
require("crt_lsp").setup({ cmd = { lsp_path } })
vim.cmd("edit " .. file)
local buf = vim.api.nvim_get_current_buf()
if vim.bo[buf].filetype ~= "crt" then fail("filetype is '" .. vim.bo[buf].filetype .. "', not crt") end
if vim.bo[buf].commentstring ~= "-- %s" then fail("ftplugin not loaded: " .. vim.bo[buf].commentstring) end
local client_id
vim.wait(5000, function()
  for _, client in pairs(vim.lsp.buf_get_clients(buf)) do
    if client.name == "crt-lsp" then client_id = client.id end
  end
  return client_id ~= nil
end, 20)
if not client_id then fail("crt-lsp did not attach to the buffer") end

local function request(method, params)
  local responses, err = vim.lsp.buf_request_sync(buf, method, params, 10000)
  if not responses then fail(method .. ": no response (" .. tostring(err) .. ")") end
  local response = responses[client_id]
  if not response then fail(method .. ": no response from crt-lsp") end
  if response.err then fail(method .. ": error " .. vim.inspect(response.err)) end
  return response.result
end

local function at(line, character)
  return { textDocument = { uri = vim.uri_from_bufnr(buf) }, position = { line = line, character = character } }
end

-- 1. The diagnostic for the typo arrives, at the right column despite the "é" before it.
step("waiting for diagnostics")
local got = vim.wait(15000, function()
  for _, d in ipairs(vim.diagnostic.get(buf)) do
    if d.message:find("radus") then return true end
  end
  return false
end, 50)
if not got then fail("no diagnostic about 'radus': " .. vim.inspect(vim.diagnostic.get(buf))) end
local typo
for _, d in ipairs(vim.diagnostic.get(buf)) do
  if d.message:find("radus") then typo = d end
end
local line = vim.api.nvim_buf_get_lines(buf, 2, 3, false)[1]
local expected_col = line:find("radus", 1, true) - 1
if typo.lnum ~= 2 or typo.col ~= expected_col then
  fail(string.format("diagnostic at %d:%d, expected 2:%d", typo.lnum, typo.col, expected_col))
end
if typo.severity ~= vim.diagnostic.severity.ERROR then fail("the typo is not an error") end
if not typo.message:find("did you mean 'radius'") then fail("no did-you-mean: " .. typo.message) end

-- 2. Hover on the object type and on the variable.
step("hover")
local hover = request("textDocument/hover", at(2, 8))
if not (hover and hover.contents and hover.contents.value:find("Sphere")) then
  fail("hover on Sphere: " .. vim.inspect(hover))
end
local ball_hover = request("textDocument/hover", at(3, 9))
if not (ball_hover and ball_hover.contents.value:find("ball: Sphere")) then
  fail("hover on ball: " .. vim.inspect(ball_hover))
end

-- 3. Definition of a name defined in the included file.
step("definition")
local gold_col = line:find("gold", 1, true) - 1
local definition = request("textDocument/definition", at(2, gold_col + 1))
if not (definition and definition[1] and definition[1].uri:find("lib.crt", 1, true)) then
  fail("definition of gold: " .. vim.inspect(definition))
end

-- 4. Completion of attributes inside the Sphere (the typo is not a given attribute).
step("completion")
local completion = request("textDocument/completion", at(2, expected_col))
local items = completion and (completion.items or completion) or {}
local labels = {}
for _, item in ipairs(items) do labels[item.label] = true end
if not labels["radius"] or labels["center"] then
  fail("attribute completion: " .. vim.inspect(vim.tbl_keys(labels)))
end

-- 5. Document symbols.
step("document symbols")
local symbols = request("textDocument/documentSymbol", { textDocument = { uri = vim.uri_from_bufnr(buf) } })
local names = {}
for _, s in ipairs(symbols or {}) do table.insert(names, s.name) end
if table.concat(names, ",") ~= 'include "lib.crt",ball,Scene' then
  fail("document symbols: " .. vim.inspect(names))
end

-- 6. Fix the typo in the buffer: the diagnostics update.
step("editing")
local fixed = line:gsub("radus", "radius")
vim.api.nvim_buf_set_lines(buf, 2, 3, false, { fixed })
local cleared = vim.wait(15000, function()
  for _, d in ipairs(vim.diagnostic.get(buf)) do
    if d.message:find("radus") then return false end
  end
  return true
end, 50)
if not cleared then fail("the diagnostic stayed after the fix: " .. vim.inspect(vim.diagnostic.get(buf))) end
if #vim.diagnostic.get(buf, { severity = vim.diagnostic.severity.ERROR }) ~= 0 then
  fail("errors after the fix: " .. vim.inspect(vim.diagnostic.get(buf)))
end
-- And break it again: a new error appears.
vim.api.nvim_buf_set_lines(buf, 3, 4, false, { "Scene { bal }" })
local broken = vim.wait(15000, function()
  for _, d in ipairs(vim.diagnostic.get(buf)) do
    if d.message:find("undefined variable 'bal'") and d.lnum == 3 then return true end
  end
  return false
end, 50)
if not broken then fail("no diagnostic for the new error: " .. vim.inspect(vim.diagnostic.get(buf))) end

step("ok")
vim.lsp.stop_client(client_id)
vim.wait(2000, function() return vim.lsp.get_client_by_id(client_id) == nil end, 50)
vim.cmd("qall!")
