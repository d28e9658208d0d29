/* browser_lab.js (bench, chapter 8): the lab's page tested in headless Chromium against
 * the native programs (make lab-test).
 *
 *   node bench/lab/browser_lab.js LAB_DIR PROGRAMS_DIR OUT_DIR
 *
 * LAB_DIR holds the page and lab-native (make lab), PROGRAMS_DIR the chapter programs
 * and lab-reference. The native side is run first, into OUT_DIR/native; the page is
 * tested in a copy, OUT_DIR/page, given a reference of its own. Checks:
 *   1. the page loads from file:// and writes nothing on its console, and a copy of it
 *      with an error planted is caught writing one (the check can fail);
 *   2. chapter 2's and chapter 7's estimators, N samples at seed 1, equal the chapter
 *      programs' images bit for bit (required: so far they have); chapter 8's equals
 *      lab-native's bit for bit or else passes the per-pixel agreement test below (its
 *      photons draw on sin and cos, whose last bit WebAssembly's libm rounds otherwise);
 *      an image is the same, bit for bit, on 1 and on 3 workers;
 *   3. the inspector's paths for given pixels and samples are lab-native's recordings,
 *      character for character, and account for the radiance;
 *   4. the scene editor's message for each bad scene is the command line's (the last
 *      chapter's program, run on the same text under the same name);
 *   5. a reference of `make lab-references` loads, and the page's error against it is
 *      what the chapter programs measure (lab-reference --error) for the same image;
 *   6. screenshots of the page's states (one panel with the inspector open on a clicked
 *      pixel, its plan, two panels side by side with their plot, the editor with an
 *      error, a refused address) in OUT_DIR, for a person to look at;
 *   7. the address, the controls and the limits (browser_address.js): the command line's
 *      words for the same values, every range's ends, hostile addresses, later changes
 *      and history, the inspector's and the editor's limits, equal time, the book's link;
 *   8. (first, on the page as make lab built it) every comparison the page offers and every
 *      chapter's own render show each panel's error against a reference, and a panel
 *      with no reference names the biases its standard error leaves out;
 *   9. chapter 10 (its passes are lab-native's bit for bit, in check 2): its panel renders
 *      to its target, its map of samples per pixel is drawn from its samples and is not
 *      uniform, the unbiased rule's relative RMSE against a reference agrees with its own
 *      estimate, and chapter 7 rendered to a target error stops there and says what it
 *      cost, its estimate beside its error against the reference.
 * The agreement test (after Mitsuba's render tests): where two values differ, z = |a - b|
 * / (sqrt(2) se), se the page's per-pixel standard error (the same estimator and samples
 * on both sides), must not reject at the Sidak-corrected level 0.01 over all values.
 * Prints one line per check; exit status 1 if any fails.
 */
"use strict";

const fs = require("fs");
const path = require("path");
const {Chromium, fileUrl} = require("./chromium.js");
const address = require("./browser_address.js");

const childProcess = require("child_process");

const [labDir, programsDir, outDir] = process.argv.slice(2);
const nativeDir = path.join(outDir, "native"), pageDir = path.join(outDir, "page");
const LEVEL = 0.01;
let failures = 0;

function report(ok, text) {
    console.log((ok ? "ok    " : "FAIL  ") + text);
    if (!ok) failures++;
}

/* A PFM's pixels as floats, rows from the top (PFM stores them from the bottom). */
function readPfm(file) {
    const bytes = fs.readFileSync(file);
    let offset = 0;
    const lines = [];
    while (lines.length < 3) {
        const end = bytes.indexOf(10, offset);
        lines.push(bytes.toString("latin1", offset, end));
        offset = end + 1;
    }
    const [width, height] = lines[1].split(/\s+/).map(Number);
    const little = Number(lines[2]) < 0, floats = new Float32Array(3 * width * height);
    for (let row = 0; row < height; row++)
        for (let i = 0; i < 3 * width; i++) {
            const at = offset + 4 * (3 * width * (height - 1 - row) + i);
            floats[3 * width * row + i] = little ? bytes.readFloatLE(at) : bytes.readFloatBE(at);
        }
    return {width: width, height: height, pixels: floats};
}

function doubles(base64) {
    const buffer = Buffer.from(base64, "base64");
    return new Float64Array(buffer.buffer.slice(buffer.byteOffset, buffer.byteOffset + buffer.length));
}

