"""The editor snippets of docs/editors.md (the README shows one of them), run as written in the real editors
against `cantools-od lsp`.

Each test makes an example EDS with two errors, opens it in the editor configured only by the documented
snippet, waits for the diagnostics the editor shows, then repairs one line in the editor's buffer and
waits for the diagnostics to follow. What the editor shows must be what `lint` reports for the same
texts. The VS Code one builds the client by the documented line and opens a corpus file in code-server
driven through headless Chromium. A test skips, saying why, when its editor is not installed."""

from __future__ import annotations

import fcntl
import json
import os
import pty
import re
import select
import shutil
import signal
import socket
import struct
import subprocess
import termios
import time
from pathlib import Path

import pytest

from support import EXAMPLES, ROOT, cli_command, corpus_file

EDITORS = ROOT / "docs" / "editors.md"
WAIT = 60  # seconds an editor has for its work (the probes give up sooner)
_PROBE_LUA = r"""
local out = vim.env.PROBE_OUT
local function seen()
  local got = {}
  for _, d in ipairs(vim.diagnostic.get(0)) do table.insert(got, { d.lnum + 1, tostring(d.code) }) end
  return got
end
local first = vim.wait(40000, function() return #vim.diagnostic.get(0) >= 2 end, 50) and seen() or {}
vim.api.nvim_buf_set_lines(0, tonumber(vim.env.PROBE_LINE) - 1, tonumber(vim.env.PROBE_LINE), false,
                           { vim.env.PROBE_TEXT })
local after = vim.wait(40000, function() return #vim.diagnostic.get(0) < #first end, 50) and seen() or {}
local file = io.open(out, "w")
file:write(vim.json.encode({ filetype = vim.bo.filetype, first = first, after = after }))
file:close()
vim.cmd("qa!")
"""
_PROBE_EL = r"""
(require 'json)
(defvar probe-first nil)
(defvar probe-after nil)
(defvar probe-until (+ (float-time) 40))
(defun probe-seen ()
  (mapcar (lambda (d)
            (list (line-number-at-pos (flymake-diagnostic-beg d))
                  (if (string-match "\\[\\([A-Z]+[0-9]+\\)\\]" (flymake-diagnostic-text d))
                      (match-string 1 (flymake-diagnostic-text d)) "")))
          (flymake-diagnostics)))
(defun probe-done ()
  (let ((seen (list (cons 'mode (symbol-name major-mode))
                    (cons 'eglot (and (fboundp 'eglot-managed-p) (eglot-managed-p) t))
                    (cons 'first (vconcat probe-first)) (cons 'after (vconcat probe-after)))))
    (with-temp-file (getenv "PROBE_OUT") (insert (json-encode seen))))
  (kill-emacs 0))
(defun probe-step ()
  "Each tick: wait for the first diagnostics, then repair the line, then wait for fewer diagnostics."
  (let ((buffer (get-file-buffer (getenv "PROBE_FILE"))))
    (when buffer
      (with-current-buffer buffer
        (let ((count (length (flymake-diagnostics))))
          (cond ((> (float-time) probe-until) (probe-done))
                ((and (null probe-first) (>= count 2))
                 (setq probe-first (probe-seen))
                 (goto-char (point-min))
                 (forward-line (1- (string-to-number (getenv "PROBE_LINE"))))
                 (delete-region (line-beginning-position) (line-end-position))
                 (insert (getenv "PROBE_TEXT")))
                ((and probe-first (< count (length probe-first)))
                 (setq probe-after (probe-seen))
                 (probe-done))))))))
(run-with-timer 0.5 0.1 #'probe-step)
"""


def _snippets(language: str, after: str) -> list[str]:
    """The ```language blocks of docs/editors.md in the part that starts with `after`, in order."""
    page = EDITORS.read_text(encoding="utf-8")
    part = page[page.index(after) :]
    part = part[: part.index("\n**", 1)] if "\n**" in part[1:] else part
    return re.findall(rf"```{language}\n(.*?)```", part, re.DOTALL)


