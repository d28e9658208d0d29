/* lab.js (bench, chapter 8): the lab's page: settings, panels, references, the scene
 * editor, and what the tests ask (labTest). docs/lab.md.
 *
 * The page's state is its address's fragment, "#chapter=3&M=1&b.M=30&fairness=samples":
 * keys without a prefix are panel A's settings (lab.h's, and scene=NAME), "b." ones
 * panel B's (B starts as A, or from A's size, seed and scene where b.chapter differs),
 * and layout, fairness, workers, reference (exact|schlick: the reference both panels are
 * measured against), pixel=COL,ROW and paths=K for the inspector. The gallery links its
 * figures here that way. Every key is checked by the C code (lab_fragment, in the helper
 * worker): an address it refuses is shown as its message, and nothing renders.
 */
"use strict";

const $ = function (id) { return document.getElementById(id); };

/* The settings a panel's form offers: key, the chapter that introduces it, and the
 * choices of a list (lab.c checks every value). */
const FIELDS = [
    {key: "chapter", chapter: 1, label: "chapter"},
    {key: "scene", chapter: 1, label: "scene"},
    {key: "size", chapter: 1, label: "width"},
    {key: "spp", chapter: 2, label: "spp"},
    {key: "passes", chapter: 8, label: "passes"},
    {key: "sampling", chapter: 2, label: "pixel sampling",
     choices: [["subpixels", 2], ["random", 2], ["stratified", 7], ["progressive", 8]]},
    {key: "depth", chapter: 1, label: "depth"},
    {key: "seed", chapter: 1, label: "seed"},
    {key: "M", chapter: 3, label: "shadow rays M"},
    {key: "fresnel", chapter: 4, label: "Fresnel", choices: [["schlick", 4], ["exact", 4]]},
    {key: "sigma", chapter: 5, label: "Oren\u2013Nayar \u03c3"},
    {key: "rr", chapter: 6, label: "roulette \u03b1 (or bounded)"},
    {key: "mis", chapter: 7, label: "MIS", choices: [["0", 7], ["1", 7]]},
    {key: "mirror", chapter: 7, label: "mirror light K"},
    {key: "guide", chapter: 7, label: "sphere guide"},
    {key: "photons", chapter: 8, label: "photons per pass"},
    {key: "radius", chapter: 8, label: "first radius"},
    {key: "alpha", chapter: 8, label: "radius \u03b1"},
    {key: "target", chapter: 7, label: "target error (relative RMSE)"},
    {key: "max", chapter: 10, label: "max spp"},
    {key: "rule", chapter: 10, label: "rule", choices: [["unbiased", 10], ["biased", 10]]},
];

/* A field the panel's chapter has: chapter 8's photon map is its own (chapter 10 builds on
 * chapter 7's estimator), as lab.c's keys. */
function hasField(field, chapter) {
    return field.chapter <= chapter && (field.chapter !== 8 || chapter === 8);
}

/* The report's comparisons as fragments. */
const PRESETS = [
    ["", "(your own settings)"],
    ["chapter=3&M=1&spp=4&b.M=30&fairness=samples", "1 against 30 shadow rays (Figure 11)"],
    ["chapter=4&fresnel=schlick&b.fresnel=exact&reference=exact&fairness=time", "Schlick against exact Fresnel"],
    ["chapter=6&rr=0.25&b.rr=0.75&spp=64&fairness=time", "roulette \u03b1 = 0.25 against 0.75"],
    ["chapter=7&spp=256&b.chapter=8&b.passes=32&fairness=time", "chapter 7 against chapter 8, equal time"],
    ["chapter=7&fresnel=exact&spp=1024&b.chapter=10&b.target=0.1&fairness=time",
     "uniform (chapter 7) against adaptive (chapter 10), equal time"],
];

const PANEL_COLOURS = {a: "#d23030", b: "#2f6fd0"};

/* Maps with no inherited names ("toString" is no scene). */
const scenes = Object.create(null);     /* name: its text as the page has it (edited, or as in scenes/) */
const references = Object.create(null); /* file name: {image, mse, relMse, spp} once loaded */
const referenceWaiters = Object.create(null);
const page = {layout: "one", fairness: "samples", reference: "", workers: 0, workersGiven: false,
              paths: 8, pixel: null, note: "", error: "", checked: 0 /* addresses answered */};
/* Characters the editor's text box shows at most: a longer text (a file opened) is kept
 * but not laid out, which would hold the page for many seconds. */
const EDITOR_SHOWN_MAX = 1 << 20;
let editorText = "";
const longTasks = [];   /* main-thread tasks over 50 ms (PerformanceObserver): {start, duration} */
let jobs = 0;
let pool = null, helper = null, inspector = null, inspected = null;

