/* pool.js (bench, chapter 8): the lab's web workers, and the renders they share.
 *
 * A render is a job (a scene, its name and the settings of lab.h) cut into tasks: step
 * s of a band of rows. Tasks go out step by step to whichever worker is free; their
 * results come back in any order, and each band's steps are added to its pixels in
 * order, by Welford's update exactly as bench/renderer.c adds a pixel's samples. So the
 * image is the chapter program's, bit for bit where the WebAssembly arithmetic is the
 * native one, for any number of workers. With two renders the pool shares the workers
 * between them at equal samples (the one behind gets the next task) or at equal
 * processor time (the one that has used less, a task in flight counting from the moment
 * it was sent; when one has taken all its samples, the other takes tasks until it has
 * used as much, and stops when those are in).
 *
 * A render to a target error (chapters 7 and 8: target=E) keeps its steps in two
 * interleaved half-images, A the even steps and B the odd ones, and stops at the first
 * even step where their estimate of its relative RMSE is at most E: the root of the mean
 * over pixels and channels of ((A - B) / 2)^2 / (F^2 + 0.01), F = (A + B) / 2, the
 * relative MSE of bench/measure.h. Chapter 10's render (AdaptiveRender) has its own
 * estimate and rule, lab.h's.
 */
"use strict";

let workerUrl = null;

/* A worker running the module and worker.js, from a Blob (a page opened from disk may
 * not start one from a file). */
function newLabWorker() {
    if (!workerUrl) {
        const source = LAB_WORKER["lab_module.js"] + "\n" + LAB_WORKER["worker.js"];
        workerUrl = URL.createObjectURL(new Blob([source], {type: "text/javascript"}));
    }
    return new Worker(workerUrl);
}

/* Pixels per task, about, at one shadow ray per vertex: a band of rows takes a few tens
 * of milliseconds. M shadow rays make a sample about (1 + M) / 2 times as costly, and the
 * band that much smaller, so that a task stays short: a render at equal time then stops
 * within a short task of its budget. */
const TASK_SAMPLES = 8192;

class Render {
    /* setup: {key, sceneName, sceneText, settings}; info: lab_configure's (worker.js);
     * bandRows: rows per task (by default, about TASK_SAMPLES samples' worth). */
    constructor(setup, info, bandRows) {
        this.setup = setup;
        this.info = info;
        this.width = info.width;
        this.height = info.height;
        this.steps = info.steps;
        const pixels = this.width * this.height;
        const perStep = info.settings.chapter === 8 ? info.settings.spp : 1;
        const cost = info.settings.M === undefined ? 1 : (1 + info.settings.M) / 2;
        this.bandRows = Math.max(1, Math.min(this.height,
                                             bandRows || Math.round(TASK_SAMPLES / (this.width * perStep * cost))));
        this.bands = Math.ceil(this.height / this.bandRows);
        this.mean = new Float64Array(3 * pixels);
        this.m2 = new Float64Array(3 * pixels);
        this.count = new Uint32Array(pixels);
        this.added = new Int32Array(this.bands);   /* each band's next step to add */
        this.waiting = new Map();                  /* results that came early */
        this.issued = 0;                           /* tasks sent: step * bands + band */
        this.inFlight = 0;
        this.seconds = 0;                          /* workers' time on its finished tasks */
        this.longest = 0;                          /* of one task, seconds */
        this.budget = Infinity;                    /* equal time: seconds it may use at most */
        this.rays = [0, 0, 0, 0];
        this.started = performance.now();
        this.finished = null;
        this.dirty = new Set();
        this.error = null;
        this.history = [];                         /* [processor seconds, wall seconds, error] */
        this.empty = this.single = pixels;         /* pixels with no step, with fewer than two */
        this.variance = 0;                         /* the sum of the pixels' squared standard errors */
        this.reference = null;
        this.spare = [];                           /* result buffers to give back to workers */
        this.target = info.settings.target || 0;   /* of the estimated relative RMSE; 0: none */
        this.halves = [new Float64Array(3 * pixels), new Float64Array(3 * pixels)];
        this.halfCounts = [new Uint32Array(pixels), new Uint32Array(pixels)];
        this.estimated = NaN;                      /* from the halves, at the last even step */
        this.estimates = [];                       /* each one made, in order */
        this.reached = null;                       /* the target: {seconds, wall, steps, estimate} */
    }

    tasksLeft() {
        return !this.error && !this.stopped && !this.stopping && !this.finished &&
               this.issued < this.steps * this.bands;
    }

    /* Stop here: the other panel, at equal time, has finished. */
    stop() {
        if (this.finished) return;
        this.stopped = true;
        this.finished = performance.now();
    }

    /* Equal time: take no more tasks, and stop once those in flight are in. */
    stopAfterTasksInFlight() {
        this.stopping = true;
        if (this.inFlight === 0) this.stop();
    }