function floats(base64) {
    const buffer = Buffer.from(base64, "base64");
    return new Float32Array(buffer.buffer, buffer.byteOffset, buffer.length / 4);
}

/* erfc(x), x >= 0, relative error below 1.2e-7 (a Chebyshev fit, Numerical Recipes). */
function erfc(x) {
    const t = 1 / (1 + 0.5 * x);
    return t * Math.exp(-x * x - 1.26551223 + t * (1.00002368 + t * (0.37409196 + t * (0.09678418 +
        t * (-0.18628806 + t * (0.27886807 + t * (-1.13520398 + t * (1.48851587 +
        t * (-0.82215223 + t * 0.17087277)))))))));
}

/* Bit for bit (required where `exact`), or how far from it: identical values, and the
 * agreement test on the rest. */
function compareImages(what, page, native, exact) {
    if (page.width !== native.width || page.height !== native.height) {
        report(false, what + ": the page's image is " + page.width + " x " + page.height +
               ", the native one " + native.width + " x " + native.height);
        return;
    }
    const a = floats(page.image), se = floats(page.stdError), b = native.pixels;
    const count = a.length, sidak = 1 - Math.pow(1 - LEVEL, 1 / count);
    let same = 0, smallestP = 1, largest = 0;
    for (let i = 0; i < count; i++) {
        if (Object.is(a[i], b[i])) { same++; continue; }
        largest = Math.max(largest, Math.abs(a[i] - b[i]) / Math.max(Math.abs(b[i]), 1e-30));
        const z = se[i] > 0 ? Math.abs(a[i] - b[i]) / (Math.SQRT2 * se[i]) : Infinity;
        smallestP = Math.min(smallestP, erfc(z / Math.SQRT2));
    }
    if (same === count) {
        report(true, what + ": bit for bit (" + count + " values)");
        return;
    }
    if (exact) {
        report(false, what + ": not bit for bit (required): " + same + " of " + count + " values the same, the others " +
               "up to " + largest.toExponential(2) + " apart relatively");
        return;
    }
    report(smallestP >= sidak, what + ": " + same + " of " + count + " values bit for bit; the other " +
           (count - same) + " differ by at most " + largest.toExponential(2) + " relatively, smallest p " +
           smallestP.toExponential(2) + " against the Sidak level " + sidak.toExponential(2) +
           " (emscripten's libm, musl's, rounds sin and cos differently from glibc's in the last bit" +
           " for a few per cent of arguments)");
}

/* ---- the native side ------------------------------------------------------------------ */

/* The images the page renders, and the native programs' images they must equal: a chapter
 * program's panel (its seed is 1, as the page's), or lab-native's for chapter 8, whose
 * program renders for a time budget rather than a number of passes. `exact`: bit for bit
 * required. */
const IMAGES = [
    {what: "chapter 2's path tracer against ch02's Figure 2 panel", chapter: 2, panel: "ch02_subpixels.pfm",
     args: ["--size", "64", "--spp", "8"], scene: "room.scene", settings: "chapter=2 size=64 spp=8", workers: 2,
     exact: true},
    {what: "chapter 7's final estimator against ch07's Figure 7", chapter: 7, panel: "ch07_figure7.pfm",
     args: ["--size", "48", "--spp", "8"], scene: "room.scene", settings: "chapter=7 size=48 spp=8", workers: 3,
     again: 1, exact: true},
    {what: "chapter 8's photon map against lab-native", scene: "room.scene",
     settings: "chapter=8 size=48 spp=2 passes=3", workers: 2},
    {what: "chapter 10's adaptive passes against lab-native", scene: "room.scene",
     settings: "chapter=10 size=48 target=0.1", workers: 3, exact: true},
];

/* Paths recorded by the page and by lab-native. */
const RECORDS = [
    {scene: "room_whitted.scene", settings: "chapter=1 size=48", col: 20, row: 33, first: 0, count: 1},
    {scene: "room.scene", settings: "chapter=2 size=48 spp=8", col: 24, row: 30, first: 0, count: 4},
    {scene: "oren_nayar.scene", settings: "chapter=5 size=48 spp=4", col: 15, row: 30, first: 0, count: 4},
    {scene: "room.scene", settings: "chapter=6 size=48 spp=8 M=2 rr=0.5", col: 30, row: 36, first: 2, count: 4},
    {scene: "room.scene", settings: "chapter=7 size=48 spp=8 mis=1", col: 24, row: 2, first: 0, count: 8},
    {scene: "room.scene", settings: "chapter=7 size=48 spp=8", col: 18, row: 27, first: 0, count: 8},
    {scene: "room.scene", settings: "chapter=8 size=48 spp=2 passes=2", col: 32, row: 38, first: 1, count: 3},
    {scene: "room.scene", settings: "chapter=10 size=48 spp=16 max=16", col: 20, row: 30, first: 0, count: 8},
];