def _case(tmp_path: Path) -> tuple[Path, int, str, set[tuple[int, str]], set[tuple[int, str]]]:
    """An example EDS with two defaults out of their type's range, the line (from 1) and text that
    repair the second, and lint's (line, code) findings before and after that repair."""
    lines = (EXAMPLES / "cia402_drive.eds").read_text(encoding="utf-8").splitlines()

    def default_of(section: str) -> int:
        header = lines.index(section)
        return next(n for n in range(header, len(lines)) if lines[n].startswith("DefaultValue="))

    lines[default_of("[1001]")] = "DefaultValue=300"  # UNSIGNED8
    repaired = default_of("[1017]")  # UNSIGNED16
    good = lines[repaired]
    check = tmp_path / "check" / "drive.eds"
    check.parent.mkdir()
    check.write_text("\n".join(lines) + "\n", encoding="utf-8")
    lines[repaired] = "DefaultValue=70000"
    path = tmp_path / "drive.eds"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path, repaired + 1, good, _lint(path), _lint(check)


def _lint(path: Path, status: int = 1) -> set[tuple[int, str]]:
    """lint's (line, code) findings for `path`, which must exit with `status` (1: errors found)."""
    done = subprocess.run([*cli_command(), "lint", "--format", "json", str(path)], capture_output=True, text=True)
    assert done.returncode == status, done.stderr
    return {(int(f["line"]), str(f["code"])) for f in json.loads(done.stdout)}


def _environment(tmp_path: Path, **extra: str) -> dict[str, str]:
    """PATH finds this installation's `cantools-od` first, as the snippets name it."""
    here = str(Path(cli_command()[0]).parent)
    return {**os.environ, "PATH": here + os.pathsep + os.environ.get("PATH", ""), "HOME": str(tmp_path), **extra}


def _nvim_version(nvim: str) -> tuple[int, int]:
    first = subprocess.run([nvim, "--version"], capture_output=True, text=True, timeout=WAIT).stdout.split("\n")[0]
    found = re.search(r"v(\d+)\.(\d+)", first)
    assert found, first
    return int(found.group(1)), int(found.group(2))


def test_the_neovim_snippet_shows_lint_findings_and_follows_an_edit(tmp_path: Path) -> None:
    nvim = shutil.which("nvim")
    if nvim is None:
        pytest.skip("Neovim (nvim) is not installed on this machine")
    version = _nvim_version(nvim)
    if version < (0, 7):
        pytest.skip(f"Neovim {version[0]}.{version[1]} predates every documented snippet (0.7 or newer)")
    modern, older = _snippets("lua", "**Neovim**")
    path, line, text, first, after = _case(tmp_path)
    (tmp_path / "init.lua").write_text(modern if version >= (0, 8) else older, encoding="utf-8")
    (tmp_path / "probe.lua").write_text(_PROBE_LUA, encoding="utf-8")
    out = tmp_path / "seen.json"
    environment = _environment(tmp_path, PROBE_OUT=str(out), PROBE_LINE=str(line), PROBE_TEXT=text)
    command = [nvim, "--headless", "--clean", "-u", "init.lua", path.name, "-c", "luafile probe.lua"]
    subprocess.run(command, cwd=tmp_path, env=environment, capture_output=True, timeout=WAIT + 30)
    seen = json.loads(out.read_text(encoding="utf-8"))
    assert seen["filetype"] == "eds"
    assert {(n, code) for n, code in seen["first"]} == first
    assert {(n, code) for n, code in seen["after"]} == after


_POM_LUA = r"""
vim.wait(3000, function() return false end, 50)
local file = io.open(vim.env.PROBE_OUT, "w")
file:write(tostring(#(vim.lsp.get_clients or vim.lsp.get_active_clients)({ bufnr = 0 })))
file:close()
vim.cmd("qa!")
"""


def test_the_neovim_snippet_leaves_other_xml_files_alone(tmp_path: Path) -> None:
    """A Maven pom.xml is XML too: the server would say it is no device description (XDD004)."""
    nvim = shutil.which("nvim")
    if nvim is None:
        pytest.skip("Neovim (nvim) is not installed on this machine")
    version = _nvim_version(nvim)
    if version < (0, 7):
        pytest.skip(f"Neovim {version[0]}.{version[1]} predates every documented snippet (0.7 or newer)")
    modern, older = _snippets("lua", "**Neovim**")
    (tmp_path / "init.lua").write_text(modern if version >= (0, 8) else older, encoding="utf-8")
    (tmp_path / "probe.lua").write_text(_POM_LUA, encoding="utf-8")
    (tmp_path / "pom.xml").write_text('<?xml version="1.0"?>\n<project><modelVersion>4.0.0</modelVersion></project>\n')
    out = tmp_path / "clients.txt"
    command = [nvim, "--headless", "--clean", "-u", "init.lua", "pom.xml", "-c", "luafile probe.lua"]
    subprocess.run(command, cwd=tmp_path, env=_environment(tmp_path, PROBE_OUT=str(out)), capture_output=True,
                   timeout=WAIT + 30)  # fmt: skip
    assert out.read_text(encoding="utf-8") == "0"


