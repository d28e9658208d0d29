/* gallery.h (bench, chapter 1): one static HTML page with every chapter's figures, tables and
 * plots.
 *
 * Introduced in chapter 1. Concept-free, like table.h: it renders nothing, it shows what
 * the chapter programs wrote into a figures folder, so that a class can see every figure
 * together with what it cost and what it bought. The page is written into that folder and
 * links every file by its bare name, so the folder can be copied or zipped as it is. It
 * works from disk: no script, no network, one small inline style sheet. Every text taken
 * from a file (names, CSV cells, text files, the run record, diffs) is HTML-escaped.
 *
 * Chapter N's files are those named chNN_* (NN two digits); each is shown once:
 *   chNN_*.png  a figure (comparison figure or plot; those named in the chapter's `plots`
 *               are shown under "Plots") unless a PFM of the same name and the same size
 *               lies beside it: then it is that panel's picture, and is linked. (A figure
 *               is taller than its panels, by its caption band, figure.h.)
 *   chNN_*.csv  an HTML table: the first row names the columns, whatever they are; cells
 *               are shown as the CSV has them, numbers right-aligned;
 *   chNN_*.txt  shown as it is, under the chapter's settings (e.g. the settings a run used);
 *   chNN_exercise*.png, .txt  the solution's exercise pictures and verdicts (README.md, "Do
 *               the chapters yourself"), under their own heading;
 *   any other   linked (the panels' PFM radiance, ...).
 * A chapter without any file is listed with a note that it is not rendered yet. A
 * figure links to the lab (bench/lab/), when the page knows where it is, with the
 * settings that render that figure live.
 *
 * run.txt in the folder, written by `make figures`, records the run as key=value lines:
 * started, finished, seconds, threads, quick (1 for QUICK figures; the page is then marked
 * QUICK). Missing, the page says that no run was recorded.
 *
 * diff-chapterN.txt or diff-chapterN.diff in the diffs folder (the lines of
 * `make diff-chapterN`) is shown in a folded block, when there is one.
 */
#ifndef GALLERY_H
#define GALLERY_H

#include <time.h>

typedef struct {
    int number;             /* N: its files are chNN_* */
    const char *title;      /* "Whitted ray tracing" */
    const char *teaches;    /* two or three sentences */
    const char *reproduces; /* which figures of the report, in a phrase */
    const char *plots;      /* names (without ".png") of its figures that are plots,
                               separated by spaces; NULL for none */
    const char *figures;    /* names (without ".png") of every figure it writes, separated
                               by spaces: one missing is shown as not rendered */
    const char *lab;        /* each figure's settings in the lab (docs/lab.md) as pairs
                               "NAME FRAGMENT", separated by spaces, e.g. "ch03_figure11
                               chapter=3&M=1&b.M=30"; NULL for none */
} GalleryChapter;

typedef struct {
    const char *title;   /* the page's title */
    const char *figures; /* the folder with the files; the page goes there */
    const char *diffs;   /* the folder with diff-chapterN.txt or .diff; NULL: none */
    const GalleryChapter *chapters;
    int chapter_count;
    time_t made;      /* when the page is made, as shown in its header */
    const char *lab;  /* the lab's page, relative to the figures folder; NULL: no links to it.
                         A figure with settings in the lab links to it with them, and with
                         the width of its chapter's panels (size=W, from their PFMs) */
    const char *book; /* the book's folder (make book), relative to the figures folder; NULL: no
                         links to it. The page links to its index.html, and each chapter to
                         its chapterN.html */
} GalleryPage;

/* Write the page as figures/index.html, whole or not at all (atomic_file.h). Returns 0,
 * or -1 with "what failed: why" in error[error_size]. */
int gallery_write(const GalleryPage *page, char *error, int error_size);

#endif
