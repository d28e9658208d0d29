/* lab_bench.js (bench, chapter 8): the lab's benchmark (make lab-bench). A benchmark, not
 * a test: it asserts nothing and prints what it measures, with the goals beside it.
 *
 *   node bench/lab/lab_bench.js LAB_DIR OUT_DIR
 *
 * 1. Speed per core: the same render (the room, chapter 2's and chapter 7's estimators)
 *    natively on one thread (lab-native-unwrapped: the native build without the
 *    recorder's wrappers; lab-native: with them, not recording) and in the page on one
 *    worker, in turns, ROUNDS times each; rays per processor second (natively the
 *    process's; in the page the worker threads', from /proc), which other programs on a
 *    shared machine change less than rays per wall second (also shown; in the page over
 *    the worker's own time in lab_render_band); the medians' ratio. Goal: WebAssembly
 *    >= 0.6 x native.
 * 2. The first full image of chapter 2's path tracer, 256 x 256, 1 spp, 2 workers: from
 *    the page's start (navigation) and from the render's start. Goal: <= 1 s.
 * 3. The main thread while rendering: the longest task (PerformanceObserver "longtask",
 *    which reports tasks over 50 ms) between a render's start and end, and the longest
 *    animation frame's work. Goal: never blocked for more than 50 ms.
 * 4. The main thread while the editor reads a scene of a million spheres (given as a
 *    file opened there is) and the page renders it: the longest task, from apply until
 *    the render is done.
 * Everything goes to stdout and OUT_DIR/lab-bench.txt.
 */
"use strict";

const childProcess = require("child_process");
const fs = require("fs");
const path = require("path");
const {Chromium, fileUrl} = require("./chromium.js");

const [labDir, outDir] = process.argv.slice(2);
const ROUNDS = 3;
const lines = [];

function say(text) {
    console.log(text);
    lines.push(text);
}

function median(values) {
    const sorted = values.slice().sort(function (a, b) { return a - b; });
    return sorted[Math.floor(sorted.length / 2)];
}

/* Rays per second of one native thread (wall, processor). */
function native(program, settings, seconds) {
    const out = childProcess.execFileSync(path.join(labDir, program),
        ["scenes/room.scene", settings, "speed", String(seconds)], {encoding: "utf8"});
    const wall = Number(/rays_per_second (\d+)/.exec(out)[1]), cpu = Number(/rays_per_cpu_second (\d+)/.exec(out)[1]);
    return {wall: wall, cpu: cpu};
}

/* Processor seconds used so far by the page's web workers: the threads Chromium names
 * DedicatedWorker in its renderer processes of this browser's profile (/proc, 100 ticks
 * a second). A worker's compiling of the module runs on other threads. */
function workerProcessorSeconds(browser) {
    let ticks = 0;
    for (const pid of fs.readdirSync("/proc").filter(function (name) { return /^\d+$/.test(name); })) {
        try {
            const command = fs.readFileSync("/proc/" + pid + "/cmdline", "latin1");
            if (command.indexOf("--type=renderer") < 0 || command.indexOf(browser.profile) < 0)
                continue;
            for (const task of fs.readdirSync("/proc/" + pid + "/task")) {
                const stat = fs.readFileSync("/proc/" + pid + "/task/" + task + "/stat", "latin1");
                const fields = stat.slice(stat.lastIndexOf(")") + 2).split(" ");
                if (stat.slice(stat.indexOf("(") + 1).indexOf("DedicatedWorker") === 0)
                    ticks += Number(fields[11]) + Number(fields[12]); /* utime, stime */
            }
        } catch (error) {
            continue; /* a process or thread that has ended */
        }
    }
    return ticks / 100;
}

/* Rays per second of one worker: its rays over its time in lab_render_band (wall), and
 * over the processor time of the workers' threads meanwhile (the render's worker kept
 * alive until it is read). */
async function webAssembly(browser, settings) {
    await browser.evaluate("labTest.release(), new Promise(r => setTimeout(r, 300))");
    const before = workerProcessorSeconds(browser);
    const result = await browser.evaluate("labTest.render('room.scene', " + JSON.stringify(settings) +
                                          ", 1, 0, 0, true)", 600);
    const rays = result.rays.reduce(function (a, b) { return a + b; }, 0);
    return {wall: rays / result.workerSeconds, cpu: rays / (workerProcessorSeconds(browser) - before)};
}

async function speed(browser, settings) {
    const runs = {plain: [], wrapped: [], wasm: []};
    for (let round = 0; round < ROUNDS; round++) {
        runs.plain.push(native("lab-native-unwrapped", settings, 3));
        runs.wrapped.push(native("lab-native", settings, 3));
        runs.wasm.push(await webAssembly(browser, settings));
    }
    const m = function (list, kind) { return median(list.map(function (r) { return r[kind]; })); };
    const text = function (list) {
        return (m(list, "cpu") / 1e6).toFixed(3) + " per processor second, " + (m(list, "wall") / 1e6).toFixed(3) +
               " per wall second   [" + list.map(function (r) { return (r.cpu / 1e6).toFixed(3); }).join(" ") + "]";
    };
    say("speed, " + settings + " (Mrays/s on one core, medians of " + ROUNDS + " rounds taken in turns):");
    say("  native build           " + text(runs.plain));
    say("  native with wrappers   " + text(runs.wrapped) + " (the recorder linked in, not recording: " +
        ((m(runs.wrapped, "cpu") / m(runs.plain, "cpu") - 1) * 100).toFixed(1) + "% per processor second)");
    say("  WebAssembly, 1 worker  " + text(runs.wasm));
    say("  ratio WebAssembly / native: " + (m(runs.wasm, "cpu") / m(runs.plain, "cpu")).toFixed(2) +
        " per processor second, " + (m(runs.wasm, "wall") / m(runs.plain, "wall")).toFixed(2) + " per wall second (goal >= 0.6)");
}