def test_the_readme_shows_a_snippet_these_tests_run() -> None:
    """The README's editor example is one of docs/editors.md's snippets, word for word, so the tests here run it."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    part = readme[readme.index("## In the editor") :]
    shown = re.findall(r"```(lua|elisp|toml)\n(.*?)```", part[: part.index("\n## ", 1)], re.DOTALL)
    assert shown, "the README shows no editor snippet"
    page = EDITORS.read_text(encoding="utf-8")
    assert all(f"```{language}\n{snippet}```" in page for language, snippet in shown), shown


def test_the_vscode_build_line_runs_where_npx_cannot_ask() -> None:
    """Outside a terminal (a task, a script, CI) npx cannot ask whether to fetch vsce, and stops: the
    documented line says yes beforehand."""
    found = re.search(r"\*\*VS Code\*\*.*?Build and install it with `([^`]+)`", EDITORS.read_text("utf-8"), re.DOTALL)
    assert found is not None, "docs/editors.md has no build line for VS Code"
    calls = re.findall(r"npx(?: +(\S+))?", found.group(1))
    assert calls and all(flag in ("--yes", "-y") for flag in calls), found.group(1)


def _eglot_installed(emacs: str, home: Path) -> bool:
    """Whether eglot loads in a plain start-up (built in from 29, an ELPA package before)."""
    probe = '(progn (package-initialize) (princ (if (locate-library "eglot") "yes" "no")))'
    done = subprocess.run(
        [emacs, "--batch", "--eval", probe],
        capture_output=True,
        text=True,
        timeout=WAIT,
        env={**os.environ, "HOME": str(home)},
    )
    return done.stdout.strip().endswith("yes")


def _in_terminal(command: list[str], cwd: Path, environment: dict[str, str]) -> None:
    """Run a full-screen program on a pseudo-terminal of its own, reading (and dropping) what it draws."""
    main, side = pty.openpty()
    process = subprocess.Popen(
        command,
        cwd=cwd,
        env=environment,
        stdin=side,
        stdout=side,
        stderr=side,
        start_new_session=True,
        preexec_fn=lambda: fcntl.ioctl(0, termios.TIOCSCTTY, 0),  # the terminal Emacs opens as /dev/tty
    )
    os.close(side)
    deadline = time.monotonic() + WAIT + 30
    try:
        while process.poll() is None and time.monotonic() < deadline:
            if select.select([main], [], [], 0.2)[0]:
                try:
                    os.read(main, 65536)
                except OSError:
                    break
        process.wait(timeout=max(deadline - time.monotonic(), 1))
    finally:
        if process.poll() is None:
            process.kill()
        os.close(main)


def test_the_emacs_snippet_shows_lint_findings_and_follows_an_edit(tmp_path: Path) -> None:
    emacs = shutil.which("emacs")
    if emacs is None:
        pytest.skip("Emacs is not installed on this machine")
    if not _eglot_installed(emacs, tmp_path):
        pytest.skip("Emacs has no eglot here (built in from Emacs 29; Debian 12's Emacs 28 needs elpa-eglot)")
    (snippet,) = _snippets("elisp", "**Emacs**")
    path, line, text, first, after = _case(tmp_path)
    (tmp_path / ".emacs.d").mkdir()
    (tmp_path / ".emacs.d" / "init.el").write_text(snippet, encoding="utf-8")
    (tmp_path / "probe.el").write_text(_PROBE_EL, encoding="utf-8")
    out = tmp_path / "seen.json"
    environment = _environment(
        tmp_path, TERM="xterm", PROBE_OUT=str(out), PROBE_LINE=str(line), PROBE_TEXT=text, PROBE_FILE=str(path)
    )
    _in_terminal([emacs, "-nw", "-l", str(tmp_path / "probe.el"), path.name], tmp_path, environment)
    seen = json.loads(out.read_text(encoding="utf-8"))
    assert seen["mode"] == "canopen-eds-mode" and seen["eglot"] is True
    assert {(n, code) for n, code in seen["first"]} == first
    assert {(n, code) for n, code in seen["after"]} == after


def _published(log: Path) -> list[set[tuple[int, str]]]:
    """Each publishDiagnostics Helix's log shows (`hx -v`), as (line from 1, code) pairs, in order."""
    found = []
    text = log.read_text(encoding="utf-8", errors="replace") if log.exists() else ""
    for line in text.splitlines():
        at = line.find("<- {")
        if at < 0 or "textDocument/publishDiagnostics" not in line:
            continue
        params = json.loads(line[at + 3 :])["params"]
        found.append({(d["range"]["start"]["line"] + 1, str(d.get("code"))) for d in params["diagnostics"]})
    return found