    /* The next task, in step order. */
    nextTask() {
        const step = Math.floor(this.issued / this.bands), band = this.issued % this.bands;
        this.issued++;
        this.inFlight++;
        const row0 = band * this.bandRows;
        return {step: step, row0: row0, rows: Math.min(this.bandRows, this.height - row0)};
    }

    /* A band's result: kept until its turn, then added. */
    accept(result) {
        this.inFlight--;
        if (this.finished) return; /* reached its target: what it cost is counted */
        this.seconds += result.seconds;
        this.longest = Math.max(this.longest, result.seconds);
        for (let k = 0; k < 4; k++)
            this.rays[k] += result.rays[k];
        const band = result.row0 / this.bandRows;
        this.waiting.set(result.step * this.bands + band, result);
        for (let next; (next = this.waiting.get(this.added[band] * this.bands + band));) {
            this.waiting.delete(this.added[band] * this.bands + band);
            this.add(next);
            this.spare.push(next.values.buffer);
            this.added[band]++;
            this.dirty.add(band);
        }
        if (this.target > 0) this.checkTarget();
        if (this.complete())
            this.finished = performance.now();
        else if (this.stopping && this.inFlight === 0)
            this.stop();
    }

    /* At each even number of steps that every pixel has, the estimate from the halves; the
     * target reached when it is at most the target. */
    checkTarget() {
        const steps = Math.min.apply(null, this.added);
        if (steps < 2 || steps % 2 !== 0 || steps === this.estimatedAt) return;
        this.estimatedAt = steps;
        let sum = 0;
        for (let p = 0; p < this.count.length; p++)
            for (let c = 0; c < 3; c++) {
                const a = this.halves[0][3 * p + c] / this.halfCounts[0][p],
                      b = this.halves[1][3 * p + c] / this.halfCounts[1][p], f = (a + b) / 2;
                sum += (a - b) * (a - b) / 4 / (f * f + 0.01);
            }
        this.estimated = Math.sqrt(sum / (3 * this.count.length));
        this.estimates.push(this.estimated);
        if (this.estimated <= this.target)
            this.reached = {seconds: this.seconds, wall: this.wallSeconds(), steps: steps,
                            estimate: this.estimated};
    }

    /* Measure against this reference from now on: {image, mse, relMse} (bench/measure.h). */
    setReference(reference) {
        this.reference = reference;
        this.squared = this.relative = 0;
        for (let i = 0; i < this.mean.length; i++)
            this.addDifference(i, 1);
    }

    /* Add (sign 1) or take out (-1) value i's squared difference from the reference. */
    addDifference(i, sign) {
        const r = this.reference.image[i], d = this.mean[i] - r;
        this.squared += sign * d * d;
        this.relative += sign * d * d / (r * r + 0.01);
    }

    /* Welford's update of each pixel with its value of this step (renderer.c's
     * pixel_sum_add), a value that is not finite being dropped. The sums behind the
     * errors follow each pixel's change, so that measuring costs nothing per pixel. */
    add(result) {
        const values = result.values, first = result.row0 * this.width, reference = this.reference;
        for (let i = 0; i < result.rows * this.width; i++) {
            const r = values[3 * i], g = values[3 * i + 1], b = values[3 * i + 2];
            if (!(isFinite(r) && isFinite(g) && isFinite(b)))
                continue;
            const p = first + i, n = ++this.count[p], half = result.step % 2;
            this.halfCounts[half][p]++;
            for (let c = 0; c < 3; c++)
                this.halves[half][3 * p + c] += values[3 * i + c];
            if (n === 1) this.empty--;
            if (n === 2) this.single--;
            for (let c = 0; c < 3; c++) {
                const k = 3 * p + c, value = values[3 * i + c], delta = value - this.mean[k];
                if (reference) this.addDifference(k, -1);
                if (n > 2) this.variance -= this.m2[k] / (n - 2) / (n - 1);
                this.mean[k] += delta / n;
                this.m2[k] += delta * (value - this.mean[k]);
                if (n > 1) this.variance += this.m2[k] / (n - 1) / n;
                if (reference) this.addDifference(k, 1);
            }
        }
    }

    complete() {
        return !!this.reached || this.added.every(function (step) { return step >= this.steps; }, this);
    }

    /* Steps every pixel has (fractional: the bands ahead count in part). */
    stepsDone() {
        let sum = 0;
        for (let band = 0; band < this.bands; band++)
            sum += this.added[band];
        return sum / this.bands;
    }

    wallSeconds() {
        return ((this.finished || performance.now()) - this.started) / 1000;
    }

