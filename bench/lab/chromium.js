/* chromium.js (bench, chapter 8): headless Chromium driven through the DevTools protocol,
 * for the lab's browser test and benchmark (node, no package needed).
 *
 * Chromium is started with --remote-debugging-pipe: commands go to its file descriptor 3
 * and answers come from 4, each a JSON message ended by a NUL byte. One page is opened
 * and attached to; whatever it writes to its console as an error or a warning, any
 * exception it does not catch and any resource that fails to load are collected in
 * `problems`. The flags are the gallery test's (bench/browser_gallery.sh), with a fresh
 * profile folder that is removed at the end.
 */
"use strict";

const childProcess = require("child_process");
const fs = require("fs");
const os = require("os");
const path = require("path");

class Chromium {
    static async open(width, height) {
        const browser = new Chromium();
        await browser.start(width, height);
        return browser;
    }

    async start(width, height) {
        this.profile = fs.mkdtempSync(path.join(os.tmpdir(), "lab-chromium-"));
        this.process = childProcess.spawn("chromium", [
            "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
            "--disable-background-networking", "--disable-component-update", "--disable-sync",
            "--disable-dev-shm-usage", "--user-data-dir=" + this.profile, "--hide-scrollbars",
            "--remote-debugging-pipe", "about:blank"], {stdio: ["ignore", "ignore", "pipe", "pipe", "pipe"]});
        this.log = "";
        this.process.stderr.on("data", (data) => { this.log += data; });
        this.next = 1;
        this.waiting = new Map();
        this.listeners = [];
        this.problems = [];
        let buffer = "";
        this.process.stdio[4].on("data", (data) => {
            buffer += data.toString("utf8");
            for (let end; (end = buffer.indexOf("\0")) >= 0; buffer = buffer.slice(end + 1))
                this.receive(JSON.parse(buffer.slice(0, end)));
        });
        this.exited = new Promise((resolve) => this.process.on("exit", resolve));
        const target = await this.send("Target.createTarget", {url: "about:blank"});
        const attached = await this.send("Target.attachToTarget", {targetId: target.targetId, flatten: true});
        this.session = attached.sessionId;
        this.on("Runtime.consoleAPICalled", (p) => {
            if (p.type === "error" || p.type === "warning" || p.type === "assert")
                this.problems.push("console." + p.type + ": " +
                                   p.args.map((a) => a.value !== undefined ? a.value : a.description).join(" "));
        });
        this.on("Runtime.exceptionThrown", (p) => {
            const d = p.exceptionDetails;
            this.problems.push("exception: " + (d.exception && d.exception.description || d.text));
        });
        this.on("Log.entryAdded", (p) => {
            if (p.entry.level === "error" || p.entry.level === "warning")
                this.problems.push("log " + p.entry.level + ": " + p.entry.text + (p.entry.url ? " (" + p.entry.url + ")" : ""));
        });
        for (const domain of ["Runtime", "Log", "Page"])
            await this.command(domain + ".enable");
        await this.command("Emulation.setDeviceMetricsOverride",
                           {width: width, height: height, deviceScaleFactor: 1, mobile: false});
    }

    receive(message) {
        if (message.id && this.waiting.has(message.id)) {
            const waiting = this.waiting.get(message.id);
            this.waiting.delete(message.id);
            if (message.error)
                waiting.reject(new Error(waiting.method + ": " + message.error.message));
            else
                waiting.resolve(message.result);
        } else if (message.method) {
            for (const listener of this.listeners)
                if (listener.method === message.method)
                    listener.handle(message.params);
        }
    }

    send(method, params, session) {
        const id = this.next++;
        const message = {id: id, method: method, params: params || {}};
        if (session)
            message.sessionId = session;
        return new Promise((resolve, reject) => {
            this.waiting.set(id, {resolve: resolve, reject: reject, method: method});
            this.process.stdio[3].write(JSON.stringify(message) + "\0");
        });
    }

    /* A command to the page. */
    command(method, params) {
        return this.send(method, params, this.session);
    }

    on(method, handle) {
        this.listeners.push({method: method, handle: handle});
    }

    /* Open url afresh (a page loaded again, not only a fragment changed) and wait until
     * it has loaded (at most `seconds`). */
    async navigate(url, seconds) {
        await this.command("Page.navigate", {url: "about:blank"});
        await this.until("location.href === 'about:blank' && document.readyState === 'complete'", seconds, "about:blank");
        await this.command("Page.navigate", {url: url});
        await this.until("location.href === " + JSON.stringify(url) + " && document.readyState === 'complete'",
                         seconds, "loading " + url);
    }

    /* The value of a JavaScript expression in the page; a promise is waited for. */
    async evaluate(expression, seconds) {
        const result = await withTimeout(this.command("Runtime.evaluate",
            {expression: expression, awaitPromise: true, returnByValue: true}),
            seconds || 120, expression.slice(0, 60));
        if (result.exceptionDetails)
            throw new Error(expression.slice(0, 60) + ": " +
                            (result.exceptionDetails.exception && result.exceptionDetails.exception.description ||
                             result.exceptionDetails.text));
        return result.result.value;
    }

    /* Evaluate `expression` every 100 ms until it is true (at most `seconds`). */
    async until(expression, seconds, what) {
        const end = Date.now() + 1000 * seconds;
        for (;;) {
            if (await this.evaluate(expression))
                return;
            if (Date.now() > end)
                throw new Error("timed out after " + seconds + " s waiting for " + what);
            await new Promise((resolve) => setTimeout(resolve, 100));
        }
    }

    async click(x, y) {
        for (const type of ["mousePressed", "mouseReleased"])
            await this.command("Input.dispatchMouseEvent", {type: type, x: x, y: y, button: "left", clickCount: 1});
    }

    async screenshot(file) {
        const shot = await this.command("Page.captureScreenshot", {format: "png", captureBeyondViewport: false});
        fs.writeFileSync(file, Buffer.from(shot.data, "base64"));
    }

    async close() {
        try {
            await withTimeout(this.send("Browser.close"), 10, "closing Chromium");
        } catch (error) {
            this.process.kill("SIGKILL");
        }
        await withTimeout(this.exited, 10, "Chromium's exit").catch(() => this.process.kill("SIGKILL"));
        fs.rmSync(this.profile, {recursive: true, force: true});
    }
}

function withTimeout(promise, seconds, what) {
    let timer;
    const timeout = new Promise((resolve, reject) => {
        timer = setTimeout(() => reject(new Error("timed out after " + seconds + " s: " + what)), 1000 * seconds);
    });
    return Promise.race([promise, timeout]).finally(() => clearTimeout(timer));
}

/* A file:// URL of a local path. */
function fileUrl(file) {
    return "file://" + path.resolve(file).split("/").map(encodeURIComponent).join("/");
}

module.exports = {Chromium: Chromium, fileUrl: fileUrl};
