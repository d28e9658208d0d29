/* browser_address.js (bench, chapter 8): the lab's address, controls and limits tested in
 * headless Chromium (part of make lab-test, run by browser_lab.js).
 *
 * Every key of the address is checked by the C code (lab.h's lab_fragment): here, that
 * each shared key says what the chapter programs' command line says of the same value
 * (bench/cli.c, run natively), that every whole-number setting takes its minimum and
 * maximum and refuses one past either, that hostile addresses are shown as a message
 * and render nothing (or are clamped, with a note), that later changes and history
 * navigation are followed, the inspector's and the editor's limits, equal time measured
 * with the tasks in flight, and the link to the book.
 */
"use strict";

const childProcess = require("child_process");
const fs = require("fs");
const path = require("path");

/* The keys the lab shares with the command line: the flag, and each one's range in words
 * (docs/lab.md's, and cli.c's) where it says one. */
const SHARED = [
    {key: "size", flag: "--size", lab: "a whole number from 1 to 4096", cli: "a whole number from 8 to 16384", min: 1, max: 4096},
    {key: "spp", flag: "--spp", lab: "a whole number from 1 to 1048576", cli: "a whole number from 1 to 1048576", min: 1, max: 1048576},
    {key: "depth", flag: "--depth", lab: "a whole number from 1 to 1000", cli: "a whole number from 1 to 1000", min: 1, max: 1000},
    {key: "M", flag: "--shadow-rays", lab: "a whole number from 0 to 1000", cli: "a whole number from 0 to 65536", min: 0, max: 1000},
    {key: "rr", flag: "--rr", lab: "a number in (0, 1] or 'bounded'", cli: "a number in (0, 1]", min: 0, max: 1, open: true, word: "bounded"},
    {key: "seed", flag: "--seed"},
    {key: "fresnel", flag: "--fresnel"},
];

/* Values a hostile address might carry: signs, leading zeros, hexadecimal, white space,
 * NaN and infinity, negative zero, unicode digits, beyond a double, 2^64, separators. */
const VALUES = ["", " 16", "16 ", "1\t6", "0x10", "nan", "NaN", "inf", "Infinity", "-inf", "1e400", "1e-400",
                "2.5", "+16", "016", "-0", "\uff11\uff16", "1e1", "abc", "16chapter=2", "16&chapter=2", "-", ".",
                "0", "1", "-1", "99999999999", "18446744073709551616", "1e23", "+1", "0.5", "1.0", "schlick",
                "exact", "Exact", "bounded", "4096", "4097", "1000", "1001", "20000"];

/* The command line's verdict on each shared key's values: {message} ("" when it takes the
 * value), from `program` (a chapter program taking all of SHARED's flags). */
function commandLine(program) {
    const verdicts = {};
    for (const shared of SHARED)
        for (const value of VALUES) {
            const result = childProcess.spawnSync(program, [shared.flag + "=" + value, "--help"], {encoding: "utf8"});
            const line = result.stderr.split("\n")[0];
            if (result.status !== 0 && result.status !== 2)
                throw new Error(program + " " + shared.flag + "=" + value + ": status " + result.status);
            verdicts[shared.key + "=" + value] = result.status === 0 ? "" : line.slice(line.indexOf(": ") + 2);
        }
    return verdicts;
}

/* lab_fragment's answers to many addresses at once: {state} or {error} each. */
function fragments(browser, list) {
    return browser.evaluate("Promise.all(" + JSON.stringify(list) + ".map(function (f) { return labTest.fragment(f); }))", 120);
}

/* What the lab must say where the command line says `message` of key=value: the same
 * words with the key for the flag and the lab's range for the command line's; or it
 * takes the value where only the command line's range refuses it, and refuses with its
 * range what only its range refuses. */
function expectedOfLab(shared, value, message) {
    if (shared.word && value === shared.word) return "";
    const number = Number(value), inLab = shared.min === undefined ||
        (number >= shared.min && number <= shared.max && !(shared.open && number === shared.min));
    const rangeMessage = shared.key + ": expected " + shared.lab + ", got '" + value + "'";
    if (message === "")
        return inLab ? "" : rangeMessage;
    if (shared.cli && message === shared.flag + ": expected " + shared.cli + ", got '" + value + "'")
        return inLab ? "" : rangeMessage;
    const words = message.replace(shared.flag + ":", shared.key + ":");
    return shared.cli ? words.split(shared.cli).join(shared.lab) : words;
}