function chapterInfo(number) {
    return LAB_CHAPTERS.filter(function (c) { return c.number === number; })[0];
}

/* ---- panels -------------------------------------------------------------------------- */

function newPanel(name) {
    const element = $("panel-" + name);
    return {name: name, element: element, chapter: LAB_CHAPTERS[LAB_CHAPTERS.length - 1].number,
            scene: "", overrides: {}, render: null, info: null, plan: null, error: "",
            image: element.querySelector("canvas.image"),
            overlay: element.querySelector("canvas.overlay"),
            stats: element.querySelector(".stats"), form: element.querySelector(".settings")};
}

const panels = {a: newPanel("a"), b: newPanel("b")};

function activePanels() {
    return page.layout === "two" ? [panels.a, panels.b] : [panels.a];
}

function setChapter(panel, number) {
    panel.chapter = number;
    panel.scene = chapterInfo(number).scene;
    const kept = {};
    for (const key of ["size", "seed"])
        if (key in panel.overrides)
            kept[key] = panel.overrides[key];
    panel.overrides = kept;
}

/* A panel as lab_fragment checked it: {chapter, scene ("": the chapter's), settings}. */
function setPanel(panel, checked) {
    setChapter(panel, checked.chapter);
    panel.overrides = {};
    if (checked.scene) panel.scene = checked.scene;
    for (const [key, value] of checked.settings) panel.overrides[key] = value;
}

/* The settings text for lab_configure: each value escaped, so that it stays one value. */
function settingsText(panel) {
    const words = ["chapter=" + panel.chapter, "program=" + chapterInfo(panel.chapter).program];
    for (const key in panel.overrides)
        words.push(key + "=" + encodeURIComponent(panel.overrides[key]));
    return words.join(" ");
}

/* The form of a panel: the fields its chapter has, each showing the value in force
 * (an empty field is the chapter program's default, shown greyed). */
function buildForm(panel) {
    const form = panel.form, effective = panel.info ? panel.info.settings : {};
    form.textContent = "";
    for (const field of FIELDS) {
        if (!hasField(field, panel.chapter)) continue;
        const label = document.createElement("label");
        label.textContent = field.label + " ";
        let input;
        if (field.key === "chapter" || field.key === "scene" || field.choices) {
            input = document.createElement("select");
            const choices = field.key === "chapter"
                ? LAB_CHAPTERS.map(function (c) { return [String(c.number), c.number + ": " + c.program]; })
                : field.key === "scene" ? Object.keys(scenes).map(function (s) { return [s, s]; })
                : field.choices.filter(function (c) { return c[1] <= panel.chapter; })
                    .map(function (c) { return [c[0], c[0]]; });
            for (const choice of choices) {
                const option = document.createElement("option");
                option.value = choice[0];
                option.textContent = choice[1];
                input.appendChild(option);
            }
            input.value = field.key === "chapter" ? String(panel.chapter)
                : field.key === "scene" ? panel.scene
                : String(field.key in panel.overrides ? panel.overrides[field.key] : effective[field.key]);
        } else {
            input = document.createElement("input");
            input.value = field.key in panel.overrides ? panel.overrides[field.key] : "";
            const value = effective[field.key];
            input.placeholder = typeof value === "number" && !Number.isInteger(value) ? String(Number(value.toPrecision(4)))
                              : value === undefined ? "" : String(value);
        }
        input.name = field.key;
        input.onchange = function () { formChanged(panel, field.key, input.value); };
        label.appendChild(input);
        form.appendChild(label);
    }
}

function formChanged(panel, key, value) {
    if (key === "chapter")
        setChapter(panel, Number(value));
    else if (key === "scene")
        panel.scene = value;
    else if (value === "")
        delete panel.overrides[key];
    else
        panel.overrides[key] = value;
    $("preset").value = "";
    writeFragment();
    applyFragment(location.hash);
}

/* ---- references (make lab-references; docs/lab.md) ------------------------------------ */

/* Called by a reference's script: meta {file, spp, mse, rel_mse}, the image as base64 of
 * little-endian floats, rows from the top. */
window.labReference = function (meta, data) {
    const bytes = Uint8Array.from(atob(data), function (c) { return c.charCodeAt(0); });
    const named = /-d(\d+)-(\w+)\.js$/.exec(meta.file);
    references[meta.file] = {image: new Float32Array(bytes.buffer), mse: meta.mse,
                             relMse: meta.rel_mse, spp: meta.spp,
                             depth: Number(named[1]), fresnel: named[2]};
    (referenceWaiters[meta.file] || []).forEach(function (resolve) { resolve(references[meta.file]); });
};

