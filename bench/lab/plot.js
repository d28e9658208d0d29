/* plot.js (bench, chapter 8): the lab's log-log plot of error against time, drawn on a
 * canvas by the page itself.
 *
 * An unbiased estimator's error falls as 1/sqrt(t): a line of slope -1/2 on log-log
 * axes. The plot draws that slope through the last point of the first series, so an
 * estimator that follows it runs parallel, one with a bias flattens out, and one with
 * infinite variance (roulette with alpha below rho^2) wanders above it.
 */
"use strict";

/* Powers of ten (with 2 and 5 between them when the range spans less than two decades)
 * from lo to hi. */
function logTicks(lo, hi) {
    const ticks = [], fine = Math.log10(hi / lo) < 2;
    for (let e = Math.floor(Math.log10(lo)); e <= Math.ceil(Math.log10(hi)); e++)
        for (const m of fine ? [1, 2, 5] : [1]) {
            const v = m * Math.pow(10, e);
            if (v >= lo * 0.999 && v <= hi * 1.001)
                ticks.push(v);
        }
    return ticks;
}

function tickLabel(v) {
    return v >= 0.01 && v < 1e4 ? String(Number(v.toPrecision(2))) : v.toExponential(0);
}

/* series: [{label, colour, points: [[x, y], ...]}]; labels: {x, y}. */
function drawLogLogPlot(canvas, series, labels) {
    const context = canvas.getContext("2d"), width = canvas.width, height = canvas.height;
    const left = 58, right = 12, top = 12, bottom = 40;
    context.clearRect(0, 0, width, height);
    context.fillStyle = "#fff";
    context.fillRect(0, 0, width, height);
    const points = [].concat.apply([], series.map(function (s) { return s.points; }))
        .filter(function (p) { return p[0] > 0 && p[1] > 0 && isFinite(p[0]) && isFinite(p[1]); });
    context.fillStyle = "#444";
    context.font = "12px sans-serif";
    if (points.length < 2) {
        context.fillText("error against time: waiting for errors to plot", left, top + 20);
        return;
    }
    let x0 = Infinity, x1 = 0, y0 = Infinity, y1 = 0;
    for (const p of points) {
        x0 = Math.min(x0, p[0]); x1 = Math.max(x1, p[0]);
        y0 = Math.min(y0, p[1]); y1 = Math.max(y1, p[1]);
    }
    x0 /= 1.5; x1 *= 1.5; y0 /= 1.5; y1 *= 1.5;
    const px = function (x) { return left + (width - left - right) * Math.log(x / x0) / Math.log(x1 / x0); };
    const py = function (y) { return height - bottom - (height - top - bottom) * Math.log(y / y0) / Math.log(y1 / y0); };

    context.strokeStyle = "#ddd";
    context.lineWidth = 1;
    context.textAlign = "center";
    for (const t of logTicks(x0, x1)) {
        context.beginPath(); context.moveTo(px(t), top); context.lineTo(px(t), height - bottom); context.stroke();
        context.fillText(tickLabel(t), px(t), height - bottom + 14);
    }
    context.textAlign = "right";
    for (const t of logTicks(y0, y1)) {
        context.beginPath(); context.moveTo(left, py(t)); context.lineTo(width - right, py(t)); context.stroke();
        context.fillText(tickLabel(t), left - 4, py(t) + 4);
    }
    context.strokeStyle = "#888";
    context.strokeRect(left, top, width - left - right, height - top - bottom);
    context.textAlign = "center";
    context.fillText(labels.x, left + (width - left - right) / 2, height - 6);
    context.save();
    context.translate(12, top + (height - top - bottom) / 2);
    context.rotate(-Math.PI / 2);
    context.fillText(labels.y, 0, 0);
    context.restore();

    const anchor = series.map(function (s) { return s.points[s.points.length - 1]; })
        .filter(function (p) { return p && p[0] > 0 && p[1] > 0; })[0];
    context.save();
    context.beginPath();
    context.rect(left, top, width - left - right, height - top - bottom);
    context.clip();
    if (anchor) { /* the slope -1/2 through it */
        context.setLineDash([6, 4]);
        context.strokeStyle = "#999";
        context.lineWidth = 1;
        context.beginPath();
        context.moveTo(px(x0), py(anchor[1] * Math.sqrt(anchor[0] / x0)));
        context.lineTo(px(x1), py(anchor[1] * Math.sqrt(anchor[0] / x1)));
        context.stroke();
        context.setLineDash([]);
        context.fillStyle = "#444";
        context.textAlign = "left";
        context.fillText("dashed: slope 1/\u221at", left + 6, top + 14);
    }
    series.forEach(function (s) {
        context.strokeStyle = s.colour;
        context.lineWidth = 2;
        context.beginPath();
        s.points.filter(function (p) { return p[0] > 0 && p[1] > 0 && isFinite(p[1]); })
            .forEach(function (p, i) {
                if (i === 0) context.moveTo(px(p[0]), py(p[1])); else context.lineTo(px(p[0]), py(p[1]));
            });
        context.stroke();
    });
    context.restore();
    context.textAlign = "right";
    series.forEach(function (s, index) {
        context.fillStyle = s.colour;
        context.fillText(s.label, width - right - 6, top + 16 + 16 * index);
    });
}
