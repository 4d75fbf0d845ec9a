-- Starts crt-lsp for CRT buffers (Neovim 0.7+, no plugin needed). In init.lua:
--   vim.opt.runtimepath:append("/path/to/crt/editors/nvim")
--   require("crt_lsp").setup({ cmd = { "crt-lsp" } })
local M = {}

function M.setup(opts)
  opts = opts or {}
  local cmd = opts.cmd or { "crt-lsp" }
  local group = vim.api.nvim_create_augroup("crt_lsp", { clear = true })
  vim.api.nvim_create_autocmd("FileType", {
    group = group,
    pattern = "crt",
    callback = function(args)
      local root = vim.fn.fnamemodify(vim.api.nvim_buf_get_name(args.buf), ":p:h")
      -- One client per folder, shared by its buffers.
      for _, client in pairs(vim.lsp.get_active_clients()) do
        if client.name == "crt-lsp" and client.config.root_dir == root then
          vim.lsp.buf_attach_client(args.buf, client.id)
          return
        end
      end
      local id = vim.lsp.start_client({
        name = "crt-lsp",
        cmd = cmd,
        root_dir = root,
        init_options = opts.init_options, -- { includeDirs = {...}, stdlib = "...", debounceMs = 20 }
        on_attach = opts.on_attach,
      })
      if id then vim.lsp.buf_attach_client(args.buf, id) end
    end,
  })
end

return M