def _helix_session(command: list[str], cwd: Path, environment: dict[str, str], log: Path, repair: tuple[int, str]
                   ) -> tuple[set[tuple[int, str]], set[tuple[int, str]]]:  # fmt: skip
    """Helix on a terminal of its own: once the server's diagnostics show, the keys that replace line
    `repair[0]` by `repair[1]`; once fewer show, `:q!`. What it showed first and last."""
    main, side = pty.openpty()
    fcntl.ioctl(side, termios.TIOCSWINSZ, struct.pack("HHHH", 40, 120, 0, 0))
    process = subprocess.Popen(
        command, cwd=cwd, env=environment, stdin=side, stdout=side, stderr=side, start_new_session=True,
        preexec_fn=lambda: fcntl.ioctl(0, termios.TIOCSCTTY, 0),
    )  # fmt: skip
    os.close(side)
    first: set[tuple[int, str]] = set()
    after: set[tuple[int, str]] = set()
    deadline, count = time.monotonic() + WAIT, 0
    try:
        while process.poll() is None and time.monotonic() < deadline:
            if select.select([main], [], [], 0.2)[0]:
                os.read(main, 65536)
            published = _published(log)
            if not first and published and len(published[-1]) >= 2:
                first, count = published[-1], len(published)
                for keys in (f":{repair[0]}\r", "x", "c", repair[1] + "\r", "\x1b"):
                    os.write(main, keys.encode())
                    time.sleep(0.3)  # an escape followed at once by a key reads as Alt+key
            elif first and len(published) > count and len(published[-1]) < len(first):
                after = published[-1]
                os.write(main, b":q!\r")
                deadline = min(deadline, time.monotonic() + 10)
    finally:
        if process.poll() is None:
            process.kill()
        process.wait()
        os.close(main)
    return first, after


def test_the_helix_snippet_shows_lint_findings_and_follows_an_edit(tmp_path: Path) -> None:
    hx = shutil.which("hx")
    if hx is None:
        pytest.skip("Helix (hx) is not installed on this machine")
    (snippet,) = _snippets("toml", "**Helix**")
    config = tmp_path / ".config" / "helix"
    config.mkdir(parents=True)
    (config / "languages.toml").write_text(snippet, encoding="utf-8")
    language = re.search(r'^name = "([^"]+)"', snippet, re.MULTILINE)
    assert language is not None
    environment = _environment(tmp_path, TERM="xterm", XDG_CONFIG_HOME=str(tmp_path / ".config"))
    health = subprocess.run([hx, "--health", language.group(1)], env=environment, capture_output=True, text=True)
    assert "cantools-od" in health.stdout and "✘ cantools-od" not in health.stdout, health.stdout
    path, line, text, first, after = _case(tmp_path)
    log = tmp_path / "helix.log"
    seen = _helix_session([hx, "-v", "--log", str(log), path.name], tmp_path, environment, log, (line, text))
    assert seen == (first, after)


def _code_server_environment(tmp_path: Path) -> dict[str, str]:
    """code-server writes a default config and its logs under the XDG folders: in tmp_path, not the user's."""
    return {**os.environ, "XDG_CONFIG_HOME": str(tmp_path / ".config"), "XDG_DATA_HOME": str(tmp_path / ".local")}


