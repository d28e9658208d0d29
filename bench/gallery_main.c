/* gallery_main.c (bench, chapter 1): the program that writes the page of every figure,
 * build/figures/index.html (gallery.h).
 *
 * Not a chapter: it renders nothing. It writes one static HTML page from the files the
 * chapter programs left in the figures folder, with what each chapter teaches and which
 * figure of the report it reproduces (the texts below), and prints "wrote PATH".
 * `make figures` runs it at the end; `make gallery` runs it alone.
 *
 *   gallery [--out DIR] [--diffs DIR] [--lab URL] [--book DIR] [--help]
 */
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <errno.h>

#include "gallery.h"

static const GalleryChapter CHAPTERS[] = {
    {1, "Whitted ray tracing",
     "One ray leaves the eye through each pixel's centre. Where it meets a diffuse surface a "
     "single shadow ray asks whether the point light is visible; mirrors and glass send the "
     "ray on, reflected or refracted, recursively. Nothing is random, so there is no noise, "
     "but the shadows are hard and no light travels from one wall to another.",
     "the report's Figure 1 (the room by Whitted ray tracing)", NULL, "ch01_figure1",
     "ch01_figure1 chapter=1"},
    {2, "Monte Carlo integration of diffuse light",
     "A diffuse surface now reflects light arriving from every direction: each bounce picks "
     "one direction at random, with the cosine-weighted density of the Lambert BRDF, and a "
     "pixel averages many such random paths. Colour bleeds from wall to wall and the light "
     "is found only when a path happens to hit it, which is the noise you see; samples "
     "placed in sub-pixels are compared with samples placed at random.",
     "the report's Figure 2 (the room by Monte Carlo ray tracing) and Figure 8 (1 against "
     "4 samples per pixel)",
     NULL, "ch02_figure2 ch02_figure8 ch02_subpixels_vs_random",
     "ch02_figure2 chapter=2&spp=64 ch02_figure8 chapter=2&spp=1&b.spp=4 "
     "ch02_subpixels_vs_random chapter=2&spp=4&b.sampling=random"},
    {3, "Shadow rays",
     "Instead of waiting for a random path to hit the small ceiling light, every diffuse hit "
     "sends M shadow rays to random points on the area light and adds what they see "
     "(the report's eq. 21). The tables measure what each extra shadow ray costs in time and "
     "what it buys in error; a sweep over M shows where more rays stop paying.",
     "the report's Figure 11 (1 against 30 shadow rays)", NULL, "ch03_figure11 ch03_figure8",
     "ch03_figure11 chapter=3&M=1&spp=4&b.M=30 ch03_figure8 chapter=3&spp=1&b.spp=4"},
    {4, "Fresnel glass and ray depth",
     "Glass bends light by Snell's law, reflects all of it beyond the critical angle, and "
     "otherwise splits it between reflection and refraction by the Fresnel equations, exactly "
     "or by Schlick's cheaper approximation. A maximum ray depth cuts long paths short: depth "
     "3 against depth 8 shows the light lost inside the glass sphere.",
     "the report's Figure 9 (ray depth 3 against 8), and Schlick against exact Fresnel: both "
     "curves over the angle, and their time and error in the room",
     "ch04_fresnel_curve", "ch04_figure9 ch04_figure9_crop ch04_fresnel_curve",
     "ch04_figure9 chapter=4&depth=3&b.depth=8 ch04_figure9_crop chapter=4&depth=3&b.depth=8 "
     "ch04_fresnel_curve "
     "chapter=4&fresnel=schlick&b.fresnel=exact&reference=exact&fairness=time"},
    {5, "The Oren-Nayar reflector",
     "A rough surface is modelled as many tiny Lambertian facets whose slopes spread by a "
     "roughness sigma (the report's eqs. 13-14, corrected). Lit from "
     "the eye, a Lambertian sphere darkens towards its rim while a rough one looks flat; a "
     "sweep over sigma goes from Lambert (sigma = 0) to very rough.",
     "the report's Figure 10 (Oren-Nayar against Lambertian)", NULL,
     "ch05_figure10 ch05_sigma_sweep",
     "ch05_figure10 chapter=5 ch05_sigma_sweep chapter=5&sigma=0&b.sigma=1"},
    {6, "Russian roulette",
     "Paths end at random instead of at a fixed depth: at each diffuse bounce a path survives "
     "with probability alpha and its weight is divided by alpha, so the estimate stays "
     "unbiased. A small alpha is fast but noisy, and below the squared reflectance of the "
     "brightest wall the variance is infinite; the sweep shows which alpha gives the most "
     "accuracy per second.",
     "the report's Figure 12 (alpha = 0.01 against 0.5)", NULL, "ch06_figure12",
     "ch06_figure12 chapter=6&rr=0.01&b.rr=0.5"},
    {7, "The final image and the benchmarks",
     "Everything together: sub-pixel sampling, shadow rays, Fresnel glass and Russian "
     "roulette render the report's final image, with the levers that spend the samples "
     "where the error is (the lamp's image in the mirror wall as a light, bounces aimed at "
     "the glass and mirror spheres, stratified pairs), each measured in the levers table. "
     "The report's six benchmark settings are timed again on this machine, each with its "
     "error. A log-log plot shows each estimator's error falling with time, against a "
     "slope of -1/2.",
     "the report's Figure 7 (the final image) and Table 1 (the benchmarks)", "ch07_convergence",
     "ch07_figure7_captioned ch07_convergence",
     "ch07_figure7_captioned chapter=7 "
     "ch07_convergence chapter=6&M=1&rr=0.25&spp=64&b.M=30&fairness=time"},
    {8, "Photon-mapped caustics",
     "Light focused by the glass sphere onto the floor (a caustic) is found by a path tracer "
     "only by chance, as bright speckles. Photons are traced from the light instead, those "
     "that land on a diffuse surface after glass are stored in a hashed grid, and the caustic "
     "is "
     "estimated from their density around each point seen.",
     "beyond the report (its section 5 names photon mapping as future work): the room "
     "without speckles, at equal time against chapter 7",
     NULL, "ch08_equal_time ch08_caustic_crop ch08_error_plot",
     "ch08_equal_time chapter=7&b.chapter=8&fairness=time ch08_caustic_crop "
     "chapter=7&b.chapter=8&fairness=time "
     "ch08_error_plot chapter=7&b.chapter=8&fairness=time"},
    {9, "Fast",
     "The same images, faster: how many rays a second one core traces when every ray tests "
     "every primitive, with chapter 2's binary tree of double boxes, and with a tree of four "
     "float boxes a node, rounded outward so that it never loses a hit; then on every core. "
     "Each stage must render the same image bit for bit. On the room a tree buys little (40 "
     "primitives); with a knot of 200,000 triangles it is everything.",
     "beyond the report (its discussion, section 5, names multithreading among the ways to "
     "cut its 311-minute final render): rays per CPU second per stage, on the room and on "
     "the room with a large mesh",
     "ch09_figure", "ch09_figure", NULL},
    {10, "Adaptive",
     "Render to an error, not to a sample count. Each pixel's samples go to two independent "
     "half-images, whose difference estimates the pixel's error, pooled over a 3 x 3 window; "
     "passes add samples only where it is above the threshold, until the image's estimated "
     "error reaches the target. Deciding from the samples that are kept biases dark pixels; "
     "deciding from one half and keeping the other does not.",
     "beyond the report: adaptive against uniform samples and the photon map at equal "
     "time, the maps of samples and of the estimated error, and the time to reach 5, 2, 1 "
     "and 0.5 % relative RMSE",
     NULL, "ch10_equal_time ch10_maps", NULL},
};