/* The reference of IMAGES[1]'s image (chapter 7: depth 64, Schlick), its error measured natively. */
const REFERENCE = {args: ["--size", "48", "--depth", "64", "--reference-spp", "8"], settings: "chapter=7 size=48 spp=8"};
/* Chapter 10's and chapter 7's renders to a target error are measured against this one. */
const EXACT_REFERENCE = ["--size", "48", "--depth", "64", "--fresnel", "exact", "--reference-spp", "256"];

/* Bad scenes for the editor: the room with one thing wrong. */
const EDITS = [
    ["an unknown keyword", function (t) { return t + "cube white 0 0 0 1\n"; }],
    ["a number missing", function (t) { return t.replace("7 -1.5 -1   1.25", "7 -1.5 -1"); }],
    ["a word for a number", function (t) { return t.replace("7 -1.5 -1", "7 -1.5 x"); }],
    ["a reflectance above 1", function (t) { return t.replace("lambert 0.75 0.15 0.15", "lambert 1.75 0.15 0.15"); }],
    ["an unknown material", function (t) { return t.replace("box         yellow", "box         golden"); }],
    ["a degenerate triangle", function (t) { return t + "triangle white 0 0 0 1 1 1 2 2 2\n"; }],
    ["no light", function (t) { return t.split("\n").filter(function (l) { return !/^quad lamp/.test(l); }).join("\n"); }],
    ["no camera", function (t) { return t.split("\n").filter(function (l) { return !/^camera/.test(l); }).join("\n"); }],
];

function run(file, args, options) {
    const result = childProcess.spawnSync(file, args, Object.assign({encoding: "utf8", maxBuffer: 1 << 28}, options));
    if (result.error)
        throw result.error;
    return result;
}

/* Chapter `number`'s program in PROGRAMS_DIR. */
function program(number) {
    const prefix = "ch" + String(number).padStart(2, "0") + "_";
    const name = fs.readdirSync(programsDir).filter(function (f) { return f.indexOf(prefix) === 0; })[0];
    if (!name) throw new Error("no chapter " + number + " program in " + programsDir);
    return path.resolve(programsDir, name);
}

/* The last chapter the lab has, and its program's name (lab_data.js). */
function lastChapter() {
    const data = fs.readFileSync(path.join(labDir, "lab_data.js"), "utf8");
    const all = Array.from(data.matchAll(/"number": (\d+), "program": "([^"]+)"/g));
    return {number: Number(all[all.length - 1][1]), program: all[all.length - 1][2],
            all: all.map(function (m) { return Number(m[1]); })};
}

/* The page's copy, with only its own files and references. */
function copyPage() {
    fs.rmSync(pageDir, {recursive: true, force: true});
    fs.mkdirSync(path.join(pageDir, "references"), {recursive: true});
    for (const file of fs.readdirSync(labDir))
        if (/\.(html|js)$/.test(file))
            fs.copyFileSync(path.join(labDir, file), path.join(pageDir, file));
}