def _vscode_tools(tmp_path: Path) -> tuple[str, str] | str:
    """code-server and Chromium, or why the VS Code test cannot run here."""
    code_server = shutil.which(os.environ.get("CODE_SERVER", "code-server"))
    chromium = shutil.which(os.environ.get("CHROMIUM", "chromium")) or shutil.which("chromium-browser")
    if code_server is None:
        return "code-server (VS Code OSS in a browser) is not installed; set CODE_SERVER or put it on PATH"
    if chromium is None:
        return "Chromium is not installed; set CHROMIUM or put chromium on PATH"
    runs = subprocess.run([code_server, "--version"], capture_output=True, text=True, timeout=WAIT,
                          env=_code_server_environment(tmp_path))  # fmt: skip
    if runs.returncode != 0:  # e.g. it needs a newer Node than the one first on PATH
        return "code-server does not run here: " + (runs.stderr.strip() or runs.stdout.strip()).split("\n")[0]
    if shutil.which("npx") is None:
        return "npm/npx is not on this machine"
    found = subprocess.run(["node", "-e", "require.resolve('playwright-core')"], capture_output=True, timeout=WAIT)
    if found.returncode != 0:
        return "playwright-core is not found by node; install it and set NODE_PATH to its node_modules"
    return code_server, chromium


def _documented_build(tmp_path: Path) -> Path:
    """The documented build line for the VS Code client, run as written in a copy of editors/vscode: the VSIX."""
    found = re.search(r"\*\*VS Code\*\*.*?Build and install it with `([^`]+)`", EDITORS.read_text("utf-8"), re.DOTALL)
    assert found is not None, "docs/editors.md has no build line for VS Code"
    shutil.copytree(ROOT / "editors" / "vscode", tmp_path / "editors" / "vscode",
                    ignore=shutil.ignore_patterns("node_modules", "out", "*.vsix"))  # fmt: skip
    # On a terminal, as a user types it, pressing Enter at every question (vsce's "[y/N]" then means no);
    # npx may fetch vsce without asking (this machine's npm config may say no to that question).
    status, output = _typed(["sh", "-c", found.group(1)], tmp_path, {**os.environ, "npm_config_yes": "true"})
    assert status == 0, output[-3000:]
    (vsix,) = (tmp_path / "editors" / "vscode").glob("*.vsix")
    return vsix


def _typed(command: list[str], cwd: Path, environment: dict[str, str]) -> tuple[int, str]:
    """Run `command` on a pseudo-terminal, answering each question ("[y/N]", "(y)") with Enter alone."""
    main, side = pty.openpty()
    process = subprocess.Popen(command, cwd=cwd, env=environment, stdin=side, stdout=side, stderr=side,
                               start_new_session=True)  # fmt: skip
    os.close(side)
    output, answered, deadline = b"", 0, time.monotonic() + 900
    try:
        while time.monotonic() < deadline:
            if select.select([main], [], [], 0.2)[0]:
                try:
                    output += os.read(main, 65536)
                except OSError:  # the terminal closed: the command ended
                    break
                questions = len(re.findall(rb"\[y/N\]|\(y\)", re.sub(rb"\x1b\[[0-9;]*[A-Za-z]", b"", output)))
                if questions > answered:
                    os.write(main, b"\r")
                    answered = questions
            elif process.poll() is not None:
                break
    finally:
        if process.poll() is None:
            process.kill()
        process.wait()
        os.close(main)
    return process.returncode, output.decode("utf-8", "replace")


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port: int = probe.getsockname()[1]
        return port


def _code_server(code_server: str, tmp_path: Path, vsix: Path, folder: Path) -> tuple[subprocess.Popen[bytes], str]:
    """code-server with only the VSIX installed, the server command set to this installation, on a free port."""
    data, extensions = tmp_path / "vscode-data", tmp_path / "vscode-extensions"
    (data / "User").mkdir(parents=True)
    settings = {"workbench.startupEditor": "none", "cantools-od.command": [*cli_command(), "lsp"]}
    (data / "User" / "settings.json").write_text(json.dumps(settings), encoding="utf-8")
    environment = _code_server_environment(tmp_path)
    dirs = ["--user-data-dir", str(data), "--extensions-dir", str(extensions)]
    installed = subprocess.run([code_server, *dirs, "--install-extension", str(vsix)], env=environment,
                               capture_output=True, text=True, timeout=WAIT)  # fmt: skip
    assert installed.returncode == 0 and "successfully installed" in installed.stdout, (
        installed.stdout + installed.stderr
    )
    port = _free_port()
    flags = ["--auth", "none", "--bind-addr", f"127.0.0.1:{port}", "--disable-telemetry", "--disable-update-check",
             "--disable-workspace-trust"]  # fmt: skip
    log = tmp_path / "code-server.log"
    with log.open("wb") as output:
        server = subprocess.Popen([code_server, *dirs, *flags, str(folder)], env=environment, stdout=output,
                                  stderr=output, start_new_session=True)  # fmt: skip
    deadline = time.monotonic() + WAIT
    while b"HTTP server listening" not in log.read_bytes():
        if server.poll() is not None or time.monotonic() > deadline:
            _stop(server)
            pytest.fail("code-server did not start: " + log.read_text(errors="replace")[-2000:])
        time.sleep(0.2)
    return server, f"http://127.0.0.1:{port}/?folder={folder}"