async function checkShared(browser, report, verdicts) {
    const list = [];
    for (const shared of SHARED)
        for (const value of VALUES)
            list.push({shared: shared, value: value, fragment: "chapter=7&" + shared.key + "=" + encodeURIComponent(value)});
    const answers = await fragments(browser, list.map(function (c) { return c.fragment; }));
    let same = 0;
    const differ = [];
    list.forEach(function (c, i) {
        const shown = answers[i].error || "", expected = expectedOfLab(c.shared, c.value, verdicts[c.shared.key + "=" + c.value]);
        if (shown === expected) same++;
        else differ.push(c.fragment + ": the lab says '" + shown + "', expected '" + expected + "' (the command line: '" +
                         verdicts[c.shared.key + "=" + c.value] + "')");
    });
    report(differ.length === 0, "the address's keys shared with the command line (" + SHARED.map(function (s) { return s.key; }).join(", ") +
           "), " + list.length + " values: the command line's verdict and words in " + same + (differ.length ? "; " + differ.slice(0, 3).join("; ") : ""));
}

/* Each whole-number key's range (docs/lab.md), and where the address puts it. */
const WHOLE = [
    ["chapter", 1, 10], ["size", 1, 4096], ["depth", 1, 1000], ["spp", 1, 1048576], ["M", 0, 1000], ["mis", 0, 1],
    ["mirror", 0, 1000], ["passes", 1, 1048576], ["photons", 1, 67108864], ["paths", 1, 64], ["workers", 0, 1024],
    ["b.size", 1, 4096], ["b.chapter", 1, 10], ["max", 4, 65536],
];
/* The real ones: the range in words, a value at each end and one past it. */
const REAL = [
    ["guide", "a number in [0, 1000]", ["0", "1000"], ["-0.001", "1000.001"]],
    ["sigma", "a number in [0, 10] or 'scene'", ["0", "10", "scene"], ["-1e-9", "10.000001"]],
    ["rr", "a number in (0, 1] or 'bounded'", ["1e-300", "1", "bounded"], ["0", "1.0000001"]],
    ["alpha", "a number in (0, 1]", ["0.001", "1"], ["0", "1.001"]],
    ["radius", "a number in (0, 1e+50]", ["1e-300", "1e50"], ["0", "1.0001e50"]],
    ["target", "a number in [0, 1]", ["0", "1"], ["-0.001", "1.001"]],
];

async function checkRanges(browser, report) {
    const cases = [];
    const address = function (key, value) {
        return key === "chapter" ? "chapter=" + value : (key === "max" ? "chapter=10&spp=1" : "chapter=8") + "&" + key + "=" + value;
    };
    for (const [key, min, max] of WHOLE) {
        for (const value of [min, max]) cases.push({fragment: address(key, value), expected: ""});
        for (const value of [min - 1, max + 1])
            cases.push({fragment: address(key, value), expected: key + ": expected a whole number from " + min + " to " + max + ", got '" + value + "'"});
    }
    for (const axis of ["COL", "ROW"])
        for (const value of [0, 4095, -1, 4096])
            cases.push({fragment: "pixel=" + (axis === "COL" ? value + ",0" : "0," + value),
                        expected: value < 0 || value > 4095 ? "pixel: expected a whole number from 0 to 4095, got '" + value + "'" : ""});
    for (const [key, words, inside, outside] of REAL) {
        for (const value of inside) cases.push({fragment: address(key, value), expected: ""});
        for (const value of outside) cases.push({fragment: address(key, value), expected: key + ": expected " + words + ", got '" + value + "'"});
    }
    const answers = await fragments(browser, cases.map(function (c) { return c.fragment; }));
    const wrong = cases.filter(function (c, i) { return (answers[i].error || "") !== c.expected; }).map(function (c) {
        const i = cases.indexOf(c);
        return c.fragment + " gives '" + (answers[i].error || "(taken)") + "'";
    });
    report(wrong.length === 0, "every whole-number setting takes its least and greatest value and refuses one past either (" +
           WHOLE.length + " keys and the pixel), the real ones their ends: " + (cases.length - wrong.length) + " of " + cases.length +
           (wrong.length ? "; " + wrong.slice(0, 4).join("; ") : ""));
}

