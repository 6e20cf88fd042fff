// Drives headless Chromium over the built page "The lab in your browser"
// for crates/workbook/tests/lab_in_browser.rs: `node lab_in_browser.js
// CASES.json` prints one JSON object of what the page did, and the Rust
// test judges it. Every request the page makes is recorded, so that the
// test can check it loads nothing from the network.
"use strict";

const fs = require("fs");
const http = require("http");
const path = require("path");
const { chromium } = require("playwright-core");

const cases = JSON.parse(fs.readFileSync(process.argv[2], "utf8"));
const timeout = 60000;

// A plain file server over the built book, on this machine only: the page
// must work served as well as from disk.
function serve(root) {
  const types = { ".html": "text/html", ".js": "text/javascript", ".css": "text/css",
                  ".png": "image/png", ".woff2": "font/woff2", ".svg": "image/svg+xml" };
  const server = http.createServer((request, response) => {
    const file = path.join(root, decodeURIComponent(new URL(request.url, "http://x").pathname));
    if (!file.startsWith(root) || !fs.existsSync(file) || fs.statSync(file).isDirectory()) {
      response.writeHead(404);
      response.end();
      return;
    }
    response.writeHead(200, { "content-type": types[path.extname(file)] || "application/octet-stream" });
    fs.createReadStream(file).pipe(response);
  });
  return new Promise((resolve) => server.listen(0, "127.0.0.1", () => resolve(server)));
}

// Wait until `selector`'s data-state is one of `states`.
async function settled(page, selector, states) {
  await page.waitForFunction(([s, wanted]) => {
    const e = document.querySelector(s);
    return e && wanted.includes(e.dataset.state);
  }, [selector, states], { timeout });
  return page.$eval(selector, (e) => Object.assign({}, e.dataset));
}

async function viewChapter(page, chapter, size) {
  // Wait for any render under way, then ask for this one.
  await settled(page, "#lab-viewer", ["done", "error"]);
  await page.selectOption("#lab-size", size);
  await page.selectOption("#lab-chapter", String(chapter));
  await page.waitForFunction((c) => {
    const e = document.querySelector("#lab-viewer");
    return e.dataset.state === "error" || (e.dataset.state === "done" && e.dataset.chapter === c);
  }, String(chapter), { timeout });
  const data = await page.$eval("#lab-viewer", (e) => Object.assign({}, e.dataset));
  data.frame = await page.$eval("#lab-frame", (e) => e.textContent);
  data.agreement = await page.$eval("#lab-agreement", (e) => e.textContent);
  return data;
}

// The text in the editor as a paste puts it there: one `input` event.
// (Playwright's `fill` takes seconds over a 500-line textarea.)
async function paste(page, text) {
  await page.$eval("#lab-editor", (area, t) => {
    area.value = t;
    area.dispatchEvent(new Event("input", { bubbles: true }));
  }, text);
}

async function tryVariant(page, variant) {
  await paste(page, variant.text);
  // The check starts after a short pause; wait for it to start, then end.
  await page.waitForFunction(() => document.querySelector("#lab-tasks").dataset.state !== "editing",
                             null, { timeout });
  const data = await settled(page, "#lab-tasks", ["passed", "failed", "compile-error", "error"]);
  data.name = variant.name;
  data.ms = Number(data.ms);
  data.verdict = await page.$eval("#lab-verdict", (e) => e.textContent);
  data.messages = await page.$eval("#lab-messages", (e) => e.textContent);
  if (cases.shots) {
    const name = variant.name.replace(/[^a-z0-9]+/gi, "-");
    await page.locator("#lab-tasks").screenshot({ path: path.join(cases.shots, "task-" + name + ".png") });
  }
  return data;
}

(async () => {
  const result = { requests: [], console: [], phases: {} };
  let last = Date.now();
  const phase = (name) => { const now = Date.now(); result.phases[name] = now - last; last = now; };
  const browser = await chromium.launch({
    executablePath: cases.chromium,
    headless: true,
    args: ["--enable-unsafe-webgpu", "--use-angle=swiftshader", "--use-webgpu-adapter=swiftshader"],
  });
  try {
    const context = await browser.newContext({ viewport: { width: 1200, height: 900 } });
    const page = await context.newPage();
    page.on("request", (r) => result.requests.push(r.url()));
    page.on("console", (m) => { if (m.type() === "error") result.console.push(m.text()); });
    page.on("pageerror", (e) => result.console.push(String(e)));

    await page.goto(cases.page);
    await page.waitForFunction(() => document.querySelector("#lab-page").dataset.gpu, null, { timeout });
    result.gpu = await page.$eval("#lab-page", (e) => e.dataset.gpu);
    result.status = await page.$eval("#lab-status", (e) => e.textContent);
    if (result.gpu === "ready") {
      // The blank, as the page first shows it, and its first check.
      result.first = await settled(page, "#lab-tasks", ["passed", "failed", "compile-error", "error"]);
      phase("launch, load and the blank's first check");
      result.chapters = [];
      for (const chapter of cases.chapters) {
        result.chapters.push(await viewChapter(page, chapter, cases.size));
      }
      phase("chapters 1-5");
      result.times = [];
      for (const size of cases.timeSizes || []) {
        for (const chapter of cases.timeChapters || []) {
          const data = await viewChapter(page, chapter, size);
          result.times.push({ chapter, size, frameMs: Number(data.frameMs), frame: data.frame });
        }
      }
      result.variants = [];
      for (const variant of cases.variants) {
        result.variants.push(await tryVariant(page, variant));
      }
      phase("answers");
      // The learner's text survives a reload.
      await paste(page, cases.kept);
      await page.reload();
      await page.waitForFunction(() => document.querySelector("#lab-page").dataset.gpu, null, { timeout });
      result.keptAfterReload = (await page.inputValue("#lab-editor")) === cases.kept;
      if (cases.shots) {
        await settled(page, "#lab-viewer", ["done", "error"]);
        await settled(page, "#lab-tasks", ["passed", "failed", "compile-error", "error"]);
        await page.screenshot({ path: path.join(cases.shots, "page.png"), fullPage: true });
      }
    }
    await page.close();
    phase("reload");

    // Served: the same page over HTTP from this machine.
    const server = await serve(cases.root);
    const served = await context.newPage();
    const base = "http://127.0.0.1:" + server.address().port + "/";
    served.on("request", (r) => result.requests.push(r.url()));
    await served.goto(base + cases.pagePath);
    await served.waitForFunction(() => document.querySelector("#lab-page").dataset.gpu, null, { timeout });
    result.served = { gpu: await served.$eval("#lab-page", (e) => e.dataset.gpu), base };
    if (result.served.gpu === "ready") {
      result.served.view = await settled(served, "#lab-viewer", ["done", "error"]);
    }
    server.close();
    phase("served");
  } catch (error) {
    result.error = String(error && error.stack || error);
  } finally {
    await browser.close();
  }
  process.stdout.write(JSON.stringify(result) + "\n");
})();