static void usage(FILE *out)
{
    fputs("usage: gallery [options]\n"
          "Writes DIR/index.html: one static page with every chapter's figures, tables and\n"
          "plots, from the files in DIR (nothing is rendered).\n\n"
          "options:\n"
          "  --out   DIR  the figures folder; the page goes there (default build/figures)\n"
          "  --diffs DIR  folder with diff-chapterN.txt or .diff (default: the --out folder)\n"
          "  --lab   URL  the lab's page, relative to the --out folder: each figure links to\n"
          "               it with its settings (default: no links)\n"
          "  --book  DIR  the book's folder (make book), relative to the --out folder: the\n"
          "               page and each chapter link to it (default: no links)\n"
          "  --help       this help\n",
          out);
}

int main(int argc, char **argv)
{
    const char *out = "build/figures", *diffs = NULL, *lab = NULL, *book = NULL;
    for (int i = 1; i < argc; i++) {
        const char **value = strcmp(argv[i], "--out") == 0     ? &out
                             : strcmp(argv[i], "--diffs") == 0 ? &diffs
                             : strcmp(argv[i], "--lab") == 0   ? &lab
                             : strcmp(argv[i], "--book") == 0  ? &book
                                                               : NULL;
        if (strcmp(argv[i], "--help") == 0) {
            usage(stdout);
            return 0;
        }
        if (!value || i + 1 == argc) {
            fprintf(stderr, "gallery: %s '%s'\n",
                    value ? "a folder must follow" : "unknown option", argv[i]);
            usage(stderr);
            return 2;
        }
        *value = argv[++i];
    }
    /* The --out folder, made as every chapter program makes it (mkdir -p). */
    char folder[4096];
    snprintf(folder, sizeof folder, "%s", out);
    for (char *p = folder + 1;; p++) {
        int end = *p == '\0';
        if (*p == '/' || end) {
            *p = '\0';
            if (mkdir(folder, 0777) != 0 && errno != EEXIST) {
                fprintf(stderr, "gallery: cannot make %s: %s\n", folder, strerror(errno));
                return 1;
            }
            if (end)
                break;
            *p = '/';
        }
    }
    GalleryPage page = {"Monte Carlo ray tracer: every figure",
                        out,
                        diffs ? diffs : out,
                        CHAPTERS,
                        (int)(sizeof CHAPTERS / sizeof CHAPTERS[0]),
                        time(NULL),
                        lab,
                        book};
    char error[4400];
    if (gallery_write(&page, error, sizeof error) != 0) {
        fprintf(stderr, "gallery: %s\n", error);
        return 1;
    }
    printf("wrote %s/index.html\n", out);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "gallery: cannot write to the standard output: %s\n", strerror(errno));
        return 1;
    }
    return 0;
}