/* Addresses that once killed the page or rendered the wrong thing, each with the message
 * the page must show; null where it renders, with what it must render. */
const HOSTILE = [
    ["chapter=99", "chapter: expected a whole number from 1 to 10, got '99'"],
    ["chapter=2.5", "chapter: '2.5' is not a whole number; expected a whole number from 1 to 10"],
    ["chapter=-1", "chapter: expected a whole number from 1 to 10, got '-1'"],
    ["chapter=2&size=%zz", "settings: 'size=%zz' has a malformed escape: '%' must be followed by two hexadecimal digits, not 00"],
    ["chapter=2&size=16%", "settings: 'size=16%' has a malformed escape: '%' must be followed by two hexadecimal digits, not 00"],
    ["chapter=%00", "settings: 'chapter=%00' has a malformed escape: '%' must be followed by two hexadecimal digits, not 00"],
    ["chapter=7&size=16%20chapter%3D2", "size: '16 chapter=2' has white space in it; expected a whole number from 1 to 4096 alone"],
    ["chapter=7&size=16%26chapter%3D2", "size: '16&chapter=2' is not a decimal number (such as 16, 0.25 or 1e-3); expected a whole number from 1 to 4096"],
    ["scene=toString", "scene: expected one of the page's scenes (oren_nayar.scene, room.scene, room_whitted.scene), got 'toString'"],
    ["b.scene=__proto__", "b.scene: expected one of the page's scenes (oren_nayar.scene, room.scene, room_whitted.scene), got '__proto__'"],
    ["toString=1", "unknown setting 'toString'"],
    ["constructor=1&chapter=2", "unknown setting 'constructor'"],
    ["program=x", "unknown setting 'program'"],
    ["seed=18446744073709551616", "seed: expected a whole number from 0 to 2^64-1, got '18446744073709551616'"],
    ["seed=1e23", "seed: expected a whole number from 0 to 2^64-1, got '1e23'"],
    ["seed=-0", "seed: expected a whole number from 0 to 2^64-1, got '-0'"],
    ["pixel=4294967296,0", "pixel: expected a whole number from 0 to 4095, got '4294967296'"],
    ["pixel=abc", "pixel: expected COL,ROW (two whole numbers), got 'abc'"],
    ["pixel=1,2,3", "pixel: '2,3' is not a decimal number (such as 16, 0.25 or 1e-3); expected a whole number from 0 to 4095"],
    ["paths=0", "paths: expected a whole number from 1 to 64, got '0'"],
    ["paths=4294967297", "paths: expected a whole number from 1 to 64, got '4294967297'"],
    ["size=16&size=32", "settings: 'size' is given twice"],
    ["b.M=3&b.M=4&chapter=3", "settings: 'b.M' is given twice"],
    ["size=", "size: expected a whole number from 1 to 4096, got an empty word"],
    ["size=%EF%BC%91%EF%BC%96", "size: '\uff11\uff16' is not a decimal number (such as 16, 0.25 or 1e-3); expected a whole number from 1 to 4096"],
    ["size=0x10", "size: '0x10' is not a decimal number (such as 16, 0.25 or 1e-3); expected a whole number from 1 to 4096"],
    ["size=1e400", "size: '1e400' is too large for a double (above 1.79769e+308); expected a whole number from 1 to 4096"],
    ["chapter=6&rr=NaN", "rr: 'NaN' is not a decimal number (such as 16, 0.25 or 1e-3); expected a number in (0, 1] or 'bounded'"],
    ["guide=Infinity", "guide: 'Infinity' is not a decimal number (such as 16, 0.25 or 1e-3); expected a number in [0, 1000]"],
    ["chapter=2&M=1", "M: chapter 3 introduces it"],
    ["b.chapter=11", "b.chapter: expected a whole number from 1 to 10, got '11'"],
    ["chapter=9", "chapter: chapter 9 measures speed and has no estimator of its own (every chapter here renders with its four-wide tree)"],
    ["chapter=10&rule=fair", "rule: expected 'biased' or 'unbiased', got 'fair'"],
    ["chapter=10&passes=2", "passes: chapter 8's only"],
    ["chapter=10&sampling=stratified", "sampling: chapter 10's passes take progressive samples"],
    ["chapter=10&spp=64&max=32", "spp: the minimum samples per pixel, 64, is above max, 32"],
    ["chapter=6&target=0.1", "target: chapter 7 introduces it"],
    ["chapter=7&rule=biased", "rule: chapter 10 introduces it"],
    ["workers=abc", "workers: 'abc' is not a decimal number (such as 16, 0.25 or 1e-3); expected a whole number from 0 to 1024"],
    ["layout=three", "layout: expected 'one' or 'two', got 'three'"],
    ["chapter=2&size" , "settings: expected key=value, got 'size'"],
    ["chapter=2&" + "x".repeat(5000) + "=1", "settings: longer than 4096 characters"],
];

