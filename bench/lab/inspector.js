/* inspector.js (bench, chapter 8): the path inspector: the paths a pixel's samples took,
 * drawn over the image and on a plan of the scene, and stepped through vertex by vertex.
 *
 * The paths are recorded by the WebAssembly module (bench/lab/record.h) as a list of
 * notes in the order the estimator made them: a "ray" opens a vertex (where it hit, or
 * nothing), and the notes after it belong to that vertex: its shadow rays, the light
 * samples and direct light added, the photon map's caustic, roulette, the bounce with
 * its pdf and weight and the throughput after it, the MIS weight of emission hit. The
 * record's end gives the emission the last vertex added, and whether the notes account
 * for the whole radiance the estimator returned.
 */
"use strict";

const PATH_COLOURS = ["#ff4040", "#40c0ff", "#ffd000", "#60ff60", "#ff60ff", "#ff9020", "#a0a0ff", "#ffffff"];

/* A recorded sample as vertices: {ray, hit, notes: {shadows, lights, segments, direct,
 * caustic, roulette, bounce, mis}}. */
function pathVertices(path) {
    const vertices = [];
    for (const note of path.events) {
        if (note.e === "ray") {
            vertices.push({ray: note, hit: note.hit, shadows: [], lights: [], segments: []});
            continue;
        }
        const vertex = vertices[vertices.length - 1];
        if (note.e === "shadow") vertex.shadows.push(note);
        else if (note.e === "light") vertex.lights.push(note);
        else if (note.e === "segment") vertex.segments.push(note);
        else vertex[note.e === "mis" ? "mis" : note.e] = note;
    }
    return vertices;
}