/* The reference file for a panel's render: the scene's hash, the image's size, the
 * depth and the Fresnel mode (the page's reference= choice, else the panel's own). */
function referenceName(info) {
    const s = info.settings;
    if (s.chapter < 2 || (s.sigma !== undefined && s.sigma !== "scene")) return null;
    const fresnel = page.reference || s.fresnel || "schlick";
    return info.hash + "-" + info.width + "x" + info.height + "-d" + s.depth + "-" + fresnel + ".js";
}

function loadReference(name) {
    if (!name || LAB_REFERENCES.indexOf(name) < 0) return Promise.resolve(null);
    if (references[name]) return Promise.resolve(references[name]);
    return new Promise(function (resolve) {
        (referenceWaiters[name] = referenceWaiters[name] || []).push(resolve);
        if (referenceWaiters[name].length > 1) return;
        const script = document.createElement("script");
        script.src = "references/" + name;
        script.onerror = function () { resolve(null); };
        document.head.appendChild(script);
    });
}

/* ---- rendering ----------------------------------------------------------------------- */

function restart() {
    clearTimeout(restart.timer);
    restart.pending = true;
    restart.timer = setTimeout(startRenders, 30);
}

let generation = 0; /* of startRenders: an older start that answers late is dropped */
let rendered = null; /* renderSignature() of the renders started */

function startRenders() {
    const mine = ++generation;
    restart.pending = false;
    rendered = renderSignature();
    pool.mode = page.fairness;
    pool.run([]);
    inspector.clear();
    const starting = activePanels().map(function (panel) {
        panel.render = null;
        panel.error = "";
        const setup = {key: "job" + (++jobs), sceneName: panel.scene, sceneText: scenes[panel.scene],
                       settings: settingsText(panel)};
        return helper.ask("scene", setup).then(function (answer) {
            panel.info = answer.info;
            panel.plan = answer.plan;
            panel.render = answer.info.settings.chapter === 10 ? new AdaptiveRender(setup, answer.info)
                                                               : new Render(setup, answer.info);
            panel.image.width = answer.info.width;
            panel.image.height = answer.info.height;
            const scale = Math.max(1, Math.ceil(640 / answer.info.width));
            panel.overlay.width = answer.info.width * scale;
            panel.overlay.height = answer.info.height * scale;
            panel.image.getContext("2d").clearRect(0, 0, panel.image.width, panel.image.height);
            buildForm(panel);
            return loadReference(referenceName(answer.info)).then(function (reference) {
                if (reference && reference.image.length === panel.render.mean.length)
                    panel.render.setReference(reference);
                return panel.render;
            });
        }, function (error) {
            panel.error = error.message;
            panel.info = null;
            buildForm(panel);
            showStats(panel);
            return null;
        });
    });
    Promise.all(starting).then(function (renders) {
        if (mine !== generation) return;
        if (!inspector.record && panels.a.plan) {
            inspector.plan = panels.a.plan;
            inspector.drawPlan();
        }
        /* After the next frame: the page laid out and painted with its new forms first, so
         * that no long task of the main thread falls into the render. */
        requestAnimationFrame(function () {
            setTimeout(function () {
                if (mine === generation) pool.run(renders.filter(function (r) { return r; }));
            }, 0);
        });
        if (page.pixel && panels.a.render) {
            inspect(panels.a, page.pixel[0], page.pixel[1]);
            page.pixel = null;
        }
    });
}

/* sRGB codes of a radiance, as bench/image.c's image_tonemap. */
function tonemap(value, exposure) {
    const v = exposure * value;
    if (!(v > 0)) return 0;
    if (v >= 1) return 255;
    const encoded = v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055;
    return Math.floor(255 * encoded + 0.5);
}

/* The map the page shows instead of the image ("show"), or null: each pixel's samples,
 * or chapter 10's estimated relative RMSE at its last plan. */
function shownMap(render) {
    const view = $("view").value;
    if (view === "samples") return render.count;
    if (view === "error" && render.estimate) return render.estimate.map(Math.sqrt);
    return null;
}

/* Draw the bands whose pixels changed (all of them with `all`), in the frame's budget of
 * milliseconds: the rest wait for the next frame, so that the page stays responsive. A map
 * is drawn in grey, its largest value white (all bands again when that changes). */