/* Addresses the page takes, and what it must then render. */
const TAKEN = [
    {fragment: "chapter=2&size=+16&spp=01&seed=007", settings: {chapter: 2, size: 16, spp: 1, seed: "7"}},
    {fragment: "chapter=3&size=16&spp=1&M=-0&&", settings: {chapter: 3, size: 16, spp: 1, M: 0}},
    {fragment: "chapter=2&size=16&spp=1&workers=0", settings: {chapter: 2}, workers: 1, note: "workers: 0 is fewer than one; using 1"},
    {fragment: "chapter=2&size=16&spp=1&workers=1000", settings: {chapter: 2}, workers: "cores",
     note: "workers: 1000 is more than this browser's cores; using CORES"},
];

async function settled(browser) {
    await browser.until("(function (s) { return s.addressRefused || !s.restarting && s.panels.every(function (p) { " +
                        "return p.complete || (p.error && p.error.indexOf('the address is refused') < 0); }); })(labTest.state())",
                        120, "the page to render or refuse its address");
    return browser.evaluate("labTest.state()");
}

async function checkHostile(browser, report, url) {
    const problems = [];
    for (const [fragment, message] of HOSTILE) {
        await browser.navigate(url + "#" + fragment, 30);
        const state = await settled(browser);
        const expected = "This address is refused: " + message;
        if (state.address !== expected)
            problems.push("#" + fragment.slice(0, 60) + ": '" + state.address + "'" + (state.panels[0].error ? " (" + state.panels[0].error + ")" : ""));
        else if (state.panels.some(function (p) { return p.done > 0 || p.chapter !== null; }))
            problems.push("#" + fragment.slice(0, 60) + ": a panel renders");
    }
    report(problems.length === 0 && browser.problems.length === 0, HOSTILE.length + " hostile addresses, each loaded afresh: " +
           (HOSTILE.length - problems.length) + " show their message and render nothing, with no console message" +
           (problems.length ? "; " + problems.slice(0, 4).join("; ") : "") + (browser.problems.length ? "; " + browser.problems.join("; ") : ""));
    browser.problems.length = 0;
    for (const c of TAKEN) {
        await browser.navigate(url + "#" + c.fragment, 30);
        const state = await settled(browser), cores = await browser.evaluate("Math.max(1, navigator.hardwareConcurrency || 1)");
        const settings = state.panels[0].settings || {};
        const wrong = Object.keys(c.settings).filter(function (k) { return settings[k] !== c.settings[k]; });
        const workers = c.workers === "cores" ? cores : c.workers, note = (c.note || "").replace("CORES", cores);
        report(!state.addressRefused && state.panels[0].complete && wrong.length === 0 && state.address === note &&
               (workers === undefined || state.workers === workers),
               "#" + c.fragment + " renders " + JSON.stringify(c.settings) + (workers !== undefined ? " on " + workers + " workers" : "") +
               (note ? ", noting '" + note + "'" : "") + ": " + (state.addressRefused ? "refused: " + state.address
               : "rendered " + JSON.stringify(settings).slice(0, 80) + " on " + state.workers + " workers" +
               (state.address ? ", noting '" + state.address + "'" : "")));
    }
}

