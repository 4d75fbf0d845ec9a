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
local opened_url
require("crt_lsp").setup({
  cmd = { lsp_path },
  crtc = os.getenv("CRT_FAKE_CRTC"),
  mappings = { rename = "<leader>R", format = "<leader>F", references = false },
  open_url = function(url) opened_url = url end,
})
-- The syntax file, on a script of its own (its invalid escape would be a diagnostic below):
-- (line, text, expected group at the text's first column).
step("syntax")
vim.cmd("edit " .. os.getenv("CRT_SYNTAX_FILE"))
for _, case in ipairs({
  { 1, "--", "crtComment" }, { 1, "for", "crtComment" }, { 1, "Scene", "crtComment" },
  { 1, "2.", "crtComment" }, { 2, "Sphere", "crtType" }, { 2, "center", "crtAttribute" },
  { 2, "->", "crtOperator" }, { 2, "-- é", "crtComment" }, { 3, "Scene", "crtKeyword" },
  { 4, "2.,", "crtNumber" }, { 4, "., .25", "crtNumber" }, { 4, ".25", "crtNumber" },
  { 4, "\\t", "crtEscape" }, { 4, "\\q", "crtEscapeError" }, { 4, "true", "crtBoolean" },
  { 4, "1e3", "crtNumber" },
}) do
  local lnum, text, want = case[1], case[2], case[3]
  local col = vim.api.nvim_buf_get_lines(0, lnum - 1, lnum, false)[1]:find(text, 1, true)
  local got = vim.fn.synIDattr(vim.fn.synID(lnum, col, 1), "name")
  if got ~= want then
    fail(string.format("syntax at %d:%d ('%s') is '%s', expected '%s'", lnum, col, text, got, want))
  end
end

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

-- The mappings set on attach: defaults, an override, a disabled one; and the omnifunc.
step("mappings")
if vim.bo[buf].omnifunc ~= "v:lua.vim.lsp.omnifunc" then fail("omnifunc is '" .. vim.bo[buf].omnifunc .. "'") end
local function mapped(lhs) return vim.fn.maparg(lhs, "n", false, true).buffer == 1 end
for _, lhs in ipairs({ "K", "gd", "<leader>R", "<leader>F" }) do
  if not mapped(lhs) then fail("no buffer mapping for " .. lhs) end
end
if mapped("gr") then fail("gr is mapped although references = false") end
if mapped("<leader>rn") then fail("the default rename mapping stayed beside its override") end

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

-- 7. Formatting, by typing the mapping (format() or, on 0.7, formatting(): both asynchronous).
step("formatting")
vim.api.nvim_buf_set_lines(buf, 3, 4, false, { "Scene{ball}" })
vim.api.nvim_feedkeys(vim.api.nvim_replace_termcodes("<leader>F", true, false, true), "mx", false)
local formatted = vim.wait(15000, function()
  return vim.api.nvim_buf_get_lines(buf, 3, 4, false)[1] == "Scene { ball }"
end, 50)
if not formatted then fail("formatting: " .. vim.api.nvim_buf_get_lines(buf, 3, 4, false)[1]) end

-- 8. :CrtPreview runs crtc --preview on the file, opens the URL it prints, and stops it
-- when the buffer goes.
step("preview")
vim.cmd("CrtPreview")
if not vim.wait(10000, function() return opened_url ~= nil end, 50) then fail("the preview URL was not opened") end
if opened_url ~= "http://127.0.0.1:8123/?token=abc" then fail("opened " .. opened_url) end
local args = table.concat(vim.fn.readfile(os.getenv("CRT_FAKE_LOG")), " ")
if args ~= "--preview " .. file then fail("crtc ran with: " .. args) end
vim.cmd("bwipeout!")
local stopped = vim.wait(10000, function() return vim.fn.filereadable(os.getenv("CRT_FAKE_LOG") .. ".stopped") == 1 end, 50)
if not stopped then fail("the preview process was not stopped when its buffer went") end

-- 9. A server that is not there: a message naming it and the option, no client.
step("missing server")
local notified = {}
vim.notify = function(message) table.insert(notified, message) end
require("crt_lsp").setup({ cmd = { "/nonexistent/crt-lsp" } })
vim.cmd("edit " .. os.getenv("CRT_SYNTAX_FILE"))
local message = table.concat(notified, "\n")
if not (message:find("'/nonexistent/crt-lsp' is not an executable", 1, true) and message:find("cmd = ", 1, true)) then
  fail("no message about the missing server: " .. message)
end

step("ok")
vim.lsp.stop_client(client_id)
vim.wait(2000, function() return vim.lsp.get_client_by_id(client_id) == nil end, 50)
vim.cmd("qall!")