function drawBands(panel, all, budget) {
    const render = panel.render, exposure = Math.pow(2, Number($("exposure").value));
    const map = shownMap(render);
    let largest = 0;
    if (map) {
        for (let p = 0; p < map.length; p++) largest = Math.max(largest, map[p]);
        if (largest !== render.mapLargest) all = true;
    }
    render.mapLargest = largest;
    const context = panel.image.getContext("2d"), start = performance.now();
    if (!render.imageData)
        render.imageData = context.createImageData(render.width, render.bandRows);
    const data = render.imageData, pixels = data.data;
    if (all)
        for (let band = 0; band < render.bands; band++) render.dirty.add(band);
    for (const band of render.dirty) {
        if (!all && performance.now() - start > budget) break;
        render.dirty.delete(band);
        const row0 = band * render.bandRows, rows = Math.min(render.bandRows, render.height - row0);
        for (let i = 0; i < render.width * rows; i++) {
            const p = row0 * render.width + i;
            for (let c = 0; c < 3; c++)
                pixels[4 * i + c] = map ? (largest > 0 ? Math.round(255 * map[p] / largest) : 0)
                                  : render.count[p] ? tonemap(render.mean[3 * p + c], exposure) : 0;
            pixels[4 * i + 3] = 255;
        }
        context.putImageData(data, 0, row0, 0, 0, render.width, rows);
    }
}

/* The panel's error now: against the reference, or the standard error of its samples,
 * which leaves out the estimator's biases (lab_biases): the page names them. */
function currentError(panel) {
    const render = panel.render;
    if (render.reference) {
        const error = render.referenceError(), r = render.reference;
        return {value: error.rmse, rmse: error.rmse, relMse: error.relMse, text: "RMSE " + number(error.rmse, 4) + ", relative MSE " +
                number(error.relMse, 4) + " against the reference (depth " + r.depth + ", " +
                (r.fresnel === "exact" ? "exact Fresnel" : "Schlick's Fresnel") + ", " + r.spp + " spp)"};
    }
    const biases = render.info.biases, leftOut = biases.length
        ? "; it leaves out the estimator's bias: " + biases.join("; ") : "";
    if (render.info.settings.chapter === 1)
        return {value: NaN, text: "Whitted's image is deterministic: no noise to measure; its error is all bias" +
                                  (biases.length ? ": it leaves out " + biases.join("; ") : "")};
    if (render instanceof AdaptiveRender)
        return {value: render.estimated, text: "estimated relative RMSE " + number(render.estimated, 4) +
                " from its own samples (no reference for these settings)" + leftOut};
    const se = render.standardError();
    return {value: se, text: (isNaN(se) ? "error: waiting for two samples in every pixel"
                                        : "standard error " + number(se, 4) + " from the samples (no reference for these settings)") + leftOut};
}

/* A render to a target error: its estimate from its own samples, what reaching the target
 * cost, and the relative RMSE against the reference beside the estimate where there is one. */
function targetText(render, error) {
    if (!(render.target > 0)) return "";
    const against = render.reference && !isNaN(error.relMse)
        ? "; against the reference: relative RMSE " + number(Math.sqrt(Math.max(0, error.relMse)), 4) : "";
    const reached = render.reached;
    if (!reached)
        return "\ntarget " + render.target + ": estimated relative RMSE " +
               (isNaN(render.estimated) ? "(after two steps)" : number(render.estimated, 4)) + " so far" + against +
               (render.finished && !render.stopped ? "; not reached within the render's samples" : "");
    return "\ntarget " + render.target + " reached: estimated relative RMSE " + number(reached.estimate, 4) +
           (render instanceof AdaptiveRender ? " (its passes' estimate)" : " (two interleaved half-images)") + against + "; it cost " + number(reached.seconds, 3) +
           " processor s (" + number(reached.wall, 3) + " s wall), " + number(reached.steps, 4) +
           (render instanceof AdaptiveRender ? " spp on average" : render.info.settings.chapter === 8 ? " passes" : " spp");
}

function showStats(panel) {
    const stats = panel.stats, render = panel.render;
    stats.className = panel.error ? "stats failed" : "stats";
    if (panel.error || !render) {
        stats.textContent = panel.error ? "cannot render: " + panel.error : "starting\u2026";
        return;
    }
    const chapter = render.info.settings.chapter, done = render.stepsDone();
    const rays = render.rays[0] + render.rays[1] + render.rays[2] + render.rays[3];
    const wall = render.wallSeconds(), error = currentError(panel);
    panel.measured = error;
    stats.textContent =
        (chapter === 10 ? "passes " + done + ", " + number(render.meanSamples(), 4) + " spp on average (" +
                          render.active + " pixels sampled in the last pass)"
         : chapter === 8 ? "passes " + number(done, 3) + " of " + render.steps + " (" +
                           number(done * render.info.settings.spp, 4) + " spp)"
         : "spp " + number(done, 3) + " of " + render.steps) +
        (render.stopped ? ", stopped at equal time" : render.reached ? ", target reached"
         : render.finished ? ", done" : "") + "  " + wall.toFixed(2) + " s  " +
        number(rays / wall / 1e6, 3) + " Mrays/s (" + number(rays / Math.max(render.seconds, 1e-9) / 1e6, 3) +
        " per worker)\n" + error.text + targetText(render, error);
    if (!isNaN(error.value) && error.value > 0) {
        const last = render.history[render.history.length - 1];
        if (!last || last[0] !== render.seconds)
            render.history.push([render.seconds, wall, error.value]);
    }
}