function prepareNative() {
    copyPage();
    fs.rmSync(nativeDir, {recursive: true, force: true});
    fs.mkdirSync(path.join(nativeDir, "editor"), {recursive: true});
    const labNative = path.resolve(labDir, "lab-native");
    IMAGES.forEach(function (c, i) {
        c.file = path.join(nativeDir, "image" + i + ".pfm");
        const out = path.join(nativeDir, "chapter" + c.chapter);
        const result = c.chapter
            ? run(program(c.chapter), c.args.concat(["--quiet", "--runs", "1", "--reference-spp", "8", "--out", out]))
            : run(labNative, [path.join("scenes", c.scene), c.settings, "render", c.file]);
        if (result.status !== 0)
            throw new Error("the native render for " + c.what + " failed: " + result.stderr);
        if (c.chapter)
            fs.copyFileSync(path.join(out, c.panel), c.file);
    });
    RECORDS.forEach(function (c) {
        const result = run(labNative, [path.join("scenes", c.scene), c.settings, "record", c.col, c.row, c.first, c.count].map(String));
        if (result.status !== 0)
            throw new Error("lab-native record " + c.settings + " failed: " + result.stderr);
        c.native = result.stdout.trim();
    });
    const reference = run(path.resolve(programsDir, "lab-reference"), REFERENCE.args.concat(
        ["--quiet", "--out", path.join(pageDir, "references")]));
    const measured = run(path.resolve(programsDir, "lab-reference"), REFERENCE.args.concat(
        ["--quiet", "--out", path.join(pageDir, "references"), "--error", path.join(nativeDir, "image1.pfm")]));
    const exact = run(path.resolve(programsDir, "lab-reference"), EXACT_REFERENCE.concat(
        ["--quiet", "--out", path.join(pageDir, "references")]));
    if (reference.status !== 0 || measured.status !== 0 || exact.status !== 0)
        throw new Error("lab-reference failed: " + reference.stderr + measured.stderr + exact.stderr);
    const numbers = /rmse (\S+) rel_mse (\S+)/.exec(measured.stdout);
    REFERENCE.rmse = Number(numbers[1]);
    REFERENCE.relMse = Number(numbers[2]);
    const names = fs.readdirSync(path.join(pageDir, "references")).filter(function (f) { return /-.*\.js$/.test(f); });
    fs.writeFileSync(path.join(pageDir, "references", "index.js"), "var LAB_REFERENCES = " + JSON.stringify(names) + ";\n");
    const last = lastChapter(), room = fs.readFileSync("scenes/room.scene", "utf8");
    const editor = path.join(nativeDir, "editor");
    EDITS.forEach(function (edit) {
        edit.text = edit[1](room);
        if (edit.text === room)
            throw new Error("the edit '" + edit[0] + "' left the room as it was");
        fs.writeFileSync(path.join(editor, "room.scene"), edit.text);
        const result = run(program(last.number), ["--scene", "room.scene", "--quiet", "--size", "8", "--out", "out"],
                           {cwd: editor});
        const line = result.stderr.split("\n")[0], prefix = last.program + ": ";
        if (result.status !== 2 || line.indexOf(prefix) !== 0)
            throw new Error("the command line did not refuse " + edit[0] + " (status " + result.status + "): " + result.stderr);
        edit.message = line.slice(prefix.length);
    });
    last.path = program(last.number);
    last.editor = editor;
    last.verdicts = address.commandLine(program(7));
    return last;
}

/* ---- the page ------------------------------------------------------------------------- */

async function checkConsole(browser, url) {
    const broken = path.join(outDir, "broken.html");
    fs.writeFileSync(broken, fs.readFileSync(path.join(pageDir, "index.html"), "utf8")
        .replace("<head>", "<head><base href=\"" + fileUrl(pageDir) + "/\"><script>console.error(\"canary\")</script>"));
    await browser.navigate(fileUrl(broken), 30);
    await browser.evaluate("new Promise(r => setTimeout(r, 500))");
    const caught = browser.problems.some(function (p) { return p.indexOf("canary") >= 0; });
    report(caught, "a console error planted in a copy of the page is caught (" + browser.problems.length + " problems)");
    browser.problems.length = 0;
    await browser.navigate(url + "#chapter=2&spp=2&size=64", 30);
    await browser.until("labTest.state().panels.every(p => p.complete || p.error)", 60, "the first render");
    const state = await browser.evaluate("labTest.state()");
    report(!state.panels[0].error && browser.problems.length === 0,
           "the page loads from " + url + " and renders chapter 2 with no console message" +
           (browser.problems.length ? ": " + browser.problems.join("; ") : "") + (state.panels[0].error ? ": " + state.panels[0].error : ""));
}

async function checkImages(browser) {
    for (const c of IMAGES) {
        const page = await browser.evaluate("labTest.render(" + JSON.stringify(c.scene) + ", " +
                                            JSON.stringify(c.settings) + ", " + c.workers + ")", 300);
        compareImages(c.what + " (" + c.settings + ", " + c.workers + " workers)", page,
                      readPfm(c.file), c.exact);
        if (c.again) { /* in bands of 8 rows, the results delayed at random: out of order */
            const render = function (workers) {
                return browser.evaluate("labTest.render(" + JSON.stringify(c.scene) + ", " +
                                        JSON.stringify(c.settings) + ", " + workers + ", 8, 200)", 300);
            };
            const one = await render(c.again), many = await render(c.workers);
            report(one.means === page.means && many.means === page.means, c.what + ": the same image, every mean " +
                   "in doubles bit for bit, on " + c.workers + " workers and on " + c.again +
                   ", with results arriving out of order");
        }
    }
}

