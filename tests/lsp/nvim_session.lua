-- End-to-end: Neovim's built-in LSP client drives `fxkit lsp` on a real effect (open, hover,
-- definition across includes, an edit that gets a diagnostic, completion in a pass, the
-- edit undone, a shader error only the compile finds and its fix, shutdown). Run headless by ctest (tests/lsp/CMakeLists.txt); exits 0 when
-- every check holds, 1 with the failures on stderr otherwise. Waits are for events (a
-- publication, a reply), bounded by FXKIT_PATIENCE_MS so a broken server cannot hang CI.
local fxkit = os.getenv("FXKIT_BINARY")
local effect = os.getenv("FXKIT_EFFECT")
local patience = tonumber(os.getenv("FXKIT_PATIENCE_MS") or "60000")
local failures = {}

local function check(ok, what)
  if not ok then table.insert(failures, what) end
end

local published, last_diagnostics, exit_code = 0, nil, nil

local function errors_with(code)
  local n = 0
  for _, d in ipairs(last_diagnostics or {}) do
    if d.severity == 1 and (code == nil or d.code == code) then n = n + 1 end
  end
  return n
end

local function main()
  vim.cmd("edit " .. vim.fn.fnameescape(effect))
  local buf = vim.api.nvim_get_current_buf()
  local client_id = vim.lsp.start_client({
    name = "fxkit",
    cmd = { fxkit, "lsp" },
    root_dir = vim.fn.fnamemodify(effect, ":h"),
    init_options = { includeDirs = { "." } },
    handlers = {
      ["textDocument/publishDiagnostics"] = function(err, result, ctx, config)
        published = published + 1
        last_diagnostics = result.diagnostics
        vim.lsp.diagnostic.on_publish_diagnostics(err, result, ctx, config)
      end,
    },
    on_exit = function(code) exit_code = code end,
  })
  check(client_id ~= nil, "the client did not start")
  vim.lsp.buf_attach_client(buf, client_id)
  check(vim.wait(patience, function() return published >= 1 end, 5), "no diagnostics were published on open")
  check(errors_with(nil) == 0, "the clean effect got errors: " .. vim.inspect(last_diagnostics))

  local uri = vim.uri_from_bufnr(buf)
  local function request(method, line, character)
    local params = { textDocument = { uri = uri }, position = { line = line, character = character } }
    local replies = vim.lsp.buf_request_sync(buf, method, params, patience) or {}
    local reply = replies[client_id]
    check(reply ~= nil and reply.err == nil, method .. " got no reply: " .. vim.inspect(replies))
    return reply and reply.result
  end

  -- Line 92 (0-based 91): `specular = guarded_pow(nh, SpecularExponent);`
  local hover = request("textDocument/hover", 91, 40)
  check(hover and hover.contents.value:find("SPECULARPOWER", 1, true), "hover: " .. vim.inspect(hover))
  local def = request("textDocument/definition", 102, 40) -- compile ps_2_0 TangentSpacePS(...)
  local loc = def and (def[1] or def)
  check(loc and loc.range.start.line == 71, "definition of the pass's entry: " .. vim.inspect(def))
  def = request("textDocument/definition", 91, 24) -- guarded_pow, in common.fxh
  loc = def and (def[1] or def)
  check(loc and loc.uri:find("common.fxh", 1, true), "definition across includes: " .. vim.inspect(def))

  -- A typo: a diagnostic as you type, with the did-you-mean.
  local before = published
  vim.api.nvim_buf_set_text(buf, 91, 35, 91, 51, { "SpecularExponant" })
  check(vim.wait(patience, function() return published > before and errors_with("unknown-identifier") == 1 end, 5),
    "no unknown-identifier after the edit: " .. vim.inspect(last_diagnostics))
  local message = (last_diagnostics and last_diagnostics[1] and last_diagnostics[1].message) or ""
  check(message:find("did you mean 'SpecularExponent'", 1, true), "message: " .. message)

  -- Completion of a state value in a pass.
  vim.api.nvim_buf_set_lines(buf, 103, 103, false, { "        CullMode = " })
  local items = request("textDocument/completion", 103, 19)
  local labels = {}
  for _, item in ipairs((items and (items.items or items)) or {}) do labels[item.label] = true end
  check(labels["CCW"] and labels["None"], "completion of CullMode's values: " .. vim.inspect(items))

  -- Undo both edits: the diagnostics clear.
  before = published
  vim.api.nvim_buf_set_lines(buf, 103, 104, false, {})
  vim.api.nvim_buf_set_text(buf, 91, 35, 91, 51, { "SpecularExponent" })
  check(vim.wait(patience, function() return published > before and errors_with(nil) == 0 end, 5),
    "diagnostics stayed after the undo: " .. vim.inspect(last_diagnostics))

  -- A call only glslang rejects (tex2D without coordinates): the compiled-shader diagnostic
  -- arrives after the debounce and the compile, and goes with the fix.
  before = published
  vim.api.nvim_buf_set_text(buf, 75, 37, 75, 44, { "" })
  check(vim.wait(patience, function() return published > before and errors_with(nil) >= 1 end, 5),
    "no compiled-shader error after the edit: " .. vim.inspect(last_diagnostics))
  check(last_diagnostics[1].range.start.line == 75, "compiled-shader error: " .. vim.inspect(last_diagnostics))
  before = published
  vim.api.nvim_buf_set_text(buf, 75, 37, 75, 37, { ", IN.uv" })
  check(vim.wait(patience, function() return published > before and errors_with(nil) == 0 end, 5),
    "the compiled-shader error stayed after the fix: " .. vim.inspect(last_diagnostics))

  vim.lsp.stop_client(client_id)
  check(vim.wait(patience, function() return exit_code ~= nil end, 5), "the server did not exit")
  check(exit_code == 0, "the server exited with " .. tostring(exit_code))
end

local ok, err = pcall(main)
if not ok then table.insert(failures, "error: " .. tostring(err)) end
if #failures == 0 then
  io.stdout:write("nvim lsp session: every check passed\n")
  vim.cmd("qa!")
else
  io.stderr:write(table.concat(failures, "\n") .. "\n")
  vim.cmd("cquit 1")
end