function drawPlot() {
    const series = activePanels().filter(function (p) { return p.render; }).map(function (panel) {
        const s = panel.render.info.settings;
        return {label: panel.name.toUpperCase() + ": " + settingsText(panel).replace(/ program=\S+/, "") +
                       (panel.render.reference ? " (RMSE)" : panel.render instanceof AdaptiveRender
                                                   ? " (estimated relative RMSE)" : panel.render.info.biases.length
                                                   ? " (standard error, bias left out)" : " (standard error)"),
                colour: PANEL_COLOURS[panel.name],
                points: panel.render.history.map(function (h) { return [h[0], h[2]]; })};
    });
    drawLogLogPlot($("plot"), series, {x: "processor seconds (all workers)", y: "error"});
}

let lastStats = 0;
function frame(now) {
    const started = performance.now();
    for (const panel of activePanels())
        if (panel.render && panel.render.dirty.size)
            drawBands(panel, false, 8);
    if (now - lastStats > 250) {
        lastStats = now;
        activePanels().forEach(showStats);
        drawPlot();
    }
    frame.longest = Math.max(frame.longest || 0, performance.now() - started);
    requestAnimationFrame(frame);
}

/* ---- the inspector ------------------------------------------------------------------- */

function inspect(panel, col, row) {
    if (!panel.render) return;
    $("inspector-hint").textContent = "recording\u2026";
    inspected = panel;
    for (const other of activePanels())
        if (other !== panel)
            other.overlay.getContext("2d").clearRect(0, 0, other.overlay.width, other.overlay.height);
    inspector.elements.overlay = panel.overlay;
    const s = panel.render.info.settings; /* paths among the render's samples */
    const count = Math.min(page.paths, s.chapter === 10 ? Math.ceil(s.spp / 4) * 4 /* the first pass's */
                                                         : panel.render.steps * (s.chapter === 8 ? s.spp : 1));
    return helper.ask("record", panel.render.setup, {col: col, row: row, first: 0, count: count})
        .then(function (answer) {
            inspector.show(JSON.parse(answer.json), panel.plan, panel.render.width, panel.render.height);
            $("inspector-hint").textContent = "panel " + panel.name.toUpperCase() + ": samples 0 to " +
                (count - 1) + " of pixel (" + col + ", " + row + "); click a row or step through its vertices";
            return answer.json;
        }, function (error) {
            $("inspector-hint").textContent = "cannot record: " + error.message;
        });
}

function overlayClicked(panel, event) {
    if (!panel.render) return;
    const box = panel.overlay.getBoundingClientRect();
    const col = Math.floor((event.clientX - box.left) / box.width * panel.render.width);
    const row = Math.floor((event.clientY - box.top) / box.height * panel.render.height);
    if (col >= 0 && col < panel.render.width && row >= 0 && row < panel.render.height)
        inspect(panel, col, row);
}

/* ---- the scene editor ---------------------------------------------------------------- */

/* The text to apply, in the box unless it is too long to show there. */
function setEditorText(text) {
    const box = $("scene-text"), long = text.length > EDITOR_SHOWN_MAX;
    editorText = text;
    box.disabled = long;
    box.value = long ? "" : text;
    box.placeholder = long ? "(" + text.length + " characters: too many to show here; apply reads them)" : "";
}

function showScene() {
    setEditorText(scenes[$("scene-name").value]);
    $("scene-error").textContent = "";
}

/* Check the edited text as the chapter program would read it (in the helper worker),
 * then render with it. */
function applyScene() {
    const name = $("scene-name").value, text = editorText;
    const setup = {key: "check" + (++jobs), sceneName: name, sceneText: text, settings: settingsText(panels.a)};
    return helper.ask("scene", setup).then(function () {
        $("scene-error").textContent = "";
        scenes[name] = text;
        for (const panel of activePanels())
            panel.scene = name;
        restart();
        return "";
    }, function (error) {
        $("scene-error").textContent = error.message;
        return error.message;
    });
}

/* ---- the address's fragment ---------------------------------------------------------- */

function cores() {
    return Math.max(1, navigator.hardwareConcurrency || 1);
}