    /* The RMS over pixels and channels of each pixel's standard error, sqrt(M2 / (n - 1)
     * / n): what the error of the image is, if its estimator is unbiased. NaN until
     * every pixel has two steps. */
    standardError() {
        return this.single > 0 ? NaN : Math.sqrt(Math.max(0, this.variance) / this.mean.length);
    }

    /* RMSE and relative MSE against the reference: the squared differences less the
     * reference's own variance. NaN until every pixel has a step. */
    referenceError() {
        if (this.empty > 0)
            return {rmse: NaN, relMse: NaN};
        const mse = this.squared / this.mean.length - this.reference.mse;
        return {rmse: mse > 0 ? Math.sqrt(mse) : 0,
                relMse: this.relative / this.mean.length - this.reference.relMse};
    }
}

/* Chapter 10's render: passes, each planned in a worker from every pixel's sums and
 * samples (lab_adaptive_plan), then its bands sampled (lab_adaptive_band), the next plan
 * waiting for the last band. Its tasks are the plan and the bands; the plan says when
 * the render is done (lab.h's rule and target). `mean` is each pixel's value as the rule
 * keeps it, `count` its samples, `estimate` its estimated relative MSE at the last plan. */
class AdaptiveRender extends Render {
    constructor(setup, info, bandRows) {
        super(setup, info, bandRows || Math.max(1, Math.round(TASK_SAMPLES / (8 * info.width))));
        const pixels = this.width * this.height;
        this.sums = new Float64Array(16 * pixels); /* quarter q's r, g, b at 16 p + 3 q, dropped at 16 p + 12 + q */
        this.estimate = new Float64Array(pixels);
        this.toAdd = null;
        this.pass = 0;                             /* passes planned */
        this.passesDone = 0;                       /* passes whose bands are all in */
        this.phase = "plan";                       /* plan, planning, sampling */
        this.bandsSent = this.bandsIn = 0;         /* of the pass being sampled */
        this.active = 0;                           /* pixels the last pass sampled */
    }

    tasksLeft() {
        return !this.error && !this.stopped && !this.stopping && !this.finished &&
               (this.phase === "plan" || (this.phase === "sampling" && this.bandsSent < this.bands));
    }

    nextTask() {
        this.inFlight++;
        if (this.phase === "plan") {
            this.phase = "planning";
            const sums = this.sums.slice(), samples = Int32Array.from(this.count);
            return {type: "plan", pass: this.pass, sums: sums, samples: samples,
                    transfer: [sums.buffer, samples.buffer]};
        }
        const row0 = this.bandsSent++ * this.bandRows, rows = Math.min(this.bandRows, this.height - row0);
        const from = row0 * this.width, to = from + rows * this.width;
        this.issued++;
        const sums = this.sums.slice(16 * from, 16 * to), samples = Int32Array.from(this.count.subarray(from, to)),
              toAdd = this.toAdd.slice(from, to);
        return {type: "adaptive", row0: row0, rows: rows, sums: sums, samples: samples, toAdd: toAdd,
                transfer: [sums.buffer, samples.buffer, toAdd.buffer]};
    }

    accept(result) {
        this.inFlight--;
        if (this.finished) return;
        this.seconds += result.seconds;
        this.longest = Math.max(this.longest, result.seconds);
        for (let k = 0; k < 4; k++)
            this.rays[k] += result.rays[k];
        if (result.type === "plan") {
            this.estimate = result.estimate;
            this.toAdd = result.toAdd;
            if (result.pass > 0) { /* the first plan has no samples to estimate from */
                this.estimated = result.error;
                this.estimates.push(result.error);
            }
            if (result.active > 0) this.active = result.active;
            this.pass++;
            this.phase = "sampling";
            this.bandsSent = this.bandsIn = 0;
            if (result.active === 0) {
                if (result.pass > 0 && result.error <= this.target)
                    this.reached = {seconds: this.seconds, wall: this.wallSeconds(),
                                    steps: this.meanSamples(), estimate: result.error};
                this.finished = performance.now();
            }
        } else {
            this.take(result);
            if (++this.bandsIn === this.bands) {
                this.phase = "plan";
                this.passesDone++;
            }
        }
        if (this.stopping && this.inFlight === 0)
            this.stop();
    }

    /* A band's new sums, samples and values, the errors' sums following each pixel. */
    take(result) {
        const first = result.row0 * this.width, reference = this.reference;
        this.sums.set(result.sums, 16 * first);
        for (let i = 0; i < result.rows * this.width; i++) {
            const p = first + i;
            if (this.count[p] === 0 && result.samples[i] > 0) this.empty--;
            this.count[p] = result.samples[i];
            for (let c = 0; c < 3; c++) {
                if (reference) this.addDifference(3 * p + c, -1);
                this.mean[3 * p + c] = result.values[3 * i + c];
                if (reference) this.addDifference(3 * p + c, 1);
            }
        }
        this.dirty.add(result.row0 / this.bandRows);
    }

