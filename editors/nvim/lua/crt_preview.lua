-- :CrtPreview runs `crtc --preview FILE` for the buffer and opens the URL it prints first
-- ("preview: http://127.0.0.1:PORT/?token=..."). One preview per buffer; it is stopped
-- (SIGTERM, as jobstop sends) when the buffer is unloaded or Neovim exits.
local M = {}

local jobs = {} -- buffer number -> { id = job id, url = the URL once printed }

local function default_open(url)
  if vim.fn.executable("xdg-open") == 1 then
    vim.fn.jobstart({ "xdg-open", url }, { detach = true })
  end
  vim.api.nvim_echo({ { "CRT preview: " .. url } }, true, {})
end

local function on_first_line(bufnr, open)
  local pending = ""
  return function(_, data)
    local job = jobs[bufnr]
    if not job or job.url then return end
    -- data holds lines split at newlines; the first continues the previous call's last
    -- (unfinished) line.
    data[1] = pending .. data[1]
    for i = 1, #data - 1 do
      local url = data[i]:match("^preview: (%S+)")
      if url then
        job.url = url
        vim.schedule(function() open(url) end)
        return
      end
    end
    pending = data[#data]
  end
end

function M.start(bufnr, opts)
  local existing = jobs[bufnr]
  local open = opts.open_url or default_open
  if existing then
    if existing.url then open(existing.url) end
    return existing.id
  end
  if vim.bo[bufnr].modified then vim.api.nvim_buf_call(bufnr, function() vim.cmd("write") end) end
  local file = vim.api.nvim_buf_get_name(bufnr)
  local crtc = opts.crtc or "crtc"
  jobs[bufnr] = {}
  local id = vim.fn.jobstart({ crtc, "--preview", file }, {
    cwd = vim.fn.fnamemodify(file, ":h"),
    on_stdout = on_first_line(bufnr, open),
    on_stderr = function(_, data)
      local text = table.concat(data, "\n")
      if text ~= "" then vim.schedule(function() vim.notify(text, vim.log.levels.WARN) end) end
    end,
    on_exit = function(_, code)
      local job = jobs[bufnr]
      jobs[bufnr] = nil
      if job and not job.url then
        vim.schedule(function()
          vim.notify("crtc --preview exited (" .. code .. ") before printing its URL",
            vim.log.levels.ERROR)
        end)
      end
    end,
  })
  if id <= 0 then
    jobs[bufnr] = nil
    vim.notify("CrtPreview: cannot run '" .. crtc .. "'", vim.log.levels.ERROR)
    return nil
  end
  jobs[bufnr].id = id
  vim.api.nvim_create_autocmd("BufUnload", {
    buffer = bufnr,
    once = true,
    callback = function() M.stop(bufnr) end,
  })
  return id
end

function M.stop(bufnr)
  local job = jobs[bufnr]
  if job and job.id then vim.fn.jobstop(job.id) end
end

function M.define_command(bufnr, opts)
  vim.api.nvim_buf_create_user_command(bufnr, "CrtPreview", function() M.start(bufnr, opts) end,
    { desc = "Preview this CRT script (crtc --preview)" })
  vim.api.nvim_buf_create_user_command(bufnr, "CrtPreviewStop", function() M.stop(bufnr) end,
    { desc = "Stop this script's preview" })
end

return M