/* Where two recordings differ: null if they are the same but for numbers within
 * `tolerance` of each other, relatively; else the first difference. */
function recordingDifference(a, b, tolerance, where) {
    if (typeof a === "number" && typeof b === "number") {
        const close = Math.abs(a - b) <= tolerance * Math.max(Math.abs(a), Math.abs(b));
        return close ? null : where + ": " + a + " against " + b;
    }
    if (typeof a !== typeof b || Array.isArray(a) !== Array.isArray(b) || (a === null) !== (b === null))
        return where + ": " + JSON.stringify(a) + " against " + JSON.stringify(b);
    if (a === null || typeof a !== "object")
        return a === b ? null : where + ": " + JSON.stringify(a) + " against " + JSON.stringify(b);
    const keys = Object.keys(a);
    if (keys.join() !== Object.keys(b).join())
        return where + ": fields " + keys.join() + " against " + Object.keys(b).join();
    for (const key of keys) {
        const difference = recordingDifference(a[key], b[key], tolerance, where + "." + key);
        if (difference) return difference;
    }
    return null;
}

/* The page's recordings against lab-native's: character for character, or else the same
 * notes with the same decisions and numbers within 1e-9 of each other (the last bits of
 * sin and cos, above, moving a direction by an ulp). */
async function checkRecords(browser) {
    const TOLERANCE = 1e-9;
    for (const c of RECORDS) {
        const json = await browser.evaluate("labTest.record(" + [JSON.stringify(c.scene), JSON.stringify(c.settings),
            c.col, c.row, c.first, c.count].join(", ") + ")", 120);
        const paths = JSON.parse(json).paths;
        const notes = paths.reduce(function (n, p) { return n + p.path.events.length; }, 0);
        const accounted = paths.every(function (p) { return p.path.accounted !== false; });
        const what = "inspector: " + c.settings + ", pixel (" + c.col + ", " + c.row + "), samples " + c.first +
                     " to " + (c.first + c.count - 1) + ", " + notes + " notes: ";
        const difference = json === c.native ? null : recordingDifference(JSON.parse(json), JSON.parse(c.native), TOLERANCE, "record");
        report(!difference && accounted, what + (json === c.native ? "the native recording, character for character"
               : difference ? "differs from the native recording at " + difference
               : "the native recording, its numbers within " + TOLERANCE + " relatively (not character for character:" +
                 " sin and cos, above)") + (accounted ? "" : "; a path's notes do not account for its radiance"));
    }
}

async function checkReference(browser, url) {
    await browser.navigate(url + "#" + REFERENCE.settings.replace(/ /g, "&"), 30);
    await browser.until("labTest.state().panels.every(p => p.complete || p.error)", 120, "chapter 7's render");
    await browser.until("labTest.state().panels[0].rmse !== null", 10, "the error against the reference");
    const panel = (await browser.evaluate("labTest.state()")).panels[0];
    const close = function (a, b) { return Math.abs(a - b) <= 1e-5 * Math.abs(b); };
    report(panel.reference && close(panel.rmse, REFERENCE.rmse) && close(panel.relMse, REFERENCE.relMse),
           "the reference loads (" + panel.reference + "), and the page's RMSE " + panel.rmse + " and relative MSE " +
           panel.relMse + " are lab-reference's " + REFERENCE.rmse + " and " + REFERENCE.relMse +
           " within 1e-5 (the page measures its mean in doubles, the programs in floats)");
}

async function checkEditor(browser, url, last) {
    await browser.navigate(url + "#chapter=" + last.number + "&size=64&spp=1" +
                           (last.number === 10 ? "&target=0.5" : "&passes=1"), 30);
    await browser.until("labTest.state().panels.every(p => p.complete || p.error)", 60, "a render");
    for (const edit of EDITS) {
        const shown = await browser.evaluate("labTest.editScene(\"room.scene\", " + JSON.stringify(edit.text) + ")", 60);
        report(shown === edit.message, "editor, " + edit[0] + ": '" + shown + "'" +
               (shown === edit.message ? " is " + last.program + "'s message" : " but " + last.program + " says '" + edit.message + "'"));
    }
    await box(browser, "#scene-name");
    await browser.screenshot(path.join(outDir, "lab_editor.png"));
}

