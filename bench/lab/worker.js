/* worker.js (bench, chapter 8): one web worker of the lab: a WebAssembly instance of
 * bench/lab/lab.c, driven by messages from the page (bench/lab/pool.js).
 *
 * It runs after the module's script in the same Blob (a page opened from disk can start
 * a worker only from a Blob), so createLabModule is defined. Messages in:
 *   {type: "band", job, setup?, step, row0, rows, buffer}   render a band (setup: the
 *                      job's scene and settings, when they are new here; buffer: an
 *                      earlier result's, to fill again if it has the size)
 *   {type: "record", id, setup, col, row, first, count}   record paths (record.h)
 *   {type: "scene", id, setup}                      the scene's plan (lab_scene)
 * and out: {type: "band", job, step, row0, rows, values, rays, seconds}, {type: "record"
 * | "scene", id, json, info}, or {type: "error", job | id, message} with lab_error's text.
 */
"use strict";

let lab = null;      /* the Lab of lab.c, in M */
let M = null;        /* the module */
let configured = ""; /* the key of the job configured in lab */
let info = null;     /* what lab_configure made of it */
const ready = createLabModule().then(function (module) {
    M = module;
    lab = M._lab_new();
});

/* A NUL-terminated UTF-8 copy of text in the module's memory (free it), and its length. */
function copyIn(text) {
    const bytes = new TextEncoder().encode(text);
    const pointer = M._malloc(bytes.length + 1);
    M.HEAPU8.set(bytes, pointer);
    M.HEAPU8[pointer + bytes.length] = 0;
    return {pointer: pointer, length: bytes.length};
}

function failure() {
    return new Error(M.UTF8ToString(M._lab_error(lab)));
}

/* Load the scene and apply the settings of `setup` ({key, sceneName, sceneText, settings})
 * unless they are the ones configured already. */
function configure(setup) {
    if (setup.key === configured)
        return info;
    configured = "";
    const text = copyIn(setup.sceneText), name = copyIn(setup.sceneName);
    const loaded = M._lab_load_scene(lab, text.pointer, text.length, name.pointer);
    M._free(text.pointer);
    M._free(name.pointer);
    if (loaded !== 0)
        throw failure();
    const settings = copyIn(setup.settings);
    const status = M._lab_configure(lab, settings.pointer);
    M._free(settings.pointer);
    if (status !== 0)
        throw failure();
    configured = setup.key;
    info = {width: M._lab_width(lab), height: M._lab_height(lab), steps: M._lab_steps(lab),
            hash: M.UTF8ToString(M._lab_scene_hash(lab)),
            settings: JSON.parse(M.UTF8ToString(M._lab_settings(lab)))};
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
    const rays = [0, 1, 2, 3].map(function (kind) { return M._lab_rays(lab, kind); });
    postMessage({type: "band", job: message.job, step: message.step, row0: message.row0,
                 rows: message.rows, values: values, rays: rays, seconds: seconds},
                [values.buffer]);
}

function answer(message, json) {
    if (json === 0)
        throw failure();
    postMessage({type: message.type, id: message.id, json: M.UTF8ToString(json), info: info});
}

onmessage = function (event) {
    const message = event.data;
    ready.then(function () {
        try {
            if (message.setup)
                configure(message.setup);
            if (message.type === "band")
                renderBand(message);
            else if (message.type === "record")
                answer(message, M._lab_record(lab, message.col, message.row, message.first,
                                              message.count));
            else if (message.type === "scene")
                answer(message, M._lab_scene(lab));
        } catch (error) {
            configured = "";
            postMessage({type: "error", job: message.job, id: message.id,
                         message: String(error.message || error)});
        }
    });
};
