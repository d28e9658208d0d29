/* worker.js (bench, chapter 8): one web worker of the lab: a WebAssembly instance of
 * bench/lab/lab.c, driven by messages from the page (bench/lab/pool.js).
 *
 * It runs after the module's script in the same Blob (a page opened from disk can start
 * a worker only from a Blob), so createLabModule is defined. Messages in:
 *   {type: "band", job, setup?, step, row0, rows, buffer}   render a band (setup: the
 *                      job's scene and settings, when they are new here; buffer: an
 *                      earlier result's, to fill again if it has the size)
 *   {type: "plan", job, setup?, pass, sums, samples}  chapter 10: plan a pass
 *   {type: "adaptive", job, setup?, row0, rows, sums, samples, toAdd}   chapter 10: sample
 *                      a band as planned (sums and samples: the band's, 16 and 1 per pixel)
 *   {type: "record", id, setup, col, row, first, count}   record paths (record.h)
 *   {type: "scene", id, setup}                      the scene's plan (lab_scene)
 *   {type: "fragment", id, fragment, scenes, cores} the address checked (lab_fragment)
 * and out: {type: "band", job, step, row0, rows, values, rays, seconds}, {type: "plan",
 * job, pass, active, error, estimate, toAdd, rays, seconds}, {type: "adaptive", job, row0,
 * rows, sums, samples, values, rays, seconds}, {type: "record",
 * id, json, info}, {type: "scene", id, plan, info}, {type: "fragment", id, state}, or
 * {type: "error", job | id, message} with lab_error's text. Text is read here, in the
 * worker, as JSON: a big scene's plan or reading keeps the page's own thread free.
 */
"use strict";

let lab = null;      /* the Lab of lab.c, in M */
let M = null;        /* the module */
let configured = ""; /* the key of the job configured in lab */
let info = null;     /* what lab_configure made of it */
let loaded = null;   /* {name, text} of the scene in lab, or null */
const ready = createLabModule().then(function (module) {
    M = module;
    lab = M._lab_new();
});

/* A NUL-terminated UTF-8 copy of text in the module's memory (free it), and its length. */
function copyIn(text) {
    const bytes = new TextEncoder().encode(text);
    const pointer = bytes.length < 0x7fffffff ? M._malloc(bytes.length + 1) : 0;
    if (!pointer)
        throw new Error("out of memory for " + bytes.length + " bytes of text");
    M.HEAPU8.set(bytes, pointer);
    M.HEAPU8[pointer + bytes.length] = 0;
    return {pointer: pointer, length: bytes.length};
}

function failure() {
    return new Error(M.UTF8ToString(M._lab_error(lab)));
}

/* Load the scene (unless it is the one loaded already) and apply the settings of `setup`
 * ({key, sceneName, sceneText, settings}) unless they are the ones configured already. */
function configure(setup) {
    if (setup.key === configured)
        return info;
    configured = "";
    if (!loaded || loaded.name !== setup.sceneName || loaded.text !== setup.sceneText) {
        loaded = null;
        const text = copyIn(setup.sceneText);
        let name;
        try {
            name = copyIn(setup.sceneName);
        } finally {
            if (!name) M._free(text.pointer);
        }
        const status = M._lab_load_scene(lab, text.pointer, text.length, name.pointer);
        M._free(text.pointer);
        M._free(name.pointer);
        if (status !== 0)
            throw failure();
        loaded = {name: setup.sceneName, text: setup.sceneText};
    }
    const settings = copyIn(setup.settings);
    const status = M._lab_configure(lab, settings.pointer);
    M._free(settings.pointer);
    if (status !== 0)
        throw failure();
    configured = setup.key;
    info = {width: M._lab_width(lab), height: M._lab_height(lab), steps: M._lab_steps(lab),
            hash: M.UTF8ToString(M._lab_scene_hash(lab)),
            settings: JSON.parse(M.UTF8ToString(M._lab_settings(lab))),
            biases: JSON.parse(M.UTF8ToString(M._lab_biases(lab)))};
    return info;
}

function renderBand(message) {
    const count = 3 * info.width * message.rows;
    const out = M._malloc(8 * count);
    const start = performance.now();
    const status = M._lab_render_band(lab, message.step, message.row0, message.rows, out);
    const seconds = (performance.now() - start) / 1000;
    if (status !== 0) {
        M._free(out);
        throw failure();
    }
    const result = new Float64Array(M.HEAPF64.buffer, out, count);
    const values = message.buffer && message.buffer.byteLength === 8 * count
        ? new Float64Array(message.buffer) : new Float64Array(count);
    values.set(result);
    M._free(out);
    postMessage({type: "band", job: message.job, step: message.step, row0: message.row0,
                 rows: message.rows, values: values, rays: rays(), seconds: seconds},
                [values.buffer]);
}

