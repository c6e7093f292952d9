// Drives VS Code (code-server) in headless Chromium as a user would, for tests/lsp/test_editors.py:
// opens PROBE_FILE from the explorer, reads the Problems panel, replaces line PROBE_LINE by PROBE_TEXT,
// reads the panel again once it changed, hovers PROBE_HOVER (a token on line PROBE_HOVER_LINE), and
// writes what it saw to PROBE_OUT as JSON and a screenshot to PROBE_SHOT. Needs playwright-core
// (found through NODE_PATH) and a Chromium at PROBE_CHROMIUM.
"use strict";
const { chromium } = require("playwright-core");

const env = process.env;
const WAIT = 40000;
const ROW = /cantools-od\s*\(?(\w+)\)?\s*\[Ln (\d+), Col (\d+)\]/;  // the brackets are drawn by CSS

async function problems(page) {
  const rows = await page.locator(".monaco-list-row:has(.marker-code)").allInnerTexts();
  return rows.map((row) => ROW.exec(row.replace(/\s+/g, " "))).filter(Boolean).map((m) => [Number(m[2]), m[1]]);
}

async function settled(page, differs) {
  // The panel's findings once they differ from `differs` (a JSON text) and hold for a second.
  const until = Date.now() + WAIT;
  let last = null;
  let since = Date.now();
  while (Date.now() < until) {
    const now = JSON.stringify(await problems(page));
    if (now !== last) {
      last = now;
      since = Date.now();
    } else if (now !== differs && now !== "[]" && Date.now() - since > 1000) {
      return JSON.parse(now);
    }
    await page.waitForTimeout(100);
  }
  return JSON.parse(last || "[]");
}

async function goToLine(page, line) {
  await page.keyboard.press("Control+G");
  await page.keyboard.type(String(line));
  await page.keyboard.press("Enter");
  await page.waitForTimeout(300);
}

async function hover(page) {
  await goToLine(page, env.PROBE_HOVER_LINE);
  const token = page.locator(".view-lines span span", { hasText: env.PROBE_HOVER }).first();
  await token.hover();
  const shown = page.locator(".monaco-hover-content").first();
  await shown.waitFor({ state: "visible", timeout: WAIT });
  await page.waitForTimeout(500);
  return shown.innerText();
}

async function main() {
  const browser = await chromium.launchPersistentContext(env.PROBE_PROFILE, {
    executablePath: env.PROBE_CHROMIUM,
    headless: true,
    viewport: { width: 1400, height: 900 },
    args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
           "--disable-component-update", "--disable-sync"],
  });
  const seen = { language: null, first: [], after: [], hover: null };
  try {
    const page = await browser.newPage();
    await page.goto(env.PROBE_URL);
    await page.locator(".explorer-folders-view").getByText(env.PROBE_FILE, { exact: true }).click({ timeout: WAIT });
    await page.locator(".monaco-editor .view-lines").first().click();
    await page.keyboard.press("Control+Shift+M");
    seen.first = await settled(page, null);
    seen.language = await page.locator(".statusbar-item[id$='editor.mode']").innerText();
    await goToLine(page, env.PROBE_LINE);
    await page.keyboard.press("Home");
    await page.keyboard.press("Shift+End");
    await page.keyboard.type(env.PROBE_TEXT);
    seen.after = await settled(page, JSON.stringify(seen.first));
    seen.hover = await hover(page);
    await page.screenshot({ path: env.PROBE_SHOT });
  } finally {
    require("fs").writeFileSync(env.PROBE_OUT, JSON.stringify(seen));
    await browser.close();
  }
}

main().catch((error) => {
  console.error(String(error && error.stack ? error.stack : error).split("\n")[0]);
  process.exit(1);
});