async function firstImage(browser, url) {
    const fromPage = [], fromRender = [];
    for (let round = 0; round < ROUNDS; round++) {
        await browser.navigate(url + "#chapter=2&spp=1&size=256&workers=2", 60);
        await browser.until("labTest.state().panels.every(p => p.complete || p.error)", 60, "the first image");
        const panel = (await browser.evaluate("labTest.state()")).panels[0];
        fromPage.push(panel.finished / 1000);
        fromRender.push((panel.finished - panel.started) / 1000);
    }
    say("first full image, chapter 2, 256 x 256, 1 spp, 2 workers (seconds, " + ROUNDS + " loads):");
    say("  from the page's start   " + fromPage.map(function (v) { return v.toFixed(3); }).join(" ") +
        " (median " + median(fromPage).toFixed(3) + ", goal <= 1)");
    say("  from the render's start " + fromRender.map(function (v) { return v.toFixed(3); }).join(" ") +
        " (median " + median(fromRender).toFixed(3) + ")");
}

async function mainThread(browser, url, fragment) {
    await browser.navigate(url + fragment, 60);
    await browser.until("labTest.state().panels.every(p => p.complete || p.error)", 600, fragment);
    const state = await browser.evaluate("labTest.state()");
    const start = Math.min.apply(null, state.panels.map(function (p) { return p.started; }));
    const end = Math.max.apply(null, state.panels.map(function (p) { return p.finished; }));
    const during = state.longTasks.filter(function (t) { return t.start + t.duration > start && t.start < end; });
    const before = state.longTasks.filter(function (t) { return t.start + t.duration <= start; });
    say("main thread, " + fragment + ", " + ((end - start) / 1000).toFixed(1) + " s of rendering: " +
        (during.length ? during.length + " tasks over 50 ms, the longest " +
                         Math.max.apply(null, during.map(function (t) { return t.duration; })).toFixed(0) + " ms"
                       : "no task over 50 ms") +
        "; longest frame's work " + state.longestFrame.toFixed(1) + " ms" +
        (before.length ? "; before the render started: " + before.map(function (t) { return t.duration.toFixed(0) + " ms"; }).join(", ") : ""));
}

/* A million small spheres in the room, as text: [x, y, z] on a 100 x 100 x 100 grid. */
const BIG_SCENE = "(function () { const parts = [LAB_SCENES['room.scene']]; for (let i = 0; i < 1000000; i++) " +
    "parts.push('sphere white ' + (1 + (i % 100) * 0.08) + ' ' + (-5 + (Math.floor(i / 100) % 100) * 0.1) + ' ' + " +
    "(-4 + Math.floor(i / 10000) * 0.08) + ' 0.01\\n'); window.bigScene = parts.join(''); return bigScene.length; })()";

async function bigScene(browser, url) {
    await browser.navigate(url + "#chapter=2&spp=1&size=16&workers=2", 60);
    await browser.until("labTest.state().panels.every(p => p.complete || p.error)", 60, "a first render");
    const length = await browser.evaluate(BIG_SCENE, 120);
    const mark = await browser.evaluate("performance.now()"), start = Date.now();
    const shown = await browser.evaluate("labTest.editScene('room.scene', bigScene)", 900);
    const read = (Date.now() - start) / 1000;
    await browser.until("!labTest.state().restarting && labTest.state().panels.every(p => p.complete || p.error)", 900,
                        "the render of a million spheres");
    const state = await browser.evaluate("labTest.state()");
    const during = state.longTasks.filter(function (t) { return t.start + t.duration > mark; });
    say("main thread, the editor with a million spheres (" + (length / 1048576).toFixed(1) + " MiB): read in " + read.toFixed(1) +
        " s" + (shown ? " (refused: " + shown + ")" : "") + ", rendered after " + ((Date.now() - start) / 1000).toFixed(1) + " s; " +
        (during.length ? during.length + " tasks over 50 ms, the longest " +
                         Math.max.apply(null, during.map(function (t) { return t.duration; })).toFixed(0) + " ms"
                       : "no task over 50 ms"));
}

(async function main() {
    fs.mkdirSync(outDir, {recursive: true});
    const browser = await Chromium.open(1400, 1400);
    const url = fileUrl(path.join(labDir, "index.html"));
    try {
        say("lab-bench on " + require("os").cpus().length + " cores, load average " +
            require("os").loadavg().map(function (v) { return v.toFixed(2); }).join(" ") + ", " + new Date().toISOString());
        await browser.navigate(url + "#chapter=2&spp=1&size=16", 60);
        await speed(browser, "chapter=2 size=256 spp=16");
        await speed(browser, "chapter=7 size=256 spp=8");
        await firstImage(browser, url);
        await mainThread(browser, url, "#chapter=2&spp=16&size=256&workers=2");
        await mainThread(browser, url, "#chapter=7&spp=4&size=800&workers=2");
        await mainThread(browser, url, "#chapter=8&passes=2&size=256&workers=2");
        await mainThread(browser, url, "#chapter=3&M=1&spp=8&size=256&b.M=30&fairness=time&workers=2");
        await bigScene(browser, url);
        if (browser.problems.length)
            say("console messages: " + browser.problems.join("; "));
    } finally {
        await browser.close();
    }
    fs.writeFileSync(path.join(outDir, "lab-bench.txt"), lines.join("\n") + "\n");
})();