/* A new address without loading the page again (its hash changed), answered. */
async function changeHash(browser, change) {
    const before = await browser.evaluate("labTest.state().checked");
    await browser.evaluate(change);
    await browser.until("labTest.state().checked > " + before, 30, "the page to check its new address");
    return settled(browser);
}

async function checkHistory(browser, report, url) {
    await browser.navigate(url + "#chapter=2&size=16&spp=1&workers=1", 30);
    const first = await settled(browser);
    const second = await changeHash(browser, "location.hash = '#chapter=2&size=16&spp=2&workers=2'");
    report(first.workers === 1 && second.workers === 2 && second.panels[0].complete && second.panels[0].steps === 2,
           "a later workers= is followed: workers=1 then, in the same page, workers=2 gives " + first.workers + " then " +
           second.workers + " workers (" + second.panels[0].stats.split("\n")[0] + ")");
    const refused = await changeHash(browser, "location.hash = '#chapter=99'");
    const back = await changeHash(browser, "history.back()");
    const forward = await changeHash(browser, "history.forward()");
    report(refused.addressRefused && !back.addressRefused && back.address === "" && back.panels[0].complete &&
           back.panels[0].chapter === 2 && back.workers === 2 && forward.addressRefused,
           "history: a refused address, then back (" + (back.addressRefused ? "refused: " + back.address : "chapter " +
           back.panels[0].chapter + " on " + back.workers + " workers, no message") + "), then forward (" +
           (forward.addressRefused ? "refused again" : "taken") + ")");
    await browser.navigate(url + "#chapter=2&size=16&spp=1", 30);
    await settled(browser);
    const typed = await changeHash(browser, "(function () { const e = document.querySelector('#panel-a .settings input[name=size]'); " +
                                            "e.value = '16 chapter=7'; e.onchange(); })()");
    report(typed.addressRefused && typed.address.indexOf("size: '16 chapter=7' has white space in it") >= 0,
           "'16 chapter=7' typed in the width field: " + typed.address);
}

async function checkLimits(browser, report, labNative) {
    const cases = [
        [["room.scene", "chapter=2 size=16 spp=4", 0, 0, 2147483647, 3], "samples 2147483647 to 2147483649: the render takes samples 0 to 3 of a pixel"],
        [["room.scene", "chapter=8 size=16 spp=2 passes=2", 0, 0, 3, 2], "samples 3 to 4: the render takes samples 0 to 3 of a pixel"],
        [["room.scene", "chapter=2 size=16 spp=64", 0, 0, 0, 65], "paths: expected a whole number from 1 to 64, got 65"],
        [["room.scene", "chapter=2 size=16 spp=4", 16, 0, 0, 1], "pixel: (16, 0) is not in the 16 x 16 image"],
        [["room.scene", "chapter=7 size=16%20chapter%3D2 spp=4", 0, 0, 0, 1], "size: '16 chapter=2' has white space in it; expected a whole number from 1 to 4096 alone"],
        [["room.scene", "chapter=7 size=16 spp=4", 3, 4, 0, 4], ""],
    ];
    for (const [args, expected] of cases) {
        const shown = await browser.evaluate("labTest.recordError(" + args.map(function (a) { return JSON.stringify(a); }).join(", ") + ")", 60);
        report(shown === expected, "the inspector's recording of " + JSON.stringify(args.slice(1)) + ": " + (shown || "recorded"));
    }
    const result = childProcess.spawnSync(labNative, ["scenes/room.scene", "chapter=2 size=16", "record", "4294967296", "0", "0", "1"], {encoding: "utf8"});
    report(result.status === 2 && result.stderr.trim() === "lab-native: expected a whole number from 0 to 2147483647, got '4294967296'",
           "lab-native refuses a column of 2^32 (status " + result.status + "): " + result.stderr.trim());
}

/* Equal time: the pool's choice counts a task in flight from the moment it was sent; and
 * M = 1 against M = 1000 (whose samples cost five hundred times more) gives both panels
 * the same processor time, within 15 % (their tasks are short: the bands shrink with M). */