/* Typed arrays copied into the module's memory: their addresses (free them). */
function arraysIn(arrays) {
    return arrays.map(function (array) {
        const pointer = M._malloc(Math.max(1, array.byteLength));
        if (!pointer)
            throw new Error("out of memory for " + array.byteLength + " bytes");
        new Uint8Array(M.HEAPU8.buffer, pointer, array.byteLength)
            .set(new Uint8Array(array.buffer, array.byteOffset, array.byteLength));
        return pointer;
    });
}

/* A copy of `count` elements of type Type at `pointer` in the module's memory. */
function arrayOut(Type, pointer, count) {
    return new Type(M.HEAPU8.buffer.slice(pointer, pointer + count * Type.BYTES_PER_ELEMENT));
}

function rays() {
    return [0, 1, 2, 3].map(function (kind) { return M._lab_rays(lab, kind); });
}

/* Chapter 10: pass `pass` planned from every pixel's sums and samples (lab_adaptive_plan). */
function planPass(message) {
    const pixels = info.width * info.height;
    const [sums, samples, estimate, toAdd] =
        arraysIn([message.sums, message.samples, new Float64Array(pixels), new Int32Array(pixels)]);
    const start = performance.now();
    const active = M._lab_adaptive_plan(lab, message.pass, sums, samples, estimate, toAdd);
    const seconds = (performance.now() - start) / 1000;
    const reply = {type: "plan", job: message.job, pass: message.pass, active: active,
                   error: M._lab_estimated_error(lab), estimate: arrayOut(Float64Array, estimate, pixels),
                   toAdd: arrayOut(Int32Array, toAdd, pixels), rays: [0, 0, 0, 0], seconds: seconds};
    [sums, samples, estimate, toAdd].forEach(function (pointer) { M._free(pointer); });
    if (active < 0)
        throw failure();
    postMessage(reply, [reply.estimate.buffer, reply.toAdd.buffer]);
}

/* Chapter 10: a band's planned samples (lab_adaptive_band). */
function sampleBand(message) {
    const pixels = info.width * message.rows;
    const [sums, samples, toAdd, values] =
        arraysIn([message.sums, message.samples, message.toAdd, new Float64Array(3 * pixels)]);
    const start = performance.now();
    const status = M._lab_adaptive_band(lab, message.row0, message.rows, sums, samples, toAdd, values);
    const seconds = (performance.now() - start) / 1000;
    const reply = {type: "adaptive", job: message.job, row0: message.row0, rows: message.rows,
                   sums: arrayOut(Float64Array, sums, 16 * pixels), samples: arrayOut(Int32Array, samples, pixels),
                   values: arrayOut(Float64Array, values, 3 * pixels), rays: rays(), seconds: seconds};
    [sums, samples, toAdd, values].forEach(function (pointer) { M._free(pointer); });
    if (status !== 0)
        throw failure();
    postMessage(reply, [reply.sums.buffer, reply.samples.buffer, reply.values.buffer]);
}

/* The answer to a question: the JSON text at `json` in the module's memory, as text
 * (recordings: the tests compare them character for character) or read (`field`). */
function answer(message, json, field) {
    if (json === 0)
        throw failure();
    const text = M.UTF8ToString(json), reply = {type: message.type, id: message.id, info: info};
    if (field)
        reply[field] = JSON.parse(text);
    else
        reply.json = text;
    postMessage(reply);
}

function checkFragment(message) {
    const fragment = copyIn(message.fragment), scenes = copyIn(message.scenes);
    const json = M._lab_fragment(lab, fragment.pointer, scenes.pointer, message.cores);
    M._free(fragment.pointer);
    M._free(scenes.pointer);
    answer(message, json, "state");
}

onmessage = function (event) {
    const message = event.data;
    ready.then(function () {
        try {
            if (message.setup)
                configure(message.setup);
            if (message.type === "band")
                renderBand(message);
            else if (message.type === "plan")
                planPass(message);
            else if (message.type === "adaptive")
                sampleBand(message);
            else if (message.type === "record")
                answer(message, M._lab_record(lab, message.col, message.row, message.first,
                                              message.count));
            else if (message.type === "scene")
                answer(message, M._lab_scene(lab), "plan");
            else if (message.type === "fragment")
                checkFragment(message);
        } catch (error) {
            configured = "";
            postMessage({type: "error", job: message.job, id: message.id,
                         message: String(error.message || error)});
        }
    });
};
