/* browser_book.js (bench, chapter 1): every page of the book in headless Chromium (make
 * book-test).
 *
 *   node bench/book/browser_book.js BOOK OUT FIGURES
 *
 * Opens each BOOK/*.html from file:// (bench/lab/chromium.js) and fails, naming the page,
 * unless: nothing is written to the console and nothing fails to load; every listing
 * directive of the page's Markdown (docs/NAME.md) is a listing on the page, each with
 * code in it; every link and image (to the gallery, the lab, other pages, source files)
 * names a file that exists, and a link to a place in a page names an element of it; each
 * figure whose picture is in FIGURES (the gallery's folder) is shown, and each that is not
 * says how to make it;
 * no raw TeX is left in the page's text ("$" or a backslash command) and the page has a
 * <math> element for each equation of its Markdown. Screenshots of chapters 1 and 8 go to
 * OUT/chapterN.png (the top) and OUT/chapterN-section.png (a derivation and its code). The check is run first on a copy of chapter 1's page with a broken
 * link, a raw "$x$" and a listing removed: unless it finds all three, the check is broken.
 */
"use strict";

const fs = require("fs");
const path = require("path");
const {Chromium, fileUrl} = require("../lab/chromium.js");

const [book, out, figures] = process.argv.slice(2);
if (!book || !out || !figures) {
    console.error("usage: node bench/book/browser_book.js BOOK OUT FIGURES");
    process.exit(2);
}
fs.mkdirSync(out, {recursive: true});