function add3(a, b, s) { return [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]]; }
function sub3(a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; }
function dot3(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
function cross3(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }

function number(x, digits) {
    if (x === null || x === undefined) return "\u2013";
    if (x === 0) return "0";
    const magnitude = Math.abs(x);
    return magnitude >= 1e4 || magnitude < 1e-3 ? x.toExponential(digits - 1) : x.toPrecision(digits);
}

function colour3(v) {
    return v ? "(" + v.map(function (x) { return number(x, 3); }).join(", ") + ")" : "\u2013";
}

class Inspector {
    /* plan: lab_scene's JSON; elements: {overlay, plan, table, detail, summary}. */
    constructor(elements) {
        this.elements = elements;
        this.record = null;
        this.plan = null;
        this.path = 0;
        this.vertex = 0;
    }

    show(record, plan, width, height) {
        this.record = record;
        this.plan = plan;
        this.width = width;
        this.height = height;
        this.paths = record.paths.map(function (p) { return pathVertices(p.path); });
        this.path = 0;
        this.vertex = this.paths[0].length - 1;
        this.draw();
    }

    clear() {
        this.record = null;
        const overlay = this.elements.overlay;
        overlay.getContext("2d").clearRect(0, 0, overlay.width, overlay.height);
    }

    setPath(index) {
        if (!this.record) return;
        this.path = (index + this.paths.length) % this.paths.length;
        this.vertex = this.paths[this.path].length - 1;
        this.draw();
    }

    step(by) {
        if (!this.record) return;
        const last = this.paths[this.path].length - 1;
        this.vertex = Math.max(0, Math.min(last, this.vertex + by));
        this.draw();
    }

    /* Where world point p is seen, in pixels (camera.h), or null behind the eye. */
    project(p) {
        const c = this.plan.camera, normal = cross3(c.right, c.up), to = sub3(p, c.eye);
        const along = dot3(to, normal);
        const t = dot3(sub3(c.bottom_left, c.eye), normal) / along;
        if (!(t > 0)) return null;
        const q = sub3(add3(c.eye, to, t), c.bottom_left);
        return [dot3(q, c.right) / dot3(c.right, c.right) * this.width,
                (1 - dot3(q, c.up) / dot3(c.up, c.up)) * this.height];
    }

    /* The segment a..b as seen, cut where it passes behind the eye. */
    projectSegment(a, b) {
        const c = this.plan.camera, normal = cross3(c.right, c.up);
        const ahead = dot3(sub3(c.bottom_left, c.eye), normal) > 0 ? 1 : -1;
        const da = ahead * dot3(sub3(a, c.eye), normal), db = ahead * dot3(sub3(b, c.eye), normal);
        const near = 1e-3 * Math.abs(dot3(sub3(c.bottom_left, c.eye), normal));
        if (da < near && db < near) return null;
        if (da < near) a = add3(a, sub3(b, a), (near - da) / (db - da));
        if (db < near) b = add3(a, sub3(b, a), (near - da) / (db - da));
        const pa = this.project(a), pb = this.project(b);
        return pa && pb ? [pa, pb] : null;
    }

    /* The rays' segments of a path up to vertex `last`: [from, to, vertex index]. */
    segments(vertices, last) {
        const far = this.sceneSize() * 4, list = [];
        vertices.forEach(function (v, i) {
            if (i > last) return;
            const end = v.hit ? v.hit.p : add3(v.ray.o, v.ray.d, far);
            list.push([v.ray.o, end, i]);
        });
        return list;
    }

    sceneSize() {
        if (!this.size) {
            let size = 1;
            for (const t of this.plan.triangles)
                for (let k = 0; k < 3; k++)
                    size = Math.max(size, Math.abs(t[k][0]), Math.abs(t[k][1]), Math.abs(t[k][2]));
            this.size = size;
        }
        return this.size;
    }

    draw() {
        this.size = 0;
        this.drawOverlay();
        this.drawPlan();
        this.writeTable();
    }

    drawOverlay() {
        const canvas = this.elements.overlay, context = canvas.getContext("2d");
        context.clearRect(0, 0, canvas.width, canvas.height);
        if (!this.record) return;
        const scale = canvas.width / this.width;
        const line = (a, b, colour, width, dash) => {
            const s = this.projectSegment(a, b);
            if (!s) return;
            context.setLineDash(dash || []);
            context.strokeStyle = colour;
            context.lineWidth = width;
            context.beginPath();
            context.moveTo(s[0][0] * scale, s[0][1] * scale);
            context.lineTo(s[1][0] * scale, s[1][1] * scale);
            context.stroke();
        };
        this.paths.forEach((vertices, index) => {
            const selected = index === this.path;
            const last = selected ? this.vertex : vertices.length - 1;
            const colour = PATH_COLOURS[index % PATH_COLOURS.length];
            for (const s of this.segments(vertices, last))
                if (s[2] > 0 || !selected) /* the camera ray is a point in the image */
                    line(s[0], s[1], colour, selected ? 2.5 : 1, selected ? [] : [3, 3]);
            if (selected) {
                const v = vertices[last];
                for (const shadow of v.shadows)
                    line(shadow.from, shadow.to, shadow.blocked ? "#ff2020" : "#20ff20", 1.5, [4, 3]);
                if (v.hit) {
                    const p = this.project(v.hit.p);
                    if (p) {
                        context.setLineDash([]);
                        context.strokeStyle = "#fff";
                        context.lineWidth = 2;
                        context.beginPath();
                        context.arc(p[0] * scale, p[1] * scale, 5, 0, 2 * Math.PI);
                        context.stroke();
                    }
                }
            }
        });
        const pixel = [this.record.col + 0.5, this.record.row + 0.5];
        context.setLineDash([]);
        context.strokeStyle = "#fff";
        context.lineWidth = 1;
        context.strokeRect(pixel[0] * scale - 4, pixel[1] * scale - 4, 8, 8);
    }

    /* The plan: the scene seen from above (x forward up the page, y to the left). */
    drawPlan() {
        const canvas = this.elements.plan, context = canvas.getContext("2d");
        const plan = this.plan;
        context.fillStyle = "#111";
        context.fillRect(0, 0, canvas.width, canvas.height);
        if (!plan) return;
        let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
        const extend = function (p) {
            x0 = Math.min(x0, p[0]); x1 = Math.max(x1, p[0]); y0 = Math.min(y0, p[1]); y1 = Math.max(y1, p[1]);
        };
        plan.triangles.forEach(function (t) { extend(t[0]); extend(t[1]); extend(t[2]); });
        plan.spheres.forEach(function (s) { extend(add3(s[0], [1, 1, 0], s[1])); extend(add3(s[0], [-1, -1, 0], s[1])); });
        extend(plan.camera.eye);
        const margin = 12, scale = Math.min((canvas.width - 2 * margin) / Math.max(y1 - y0, 1e-9),
                                            (canvas.height - 2 * margin) / Math.max(x1 - x0, 1e-9));
        const at = function (p) {
            return [canvas.width / 2 - (p[1] - (y0 + y1) / 2) * scale,
                    canvas.height / 2 - (p[0] - (x0 + x1) / 2) * scale];
        };
        const segment = function (a, b, colour, width, dash) {
            const pa = at(a), pb = at(b);
            context.setLineDash(dash || []);
            context.strokeStyle = colour;
            context.lineWidth = width;
            context.beginPath();
            context.moveTo(pa[0], pa[1]);
            context.lineTo(pb[0], pb[1]);
            context.stroke();
        };
        for (const t of plan.triangles) {
            const m = plan.materials[t[3]];
            const normal = cross3(sub3(t[1], t[0]), sub3(t[2], t[0]));
            const flat = Math.abs(normal[2]) > 0.9 * Math.sqrt(dot3(normal, normal));
            if (m.kind === "light") {
                context.fillStyle = "#ffe070";
                context.beginPath();
                [t[0], t[1], t[2]].forEach(function (p, i) {
                    const q = at(p);
                    if (i === 0) context.moveTo(q[0], q[1]); else context.lineTo(q[0], q[1]);
                });
                context.fill();
            } else if (!flat) {
                const colour = m.kind === "mirror" ? "#c0c0ff" : "rgb(" + m.reflectance.map(function (x) {
                    return Math.round(80 + 175 * Math.min(1, x));
                }).join(",") + ")";
                segment(t[0], t[1], colour, 1);
                segment(t[1], t[2], colour, 1);
                segment(t[2], t[0], colour, 1);
            }
        }
        for (const s of plan.spheres) {
            const c = at(s[0]);
            context.setLineDash([]);
            context.strokeStyle = plan.materials[s[2]].kind === "glass" ? "#80e0ff" : "#c0c0ff";
            context.lineWidth = 1.5;
            context.beginPath();
            context.arc(c[0], c[1], s[1] * scale, 0, 2 * Math.PI);
            context.stroke();
        }
        const camera = plan.camera;
        for (const corner of [camera.bottom_left, add3(camera.bottom_left, camera.right, 1)])
            segment(camera.eye, corner, "#888", 1, [2, 2]);
        if (!this.record) return;
        this.paths.forEach((vertices, index) => {
            const selected = index === this.path;
            const last = selected ? this.vertex : vertices.length - 1;
            const colour = PATH_COLOURS[index % PATH_COLOURS.length];
            for (const s of this.segments(vertices, last))
                segment(s[0], s[1], colour, selected ? 2.5 : 1, selected ? [] : [3, 3]);
            if (selected) {
                const v = vertices[last];
                for (const shadow of v.shadows)
                    segment(shadow.from, shadow.to, shadow.blocked ? "#ff2020" : "#20ff20", 1.5, [4, 3]);
                for (const piece of v.segments)
                    segment(piece.o, add3(piece.o, piece.d, piece.t), "#20ff20", 1, [1, 2]);
                if (v.hit) {
                    const p = at(v.hit.p);
                    context.setLineDash([]);
                    context.strokeStyle = "#fff";
                    context.beginPath();
                    context.arc(p[0], p[1], 5, 0, 2 * Math.PI);
                    context.stroke();
                }
            }
        });
    }

    /* One row per vertex of the selected path; the current one marked, its notes in full
     * below the table. */
    writeTable() {
        const table = this.elements.table, detail = this.elements.detail, summary = this.elements.summary;
        table.textContent = "";
        detail.textContent = "";
        summary.textContent = "";
        if (!this.record) return;
        const record = this.record.paths[this.path], vertices = this.paths[this.path];
        const path = record.path, plan = this.plan;
        summary.textContent = "pixel (" + this.record.col + ", " + this.record.row + "), sample " +
            record.sample + " (path " + (this.path + 1) + " of " + this.paths.length + "): " +
            vertices.length + " rays, radiance " + colour3(path.radiance) +
            (path.accounted === null ? "" : path.accounted
                ? "; the notes account for all of it"
                : "; THE NOTES DO NOT ACCOUNT FOR IT (a call the recorder does not see)");
        const head = table.insertRow();
        ["#", "surface", "bounce (pdf)", "throughput after", "shadow rays", "direct light added",
         "roulette", "emission added (MIS weight)"].forEach(function (text) {
            const cell = document.createElement("th");
            cell.textContent = text;
            head.appendChild(cell);
        });
        vertices.forEach((v, i) => {
            const row = table.insertRow();
            if (i === this.vertex) row.className = "current";
            row.onclick = () => { this.vertex = i; this.draw(); };
            const m = v.hit ? plan.materials[v.hit.m] : null;
            const reached = v.shadows.filter(function (s) { return !s.blocked; }).length;
            const last = i === vertices.length - 1;
            const emission = last && path.emission
                ? colour3(path.emission.added) + " (" + number(path.emission.weight, 3) + ")"
                : v.mis ? "(" + number(v.mis.weight, 3) + ")" : "";
            const cells = [
                String(i),
                m ? m.name + " (" + m.kind + (v.hit.front ? "" : ", back") + ")" : "nothing: the path leaves",
                v.bounce ? v.bounce.kind + " (" + (v.bounce.pdf === null ? "\u03b4" : number(v.bounce.pdf, 3)) + ")" : "",
                v.bounce ? colour3(v.bounce.throughput) : v.roulette ? colour3(v.roulette.throughput) : "",
                v.shadows.length ? reached + " reach, " + (v.shadows.length - reached) + " blocked" : "",
                v.direct ? colour3(v.direct.added) : "",
                v.roulette ? (v.roulette.survived ? "survives" : "ends") + " (q " + number(v.roulette.q, 3) + ")" : "",
                emission];
            if (v.caustic) cells[5] += (cells[5] ? " + " : "") + "caustic " + colour3(v.caustic.added);
            cells.forEach(function (text) { row.insertCell().textContent = text; });
        });
        const v = vertices[this.vertex];
        const lines = ["vertex " + this.vertex + ": ray from " + colour3(v.ray.o) + " along " + colour3(v.ray.d) +
                       (v.hit ? ", hits at " + colour3(v.hit.p) + " (t " + number(v.hit.t, 4) + ")" : ", hits nothing")];
        v.shadows.forEach(function (s, k) {
            lines.push("  shadow ray " + (k + 1) + " to " + colour3(s.to) + ": " + (s.blocked ? "blocked" : "reaches the light"));
        });
        v.lights.forEach(function (l, k) {
            lines.push("  light sample " + (k + 1) + " (" + (l.via === "mirror" ? "the lamp's image in a mirror" : "the lamp") +
                       "): pdf " + number(l.pdf, 4) + ", value " + colour3(l.value));
        });
        if (v.direct) lines.push("  direct light " + colour3(v.direct.value) + " x throughput = " + colour3(v.direct.added));
        if (v.caustic) lines.push("  photon map: " + colour3(v.caustic.value) + " x throughput = " + colour3(v.caustic.added));
        if (v.roulette) lines.push("  roulette: survival probability " + number(v.roulette.q, 4) + ", " +
                                   (v.roulette.survived ? "survives, throughput divided by it: " + colour3(v.roulette.throughput) : "the path ends"));
        if (v.bounce) lines.push("  bounce: " + v.bounce.kind + ", pdf " + (v.bounce.pdf === null ? "\u03b4 (specular)" : number(v.bounce.pdf, 4)) +
                                 ", weight f cos/pdf " + colour3(v.bounce.weight) + ", throughput " + colour3(v.bounce.throughput));
        if (v.mis) lines.push("  MIS weight of the emission hit: " + number(v.mis.weight, 4) + " (the bounce's pdf " + number(v.mis.bsdf_pdf, 4) + ")");
        if (this.vertex === vertices.length - 1 && path.emission)
            lines.push("  emission Le " + colour3(path.emission.le) + " x throughput x weight " +
                       number(path.emission.weight, 4) + " = " + colour3(path.emission.added));
        detail.textContent = lines.join("\n");
    }
}
