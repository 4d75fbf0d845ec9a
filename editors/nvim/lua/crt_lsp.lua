-- Starts crt-lsp for CRT buffers (Neovim 0.7+, no plugin manager needed). In init.lua:
--   vim.opt.runtimepath:append("/path/to/crt/editors/nvim")
--   require("crt_lsp").setup()
-- Options (all optional):
--   cmd          the server command, default { "crt-lsp" } (the installed one, on PATH)
--   crtc         the crtc executable :CrtPreview runs, default "crtc"
--   init_options initializationOptions: { includeDirs = {...}, assetRoots = {...}, ... }
--   on_attach    function(client, bufnr) called after the plugin's own set-up
--   mappings     false for none, or a table overriding the defaults below (a key set to
--                false drops that mapping)
--   open_url     function(url) showing the preview; default xdg-open, else echo the URL
local M = {}

M.default_mappings = {
  hover = "K",
  definition = "gd",
  references = "gr",
  rename = "<leader>rn",
  format = "<leader>f",
}

-- Neovim 0.8 renamed formatting() to format(); 0.7 only has the old name.
local function format_buffer()
  if vim.lsp.buf.format then
    vim.lsp.buf.format({ async = true })
  else
    vim.lsp.buf.formatting()
  end
end

local actions = {
  hover = vim.lsp.buf.hover,
  definition = vim.lsp.buf.definition,
  references = vim.lsp.buf.references,
  rename = vim.lsp.buf.rename,
  format = format_buffer,
}

local function set_mappings(bufnr, overrides)
  if overrides == false then return end
  local keys = vim.tbl_extend("force", M.default_mappings, overrides or {})
  for action, lhs in pairs(keys) do
    if lhs and actions[action] then
      vim.keymap.set("n", lhs, actions[action],
        { buffer = bufnr, silent = true, desc = "crt-lsp " .. action })
    end
  end
end

local function attach(opts)
  return function(client, bufnr)
    vim.bo[bufnr].omnifunc = "v:lua.vim.lsp.omnifunc"
    set_mappings(bufnr, opts.mappings)
    if opts.on_attach then opts.on_attach(client, bufnr) end
  end
end

local function start_or_reuse(bufnr, opts)
  local cmd = opts.cmd or { "crt-lsp" }
  if vim.fn.executable(cmd[1]) ~= 1 then
    vim.notify("crt-lsp: '" .. cmd[1] .. "' is not an executable; install crt or pass "
      .. "cmd = { '/path/to/crt-lsp' } to require('crt_lsp').setup()", vim.log.levels.ERROR)
    return
  end
  local config = {
    name = "crt-lsp",
    cmd = cmd,
    -- One client per folder, shared by its buffers.
    root_dir = vim.fn.fnamemodify(vim.api.nvim_buf_get_name(bufnr), ":p:h"),
    init_options = opts.init_options,
    on_attach = attach(opts),
  }
  -- Neovim 0.8 and later reuse a client of the same name and folder themselves (and
  -- deprecate start_client); 0.7 has only the pieces.
  if vim.lsp.start then
    vim.lsp.start(config, { bufnr = bufnr })
    return
  end
  for _, client in pairs(vim.lsp.get_active_clients()) do
    if client.name == config.name and client.config.root_dir == config.root_dir then
      vim.lsp.buf_attach_client(bufnr, client.id)
      return
    end
  end
  local id = vim.lsp.start_client(config)
  if id then vim.lsp.buf_attach_client(bufnr, id) end
end

function M.setup(opts)
  opts = opts or {}
  local group = vim.api.nvim_create_augroup("crt_lsp", { clear = true })
  vim.api.nvim_create_autocmd("FileType", {
    group = group,
    pattern = "crt",
    callback = function(args)
      start_or_reuse(args.buf, opts)
      require("crt_preview").define_command(args.buf, opts)
    end,
  })
end

return M