def _stop(server: subprocess.Popen[bytes]) -> None:
    """code-server and what it started (its extension hosts, the language server)."""
    if server.poll() is None:
        os.killpg(server.pid, signal.SIGTERM)
    server.wait(timeout=WAIT)


def test_the_vscode_client_built_as_documented_shows_lint_findings_in_code_server(tmp_path: Path) -> None:
    """The documented VS Code build line, its VSIX installed into code-server (VS Code OSS), a real corpus file
    opened from the explorer in headless Chromium (driven by playwright-core through vscode_probe.js): the
    Problems panel shows lint's findings, follows a one-line edit, and a mapping entry's hover names the
    object it maps. Runs when code-server (CODE_SERVER or PATH; it needs the Node it was built for first
    on PATH), Chromium (CHROMIUM or PATH) and playwright-core (NODE_PATH) are found, e.g. after
    `npm install --prefix /tmp/vsc code-server playwright-core` and `apt-get install chromium`:
    `CODE_SERVER=/tmp/vsc/node_modules/.bin/code-server NODE_PATH=/tmp/vsc/node_modules pytest -k vscode`."""
    tools = _vscode_tools(tmp_path)
    if isinstance(tools, str):
        pytest.skip(tools)
    code_server, chromium = tools
    device = corpus_file("canopendemo__demoDevice.eds")
    folder = tmp_path / "work"
    folder.mkdir()
    path = folder / device.name
    shutil.copyfile(device, path)
    lines = path.read_text(encoding="utf-8").splitlines()
    line = next(n for n, row in enumerate(lines, 1) if row.startswith("ModificationTime="))
    mapping = next(n for n, row in enumerate(lines, 1) if re.fullmatch(r"DefaultValue=0x6000\d{4}", row))
    repaired = tmp_path / "check" / device.name
    repaired.parent.mkdir()
    text = "ModificationTime=04:49PM"  # CiA 306's hh:mm, the one change
    repaired.write_text("\n".join([*lines[: line - 1], text, *lines[line:]]) + "\n", "utf-8")
    first, after = _lint(path, 0), _lint(repaired, 0)  # warnings and infos only
    assert after < first, "the edit must change lint's findings"
    server, url = _code_server(code_server, tmp_path, _documented_build(tmp_path), folder)
    out = tmp_path / "seen.json"
    probe = {"PROBE_URL": url, "PROBE_FILE": path.name, "PROBE_LINE": str(line), "PROBE_TEXT": text,
             "PROBE_HOVER_LINE": str(mapping), "PROBE_HOVER": lines[mapping - 1].split("=")[1], "PROBE_OUT": str(out),
             "PROBE_SHOT": str(tmp_path / "vscode.png"), "PROBE_CHROMIUM": chromium,
             "PROBE_PROFILE": str(tmp_path / "chromium")}  # fmt: skip
    try:
        done = subprocess.run(["node", str(Path(__file__).parent / "vscode_probe.js")], env={**os.environ, **probe},
                              capture_output=True, text=True, timeout=WAIT * 4)  # fmt: skip
    finally:
        _stop(server)
    assert out.is_file(), done.stderr[-2000:]
    seen = json.loads(out.read_text(encoding="utf-8"))
    assert seen["language"] == "CANopen EDS/DCF"
    assert {(n, code) for n, code in seen["first"]} == first and len(seen["first"]) == len(first)
    assert {(n, code) for n, code in seen["after"]} == after
    assert done.returncode == 0, done.stderr[-2000:]
    assert "Mapping entry" in seen["hover"] and "6000h" in seen["hover"]