    complete() { return !!this.finished; }

    stepsDone() { return this.passesDone; }

    meanSamples() {
        let sum = 0;
        for (let p = 0; p < this.count.length; p++) sum += this.count[p];
        return sum / this.count.length;
    }

    /* Its estimate, which the rule's samples are spread by, stands for the standard error. */
    standardError() { return this.estimated; }
}

class Pool {
    /* onResult(render): called after each band is added; onError(render, text). */
    constructor(count, onResult, onError) {
        this.workers = [];
        this.renders = [];
        this.mode = "samples";
        this.jitter = 0; /* ms: a test delays each result by up to this, at random */
        this.onResult = onResult;
        this.onError = onError;
        this.setWorkers(count);
    }

    /* Start `count` workers afresh: the renders running are to be started again. */
    setWorkers(count) {
        for (const slot of this.workers)
            slot.worker.terminate();
        this.workers = [];
        this.renders = [];
        while (this.workers.length < count) {
            const slot = {worker: newLabWorker(), key: "", render: null};
            slot.worker.onmessage = this.message.bind(this, slot);
            this.workers.push(slot);
        }
        this.schedule();
    }

    /* Render these renders from now on (the others stop: their results are ignored); their
     * time starts now. */
    run(renders) {
        this.renders = renders;
        for (const render of renders)
            render.started = performance.now();
        this.schedule();
    }

    /* The processor time a render has used: its finished tasks' time in the workers, and
     * each task in flight from the moment it was sent. */
    secondsUsed(render) {
        const now = performance.now();
        let seconds = render.seconds;
        for (const slot of this.workers)
            if (slot.render === render)
                seconds += (now - slot.sent) / 1000;
        return seconds;
    }

    /* The render that gets the next task: at equal samples the one behind in steps, at
     * equal time the one that has used less processor time (secondsUsed). At equal time
     * a render that has used its budget (what the other took to finish) takes no more. */
    choose() {
        let best = null, bestScore = Infinity;
        for (const render of this.renders) {
            if (!render.tasksLeft())
                continue;
            const score = this.mode === "time" ? this.secondsUsed(render) : render.issued / render.bands;
            if (this.mode === "time" && score >= render.budget) {
                render.stopAfterTasksInFlight();
                continue;
            }
            if (score < bestScore)
                best = render, bestScore = score;
        }
        return best;
    }

    schedule() {
        for (const slot of this.workers) {
            if (slot.render)
                continue;
            const render = this.choose();
            if (!render)
                return;
            const task = render.nextTask();
            task.type = task.type || "band";
            task.job = render.setup.key;
            if (task.type === "band")
                task.buffer = render.spare.pop() || null; /* filled and sent back: less garbage */
            const transfer = task.transfer || (task.buffer ? [task.buffer] : []);
            delete task.transfer;
            if (slot.key !== render.setup.key) {
                task.setup = render.setup;
                slot.key = render.setup.key;
            }
            slot.render = render;
            slot.sent = performance.now();
            slot.worker.postMessage(task, transfer);
        }
    }

    message(slot, event) {
        const message = event.data, render = slot.render;
        slot.render = null;
        if (this.jitter > 0 && message.type === "band") /* a test's: results out of order */
            setTimeout(this.deliver.bind(this, render, message), Math.random() * this.jitter);
        else
            this.deliver(render, message);
        if (message.type === "error")
            slot.key = "";
        this.schedule();
    }

    deliver(render, message) {
        if (render && !render.stopped && this.renders.indexOf(render) >= 0 &&
            message.job === render.setup.key) {
            if (message.type !== "error") {
                render.accept(message);
                if (render.finished && !render.stopped && this.mode === "time") /* its time is the budget */
                    for (const other of this.renders)
                        if (!other.finished)
                            other.budget = Math.min(other.budget, render.seconds);
                this.onResult(render);
            } else {
                render.error = message.message;
                this.onError(render, message.message);
            }
        }
    }
}

/* One more worker, for the page's questions: a scene and its settings checked, a plan,
 * paths recorded. Answers come as promises. */
class Helper {
    constructor() {
        this.worker = newLabWorker();
        this.pending = new Map();
        this.next = 1;
        this.worker.onmessage = (event) => {
            const message = event.data, waiting = this.pending.get(message.id);
            this.pending.delete(message.id);
            if (message.type === "error")
                waiting.reject(new Error(message.message));
            else
                waiting.resolve(message);
        };
    }

    ask(type, setup, fields) {
        const id = this.next++;
        const message = Object.assign({type: type, id: id, setup: setup}, fields || {});
        return new Promise((resolve, reject) => {
            this.pending.set(id, {resolve: resolve, reject: reject});
            this.worker.postMessage(message);
        });
    }
}