async function checkEqualTime(browser, report, url) {
    const choice = await browser.evaluate("labTest.equalTimeChoice()");
    report(choice.chose === "B" && Math.abs(choice.used[0] - 3) < 0.1 && choice.used[1] === 2.5,
           "equal time: A with 1 s of finished tasks and one in flight for 2 s has used " + choice.used[0].toFixed(2) +
           " s, B with 2.5 s and none " + choice.used[1] + " s: the next task goes to " + choice.chose);
    await browser.navigate(url + "#chapter=3&size=32&M=1&spp=250&b.M=1000&fairness=time&workers=2", 30);
    await browser.until("labTest.state().panels.every(p => p.complete || p.error)", 300, "the two panels at equal time");
    const [a, b] = (await browser.evaluate("labTest.state()")).panels;
    const ratio = b.seconds / a.seconds;
    report(a.complete && b.stopped && Math.abs(ratio - 1) <= 0.15,
           "equal time, M = 1 against M = 1000 on 2 workers: processor seconds " + a.seconds.toFixed(3) + " and " +
           b.seconds.toFixed(3) + " (ratio " + ratio.toFixed(2) + ", the longest tasks " + a.longest.toFixed(3) + " and " +
           b.longest.toFixed(3) + " s), " + a.done + " and " + b.done.toFixed(2) + " samples");
}

/* The editor refuses what the command line refuses: a scene over 64 MiB, with its message. */
async function checkSceneSize(browser, report, url, last, editorDir) {
    const room = fs.readFileSync("scenes/room.scene", "utf8"), size = 65 * 1024 * 1024;
    const file = path.join(editorDir, "room.scene");
    fs.writeFileSync(file, room + "#" + "x".repeat(size - room.length - 1));
    const result = childProcess.spawnSync(last.path, ["--scene", "room.scene", "--quiet", "--size", "8", "--out", "out"],
                                          {cwd: editorDir, encoding: "utf8"});
    fs.rmSync(file);
    const message = result.stderr.split("\n")[0].slice(last.program.length + 2);
    await browser.navigate(url + "#chapter=2&size=16&spp=1", 30);
    await settled(browser);
    const shown = await browser.evaluate("labTest.editScene('room.scene', LAB_SCENES['room.scene'] + '#' + 'x'.repeat(" +
                                         (size - room.length - 1) + "))", 120);
    report(result.status === 2 && shown === message, "the editor, a scene of 65 MiB: '" + shown + "'" +
           (shown === message ? " is " + last.program + "'s message" : " but " + last.program + " says '" + message + "'"));
}

/* A scene file opened in the editor (the file input): its text is what apply reads. */
async function checkSceneFile(browser, report, url, editorDir) {
    const file = path.resolve(editorDir, "opened.scene");
    fs.writeFileSync(file, fs.readFileSync("scenes/room.scene", "utf8") + "cube white 0 0 0 1\n");
    await browser.navigate(url + "#chapter=2&size=16&spp=1", 30);
    await settled(browser);
    const input = await browser.command("Runtime.evaluate", {expression: "document.getElementById('scene-file')"});
    await browser.command("DOM.enable");
    await browser.command("DOM.setFileInputFiles", {files: [file], objectId: input.result.objectId});
    await browser.until("editorText.indexOf('cube white') >= 0", 30, "the opened file in the editor");
    const shown = await browser.evaluate("applyScene()", 60);
    fs.rmSync(file);
    report(shown === "room.scene:31: unknown keyword 'cube'",
           "a scene file opened in the editor is what apply reads: '" + shown + "'");
}

async function checkBook(browser, report, url) {
    await browser.navigate(url + "#chapter=3&size=16&spp=1", 30);
    const state = await settled(browser);
    const later = await changeHash(browser, "(function () { const e = document.querySelector('#panel-a .settings select[name=chapter]'); " +
                                            "e.value = '5'; e.onchange(); })()");
    const text = await browser.evaluate("document.getElementById('book').textContent");
    report(state.book === "../book/chapter3.html" && later.book === "../book/chapter5.html" && text === "chapter 5 in the book",
           "the link to the book follows panel A's chapter: " + state.book + ", then " + later.book + " ('" + text + "')");
}

module.exports = {commandLine, checkShared, checkRanges, checkHostile, checkHistory, checkLimits, checkEqualTime,
                  checkSceneSize, checkSceneFile, checkBook};