/* What the page's Markdown asks for: its listing directives and its equations. */
function expected(markdown) {
    const text = fs.readFileSync(markdown, "utf8");
    const listings = (text.match(/^```\{\.listing[^}]*\}/gm) || []).length;
    const withoutCode = text.replace(/^```[\s\S]*?^```/gm, "").replace(/`[^`\n]*`/g, "");
    const display = (withoutCode.match(/\$\$[\s\S]+?\$\$/g) || []).length;
    const inline = (withoutCode.replace(/\$\$[\s\S]+?\$\$/g, "").match(/\$[^$\s][^$]*?\$/g) || []).length;
    return {listings: listings, math: display + inline};
}

/* Runs in the page: what it shows. */
const INSPECT = `(() => {
    const links = [];
    for (const a of document.querySelectorAll("a[href]")) links.push(a.getAttribute("href"));
    for (const img of document.querySelectorAll("img")) links.push(img.getAttribute("src"));
    const ids = Array.from(document.querySelectorAll("[id]")).map((e) => e.id);
    const listings = Array.from(document.querySelectorAll("div.listing"));
    const clone = document.body.cloneNode(true);
    for (const e of clone.querySelectorAll("code, pre, math")) e.remove();
    return {
        links: links, ids: ids,
        listings: listings.length,
        emptyListings: listings.filter((l) => !l.querySelector("pre code") ||
                                              !l.querySelector("pre code").textContent.trim()).length,
        math: document.querySelectorAll("math").length,
        figures: Array.from(document.querySelectorAll("div.figure")).map((f) => ({
            name: f.dataset.figure, image: f.querySelector("img") !== null,
            note: /make chapter[0-9]/.test(f.textContent)})),
        text: clone.textContent,
        images: Array.from(document.images).filter((i) => !(i.complete && i.naturalWidth > 0)).map((i) => i.src),
    };
})()`;

async function check(browser, page, markdown) {
    const problems = [];
    browser.problems = [];
    await browser.navigate(fileUrl(page), 60);
    const seen = await browser.evaluate(INSPECT);
    for (const p of browser.problems) problems.push(p);
    for (const src of seen.images) problems.push("an image did not load: " + src);
    const dir = path.dirname(page);
    for (const href of seen.links) {
        if (/^[a-z]+:/i.test(href)) {
            problems.push("a link leaves the book's files: " + href);
            continue;
        }
        const [file, anchor] = href.split("#");
        const target = file === "" ? page : path.resolve(dir, decodeURIComponent(file));
        if (!fs.existsSync(target)) {
            problems.push("a link to a missing file: " + href);
        } else if (anchor && file === "" && !seen.ids.includes(decodeURIComponent(anchor))) {
            problems.push("a link to a missing place: " + href);
        } else if (anchor && file !== "" && target.endsWith(".html") && !target.includes("/lab/") &&
                   !fs.readFileSync(target, "utf8").includes('id="' + decodeURIComponent(anchor) + '"')) {
            problems.push("a link to a missing place: " + href);
        }
    }
    /* a figure of the folder is shown; one missing says how to make it */
    for (const f of seen.figures) {
        const there = fs.existsSync(path.join(figures, f.name + ".png"));
        if (there && !f.image) problems.push("figure " + f.name + " is in " + figures + " but not shown");
        if (!there && (f.image || !f.note)) problems.push("figure " + f.name + " is missing but the page does not say how to make it");
    }
    const tex = seen.text.match(/\$[^\n]{0,40}|\\[a-zA-Z]+\{?[^\n]{0,20}/);
    if (tex) problems.push("raw TeX in the text: " + JSON.stringify(tex[0]));
    if (markdown && fs.existsSync(markdown)) {
        const want = expected(markdown);
        if (seen.listings !== want.listings)
            problems.push(seen.listings + " listings on the page, " + want.listings + " directives in " + markdown);
        if (seen.emptyListings > 0) problems.push(seen.emptyListings + " listings without code");
        if (seen.math < want.math)
            problems.push(seen.math + " <math> elements, " + want.math + " equations in " + markdown);
    }
    return {problems: problems, listings: seen.listings, math: seen.math, links: seen.links.length,
            figures: seen.figures.filter((f) => f.image).length + "/" + seen.figures.length};
}

(async () => {
    const browser = await Chromium.open(1100, 1400);
    let failed = 0;
    try {
        /* The check itself, on a spoiled copy of chapter 1's page (beside it, so that its
         * links resolve as the page's do). */
        const page1 = path.join(book, "chapter1.html");
        const spoiled = path.join(book, "spoiled-chapter1.html");
        let html = fs.readFileSync(page1, "utf8");
        html = html.replace('href="chapter2.html"', 'href="no-such-chapter.html"')
                   .replace("<h2", "<p>raw $x$ left</p><h2")
                   .replace(/<div class="listing"/, '<div class="spoiled"');
        fs.writeFileSync(spoiled, html);
        const planted = await check(browser, spoiled, "docs/chapter1.md");
        fs.rmSync(spoiled);
        const wanted = ["no-such-chapter.html", "raw TeX", "listings on the page"];
        const missed = wanted.filter((w) => !planted.problems.some((p) => p.includes(w)));
        if (missed.length > 0) {
            console.error("browser_book: the check missed what was planted: " + missed.join(", "));
            process.exit(1);
        }
        console.log("planted (broken link, raw $x$, a listing removed): all three found");

        for (const name of fs.readdirSync(book).filter((f) => f.endsWith(".html")).sort()) {
            const page = path.join(book, name);
            const markdown = path.join("docs", name.replace(/\.html$/, ".md"));
            const result = await check(browser, page, markdown);
            console.log(name + ": " + result.listings + " listings, " + result.math + " equations, " + result.figures + " figures shown, " +
                        result.links + " links" + (result.problems.length ? ", FAILED" : ", ok"));
            for (const p of result.problems) console.log("    " + p);
            failed += result.problems.length > 0;
            const shots = {"chapter1.html": "10. Spheres", "chapter8.html": "5. Progressive"};
            if (shots[name]) {
                const base = path.join(out, name.replace(/\.html$/, ""));
                await browser.screenshot(base + ".png");
                /* and a derivation with its code: the section that `shots` names */
                await browser.evaluate("Array.from(document.querySelectorAll('h2')).find((h) => " +
                                       "h.textContent.startsWith(" + JSON.stringify(shots[name]) +
                                       ")).scrollIntoView()");
                await browser.screenshot(base + "-section.png");
            }
        }
    } finally {
        await browser.close();
    }
    if (failed) {
        console.error("browser_book: " + failed + " page(s) failed");
        process.exit(1);
    }
    console.log("browser_book: every page passed; screenshots in " + out);
})().catch((error) => {
    console.error("browser_book: " + error.message);
    process.exit(1);
});