let addressGeneration = 0; /* of applyFragment: an older answer is dropped */

/* Check the address's fragment in C (lab_fragment) and take its settings; or show its
 * message, render nothing, and keep the settings as they were. */
function applyFragment(fragment) {
    const mine = ++addressGeneration;
    const question = {fragment: fragment.replace(/^#/, ""), scenes: Object.keys(scenes).join("\n"), cores: cores()};
    return helper.ask("fragment", null, question).then(function (answer) {
        if (mine !== addressGeneration) return;
        page.checked++;
        const given = answer.state.page;
        page.error = "";
        page.note = given.note;
        page.layout = given.layout || (given.b ? "two" : "one");
        page.fairness = given.fairness || "samples";
        page.reference = given.reference || "";
        page.paths = given.paths || 8;
        page.pixel = given.pixel || null;
        page.workersGiven = given.workers !== undefined;
        page.workers = page.workersGiven ? given.workers : cores();
        setPanel(panels.a, answer.state.a);
        setPanel(panels.b, answer.state.b);
        if (pool.workers.length !== page.workers) pool.setWorkers(page.workers);
        showAddress();
        showPage();
        if (renderSignature() !== rendered) {
            restart();
        } else if (page.pixel && panels.a.render) { /* the same renders: the inspector only */
            inspect(panels.a, page.pixel[0], page.pixel[1]);
            page.pixel = null;
        } else if (inspector.record && inspected) {
            inspect(inspected, inspector.record.col, inspector.record.row);
        }
    }, function (error) {
        if (mine !== addressGeneration) return;
        page.checked++;
        page.error = error.message;
        page.note = "";
        stopRenders("the address is refused (above)");
        showAddress();
    });
}

/* What the renders running depend on: when it changes, they start again. */
function renderSignature() {
    return JSON.stringify([page.layout, page.fairness, page.reference, page.workers,
                           activePanels().map(function (p) { return [p.scene, settingsText(p)]; })]);
}

function showAddress() {
    const shown = $("address-message");
    shown.textContent = page.error ? "This address is refused: " + page.error : page.note;
    shown.className = page.error ? "failed" : "note";
}

function stopRenders(why) {
    clearTimeout(restart.timer);
    restart.pending = false;
    generation++;
    rendered = null;
    pool.run([]);
    for (const panel of activePanels()) {
        panel.render = null;
        panel.error = why;
        showStats(panel);
    }
}

function writeFragment() {
    const words = [];
    const add = function (prefix, panel) {
        words.push(prefix + "chapter=" + panel.chapter);
        if (panel.scene !== chapterInfo(panel.chapter).scene) words.push(prefix + "scene=" + panel.scene);
        for (const key in panel.overrides) words.push(prefix + key + "=" + encodeURIComponent(panel.overrides[key]));
    };
    add("", panels.a);
    if (page.layout === "two") add("b.", panels.b);
    words.push("fairness=" + page.fairness);
    if (page.reference) words.push("reference=" + page.reference);
    if (page.workersGiven) words.push("workers=" + encodeURIComponent(page.workers));
    if (String(page.paths) !== "8") words.push("paths=" + encodeURIComponent(page.paths));
    history.replaceState(null, "", "#" + words.join("&"));
}

function showPage() {
    panels.b.element.hidden = page.layout !== "two";
    $("layout").value = page.layout;
    $("fairness").value = page.fairness;
    $("workers").value = page.workers;
    $("paths").value = page.paths;
    $("book").href = "../book/chapter" + panels.a.chapter + ".html";
    $("book").textContent = "chapter " + panels.a.chapter + " in the book";
    buildForm(panels.a);
    buildForm(panels.b);
}

/* ---- what the browser test asks (bench/lab/browser_lab.js) ---------------------------- */

function base64(floats) {
    const bytes = new Uint8Array(floats.buffer);
    let text = "";
    for (let i = 0; i < bytes.length; i += 0x8000)
        text += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
    return btoa(text);
}

window.labTest = {
    /* Render a scene of scenes/ with these settings on `workers` workers of their own, in
     * bands of `bandRows` rows (default: the page's), each result delayed by up to
     * `jitter` ms at random (so that they arrive out of order): the image (float32, rows
     * from the top), the means as the page keeps them (float64), and each pixel's
     * standard error, as base64. With `keep`, its workers live on until release() (the
     * benchmark reads their threads' processor time). */
    render: function (sceneName, settings, workers, bandRows, jitter, keep) {
        const setup = {key: "test" + (++jobs), sceneName: sceneName, sceneText: scenes[sceneName],
                       settings: settings};
        return helper.ask("scene", setup).then(function (answer) {
            return new Promise(function (resolve, reject) {
                const render = answer.info.settings.chapter === 10 ? new AdaptiveRender(setup, answer.info, bandRows)
                                                                  : new Render(setup, answer.info, bandRows);
                const own = new Pool(workers, function () {
                    if (!render.complete()) return;
                    const image = Float32Array.from(render.mean), se = new Float32Array(render.mean.length);
                    for (let i = 0; i < se.length; i++) {
                        const n = render.count[Math.floor(i / 3)];
                        se[i] = n > 1 ? Math.sqrt(render.m2[i] / (n - 1) / n) : 0;
                    }
                    if (keep) labTest.kept = own; else own.setWorkers(0);
                    resolve({width: render.width, height: render.height, image: base64(image),
                             means: base64(render.mean),
                             stdError: base64(se), rays: render.rays, seconds: render.wallSeconds(),
                             workerSeconds: render.seconds});
                }, function (r, message) { own.setWorkers(0); reject(new Error(message)); });
                own.jitter = jitter || 0;
                own.run([render]);
            });
        });
    },
    /* What lab_record says to these numbers: "" when it records, else its message. */
    recordError: function (sceneName, settings, col, row, first, count) {
        return labTest.record(sceneName, settings, col, row, first, count)
            .then(function () { return ""; }, function (error) { return error.message; });
    },
    record: function (sceneName, settings, col, row, first, count) {
        const setup = {key: "test" + (++jobs), sceneName: sceneName, sceneText: scenes[sceneName],
                       settings: settings};
        return helper.ask("record", setup, {col: col, row: row, first: first, count: count})
            .then(function (answer) { return answer.json; });
    },
    /* Put this text in the editor as scene NAME (as a file opened there) and apply it: the
     * error shown, or "". While it is read, labTest.applying is true. */
    editScene: function (name, text) {
        $("scene-name").value = name;
        setEditorText(text);
        labTest.applying = true;
        return applyScene().then(function () {
            labTest.applying = false;
            return $("scene-error").textContent;
        });
    },
    /* lab_fragment's answer for an address: {state} or {error}. */
    fragment: function (fragment) {
        return helper.ask("fragment", null, {fragment: fragment, scenes: Object.keys(scenes).join("\n"), cores: cores()})
            .then(function (answer) { return {state: answer.state}; }, function (error) { return {error: error.message}; });
    },
    /* The pool's choice at equal time between two renders: A with 1 s of finished tasks
     * and one task in flight for 2 s, B with 2.5 s and none: {chose, used: [A's, B's]}. */
    equalTimeChoice: function () {
        const info = {width: 16, height: 16, steps: 100, settings: {chapter: 3, M: 1}};
        const a = new Render({key: "probe-a"}, info), b = new Render({key: "probe-b"}, info);
        const probe = new Pool(0, function () {}, function () {});
        probe.mode = "time";
        probe.renders = [a, b];
        a.seconds = 1;
        a.issued = 3;
        a.inFlight = 1;
        b.seconds = 2.5;
        b.issued = 2;
        probe.workers = [{render: a, sent: performance.now() - 2000}];
        return {chose: probe.choose() === a ? "A" : "B", used: [probe.secondsUsed(a), probe.secondsUsed(b)]};
    },
    /* Panel A's map of samples per pixel as drawn on its canvas ("show": samples per pixel,
     * grey, the red channel's byte) and the samples it is drawn from. */
    samplesMap: function () {
        const panel = panels.a, render = panel.render;
        $("view").value = "samples";
        drawBands(panel, true);
        const data = panel.image.getContext("2d").getImageData(0, 0, render.width, render.height).data;
        const drawn = [];
        for (let i = 0; i < data.length; i += 4) drawn.push(data[i]);
        return {samples: Array.from(render.count), drawn: drawn};
    },
    /* Panel A's image as the page keeps it (float64) and its reference's (float32), as
     * base64; the reference's is "" when there is none. */
    images: function () {
        const render = panels.a.render;
        return {image: base64(render.mean), reference: render.reference ? base64(render.reference.image) : ""};
    },
    release: function () {
        if (labTest.kept) labTest.kept.setWorkers(0);
        labTest.kept = null;
    },
    /* The comparisons the page offers: [fragment, name]. */
    presets: function () { return PRESETS.filter(function (p) { return p[0]; }); },
    inspect: function (panel, col, row) { return inspect(panels[panel], col, row); },
    step: function (by) { inspector.step(by); },
    state: function () {
        return {
            panels: activePanels().map(function (panel) {
                const r = panel.render;
                return {error: panel.error, stats: panel.stats.textContent,
                        complete: !!(r && r.finished), steps: r ? r.steps : 0,
                        done: r ? r.stepsDone() : 0, started: r ? r.started : null,
                        finished: r ? r.finished : null, reference: !!(r && r.reference),
                        stopped: !!(r && r.stopped), seconds: r ? r.seconds : 0, longest: r ? r.longest : 0,
                        chapter: r ? r.info.settings.chapter : null, settings: r ? r.info.settings : null,
                        rmse: panel.measured ? panel.measured.rmse : null,
                        relMse: panel.measured ? panel.measured.relMse : null,
                        history: r ? r.history.length : 0, target: r ? r.target : 0,
                        estimated: r ? r.estimated : null, estimates: r ? r.estimates : [],
                        reached: r ? r.reached : null,
                        meanSamples: r instanceof AdaptiveRender ? r.meanSamples() : null};
            }),
            inspector: {summary: $("path-summary").textContent, rows: $("path-table").rows.length,
                        hint: $("inspector-hint").textContent},
            longTasks: longTasks.slice(), longestFrame: frame.longest || 0,
            workers: pool.workers.length, address: $("address-message").textContent,
            addressRefused: !!page.error, checked: page.checked, restarting: !!restart.pending, book: $("book").getAttribute("href"),
        };
    },
};

/* ---- start --------------------------------------------------------------------------- */

function start() {
    if ("PerformanceObserver" in window &&
        (PerformanceObserver.supportedEntryTypes || []).indexOf("longtask") >= 0)
        new PerformanceObserver(function (list) {
            list.getEntries().forEach(function (entry) {
                longTasks.push({start: entry.startTime, duration: entry.duration});
            });
        }).observe({entryTypes: ["longtask"]});
    Object.keys(LAB_SCENES).sort().forEach(function (name) { scenes[name] = LAB_SCENES[name]; });
    for (const name in scenes) {
        const option = document.createElement("option");
        option.value = option.textContent = name;
        $("scene-name").appendChild(option);
    }
    for (const preset of PRESETS) {
        const option = document.createElement("option");
        option.value = preset[0];
        option.textContent = preset[1];
        $("preset").appendChild(option);
    }
    page.workers = cores();
    for (const name of ["a", "b"]) setChapter(panels[name], panels[name].chapter);
    $("scene-name").value = panels.a.scene;
    showScene();
    showPage();
    helper = new Helper();
    pool = new Pool(0, function (render) {
        for (const panel of activePanels())
            if (panel.render && panel.render.finished)
                showStats(panel);
    }, function (render, message) {
        for (const panel of activePanels())
            if (panel.render === render) {
                panel.error = message;
                showStats(panel);
            }
    });
    inspector = new Inspector({overlay: panels.a.overlay, plan: $("plan"), table: $("path-table"),
                               detail: $("vertex-detail"), summary: $("path-summary")});
    for (const name of ["a", "b"])
        panels[name].overlay.onclick = overlayClicked.bind(null, panels[name]);
    /* Each control writes the address, which is then checked as any address is. */
    const changed = function () { writeFragment(); applyFragment(location.hash); };
    $("layout").onchange = function () { page.layout = this.value; changed(); };
    $("fairness").onchange = function () { page.fairness = this.value; changed(); };
    $("workers").onchange = function () { page.workers = this.value; page.workersGiven = true; changed(); };
    $("preset").onchange = function () {
        if (!this.value) return;
        history.replaceState(null, "", "#" + this.value);
        applyFragment(location.hash);
    };
    $("exposure").oninput = function () {
        for (const panel of activePanels()) if (panel.render) drawBands(panel, true);
    };
    $("view").onchange = $("exposure").oninput;
    $("restart").onclick = restart;
    $("paths").onchange = function () {
        page.paths = this.value;
        changed();
    };
    $("previous-path").onclick = function () { inspector.setPath(inspector.path - 1); };
    $("next-path").onclick = function () { inspector.setPath(inspector.path + 1); };
    $("previous-vertex").onclick = function () { inspector.step(-1); };
    $("next-vertex").onclick = function () { inspector.step(1); };
    $("scene-name").onchange = showScene;
    $("scene-text").oninput = function () { editorText = this.value; };
    $("scene-file").onchange = function () {
        if (this.files.length) this.files[0].text().then(setEditorText);
    };
    $("apply-scene").onclick = applyScene;
    $("revert-scene").onclick = function () {
        const name = $("scene-name").value;
        scenes[name] = LAB_SCENES[name];
        showScene();
        restart();
    };
    window.onhashchange = function () { applyFragment(location.hash); };
    applyFragment(location.hash);
    requestAnimationFrame(frame);
}

start();