/* The element's box on the page, scrolled into view. */
async function box(browser, selector) {
    return JSON.parse(await browser.evaluate("(function () { const e = document.querySelector(" +
        JSON.stringify(selector) + "); e.scrollIntoView({block: 'start'}); return JSON.stringify(e.getBoundingClientRect()); })()"));
}

async function screenshots(browser, url) {
    await browser.navigate(url + "#chapter=7&spp=16&size=200&workers=2", 30);
    await browser.until("labTest.state().panels.every(p => p.complete || p.error)", 300, "chapter 7's render");
    const overlay = await box(browser, "#panel-a canvas.overlay");
    await browser.click(overlay.left + 0.63 * overlay.width, overlay.top + 0.78 * overlay.height);
    await browser.until("labTest.state().inspector.rows > 0", 60, "the inspector after a click");
    const state = await browser.evaluate("labTest.state()");
    report(/pixel \(\d+, \d+\), sample 0/.test(state.inspector.summary) && state.inspector.rows > 1,
           "a click on the image opens the inspector: " + state.inspector.summary);
    await browser.evaluate("labTest.step(-1)");
    await box(browser, "#panel-a");
    await browser.screenshot(path.join(outDir, "lab_inspector.png"));
    await box(browser, "#plan");
    await browser.screenshot(path.join(outDir, "lab_inspector_plan.png"));

    await browser.navigate(url + "#chapter=3&M=1&spp=8&size=128&b.M=30&fairness=samples", 30);
    await browser.until("labTest.state().panels.every(p => p.complete || p.error)", 300, "the two panels");
    const two = await browser.evaluate("labTest.state()");
    report(two.panels.length === 2 && two.panels.every(function (p) { return !p.error && p.history > 2; }),
           "two panels side by side, each with its running error: " +
           two.panels.map(function (p) { return p.stats.replace(/\n/g, "; "); }).join(" | "));
    await box(browser, "#controls");
    await browser.screenshot(path.join(outDir, "lab_two_panels.png"));
}

/* The page as `make lab` built it, with its references: every comparison the page offers
 * and every chapter's own render (chapter 1's, deterministic, apart) has, in each panel,
 * its error against a reference; a panel with none (a width with no reference, an edited
 * scene) names its estimator's biases, which its standard error leaves out, and only
 * those its settings have (lab_biases). */
async function checkPageReferences(browser, labUrl, chapters) {
    const panelsShown = async function (fragment) {
        await browser.navigate(labUrl + "#" + fragment, 30);
        await browser.until("labTest.state().panels.every(p => p.error || p.done > 0)", 300, fragment + "'s first step");
        await browser.evaluate("new Promise(r => setTimeout(r, 600))"); /* the stats shown after it */
        return (await browser.evaluate("labTest.state()")).panels;
    };
    await browser.navigate(labUrl + "#chapter=2&size=16", 30);
    const presets = await browser.evaluate("labTest.presets()");
    const cases = presets.concat(chapters.filter(function (n) { return n > 1; }).map(function (n) {
        return ["chapter=" + n, "chapter " + n + "'s own render"];
    }));
    for (const [fragment, name] of cases) {
        let panels = await panelsShown(fragment);
        if (presets.some(function (p) { return p[0] === fragment; })) { /* a screenshot after two steps */
            await browser.until("labTest.state().panels.every(p => p.error || p.done >= 2)", 300, fragment + "'s second step");
            await browser.evaluate("new Promise(r => setTimeout(r, 600))");
            panels = (await browser.evaluate("labTest.state()")).panels;
            await box(browser, "#controls");
            await browser.screenshot(path.join(outDir, "lab_preset" + presets.findIndex(function (p) { return p[0] === fragment; }) + ".png"));
        }
        const without = panels.map(function (p, i) { return p.reference && / against the reference \(/.test(p.stats) ? "" : "AB"[i]; })
            .filter(function (n) { return n; });
        report(panels.length > 0 && without.length === 0, "'" + name + "' (#" + fragment + "): " + (without.length
            ? "no reference for panel " + without.join(" and ") + " after make lab: " + panels.map(function (p) { return p.error || p.stats.split("\n")[1]; }).join(" | ")
            : "every panel's error against a reference: " + panels.map(function (p) { return p.stats.split("\n")[1]; }).join(" | ")));
    }
    const BIASED = [
        {fragment: "chapter=8&size=64&passes=4", has: ["photon map", "longer than 64 segments", "Schlick"], not: []},
        {fragment: "chapter=8&size=64&passes=4&fresnel=exact", has: ["photon map", "longer than 64 segments"], not: ["Schlick"]},
        {fragment: "chapter=4&size=64&fresnel=schlick", has: ["Schlick", "longer than 8 segments"], not: ["photon map"]},
        {fragment: "chapter=4&size=64&fresnel=exact", has: ["longer than 8 segments"], not: ["Schlick", "photon map"]},
        {fragment: "chapter=1&size=64", has: ["all bias", "diffuse surfaces"], not: ["segments"]},
    ];
    const LEAVES_OUT = "it leaves out the estimator's bias: ";
    for (const c of BIASED) {
        const panel = (await panelsShown(c.fragment))[0], line = panel.stats.split("\n")[1] || "";
        const named = c.has.every(function (w) { return line.indexOf(w) >= 0; }) &&
                      !c.not.some(function (w) { return line.indexOf(w) >= 0; });
        report(!panel.reference && (c.fragment.indexOf("chapter=1&") === 0 || line.indexOf(LEAVES_OUT) >= 0) && named,
               "no reference at #" + c.fragment + ": the panel names its biases (" + c.has.join(", ") + (c.not.length ? "; not " + c.not.join(", ") : "") + "): '" + line + "'");
    }
    /* An edited scene: its hash has no reference. */
    await panelsShown("chapter=8&passes=3");
    const room = await browser.evaluate("LAB_SCENES[\"room.scene\"]");
    const refused = await browser.evaluate("labTest.editScene(\"room.scene\", " + JSON.stringify(room + "# edited\n") + ")", 60);
    await browser.until("!labTest.state().restarting && labTest.state().panels.every(p => p.error || p.complete)", 300,
                        "the edited scene's render");
    await browser.evaluate("new Promise(r => setTimeout(r, 600))");
    const edited = (await browser.evaluate("labTest.state()")).panels[0], line = edited.stats.split("\n")[1] || "";
    report(!refused && !edited.reference && line.indexOf(LEAVES_OUT) >= 0 && line.indexOf("photon map") >= 0,
           "an edited scene (no reference) in chapter 8: '" + line + "'");
    await box(browser, "#panel-a");
    await browser.screenshot(path.join(outDir, "lab_no_reference.png"));
}

/* The panel of a fragment once its render is complete. */
async function completed(browser, url, fragment, seconds) {
    await browser.navigate(url + "#" + fragment, 30);
    await browser.until("labTest.state().panels.every(p => p.error || p.complete)", seconds, fragment + "'s render");
    await browser.evaluate("new Promise(r => setTimeout(r, 600))"); /* the stats shown after it */
    return (await browser.evaluate("labTest.state()")).panels[0];
}

/* A render to a target stopped at the first estimate at most the target. */
function stoppedAt(list, target) {
    return list.length >= 2 && list[list.length - 1] <= target && list.slice(0, -1).every(function (e) { return e > target; });
}

function estimates(panel) {
    return panel.estimates.slice(-3).map(function (e) { return e.toFixed(4); }).join(", ") +
           (panel.estimates.length > 3 ? " (the last three of " + panel.estimates.length + ")" : "");
}

async function checkAdaptive(browser, url) {
    const target = 0.1, fragment = "chapter=10&size=48&target=" + target;
    let panel = await completed(browser, url, fragment, 300);
    const line = panel.stats.split("\n").slice(-1)[0];
    report(!panel.error && panel.done >= 2 && panel.reached && stoppedAt(panel.estimates, target) &&
           line.indexOf("target " + target + " reached: estimated relative RMSE") === 0,
           "chapter 10's panel (#" + fragment + ") renders to its target in " + panel.done + " passes, its estimates " +
           estimates(panel) + ": '" + line + "'");

    const map = await browser.evaluate("labTest.samplesMap()");
    const most = Math.max.apply(null, map.samples), least = Math.min.apply(null, map.samples);
    const wrong = map.samples.filter(function (n, i) { return map.drawn[i] !== Math.round(255 * n / most); }).length;
    report(most > least && wrong === 0, "chapter 10's map of samples per pixel: " + least + " to " + most +
           " samples (not uniform), drawn grey from the samples (" + wrong + " of " + map.samples.length + " pixels otherwise)");
    await box(browser, "#panel-a");
    await browser.screenshot(path.join(outDir, "lab_adaptive_samples.png"));
    await browser.evaluate("($('view').value = 'image', $('view').onchange(), 0)");

    /* The unbiased rule's image against the reference: the mean of the differences over
     * all values, in units of its standard error (the values' spread over sqrt N), within
     * 3.29 (p = 0.001 either way); its relative RMSE (the reference's noise taken out)
     * within a factor of 2 of its own estimate. */
    const images = await browser.evaluate("labTest.images()");
    const kept = doubles(images.image), truth = images.reference ? floats(images.reference) : [];
    let sum = 0, squares = 0;
    for (let i = 0; i < truth.length; i++) {
        const d = kept[i] - truth[i];
        sum += d;
        squares += d * d;
    }
    const n = truth.length, mean = sum / n, z = mean / Math.sqrt((squares / n - mean * mean) / (n - 1));
    const measured = Math.sqrt(Math.max(0, panel.relMse)), ratio = measured / panel.estimated;
    report(panel.reference && n === kept.length && Math.abs(z) < 3.29 && ratio > 0.5 && ratio < 2,
           "chapter 10, unbiased rule, against the reference (depth 64, exact Fresnel, 256 spp): mean difference " +
           mean.toExponential(2) + " (z = " + z.toFixed(2) + ", within 3.29); relative RMSE " + measured.toFixed(4) +
           ", its own estimate " + Number(panel.estimated).toFixed(4) + " (ratio " + ratio.toFixed(2) + ", within 2 either way)");

    const uniform = "chapter=7&size=48&fresnel=exact&spp=1024&target=" + target;
    panel = await completed(browser, url, uniform, 300);
    const said = panel.stats.split("\n").slice(-1)[0];
    report(!panel.error && panel.reached && panel.reached.steps < 1024 && panel.reached.steps % 2 === 0 &&
           stoppedAt(panel.estimates, target) && said.indexOf("target " + target + " reached") === 0 &&
           / it cost \S+ processor s/.test(said) && /against the reference: relative RMSE/.test(said),
           "chapter 7 rendered to a target (#" + uniform + ") stops at " + (panel.reached ? panel.reached.steps : panel.done) +
           " spp, its estimates " + estimates(panel) + ": '" + said + "'");
    await box(browser, "#panel-a");
    await browser.screenshot(path.join(outDir, "lab_target.png"));
}

(async function main() {
    fs.mkdirSync(outDir, {recursive: true});
    const last = prepareNative();
    const browser = await Chromium.open(1400, 1400);
    const url = fileUrl(path.join(pageDir, "index.html"));
    try {
        await checkPageReferences(browser, fileUrl(path.join(labDir, "index.html")),
                                  lastChapter().all);
        await checkConsole(browser, url);
        await checkImages(browser);
        await checkRecords(browser);
        await checkReference(browser, url);
        await checkEditor(browser, url, last);
        await checkAdaptive(browser, url);
        await screenshots(browser, url);
        await address.checkShared(browser, report, last.verdicts);
        await address.checkRanges(browser, report);
        await address.checkHostile(browser, report, url);
        await address.checkHistory(browser, report, url);
        await address.checkLimits(browser, report, path.resolve(labDir, "lab-native"));
        await address.checkEqualTime(browser, report, url);
        await address.checkSceneSize(browser, report, url, last, last.editor);
        await address.checkSceneFile(browser, report, url, last.editor);
        await address.checkBook(browser, report, url);
        await browser.navigate(url + "#chapter=7&size=16%20chapter%3D2&workers=1000", 30);
        await browser.until("labTest.state().addressRefused", 30, "the refused address");
        await browser.screenshot(path.join(outDir, "lab_address_refused.png"));
        report(browser.problems.length === 0, "no console message on the page through all of it" +
               (browser.problems.length ? ": " + browser.problems.join("; ") : ""));
    } catch (error) {
        report(false, String(error.stack || error));
    } finally {
        await browser.close();
    }
    console.log(failures ? "browser_lab: " + failures + " checks failed" :
                "browser_lab: every check passed; screenshots in " + outDir);
    process.exit(failures ? 1 : 0);
})();
